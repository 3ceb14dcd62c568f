// Adapter: the MIM solver as a tangential (creep-force) model, name "mim".
//
// References: Toumi (2016) chapter 2, eqs. (74)-(123) (normal problem, steady rolling) and
// eqs. (38)-(40) (force signs: on the wheel, F_x = -G a b C11 xi_x in the linear range; the MIM
// solver returns the forces on body 1 = wheel with the same signs, see mim/mim.hpp).
// Known deviations: see mim_model.hpp (K = 0; one patch at a time; no K_ij).
#include "ferro/contact/tangential/mim_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ferro/contact/mim/grid.hpp"
#include "ferro/contact/mim/influence_operator.hpp"
#include "ferro/contact/mim/mim.hpp"
#include "ferro/numerics/interpolation.hpp"

namespace ferro::contact {

void MimModelOptions::validate() const {
  if (elements < 6 || elements > 400) {
    throw std::invalid_argument(
        fmt::format("mim option 'elements': must be in [6, 400], got {}", elements));
  }
  if (extrapolate && (!grid_over_patch || elements < 12)) {
    throw std::invalid_argument(fmt::format(
        "mim option 'grid' = patch_richardson: needs 'elements' >= 12, got {}", elements));
  }
}

MimTangentialModel::MimTangentialModel(MimModelOptions options)
    : options_(options), solver_(std::make_unique<mim::HertzMimSolver>()) {
  options_.validate();
}

MimTangentialModel::~MimTangentialModel() = default;

namespace {

void check_unit_reduction(const ReductionFactors& k) {
  if (k.k11 != 1.0 || k.k22 != 1.0 || k.k23 != 1.0 || k.k33 != 1.0) {
    throw std::invalid_argument(
        "tangential problem.reduction: the mim model solves the full theory and takes no K_ij "
        "reduction factors (all must be 1)");
  }
}

// Linear interpolation of the lateral gap samples (clamped at the ends).
double lateral_gap(const NormalProblem& g, double y) {
  return numerics::interpolate_linear(g.gap_y, g.gap_z, y);
}

// Full gap of a non-elliptic patch: z = A x^2 + z(y_center + y) on a grid centred on the patch
// centre (so that the moment comes out about it), square elements, 10 % margin.
mim::MimResult solve_full_gap(const TangentialProblem& p, int elements) {
  const ContactPatch& patch = *p.patch;
  const NormalProblem& g = *p.gap;
  if (!(g.curvature_x > 0.0) || g.gap_y.size() < 2 || g.gap_y.size() != g.gap_z.size()) {
    throw std::invalid_argument(
        "tangential problem.gap: the mim model needs curvature_x > 0 and matching gap_y/gap_z "
        "samples for a non-elliptic patch");
  }
  double ylo = 1e300, yhi = -1e300, half_length = 0.0;
  for (const PatchStrip& s : patch.strips) {
    ylo = std::min(ylo, s.y - 0.5 * s.width);
    yhi = std::max(yhi, s.y + 0.5 * s.width);
    half_length = std::max(half_length, std::abs(s.x_center) + s.half_length);
  }
  const double margin = 1.10;
  const double lx = 2.0 * half_length * margin, ly = (yhi - ylo) * margin;
  const double h = std::min(lx, ly) / elements;
  const int nx = std::max(4, static_cast<int>(std::ceil(lx / h)));
  const int ny = std::max(4, static_cast<int>(std::ceil(ly / h)));
  mim::Grid grid = mim::Grid::centred(nx, ny, h, h);
  grid.y0 += 0.5 * (ylo + yhi);  // patch frame: y relative to y_center
  const double yc = patch.y_center;
  const mim::Field gap = mim::sample(
      grid, [&](double x, double y) { return g.curvature_x * x * x + lateral_gap(g, yc + y); });
  mim::InfluenceOperator op(grid, combine(p.body1, p.body2));
  mim::NormalLoad load;
  load.normal_force = patch.normal_force;
  const mim::RollingInput rolling{p.creepage.longitudinal, p.creepage.lateral, p.creepage.spin,
                                  p.friction};
  return mim::solve_rolling_contact(op, gap, load, rolling);
}

}  // namespace

mim::MimResult MimTangentialModel::solve_full(const TangentialProblem& problem) const {
  problem.validate();
  check_unit_reduction(problem.reduction);
  const ContactPatch& patch = *problem.patch;
  const bool full_gap = !patch.elliptic() && problem.gap != nullptr && !problem.gap->gap_y.empty();
  if (full_gap) return solve_full_gap(problem, options_.elements);
  mim::HertzRollingInput in;
  in.semi_axis_x = patch.semi_axis_x;
  in.semi_axis_y = patch.semi_axis_y;
  in.normal_force = patch.normal_force;
  in.rolling = mim::RollingInput{problem.creepage.longitudinal, problem.creepage.lateral,
                                 problem.creepage.spin, problem.friction};
  in.body1 = problem.body1;
  in.body2 = problem.body2;
  in.elements_minor = options_.elements;
  in.grid_over_patch = options_.grid_over_patch;
  in.extrapolate = options_.extrapolate;
  try {
    in.validate("mim");
  } catch (const std::invalid_argument& e) {
    // The grid bound depends on the patch shape: name the model option, not the field.
    std::string msg = e.what();
    const std::string field = "mim.elements_minor";
    if (msg.rfind(field, 0) == 0) msg = "mim option 'elements'" + msg.substr(field.size());
    throw std::invalid_argument(msg);
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  return solver_->solve(in);
}

TangentialSolution MimTangentialModel::solve(const TangentialProblem& problem) const {
  const mim::MimResult r = solve_full(problem);
  if (!r.converged) {
    throw std::runtime_error(fmt::format(
        "mim: steady-rolling solve did not converge (stick residual {:.3g}, direction residual "
        "{:.3g}, {} products)",
        r.stick_residual, r.direction_residual, r.tangential_matvecs));
  }
  TangentialSolution s;
  s.force_x = r.force_x;
  s.force_y = r.force_y;
  s.moment_z = r.moment_z;
  std::size_t stick = 0, slip = 0;
  for (mim::ElementState e : r.state) {
    stick += e == mim::ElementState::stick ? 1 : 0;
    slip += e == mim::ElementState::slip ? 1 : 0;
  }
  if (stick + slip > 0) s.adhesion_fraction = static_cast<double>(stick) / (stick + slip);
  if (problem.map != nullptr) {
    TractionMap& m = *problem.map;
    m.clear();
    for (int iy = 0; iy < r.grid.ny; ++iy) {
      for (int ix = 0; ix < r.grid.nx; ++ix) {
        const std::size_t k = r.grid.index(ix, iy);
        if (r.state[k] == mim::ElementState::exterior) continue;
        m.x.push_back(r.grid.x(ix));
        m.y.push_back(r.grid.y(iy));
        m.dx.push_back(r.grid.dx);
        m.dy.push_back(r.grid.dy);
        m.pressure.push_back(r.pressure[k]);
        m.traction_x.push_back(r.traction_x[k]);
        m.traction_y.push_back(r.traction_y[k]);
        m.slip.push_back(r.state[k] == mim::ElementState::slip ? 1 : 0);
      }
    }
  }
  return s;
}

std::unique_ptr<TangentialModel> MimTangentialModel::from_options(const ModelOptions& options) {
  check_option_keys("mim", options, {"elements", "grid"});
  MimModelOptions o;
  o.elements = option_int(options, "elements", o.elements);
  enum class Grid { kMinor, kPatch, kPatchRichardson };
  const Grid grid = option_choice<Grid>("mim", options, "grid",
                                        {{"minor", Grid::kMinor},
                                         {"patch", Grid::kPatch},
                                         {"patch_richardson", Grid::kPatchRichardson}},
                                        "minor");
  o.grid_over_patch = grid != Grid::kMinor;
  o.extrapolate = grid == Grid::kPatchRichardson;
  return std::make_unique<MimTangentialModel>(o);
}

}  // namespace ferro::contact
