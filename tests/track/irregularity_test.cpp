// Isolated defects, sums, per-rail values and measured (CSV) irregularities.

#include "ferro/track/irregularity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <string>

#include "ferro/track/measured_irregularity.hpp"

namespace ferro::track {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(IsolatedDefect, one_minus_cosine_lateral_alignment) {
  // Toumi §4.4: a lateral alignment defect of 0.01 m amplitude excites the hunting motion.
  IsolatedDefectSpec spec;
  spec.amplitude = 0.01;
  spec.wavelength = 20.0;
  spec.start_s = 100.0;
  const IsolatedDefect d(spec);
  EXPECT_DOUBLE_EQ(d.at(110.0).lateral, 0.01);  // peak at mid-wavelength
  EXPECT_EQ(d.at(99.0).lateral, 0.0);
  EXPECT_EQ(d.at(121.0).lateral, 0.0);
  EXPECT_EQ(d.at(110.0).vertical, 0.0);
  // Largest slope A pi / lambda at a quarter wavelength.
  EXPECT_NEAR(d.at(105.0).d_lateral, 0.01 * kPi / 20.0, 1e-17);
  // Value and slope continuous at both ends: near the ends both vanish like x^2 and x.
  for (const double s : {100.0 + 1e-6, 120.0 - 1e-6}) {
    EXPECT_LT(std::abs(d.at(s).lateral), 1e-15);
    EXPECT_LT(std::abs(d.at(s).d_lateral), 1e-8);
  }
  // Derivative against a central difference (error h^2 A k^3 / 12 ~ 3e-12).
  for (double s = 100.5; s < 120.0; s += 1.1) {
    const double fd = (d.at(s + 1e-4).lateral - d.at(s - 1e-4).lateral) / 2e-4;
    EXPECT_NEAR(d.at(s).d_lateral, fd, 1e-10) << s;
  }
}

TEST(IsolatedDefect, cross_level_twist_and_rails) {
  IsolatedDefectSpec spec;
  spec.channel = IrregularityChannel::kCrossLevel;
  spec.amplitude = -0.012;  // left rail up
  spec.wavelength = 6.0;
  spec.start_s = 160.0;
  const IsolatedDefect d(spec);
  const IrregularitySample mid = d.at(163.0);
  EXPECT_DOUBLE_EQ(mid.cross_level, -0.012);
  EXPECT_DOUBLE_EQ(mid.left_rail().vertical, 0.006);
  EXPECT_DOUBLE_EQ(mid.right_rail().vertical, -0.006);
  // Twist (d cross-level / ds) peaks at A pi / lambda = 6.28 mm/m at a quarter wavelength.
  EXPECT_NEAR(d.at(161.5).d_cross_level, -0.012 * kPi / 6.0, 1e-16);
  EXPECT_NEAR(d.at(161.5).left_rail().d_vertical, 0.006 * kPi / 6.0, 1e-16);
}

TEST(IrregularitySum, adds_channels_and_rails) {
  IsolatedDefectSpec a;
  a.amplitude = 0.004;
  a.wavelength = 10.0;
  a.start_s = 0.0;
  IsolatedDefectSpec g = a;
  g.channel = IrregularityChannel::kGauge;
  g.amplitude = 0.002;
  g.shape = DefectShape::kSine;
  g.periods = 2;
  IrregularitySum sum;
  sum.add(std::make_shared<IsolatedDefect>(a));
  sum.add(std::make_shared<IsolatedDefect>(g));
  sum.add(std::make_shared<IsolatedDefect>(a));
  EXPECT_EQ(sum.size(), 3u);
  const IrregularitySample s = sum.at(2.5);
  EXPECT_NEAR(s.lateral, 2 * 0.002, 1e-17);  // two 1-cos at a quarter wavelength: A/2 each
  EXPECT_NEAR(s.gauge, 0.002, 1e-17);        // sine at a quarter wavelength
  EXPECT_NEAR(s.left_rail().lateral, 0.004 + 0.001, 1e-17);
  EXPECT_NEAR(s.right_rail().lateral, 0.004 - 0.001, 1e-17);
  EXPECT_NEAR(sum.at(15.0).gauge, 0.0, 1e-17);  // second sine period, at its zero crossing
  EXPECT_NEAR(sum.at(17.5).gauge, -0.002, 1e-17);
  EXPECT_EQ(sum.at(25.0).gauge, 0.0);
  EXPECT_THROW(sum.add(nullptr), std::invalid_argument);
}

TEST(IsolatedDefect, validate_names_the_field) {
  IsolatedDefectSpec spec;  // NaN amplitude
  try {
    spec.validate("irregularities[1]");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("irregularities[1].amplitude:", 0), 0u) << e.what();
  }
  spec.amplitude = 0.01;
  spec.wavelength = -3.0;
  EXPECT_THROW(spec.validate(), std::invalid_argument);
  EXPECT_THROW((void)irregularity_channel_from_string("twist", "defect.channel"),
               std::invalid_argument);
}

// ---- measured irregularities -------------------------------------------------------------

class MeasuredCsv : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) {
    const auto dir = std::filesystem::temp_directory_path() / "ferro_track_tests";
    std::filesystem::create_directories(dir);
    const auto path = (dir / name).string();
    std::ofstream(path) << text;
    return path;
  }
  static std::string error_of(const std::string& path) {
    try {
      const MeasuredIrregularity m(path);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(MeasuredCsv, reproduces_a_quadratic_exactly) {
  // Hermite interpolation with three-point parabolic slopes is exact for quadratics; data: lateral
  // = 1 + 0.5 s - 0.02 s^2 mm on non-uniform s.
  std::string text = "# test data\n\ncross_level_mm; s_m; lateral_mm\n";
  const double ss[] = {0.0, 0.7, 1.0, 2.5, 2.6, 4.0, 5.5};
  for (const double s : ss) {
    text += std::to_string(0.3) + "; " + std::to_string(s) + "; " +
            std::to_string(1.0 + 0.5 * s - 0.02 * s * s) + "\n";
  }
  const MeasuredIrregularity m(write("quadratic.csv", text));
  EXPECT_EQ(m.size(), 7u);
  for (double s = 0.01; s < 5.5; s += 0.173) {
    const IrregularitySample v = m.at(s);
    // std::to_string keeps 6 decimals of mm: 5e-7 mm = 5e-10 m of rounding in the data.
    EXPECT_NEAR(v.lateral, 1e-3 * (1.0 + 0.5 * s - 0.02 * s * s), 2e-9) << s;
    EXPECT_NEAR(v.d_lateral, 1e-3 * (0.5 - 0.04 * s), 2e-8) << s;
    EXPECT_NEAR(v.cross_level, 3e-4, 1e-15);
    EXPECT_EQ(v.vertical, 0.0);  // column absent
  }
  // Outside the data the end values hold.
  EXPECT_NEAR(m.at(-3.0).lateral, 1e-3, 1e-12);
  EXPECT_EQ(m.at(-3.0).d_lateral, 0.0);
  EXPECT_NEAR(m.at(9.0).lateral, 1e-3 * (1.0 + 2.75 - 0.02 * 30.25), 1e-9);
}

TEST_F(MeasuredCsv, errors_name_file_and_line) {
  const std::string header = "s_m,lateral_mm,vertical_mm,cross_level_mm,gauge_mm\n";
  auto starts = [](const std::string& msg, const std::string& prefix) {
    return msg.rfind(prefix, 0) == 0;
  };
  {
    const auto p = write("bad_number.csv", "# c\n" + header + "0,0,0,0,0\n1,0,x1,0,0\n");
    const auto e = error_of(p);
    EXPECT_TRUE(starts(e, p + ":4, column 'vertical_mm': not a number: 'x1'")) << e;
  }
  {
    const auto p = write("not_increasing.csv", header + "0,0,0,0,0\n1,0,0,0,0\n1,0,0,0,0\n");
    const auto e = error_of(p);
    EXPECT_TRUE(starts(e, p + ":4: s = 1 m does not increase")) << e;
  }
  {
    const auto p = write("fields.csv", header + "0,0,0,0,0\n1,0,0,0\n");
    EXPECT_TRUE(starts(error_of(p), p + ":3: 4 cells, the header has 5")) << error_of(p);
  }
  {
    const auto p = write("unknown.csv", "s_m,lateral_inch\n0,0\n");
    EXPECT_TRUE(starts(error_of(p), p + ":1: unknown column 'lateral_inch'")) << error_of(p);
  }
  {
    const auto p = write("no_s.csv", "lateral_m,gauge_m\n0,0\n");
    EXPECT_TRUE(starts(error_of(p), p + ":1: the header has no arc-length column")) << error_of(p);
  }
  {
    const auto p = write("one_row.csv", header + "0,0,0,0,0\n");
    EXPECT_TRUE(starts(error_of(p), p + ":2: at least two data rows")) << error_of(p);
  }
  {
    const auto p = write("empty.csv", "# nothing\n");
    EXPECT_TRUE(starts(error_of(p), p + ": empty input")) << error_of(p);
  }
  const std::string missing = "/nonexistent/dir/irr.csv";
  EXPECT_TRUE(starts(error_of(missing), missing + ": cannot open")) << error_of(missing);
}

}  // namespace
}  // namespace ferro::track
