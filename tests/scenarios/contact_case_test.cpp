// Contact case files through the strict YAML reader: the shipped cases load, and bad input is
// located (file:line:column, key) instead of being ignored or reported by the YAML library.
#include "ferro/scenarios/contact_case.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "ferro/scenarios/yaml_reader.hpp"

namespace ferro::scenarios {
namespace {

namespace fs = std::filesystem;

const std::string kCases = std::string(FERRO_SOURCE_DIR) + "/scenarios/cases/contact/";

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The thesis sphere case with `from` replaced by `to`, written to a scratch file.
std::string variant(const std::string& name, const std::string& from, const std::string& to) {
  std::string text = read_text(kCases + "thesis_spheres.yaml");
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  const fs::path path = fs::temp_directory_path() / ("ferro_case_" + name + ".yaml");
  std::ofstream(path) << text;
  return path.string();
}

int line_of(const std::string& path, const std::string& fragment) {
  std::ifstream in(path);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.find(fragment) != std::string::npos) return n;
  }
  return 0;
}

void expect_error(const std::string& path, const std::string& key, int line,
                  const std::string& hint) {
  try {
    (void)load_contact_case(path);
    ADD_FAILURE() << path << " was accepted";
  } catch (const YamlInputError& e) {
    EXPECT_EQ(e.key(), key) << e.what();
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(hint), std::string::npos) << e.what();
  }
}

TEST(contact_case, shipped_cases_load) {
  const ContactCase spheres = load_contact_case(kCases + "thesis_spheres.yaml");
  // R1 = 300 mm and R2 = 460 mm spheres: A = B = 1/(2 R1) + 1/(2 R2).
  EXPECT_DOUBLE_EQ(spheres.normal.curvature_x, 0.5 / 0.300 + 0.5 / 0.460);
  EXPECT_DOUBLE_EQ(spheres.friction, 0.2);
  EXPECT_EQ(spheres.models.size(), 9u);
  EXPECT_TRUE(spheres.combined.enabled);
  const ContactCase lobes = load_contact_case(kCases + "semi_hertz_two_lobes.yaml");
  EXPECT_GE(lobes.normal.gap_y.size(), 3u);
}

TEST(contact_case, duplicate_key_names_both_lines) {
  const std::string path = variant("duplicate", "friction: 0.2", "friction: 0.2\nfriction: 0.4");
  const int first = line_of(path, "friction: 0.2");
  expect_error(path, "friction", first + 1,
               "first given at line " + std::to_string(first) + ", again at line " +
                   std::to_string(first + 1));
}

TEST(contact_case, unknown_and_misspelt_keys_are_errors) {
  const std::string path = variant("misspelt", "friction: 0.2", "fricton: 0.2");
  expect_error(path, "fricton", line_of(path, "fricton"), "'friction' is required here");
  const std::string extra = variant("extra", "curves:", "curve_style: dashed\ncurves:");
  expect_error(extra, "curve_style", line_of(extra, "curve_style"), "unknown key");
}

TEST(contact_case, wrong_types_are_located) {
  const std::string list = variant("list", "friction: 0.2", "friction: [0.2]");
  expect_error(list, "friction", line_of(list, "friction: [0.2]"), "expected a number, got a list");
  const std::string points =
      variant("points", "{max: 0.02, points: 81}", "{max: 0.02, points: many}");
  expect_error(points, "curves.longitudinal.points", line_of(points, "points: many"),
               "expected a whole number");
}

}  // namespace
}  // namespace ferro::scenarios
