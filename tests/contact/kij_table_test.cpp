// K_ij tables: HDF5 round trip in the docs/KIJ_TABLE.md layout and multilinear interpolation.
#include "ferro/contact/kij/kij_table.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace fc = ferro::contact;

namespace {
// K11 linear in both axes: multilinear interpolation must reproduce it exactly anywhere inside.
double k11_of(double load, double thickness) {
  return 0.9 - 2e-6 * load - 1000.0 * thickness;
}

fc::KijTable make_table() {
  const std::vector<double> loads = {50e3, 75e3, 100e3, 150e3};  // N
  const std::vector<double> thick = {0.0, 50e-6, 125e-6};        // m
  std::vector<double> k11, k22, k23;
  for (double l : loads) {
    for (double t : thick) {
      k11.push_back(k11_of(l, t));
      k22.push_back(0.8 * k11_of(l, t));
      k23.push_back(0.7);
    }
  }
  return fc::KijTable({"normal_force", "layer_thickness"}, {loads, thick}, k11, k22, k23);
}
}  // namespace

TEST(kij_table, hdf5_round_trip_and_interpolation) {
  constexpr double kExact = 1e-12;  // bilinear data, bilinear interpolation
  const std::string path =
      (std::filesystem::temp_directory_path() / "ferro_kij_table_test.h5").string();
  make_table().write_hdf5(path);
  const fc::KijTable t = fc::KijTable::read_hdf5(path);
  std::remove(path.c_str());
  ASSERT_EQ(t.axis_names().size(), 2u);
  EXPECT_EQ(t.axis_names()[0], "normal_force");
  EXPECT_EQ(t.axis_names()[1], "layer_thickness");
  for (double load : {50e3, 61e3, 75e3, 123.4e3, 150e3}) {
    for (double th : {0.0, 10e-6, 80e-6, 125e-6}) {
      const fc::ReductionFactors k = t.at({{"normal_force", load}, {"layer_thickness", th}});
      EXPECT_NEAR(k.k11, k11_of(load, th), kExact);
      EXPECT_NEAR(k.k22, 0.8 * k11_of(load, th), kExact);
      EXPECT_NEAR(k.k23, 0.7, kExact);
      EXPECT_NEAR(k.k33, 1.0, kExact);  // no K33 dataset: 1
    }
  }
  EXPECT_EQ(t.clamped_queries(), 0);
  const fc::ReductionFactors c =
      t.at(std::vector<double>{200e3, 0.0});  // clamped to the 150 kN end
  EXPECT_NEAR(c.k11, k11_of(150e3, 0.0), kExact);
  EXPECT_EQ(t.clamped_queries(), 1);
  EXPECT_THROW((void)t.at({{"normal_force", 1.0}}), std::invalid_argument);
  // at_patch fills normal_force from the patch; the other axes must still be given.
  const fc::ContactPatch patch = fc::elliptic_patch(6e-3, 5e-3, 90e3);
  EXPECT_NEAR(t.at_patch(patch, {{"layer_thickness", 50e-6}}).k11, k11_of(90e3, 50e-6), kExact);
  EXPECT_THROW((void)t.at_patch(patch), std::invalid_argument);
}

TEST(kij_table, bad_files_and_tables) {
  EXPECT_THROW((void)fc::KijTable::read_hdf5("/nonexistent/kij.h5"), std::invalid_argument);
  EXPECT_THROW(fc::KijTable({"a"}, {{1.0, 0.5}}, {1, 1}, {1, 1}, {1, 1}), std::invalid_argument);
  EXPECT_THROW(fc::KijTable({"a"}, {{1.0, 2.0}}, {1}, {1, 1}, {1, 1}), std::invalid_argument);
  EXPECT_THROW(fc::KijTable({"a"}, {{1.0, 2.0}}, {1, -1}, {1, 1}, {1, 1}), std::invalid_argument);
}
