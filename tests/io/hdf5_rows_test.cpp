// Reading a 2-D HDF5 dataset by blocks of rows (H5File::read_rows), as a large contact table is
// read: every block equals the corresponding rows of the whole dataset, bit for bit; rows past
// the end and a dataset of another rank are refused, naming the dataset and the file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "ferro/io/hdf5.hpp"

namespace ferro::io {
namespace {

TEST(Hdf5Rows, blocks_of_rows_equal_the_whole_dataset) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("ferro_hdf5_rows_" + std::to_string(::getpid()) + ".h5"))
                               .string();
  constexpr std::size_t kRows = 7, kCols = 3;
  std::vector<double> m(kRows * kCols);
  for (std::size_t i = 0; i < m.size(); ++i) m[i] = 0.1 * static_cast<double>(i) - 1.0 / 3.0;
  {
    H5File f = H5File::create(path);
    f.write_matrix("m", m, kRows, kCols, "m");
    f.write_vector("v", m, "m");
  }
  const H5File f = H5File::open_read(path);
  EXPECT_EQ(f.dimensions("m"), (Dims{kRows, kCols}));
  std::vector<double> whole;
  for (std::size_t first = 0; first < kRows; first += 3) {
    const std::size_t rows = std::min<std::size_t>(3, kRows - first);
    std::vector<double> block(rows * kCols);
    f.read_rows("m", first, rows, block);
    whole.insert(whole.end(), block.begin(), block.end());
  }
  EXPECT_EQ(whole, m);
  std::vector<double> two(2 * kCols);
  EXPECT_THROW(f.read_rows("m", 6, 2, two), Hdf5Error);  // rows 6-7 of 7
  try {
    f.read_rows("v", 0, 2, two);
    ADD_FAILURE() << "a 1-D dataset was read by rows";
  } catch (const Hdf5Error& e) {
    EXPECT_NE(std::string(e.what()).find("v"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace ferro::io
