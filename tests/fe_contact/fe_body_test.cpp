// Structured finite-element bodies: pairing of two bodies' coefficients, node lines, input checks
// (the FE solves themselves are in slow/).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ferro/contact/mim/dense_operator.hpp"
#include "ferro/fe_contact/fe_body.hpp"
#include "ferro/fe_contact/rail_wheel.hpp"

using namespace ferro;
using namespace ferro::contact::mim;

namespace {

const contact::Material kSteel = contact::Material::from_young(210.0e9, 0.28);

// Round-off of a sum of two halves.
constexpr double kRoundOff = 1.0e-14;

// A half-space is its own mirror image about the rolling axis (u_y even, the x-y coupling odd in
// the lateral offset), so one half-space turned by pi about the rolling axis plus another one
// is the half-space pair of annex B.3.
TEST(PairOfBodies, two_half_spaces_make_the_half_space_pair) {
  const Grid grid = Grid::centred(5, 6, 1.0e-3, 0.8e-3);
  const ColumnInfluence pair = ColumnInfluence::half_space(grid, contact::combine(kSteel, kSteel));
  ColumnInfluence half = pair;
  for (std::vector<double>* v : {&half.zz, &half.xx, &half.xy, &half.yx, &half.yy})
    for (double& x : *v) x *= 0.5;
  const ColumnInfluence sum = fe_contact::pair_of_bodies(half, half);
  double scale = 0.0;
  for (double v : pair.zz) scale = std::max(scale, std::abs(v));
  for (std::size_t k = 0; k < pair.size(); ++k) {
    EXPECT_NEAR(sum.zz[k], pair.zz[k], kRoundOff * scale);
    EXPECT_NEAR(sum.xx[k], pair.xx[k], kRoundOff * scale);
    EXPECT_NEAR(sum.yy[k], pair.yy[k], kRoundOff * scale);
    EXPECT_NEAR(sum.xy[k], pair.xy[k], kRoundOff * scale);
    EXPECT_NEAR(sum.yx[k], pair.yx[k], kRoundOff * scale);
  }
}

TEST(GradedLines, uniform_zone_growth_and_required_lines) {
  const std::vector<double> l =
      fe_contact::graded_lines(-1.5e-3, 1.5e-3, 1.0e-3, 2.0, -0.1, 0.1, {-0.02, 0.02});
  ASSERT_GE(l.size(), 8u);
  EXPECT_DOUBLE_EQ(l.front(), -0.1);
  EXPECT_DOUBLE_EQ(l.back(), 0.1);
  for (std::size_t i = 1; i < l.size(); ++i) EXPECT_GT(l[i], l[i - 1]);
  for (double v : {-1.5e-3, -0.5e-3, 0.5e-3, 1.5e-3, -0.02, 0.02})
    EXPECT_TRUE(std::any_of(l.begin(), l.end(), [v](double x) { return std::abs(x - v) < 1e-12; }))
        << v;
}

TEST(FeMeshLevel, rejects_bad_settings_by_name) {
  fe_contact::FeMeshLevel lv;
  lv.degree = 3;
  try {
    lv.validate();
    FAIL() << "degree 3 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("FeMeshLevel.degree"), std::string::npos) << e.what();
  }
  fe_contact::RailSpec rs;
  rs.grid = Grid::centred(4, 80, 1.0e-3, 1.0e-3);  // 80 mm wide: wider than the head
  rs.material = kSteel;
  EXPECT_THROW(rs.validate(), std::invalid_argument);
}

}  // namespace
