// Tabulated MIM ("mim_table"): interpolated forces against direct MIM solves at off-node
// points, symmetries, HDF5 round trip, registry.
#include "ferro/contact/tangential/mim_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

#include "ferro/contact/tangential/mim_model.hpp"
#include "ferro/contact/tangential/tangential_model.hpp"

namespace fc = ferro::contact;

namespace {

const fc::Material kSteel = fc::Material::from_young(210.0e9, 0.28);

// Coarse table: 3 ratios, 8 x 8 x 11 creepage nodes, 12 elements (a few s to build).
fc::MimTableSpec coarse_spec() {
  fc::MimTableSpec s;
  s.ratio = {0.5, 1.0, 2.0};
  s.xi_x = {0.0, 0.3, 0.6, 1.0, 1.5, 2.2, 3.2, 5.0};
  s.xi_y = s.xi_x;
  s.spin = {-8.0, -4.5, -2.5, -1.2, -0.5, 0.0, 0.5, 1.2, 2.5, 4.5, 8.0};
  s.elements = 12;
  s.threads = 2;
  return s;
}

const fc::MimTable& coarse_table() {
  static const fc::MimTable t = fc::MimTable::build(coarse_spec());
  return t;
}

}  // namespace

// Interpolated forces against the direct MIM at the table's own grid (12 elements across the
// short axis), so that only the interpolation error is measured, at 40 seeded random off-node
// points: a/b in [0.55, 1.9], creepages of any sign with |xi*| <= 3.5, |psi| <= 5 (micro-slip
// to full slip). Tolerances kTolTable = 0.06 mu F_n (max) and kTolTableMean = 0.015 mu F_n
// (mean): with 3 nodes per unit of normalised creepage at the saturation knee the cubic
// interpolant follows pure and moderately combined creepage to ~1 %, but where lateral creepage
// and spin oppose each other f_y changes sign over less than a node spacing (measured: mean
// 0.009, max 0.048 mu F_n). Also checks the sign symmetries used to halve the table (negative
// xi_x, xi_y are off-table and evaluated through them).
TEST(mim_table, interpolation_matches_direct_mim_off_nodes) {
  constexpr double kTolTable = 0.06, kTolTableMean = 0.015;
  const fc::MimTable& table = coarse_table();
  const fc::MimTableModel model(table);
  const fc::MimTangentialModel mim(fc::MimModelOptions{12});
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worst = 0.0, sum = 0.0;
  const int n = 40;
  for (int k = 0; k < n; ++k) {
    const double ratio = std::exp(std::log(0.55) + (u(rng) + 1.0) * 0.5 * std::log(1.9 / 0.55));
    const double b = 4.0e-3, a = ratio * b;
    const fc::ContactPatch patch = fc::elliptic_patch(a, b, 70.0e3);
    fc::TangentialProblem p;
    p.patch = &patch;
    p.friction = 0.3;
    p.body1 = p.body2 = kSteel;
    // Pick normalised creepages, convert back with the table's own scaling (linear in xi).
    p.creepage = {1.0, 1.0, 1.0};
    const fc::MimTablePoint unit = table.normalise(p);
    // Spin drawn in the table's spin axis units (psi, its saturation scale), |psi| <= 5.
    const double psi_scale = fc::mim_table_spin_scale(ratio, table.spec().poisson);
    p.creepage = {3.5 * u(rng) / unit.xi_x, 3.5 * u(rng) / unit.xi_y,
                  5.0 * u(rng) / psi_scale / unit.spin};
    const fc::TangentialSolution t = model.solve(p);
    const fc::TangentialSolution d = mim.solve(p);
    const double mu_fn = 0.3 * 70.0e3, c = std::sqrt(a * b);
    const double err = std::max({std::abs(t.force_x - d.force_x), std::abs(t.force_y - d.force_y),
                                 std::abs(t.moment_z - d.moment_z) / c}) / mu_fn;
    std::printf("a/b %.3f xi* (%+.2f %+.2f %+.2f): direct (%+.4f %+.4f %+.4f) table (%+.4f %+.4f "
                "%+.4f) err %.4f\n",
                ratio, p.creepage.longitudinal * unit.xi_x, p.creepage.lateral * unit.xi_y,
                p.creepage.spin * unit.spin, d.force_x / mu_fn, d.force_y / mu_fn,
                d.moment_z / (mu_fn * c), t.force_x / mu_fn, t.force_y / mu_fn,
                t.moment_z / (mu_fn * c), err);
    worst = std::max(worst, err);
    sum += err;
  }
  std::printf("mim_table vs direct MIM (12 elements): mean %.4f, max %.4f mu Fn\n", sum / n, worst);
  EXPECT_LT(worst, kTolTable);
  EXPECT_LT(sum / n, kTolTableMean);
}

// At the nodes the table returns the MIM values exactly (to interpolation round-off), and the
// micro-creepage slope (xi* = 0.05, between the nodes 0 and 0.3) is the direct MIM's on the same
// grid within kTolSlope = 2 % (cubic through f(0) = 0 and the nodes 0.3, 0.6: the linear range
// is nearly straight there), and Kalker's (f = -xi*) within kTolKalker = 12 % (the MIM's
// first-order discretisation error at only 12 elements, +8 % measured).
TEST(mim_table, nodes_exact_and_linear_slope) {
  constexpr double kTolSlope = 0.02, kTolKalker = 0.12;
  const fc::MimTangentialModel mim(fc::MimModelOptions{12});
  const fc::MimTable& t = coarse_table();
  const fc::MimTableSpec& s = t.spec();
  for (int ir = 0; ir < 3; ++ir) {
    // Spin node psi = phi* x mim_table_spin_scale(a/b).
    const double phi_node = s.spin[6] / fc::mim_table_spin_scale(s.ratio[ir], s.poisson);
    const fc::MimTableValue v = t.at(s.ratio[ir], {s.xi_x[2], s.xi_y[3], phi_node});
    const fc::MimTableValue nd = t.node(ir, 2, 3, 6);
    EXPECT_NEAR(v.f_x, nd.f_x, 1e-12);
    EXPECT_NEAR(v.f_y, nd.f_y, 1e-12);
    EXPECT_NEAR(v.m_z, nd.m_z, 1e-12);
    const fc::MimTableValue lin = t.at(s.ratio[ir], {0.05, 0.0, 0.0});
    const fc::ContactPatch patch = fc::elliptic_patch(s.ratio[ir] * 4.0e-3, 4.0e-3, 70.0e3);
    fc::TangentialProblem p;
    p.patch = &patch;
    p.friction = 0.3;
    p.body1 = p.body2 = kSteel;
    p.creepage = {1.0, 0.0, 0.0};
    p.creepage.longitudinal = 0.05 / t.normalise(p).xi_x;
    const double direct = mim.solve(p).force_x / (0.3 * 70.0e3);
    std::printf("a/b %.1f: slope table %.4f, direct MIM %.4f (Kalker 1)\n", s.ratio[ir],
                -lin.f_x / 0.05, -direct / 0.05);
    EXPECT_NEAR(lin.f_x / direct, 1.0, kTolSlope);
    EXPECT_NEAR(-lin.f_x / 0.05, 1.0, kTolKalker);
  }
}

TEST(mim_table, hdf5_round_trip_and_registry) {
  const fc::MimTable& t = coarse_table();
  const std::string path = std::string(FERRO_BINARY_DIR) + "/mim_table_test.h5";
  t.write_hdf5(path);
  const fc::MimTable r = fc::MimTable::read_hdf5(path);
  EXPECT_EQ(r.spec().ratio, t.spec().ratio);
  EXPECT_EQ(r.spec().spin, t.spec().spin);
  EXPECT_EQ(r.spec().elements, 12);
  for (int ix = 0; ix < 6; ++ix) {
    EXPECT_EQ(r.node(1, ix, 2, 3).f_x, t.node(1, ix, 2, 3).f_x);
    EXPECT_EQ(r.node(2, ix, 4, 7).m_z, t.node(2, ix, 4, 7).m_z);
  }
  const auto model = fc::make_tangential_model("mim_table", {{"table", path}});
  EXPECT_EQ(model->name(), "mim_table");
  // A table that cannot be opened is bad input, as every table the user names.
  EXPECT_THROW((void)fc::make_tangential_model("mim_table", {{"table", path + ".missing"}}),
               std::invalid_argument);
  EXPECT_THROW((void)fc::make_tangential_model("mim_table", {{"tabel", path}}),
               std::invalid_argument);
  // nu of the problem must match the table's.
  const fc::ContactPatch patch = fc::elliptic_patch(4.0e-3, 4.0e-3, 50.0e3);
  fc::TangentialProblem p;
  p.patch = &patch;
  p.friction = 0.3;
  p.body1 = p.body2 = fc::Material::from_young(210.0e9, 0.4);
  EXPECT_THROW((void)model->solve(p), std::invalid_argument);
  std::filesystem::remove(path);
}
