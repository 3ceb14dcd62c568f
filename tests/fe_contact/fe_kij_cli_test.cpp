// `ferrodyn fe-kij`: writes a version 2 K_ij table whose values match the library computation,
// resumes from its journal after an interruption, and rejects bad input with exit code 2.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

#include "ferro/contact/kij/kij_table.hpp"
#include "ferro/fe_contact/hertz_case.hpp"

namespace fs = std::filesystem;

namespace {

// Runs `ferrodyn fe-kij ARGS`, returns the exit code.
int run(const std::string& args) {
  const std::string cmd = std::string(FERRODYN_EXE) + " fe-kij " + args + " > /dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Runs `ferrodyn fe-kij ARGS`, returns the exit code and the standard error text.
std::pair<int, std::string> run_capture(const std::string& args) {
  const fs::path err = fs::temp_directory_path() / "ferro_fe_kij_cli_test.err";
  const std::string cmd =
      std::string(FERRODYN_EXE) + " fe-kij " + args + " > /dev/null 2> " + err.string();
  const int status = std::system(cmd.c_str());
  std::ifstream in(err);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text};
}

fs::path write_config(const std::string& name, const std::string& axes) {
  const fs::path dir = fs::temp_directory_path() / "ferro_fe_kij_cli_test";
  fs::create_directories(dir);
  const fs::path p = dir / name;
  std::ofstream(p) << "schema_version: 1\n"
                      "contact: {reference_force: 73575.0, semi_axis_x: 6.66e-3, semi_axis_y: "
                      "5.05e-3, young_modulus: 210.0e9, poisson: 0.28, friction: 0.2, "
                      "elements_minor: 10}\n"
                      "layer: {shear_modulus: 820.0e6}\n"
                      "axes: {"
                   << axes
                   << "}\n"
                      "output: "
                   << name << ".h5\nplots: 'false'\n";
  return p;
}

}  // namespace

TEST(fe_kij_cli, table_matches_library_and_resumes) {
  const fs::path cfg = write_config("two.yaml", "layer_thickness: [0.0, 125.0e-6]");
  const std::string out = cfg.string() + ".h5";
  fs::remove_all(out + ".d");
  ASSERT_EQ(run(cfg.string()), 0);
  const ferro::contact::KijTable t = ferro::contact::KijTable::read_hdf5(out);
  EXPECT_EQ(t.provenance().count("solver_tolerance"), 1u);
  // The same point computed by the library (the verb's numbers are not post-processed).
  ferro::fe_contact::HertzCase c;
  c.reference_force = c.normal_force = 73575.0;
  c.reference_semi_axis_x = 6.66e-3;
  c.reference_semi_axis_y = 5.05e-3;
  c.body = ferro::contact::Material::from_young(210.0e9, 0.28);
  c.friction = 0.2;
  c.elements_minor = 10;
  ferro::fe_contact::InterfaceLayer layer;
  layer.thickness = 125.0e-6;
  layer.shear_modulus = 820.0e6;
  ferro::fe_contact::SlopeOptions opt;
  opt.mim.tangential.tolerance = 1.0e-6;  // the verb's default
  const ferro::fe_contact::SlopeResult r = ferro::fe_contact::layer_reduction_factors(c, layer, opt);
  constexpr double kSame = 1e-12;  // same computation, numbers written with 17 digits
  EXPECT_NEAR(t.at(std::vector<double>{125.0e-6}).k11, r.k.k11, kSame);
  EXPECT_NEAR(t.at(std::vector<double>{125.0e-6}).k22, r.k.k22, kSame);
  EXPECT_NEAR(t.at(std::vector<double>{0.0}).k11, 1.0, kSame);
  // Resume: a removed point is recomputed, the kept one is read back; same table.
  fs::remove(fs::path(out + ".d") / "point_00001.txt");
  fs::remove(out);
  ASSERT_EQ(run(cfg.string()), 0);
  EXPECT_NEAR(ferro::contact::KijTable::read_hdf5(out).at(std::vector<double>{125.0e-6}).k11,
              r.k.k11, kSame);
}

TEST(fe_kij_cli, bad_input_exits_2) {
  EXPECT_EQ(run(write_config("bad_axis.yaml", "layer_thicknes: [0.0]").string()), 2);
  // The rail's yield stress: a bad value, a layer axis beside it; each message names the key.
  for (const auto& [axes, key] :
       {std::pair{"yield_stress: [-489.0e6]", "yield_stress"},
        std::pair{"yield_stress: [489.0e6, 400.0e6]", "yield_stress"},
        std::pair{"yield_stress: [489.0e6], layer_thickness: [0.0]", "layer_thickness"}}) {
    const auto [rc, err] = run_capture(write_config("plastic.yaml", axes).string());
    EXPECT_EQ(rc, 2) << axes;
    EXPECT_NE(err.find(key), std::string::npos) << err;
  }
  {
    const fs::path cfg = write_config("plastic_steps.yaml", "yield_stress: [489.0e6]");
    std::ofstream(cfg, std::ios::app) << "plastic: {load_steps: 0}\n";
    const auto [rc, err] = run_capture(cfg.string());
    EXPECT_EQ(rc, 2);
    EXPECT_NE(err.find("load_steps"), std::string::npos) << err;
  }
  EXPECT_EQ(run(write_config("order.yaml", "layer_thickness: [1.0e-4, 0.0]").string()), 2);
  EXPECT_EQ(run("/nonexistent/fe_kij.yaml"), 2);
}
