// The shipped elasto-plastic K_ij table (fe_contact/examples/thesis_elastoplastic_study.yaml run
// by `ferrodyn fe-kij`) read by the contact layer's reader: its axes, its first-pass range, and
// the point the closed form says is elastic (350HT at 7.5 t: p0 = 1044 MPa < first yield
// 1.59 sigma_y = 1193 MPa) at K = 1 at both ends of the range.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ferro/contact/kij/kij_table.hpp"
#include "ferro/fe_contact/elastoplastic.hpp"

namespace {

// Two MIM runs with the same compliance agree to the tangential solver's tolerance.
constexpr double kSameCompliance = 1.0e-4;
// The yielded R900A rail lowers the first-pass K22 by more than the solver noise.
constexpr double kVisibleReduction = 1.0e-3;

TEST(ElastoplasticTable, shipped_table_reads_with_its_range) {
  const std::string path =
      std::string(FERRO_SOURCE_DIR) + "/fe_contact/examples/thesis_elastoplastic_study.h5";
  const ferro::contact::KijTable t = ferro::contact::KijTable::read_hdf5(path);
  ASSERT_EQ(t.axis_names(), (std::vector<std::string>{"normal_force", "yield_stress"}));
  ASSERT_TRUE(t.has_first_pass());
  EXPECT_NE(t.provenance().at("range").find("first pass"), std::string::npos);

  const double fn = 73575.0;  // 7.5 t
  const double p0 = 1044.5e6;  // Hertz peak of the thesis patch (a = 6.66 mm, b = 5.05 mm)
  const double ht350 = 750.7e6, r900a = 489.0e6;
  const double ratio = ferro::fe_contact::hertz_circular_axis_von_mises_peak(0.28).ratio;
  ASSERT_LT(p0, ht350 / ratio);  // elastic by the closed form
  ASSERT_GT(p0, r900a / ratio);  // yielded
  for (const ferro::contact::ReductionFactors& k :
       {t.at(std::vector<double>{fn, ht350}), t.first_pass_at(std::vector<double>{fn, ht350})}) {
    EXPECT_NEAR(k.k11, 1.0, kSameCompliance);
    EXPECT_NEAR(k.k22, 1.0, kSameCompliance);
    EXPECT_NEAR(k.k23, 1.0, kSameCompliance);
    EXPECT_NEAR(k.k33, 1.0, kSameCompliance);
  }
  EXPECT_LT(t.first_pass_at(std::vector<double>{fn, r900a}).k22, 1.0 - kVisibleReduction);
}

}  // namespace
