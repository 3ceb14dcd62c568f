// The scene's track part: YAML -> track::Track. Oracles: the design values written in the YAML
// (curvature 1/R in the curve, half of it at the middle of a linear clothoid, the cant), the
// closed form of a one-minus-cosine defect, a measured file's own samples, and the sum of the
// parts for a summed irregularity.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "ferro/scenarios/track_config.hpp"
#include "ferro/track/stochastic_irregularity.hpp"

namespace ferro::scenarios {
namespace {

// Geometry from the alignment is exact up to the quadrature of the clothoid (1e-13 m).
constexpr double kExact = 1e-12;

TrackConfig read_text(const std::string& text, const std::string& path = "track.yaml") {
  const YamlFile f = parse_yaml_text(text, path);
  MapReader r(f.root, path, "track");
  return read_track(r);
}

std::string error_of(const std::string& text) {
  try {
    (void)read_text(text);
  } catch (const YamlInputError& e) {
    return e.what();
  }
  return "(no error)";
}

const char* kCurve = R"(
gauge: 1.435
rail_inclination: 0.025
sections:
  - {kind: straight, length: 100}
  - {kind: transition, length: 80}
  - {kind: curve, length: 300, radius: -1200, cant_mm: -150}
  - {kind: transition, length: 80}
  - {kind: straight, length: 100}
irregularities:
  - {type: defect, channel: lateral, amplitude: 0.004, wavelength: 20, start_s: 40}
  - {type: stochastic, spectrum: erri_high, channels: [vertical], seed: 7, wavelength_min: 3}
)";

TEST(TrackConfig, design_sections_cant_and_gauge) {
  const TrackConfig c = read_text(kCurve);
  EXPECT_EQ(c.type, "design");
  ASSERT_EQ(c.design.sections.size(), 5u);
  EXPECT_DOUBLE_EQ(c.rail_inclination, 0.025);
  const auto t = build_track(c);
  ASSERT_TRUE(t);
  EXPECT_DOUBLE_EQ(t->alignment().end_s(), 660.0);
  const auto mid_curve = t->at(330.0).frame;
  EXPECT_NEAR(mid_curve.curvature, -1.0 / 1200.0, kExact);
  EXPECT_NEAR(mid_curve.cant, -0.150, kExact);
  EXPECT_NEAR(mid_curve.gauge, 1.435, kExact);
  const auto mid_transition = t->at(140.0).frame;  // linear ramps: half way
  EXPECT_NEAR(mid_transition.curvature, -0.5 / 1200.0, kExact);
  EXPECT_NEAR(mid_transition.cant, -0.075, kExact);
  EXPECT_NEAR(t->at(50.0).frame.curvature, 0.0, kExact);
}

TEST(TrackConfig, summed_irregularities_equal_their_parts) {
  const TrackConfig c = read_text(kCurve);
  ASSERT_EQ(c.irregularities.size(), 2u);
  const auto t = build_track(c);
  // Defect: amplitude/2 (1 - cos(2 pi x / wavelength)) over one wavelength from start_s.
  const double s = 47.0, x = s - 40.0;
  const double defect = 0.002 * (1.0 - std::cos(2.0 * M_PI * x / 20.0));
  const track::StochasticIrregularity stochastic(c.irregularities[1].stochastic);
  const auto sum = t->at(s).irregularity;
  EXPECT_NEAR(sum.lateral, defect + stochastic.at(s).lateral, kExact);
  EXPECT_NEAR(sum.vertical, stochastic.at(s).vertical, kExact);
  EXPECT_NE(sum.vertical, 0.0);
  EXPECT_EQ(stochastic.at(s).lateral, 0.0);  // only the vertical channel was asked for
  // The realisation spans the whole design by default.
  EXPECT_DOUBLE_EQ(c.irregularities[1].stochastic.length, 660.0);
}

TEST(TrackConfig, measured_file_relative_to_the_track_file) {
  const auto dir = std::filesystem::temp_directory_path() / "ferro_track_config_test";
  std::filesystem::create_directories(dir);
  {
    std::ofstream f(dir / "measured.csv");
    f << "s_m,lateral_mm\n0,0\n10,2\n20,4\n30,6\n";
  }
  const TrackConfig c = read_text(R"(
type: straight
length: 40
irregularities:
  - {type: measured, file: measured.csv}
)",
                                  (dir / "track.yaml").string());
  const auto t = build_track(c);
  // A linear record is reproduced exactly by the quadratic-exact Hermite interpolation.
  EXPECT_NEAR(t->at(15.0).irregularity.lateral, 3.0e-3, kExact);
}

TEST(TrackConfig, plain_straight_is_the_unbounded_perfect_track) {
  const TrackConfig c = read_text("type: straight\n");
  EXPECT_EQ(c.type, "straight");
  EXPECT_EQ(build_track(c), nullptr);
}

struct BadTrack {
  const char* text;
  int line;
  const char* key;
  const char* hint;
};

TEST(TrackConfig, located_errors) {
  const BadTrack cases[] = {
      {"sections:\n  - {kind: curve, length: 100}\n", 2, "track.sections[0].radius",
       "missing required key"},
      {"sections:\n  - {kind: straight, length: 10}\n  - {kind: clothoid, length: 5}\n"
       "  - {kind: transition, length: 5}\n",
       4, "track.sections[2]", "transition"},
      {"sections:\n  - {kind: bend, length: 10}\n", 2, "track.sections[0].kind",
       "allowed: straight, transition"},
      {"length: 100\nirregularities:\n  - {type: stochastic, spectrum: erri_hihg}\n", 3,
       "track.irregularities[0].spectrum", "did you mean 'erri_high'?"},
      {"length: 100\nirregularities:\n  - {type: defect, channel: lateral, amplitude: 0.01, "
       "wavelength: -3, start_s: 0}\n",
       3, "track.irregularities[0].wavelength", ""},
      {"irregularities:\n  - {type: measured, file: none.csv}\n", 2,
       "track.irregularities[0].file", "does not exist"},
      {"type: straight\nirregularities:\n  - {type: defect, channel: lateral, amplitude: 0.01, "
       "wavelength: 3, start_s: 0}\n",
       3, "track.irregularities", "need a bounded track"},
      {"sections:\n  - {kind: straight, length: 10, radius: 100}\n", 2,
       "track.sections[0].radius", "unknown key"},
      {"gauge: 1.435\nrail_inclinaton: 0.025\nsections:\n  - {kind: straight, length: 10}\n", 2,
       "track.rail_inclinaton", "did you mean 'rail_inclination'?"},
  };
  for (const auto& c : cases) {
    const std::string msg = error_of(c.text);
    EXPECT_NE(msg.find("track.yaml:" + std::to_string(c.line) + ":"), std::string::npos)
        << c.text << "\n-> " << msg;
    EXPECT_NE(msg.find(c.key), std::string::npos) << c.text << "\n-> " << msg;
    EXPECT_NE(msg.find(c.hint), std::string::npos) << c.text << "\n-> " << msg;
  }
}

}  // namespace
}  // namespace ferro::scenarios
