// K_ij tables, layout version 2 (docs/KIJ_TABLE.md): provenance and first-pass range round trip;
// a version 1 file written with the plain HDF5 C API is still read.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "ferro/contact/kij/kij_table.hpp"

namespace fc = ferro::contact;

namespace {

std::string temp_path(const char* name) {
  return (std::filesystem::temp_directory_path() / name).string();
}

// Writes a version 1 table by hand: axis "layer_thickness" {0, 1e-4}, K11 {1, 0.5}, K22 = K23 = 1.
void write_version1(const std::string& path) {
  const hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  const hid_t scalar = H5Screate(H5S_SCALAR);
  const hid_t a = H5Acreate2(f, "schema_version", H5T_NATIVE_INT, scalar, H5P_DEFAULT, H5P_DEFAULT);
  const int one = 1;
  H5Awrite(a, H5T_NATIVE_INT, &one);
  H5Aclose(a);
  const hid_t g = H5Gcreate2(f, "axes", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  const hsize_t n = 2;
  const hid_t space = H5Screate_simple(1, &n, nullptr);
  auto put = [&](hid_t where, const char* name, const double* v) {
    const hid_t d =
        H5Dcreate2(where, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v);
    return d;
  };
  const double axis[2] = {0.0, 1.0e-4}, k11[2] = {1.0, 0.5}, ones[2] = {1.0, 1.0};
  const hid_t d = put(g, "layer_thickness", axis);
  const hid_t ia = H5Acreate2(d, "index", H5T_NATIVE_INT, scalar, H5P_DEFAULT, H5P_DEFAULT);
  const int zero = 0;
  H5Awrite(ia, H5T_NATIVE_INT, &zero);
  H5Aclose(ia);
  H5Dclose(d);
  H5Dclose(put(f, "K11", k11));
  H5Dclose(put(f, "K22", ones));
  H5Dclose(put(f, "K23", ones));
  H5Sclose(space);
  H5Sclose(scalar);
  H5Gclose(g);
  H5Fclose(f);
}

}  // namespace

TEST(kij_table_v2, provenance_and_first_pass_round_trip) {
  constexpr double kExact = 1e-12;  // stored doubles, linear data
  fc::KijTable t({"normal_force", "layer_yield_shear"}, {{73.6e3, 147.2e3}, {1.0e8, 3.0e8}},
                 {0.6, 0.7, 0.5, 0.6}, {0.5, 0.55, 0.45, 0.5}, {0.8, 0.8, 0.8, 0.8},
                 {0.9, 0.9, 0.9, 0.9});
  t.set_first_pass({0.5, 0.6, 0.4, 0.5}, {0.4, 0.45, 0.35, 0.4}, {0.7, 0.7, 0.7, 0.7});
  t.set_provenance({{"grid", "40 x 31 elements, dx = 0.41 mm"}, {"solver_tolerance", "1e-05"}});
  const std::string path = temp_path("ferro_kij_v2_test.h5");
  t.write_hdf5(path);
  const fc::KijTable r = fc::KijTable::read_hdf5(path);
  std::remove(path.c_str());
  ASSERT_TRUE(r.has_first_pass());
  EXPECT_EQ(r.provenance().at("grid"), "40 x 31 elements, dx = 0.41 mm");
  EXPECT_EQ(r.provenance().at("solver_tolerance"), "1e-05");
  const fc::ReductionFactors k = r.at(std::vector<double>{110.4e3, 2.0e8});
  EXPECT_NEAR(k.k11, 0.6, kExact);
  EXPECT_NEAR(k.k33, 0.9, kExact);
  const fc::ReductionFactors f = r.first_pass_at(std::vector<double>{110.4e3, 2.0e8});
  EXPECT_NEAR(f.k11, 0.5, kExact);
  EXPECT_NEAR(f.k22, 0.4, kExact);
  EXPECT_NEAR(f.k33, 1.0, kExact);  // no first-pass K33: 1
  EXPECT_THROW(t.set_first_pass({0.5}, {0.4}, {0.7}), std::invalid_argument);
}

TEST(kij_table_v2, reads_version_1) {
  const std::string path = temp_path("ferro_kij_v1_test.h5");
  write_version1(path);
  const fc::KijTable t = fc::KijTable::read_hdf5(path);
  std::remove(path.c_str());
  EXPECT_FALSE(t.has_first_pass());
  EXPECT_TRUE(t.provenance().empty());
  EXPECT_NEAR(t.at(std::vector<double>{5.0e-5}).k11, 0.75, 1e-12);
  EXPECT_THROW((void)t.first_pass_at(std::vector<double>{5.0e-5}), std::logic_error);
}
