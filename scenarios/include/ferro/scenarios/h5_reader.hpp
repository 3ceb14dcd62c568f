#pragma once
// Reading any ferrodyn HDF5 file back (run outputs, analyses, contact tables, K_ij tables, MIM
// fields; layouts in docs/OUTPUT.md): every dataset with its dimensions and values (numbers as
// float64, text as text) and every attribute of the root, the groups and the datasets, through
// the one HDF5 layer (ferro/io/hdf5.hpp).

#include <cstddef>
#include <string>
#include <vector>

namespace ferro::scenarios {

struct H5Dataset {
  std::string name;                ///< absolute path, e.g. "/signals/wheelset_1.y"
  std::vector<std::size_t> dims;   ///< slowest first; empty for a scalar or text
  std::vector<double> values;      ///< row-major (numeric datasets)
  bool is_text = false;
  std::string text;                ///< text datasets (e.g. /scene/text)
};

struct H5Attribute {
  std::string object;  ///< "/" or the group's or dataset's path
  std::string name;
  bool is_text = false;
  std::string text;
  double number = 0.0;
};

struct H5Contents {
  std::vector<H5Dataset> datasets;      ///< in path order
  std::vector<H5Attribute> attributes;  ///< in path order, then name order
};

/// Reads the whole file. Throws io::Hdf5Error naming the file for a file that is not HDF5.
[[nodiscard]] H5Contents read_h5_file(const std::string& path);

}  // namespace ferro::scenarios
