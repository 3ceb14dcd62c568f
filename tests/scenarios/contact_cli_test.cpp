// Smoke and consistency tests of `ferrodyn contact eval | curve | patch` on the shipped cases.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>

#include "ferro/contact/kij/kij_table.hpp"
#include "ferro/contact/material.hpp"
#include "ferro/contact/tangential/kalker_coefficients.hpp"
#include "ferro/io/hdf5.hpp"

namespace fs = std::filesystem;

namespace {

struct CliRun {
  int code = -1;
  std::string out;
};

CliRun run(const std::string& args) {
  const std::string cmd = std::string("'") + FERRODYN_EXE + "' " + args + " 2>&1";
  CliRun r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), buf.size(), pipe)) r.out += buf.data();
  const int status = pclose(pipe);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// A number of the JSON object the program printed first (NaN when absent or not a number).
double json_field(const std::string& output, const std::string& key) {
  const auto start = output.find('{');
  if (start == std::string::npos) return NAN;
  const auto j = nlohmann::json::parse(output.substr(start), nullptr, /*allow_exceptions=*/false);
  if (!j.is_object() || !j.contains(key) || !j[key].is_number()) return NAN;
  return j[key].get<double>();
}

fs::path scratch(const std::string& name) {
  const fs::path p = fs::path(FERRO_BINARY_DIR) / "test_output" / name;
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

}  // namespace

// Thesis spheres (R1 = 300 mm, R2 = 460 mm, E = 210 GPa, nu = 0.28, F = 10 kN): kalker_linear
// through the CLI equals F_x = -G a^2 C11 xi_x with the closed-form radius (oracle: Hertz +
// annex A.2 at a/b = 1, interpolated in nu).
TEST(contact_cli_eval, thesis_spheres_linear_theory) {
  constexpr double kTol = 1e-8;  // JSON prints 10 significant digits
  const double r1 = 0.3, r2 = 0.46, force = 1e4, xi = 1e-3;
  const auto steel = ferro::contact::Material::from_young(210e9, 0.28);
  const auto m = ferro::contact::combine(steel, steel);
  const double r = 1.0 / (1.0 / r1 + 1.0 / r2);
  const double a = std::cbrt(3.0 * force * r / (4.0 * m.contact_modulus));
  const double c11 = ferro::contact::kalker_coefficients_table(1.0, 1.0, 0.28).c11;
  const double curv = 0.5 / r1 + 0.5 / r2;
  const CliRun out = run(
      "contact eval --model kalker_linear --curvature-x " + std::to_string(curv) +
      " --curvature-y " + std::to_string(curv) + " --fn 10000 --mu 0.2 --xi-x 0.001" + " --g1 " +
      std::to_string(steel.shear_modulus) + " --g2 " + std::to_string(steel.shear_modulus));
  ASSERT_EQ(out.code, 0) << out.out;
  EXPECT_NEAR(json_field(out.out, "semi_axis_x") / a, 1.0, 1e-6);  // curvature printed to 6 digits
  EXPECT_NEAR(
      json_field(out.out, "force_x") / (-m.shear_modulus * json_field(out.out, "semi_axis_x") *
                                        json_field(out.out, "semi_axis_y") * c11 * xi),
      1.0, kTol);
  EXPECT_NE(out.out.find("on the wheel from the rail"), std::string::npos);
}

TEST(contact_cli_eval, batch_and_errors) {
  const fs::path dir = scratch("contact_cli_batch");
  const fs::path csv = dir / "in.csv";
  std::ofstream(csv)
      << "model,xi_x,xi_y,k11\nfastsim,0.001,0,1\nchopaya,0.001,0,0.5\npolach,0,0.002,1\n";
  const CliRun out = run("contact eval --batch --a 0.0065 --b 0.0049 --fn 73575 --mu 0.3 < '" +
                         csv.string() + "'");
  ASSERT_EQ(out.code, 0) << out.out;
  std::istringstream lines(out.out);
  std::string line;
  int rows = 0;
  while (std::getline(lines, line)) ++rows;
  EXPECT_EQ(rows, 4);  // header + 3 cases
  std::ofstream(csv) << "model,xi_z\nfastsim,0.001\n";
  const CliRun bad = run("contact eval --batch --a 0.0065 --b 0.0049 --fn 73575 --mu 0.3 < '" +
                         csv.string() + "'");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.out.find("xi_z"), std::string::npos);
  EXPECT_EQ(run("contact eval --a 0.0065 --b 0.005 --fn 1 --mu 0.3 --model nope").code, 2);
  EXPECT_EQ(run("contact eval --a 0.0065 --fn 1 --mu 0.3").code, 2);
}

// Creep curves of the thesis sphere case: CSV (every model x every curve), HDF5, PNG.
TEST(contact_cli_curve, thesis_spheres_all_models) {
  const fs::path dir = scratch("contact_cli_curve");
  const std::string yaml =
      std::string(FERRO_SOURCE_DIR) + "/scenarios/cases/contact/thesis_spheres.yaml";
  const CliRun out = run("contact curve '" + yaml + "' -o '" + dir.string() + "'");
  if (out.code == 1 && out.out.find("no Python with matplotlib") != std::string::npos) {
    GTEST_SKIP() << "matplotlib unavailable: " << out.out;
  }
  ASSERT_EQ(out.code, 0) << out.out;
  {
    // HDF5: /longitudinal/kalker_linear/force_x has one value per point.
    const std::string h5 = (dir / "thesis_spheres_curves.h5").string();
    const auto f = ferro::io::H5File::open_read(h5);
    EXPECT_EQ(f.read_array("/longitudinal/kalker_linear/force_x").size(), 81u);
  }
  EXPECT_GT(fs::file_size(dir / "thesis_spheres_curves.png"), 10000u);
  std::ifstream csv(dir / "thesis_spheres_curves.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "curve,model,creepage,force_x,force_y,moment_z,force_t");
  std::map<std::string, int> per_model;
  int rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    const auto q1 = line.find('"'), q2 = line.find('"', q1 + 1);
    ++per_model[line.substr(q1 + 1, q2 - q1 - 1)];
  }
  EXPECT_EQ(per_model.size(), 9u);  // 9 model entries in the case
  EXPECT_EQ(rows, 9 * (81 + 81 + 81 + 41));
  EXPECT_EQ(run("contact curve /nonexistent.yaml").code, 2);
}

TEST(contact_cli_patch, spheres_and_two_lobes) {
  const fs::path dir = scratch("contact_cli_patch");
  for (const char* name : {"thesis_spheres", "semi_hertz_two_lobes"}) {
    const std::string yaml =
        std::string(FERRO_SOURCE_DIR) + "/scenarios/cases/contact/" + name + ".yaml";
    const CliRun out = run("contact patch '" + yaml + "' --no-plots -o '" + dir.string() + "'");
    ASSERT_EQ(out.code, 0) << out.out;
    EXPECT_TRUE(fs::exists(dir / (std::string(name) + "_patch.csv")));
    const bool two = std::string(name) == "semi_hertz_two_lobes";
    EXPECT_EQ(out.out.find("\"patch\": 1") != std::string::npos, two) << out.out;
  }
}

// --kij-table: a K_ij table interpolated at the given point scales the linear force exactly.
TEST(contact_cli_eval, kij_table_scales_linear_force) {
  const fs::path dir = scratch("contact_cli_kij");
  const std::string table = (dir / "kij.h5").string();
  ferro::contact::KijTable({"normal_force"}, {{5e4, 1e5}}, {0.8, 0.6}, {0.7, 0.5}, {0.7, 0.5})
      .write_hdf5(table);
  const std::string common =
      "contact eval --model kalker_linear --a 0.0065 --b 0.0049 --fn 73575 --mu 0.3 --xi-x 1e-3 ";
  const CliRun plain = run(common);
  const CliRun reduced = run(common + "--kij-table '" + table + "' --kij-at normal_force=75000");
  ASSERT_EQ(plain.code, 0) << plain.out;
  ASSERT_EQ(reduced.code, 0) << reduced.out;
  EXPECT_NEAR(json_field(reduced.out, "force_x") / json_field(plain.out, "force_x"), 0.7, 1e-9);
  // Without --kij-at the normal_force axis takes the patch's load (73575 N).
  const CliRun from_patch = run(common + "--kij-table '" + table + "'");
  ASSERT_EQ(from_patch.code, 0) << from_patch.out;
  EXPECT_NEAR(json_field(from_patch.out, "force_x") / json_field(plain.out, "force_x"),
              0.8 - 0.2 * (73575.0 - 5e4) / 5e4, 1e-9);
  EXPECT_EQ(run(common + "--kij-table '" + table + "' --kij-at load=1").code, 2);
  // K23 follows K22 unless given (thesis 4.2.4): the spin-induced F_y scales with --k22.
  const std::string spin =
      "contact eval --model kalker_linear --a 0.0065 --b 0.0049 --fn 73575 "
      "--mu 0.3 --phi 0.1 ";
  const CliRun s1 = run(spin), s2 = run(spin + "--k22 0.56"), s3 = run(spin + "--k22 0.56 --k23 1");
  EXPECT_NEAR(json_field(s2.out, "force_y") / json_field(s1.out, "force_y"), 0.56, 1e-9);
  EXPECT_NEAR(json_field(s3.out, "force_y") / json_field(s1.out, "force_y"), 1.0, 1e-9);
}
