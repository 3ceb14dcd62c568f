// Smoke test of `ferrodyn mim`: runs, writes the HDF5 file, exit codes of the CLI convention.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace {

int run(const std::string& args) {
  const std::string cmd = std::string(FERRODYN_EXE) + " " + args + " > /dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST(MimCli, solves_and_writes_hdf5) {
  const std::string out = std::string(FERRO_BINARY_DIR) + "/mim_cli_test.h5";
  std::remove(out.c_str());
  EXPECT_EQ(
      run("contact mim --a 4e-3 --b 3e-3 --fn 30000 --xi-x 0.002 --spin 0.5 --mu 0.3 --elements 16 -o " +
          out),
      0);
  std::ifstream f(out, std::ios::binary);
  char magic[8] = {};
  f.read(magic, 8);
  EXPECT_EQ(std::string(magic + 1, 3), "HDF");  // HDF5 signature \x89HDF\r\n\x1a\n
  std::remove(out.c_str());
}

TEST(MimCli, bad_input_exits_2) {
  EXPECT_EQ(run("contact mim --a -4e-3 --b 3e-3 --fn 30000"), 2);
  EXPECT_EQ(run("contact mim --a 4e-3 --b 3e-3"), 2);  // --fn missing
}
