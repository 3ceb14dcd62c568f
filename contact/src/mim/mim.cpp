// One-call MIM rolling contact: normal, then steady rolling.
//
// References: Toumi (2016) chapter 2, eqs. (74)-(123).
// Known deviations: see normal_solver.hpp and tangential_solver.hpp.

#include "ferro/contact/mim/mim.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ferro/contact/mim/hertz_gap.hpp"

namespace ferro::contact::mim {

void NormalLoad::validate(const std::string& where) const {
  const bool has_force = !std::isnan(normal_force);
  const bool has_approach = !std::isnan(approach);
  if (has_force == has_approach) {
    throw std::invalid_argument(
        fmt::format("{}: set exactly one of normal_force (N) and approach (m), got {} and {}",
                    where, normal_force, approach));
  }
  if (has_force && !(normal_force > 0.0 && std::isfinite(normal_force))) {
    throw std::invalid_argument(
        fmt::format("{}.normal_force: must be finite and > 0 N, got {}", where, normal_force));
  }
  if (has_approach && !std::isfinite(approach)) {
    throw std::invalid_argument(
        fmt::format("{}.approach: must be finite (m), got {}", where, approach));
  }
}

namespace {

// Largest aspect ratio for which 4 elements across the shorter axis stay within the cap.
int max_resolved_aspect() {
  int r = 1;
  while (max_elements_minor(1.0, 2.0 * r) >= 4) r *= 2;
  int lo = r / 2, hi = r;  // max_elements_minor(1, lo) >= 4 > max_elements_minor(1, hi)
  while (hi - lo > 1) {
    const int mid = lo + (hi - lo) / 2;
    (max_elements_minor(1.0, mid) >= 4 ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace

int max_elements_minor(double a, double b) {
  if (!(a > 0.0) || !(b > 0.0) || !std::isfinite(a) || !std::isfinite(b)) return 0;
  const double aspect = std::max(a, b) / std::min(a, b);
  // The grid has about e^2 * aspect elements: settle hopeless ratios before counting.
  if (16.0 * aspect > static_cast<double>(kMaxGridElements)) return 0;
  int e = static_cast<int>(std::sqrt(static_cast<double>(kMaxGridElements) / aspect)) + 2;
  while (e >= 2 && grid_for_ellipse(a, b, e).size() > kMaxGridElements) --e;
  return e;
}

void HertzRollingInput::validate(const std::string& where) const {
  if (!(semi_axis_x > 0.0) || !(semi_axis_y > 0.0)) {
    throw std::invalid_argument(
        fmt::format("{}.semi_axis_x/semi_axis_y: must be > 0 m, got {} and {}", where, semi_axis_x,
                    semi_axis_y));
  }
  if (!(normal_force > 0.0) || !std::isfinite(normal_force)) {
    throw std::invalid_argument(
        fmt::format("{}.normal_force: must be > 0 N, got {}", where, normal_force));
  }
  const int most = max_elements_minor(semi_axis_x, semi_axis_y);
  const double aspect = std::max(semi_axis_x, semi_axis_y) / std::min(semi_axis_x, semi_axis_y);
  if (most < 4) {
    throw std::invalid_argument(fmt::format(
        "{}.semi_axis_x/semi_axis_y: an ellipse of {} m x {} m (aspect ratio {:.3g}) needs more "
        "than {} grid elements even with 4 elements across its shorter axis; the grid resolves "
        "aspect ratios up to about {}",
        where, semi_axis_x, semi_axis_y, aspect, kMaxGridElements, max_resolved_aspect()));
  }
  if (elements_minor < 4 || elements_minor > most) {
    throw std::invalid_argument(fmt::format(
        "{}.elements_minor: must lie in [4, {}] for this ellipse (aspect ratio {:.3g}, at most {} "
        "grid elements), got {}",
        where, most, aspect, kMaxGridElements, elements_minor));
  }
  if (extrapolate && (!grid_over_patch || elements_minor < 12)) {
    throw std::invalid_argument(fmt::format(
        "{}.extrapolate: needs grid_over_patch and elements_minor >= 12, got {} and {}", where,
        grid_over_patch, elements_minor));
  }
  rolling.validate(where + ".rolling");
  body1.validate(where + ".body1");
  body2.validate(where + ".body2");
}

namespace {

// Steady rolling on a solved normal problem, assembled into a MimResult.
MimResult rolling_on(ComplianceOperator& op, const NormalGridSolution& n,
                     const RollingInput& rolling, const MimOptions& options,
                     TangentialWorkspace& workspace) {
  TangentialSolverOptions tangential = options.tangential;
  tangential.nested = tangential.nested && op.has_coarse();  // dense operators have no coarse grid
  const TangentialGridSolution t =
      solve_steady_rolling(op, n.pressure, rolling, tangential, workspace);
  MimResult r;
  r.grid = op.grid();
  r.normal_force = n.normal_force;
  r.approach = n.approach;
  r.force_x = t.force_x;
  r.force_y = t.force_y;
  r.moment_z = t.moment_z;
  r.pressure = n.pressure;
  r.traction_x = t.traction_x;
  r.traction_y = t.traction_y;
  r.slip_x = t.slip_x;
  r.slip_y = t.slip_y;
  r.state = t.state;
  r.patch_truncated = n.boundary_contact_elements > 0;
  r.normal_iterations = n.iterations;
  r.gap_residual = n.gap_residual;
  r.penetration_residual = n.penetration_residual;
  r.tangential_matvecs = t.matvecs;
  r.stick_residual = t.stick_residual;
  r.direction_residual = t.direction_residual;
  r.coulomb_residual = t.coulomb_residual;
  r.converged = n.converged && t.converged;
  return r;
}

}  // namespace

MimResult solve_rolling_contact(ComplianceOperator& op, const Field& gap, const NormalLoad& load,
                                const RollingInput& rolling, const MimOptions& options,
                                TangentialWorkspace& workspace) {
  load.validate();
  rolling.validate();
  const NormalGridSolution n = std::isnan(load.normal_force)
                                   ? solve_normal_approach(op, gap, load.approach, options.normal)
                                   : solve_normal_force(op, gap, load.normal_force, options.normal);
  return rolling_on(op, n, rolling, options, workspace);
}

MimResult solve_rolling_contact(ComplianceOperator& op, const Field& gap, const NormalLoad& load,
                                const RollingInput& rolling, const MimOptions& options) {
  TangentialWorkspace workspace;
  return solve_rolling_contact(op, gap, load, rolling, options, workspace);
}

struct HertzMimSolver::Entry {
  int nx = 0;
  int ny = 0;
  double poisson = 0.0;
  double aspect = 1.0;  // dy / dx
  std::unique_ptr<InfluenceOperator> op;
  // Last normal solution on this grid and the unit-grid inputs it was solved for: the normal
  // problem does not depend on the creepages (K = 0), so a repeated patch reuses it exactly.
  double curvature_x = kNaN, curvature_y = kNaN, load = kNaN;
  NormalGridSolution normal;
};

HertzMimSolver::HertzMimSolver(MimOptions options, std::size_t max_cached_grids)
    : options_(options), max_cached_(std::max<std::size_t>(1, max_cached_grids)) {}

HertzMimSolver::~HertzMimSolver() = default;

MimResult HertzMimSolver::solve(const HertzRollingInput& input) {
  input.validate();
  if (!input.extrapolate) return solve_grid(input);
  MimResult fine = solve_grid(input);
  HertzRollingInput half = input;
  half.elements_minor = (input.elements_minor + 1) / 2;
  const MimResult coarse = solve_grid(half);
  // Second-order Richardson extrapolation in the element count.
  const double n2 = static_cast<double>(input.elements_minor) * input.elements_minor;
  const double m2 = static_cast<double>(half.elements_minor) * half.elements_minor;
  const double w = m2 / (n2 - m2);
  fine.force_x += w * (fine.force_x - coarse.force_x);
  fine.force_y += w * (fine.force_y - coarse.force_y);
  fine.moment_z += w * (fine.moment_z - coarse.moment_z);
  fine.tangential_matvecs += coarse.tangential_matvecs;
  fine.converged = fine.converged && coarse.converged;
  return fine;
}

MimResult HertzMimSolver::solve_grid(const HertzRollingInput& input) {
  const CombinedMaterial m = combine(input.body1, input.body2);
  const double a = input.semi_axis_x, b = input.semi_axis_y;
  const HertzGap hg = hertz_gap_for_ellipse(a, b, input.normal_force, m.contact_modulus);
  const Grid grid = input.grid_over_patch ? grid_over_ellipse(a, b, input.elements_minor)
                                          : grid_for_ellipse(a, b, input.elements_minor);
  const double h = grid.dx;
  const double aspect = grid.dy / grid.dx;  // 1 for square elements

  // Unit grid and material: lengths in h = dx, stresses in G.
  Entry* entry = nullptr;
  for (auto& e : cache_) {
    if (e->nx == grid.nx && e->ny == grid.ny && e->poisson == m.poisson && e->aspect == aspect)
      entry = e.get();
  }
  if (entry == nullptr) {
    if (cache_.size() >= max_cached_) cache_.erase(cache_.begin());  // oldest first
    auto e = std::make_unique<Entry>();
    e->nx = grid.nx;
    e->ny = grid.ny;
    e->poisson = m.poisson;
    e->aspect = aspect;
    CombinedMaterial unit;
    unit.shear_modulus = 1.0;
    unit.poisson = m.poisson;
    unit.contact_modulus = 1.0 / (1.0 - m.poisson);  // E*/G for the pair; not used by the operator
    // Grids over the patch have the same N x N shape at every a/b: FFTW's measured plans
    // (a few tens of ms, once per size per process) make every product about 30 % faster.
    // Square-element grids change shape with a/b, where estimated plans cost less overall.
    e->op = std::make_unique<InfluenceOperator>(Grid::centred(grid.nx, grid.ny, 1.0, aspect), unit,
                                                /*measure_plans=*/input.grid_over_patch);
    ++operators_built_;
    entry = e.get();
    cache_.push_back(std::move(e));
  }
  InfluenceOperator& op = *entry->op;
  const double cx = hg.curvature_x * h, cy = hg.curvature_y * h;  // z / h in units of h
  const double load = input.normal_force / (m.shear_modulus * h * h);
  if (!(entry->curvature_x == cx && entry->curvature_y == cy && entry->load == load)) {
    entry->normal = solve_normal_force(op, quadratic_gap(op.grid(), cx, cy), load, options_.normal);
    entry->curvature_x = cx;
    entry->curvature_y = cy;
    entry->load = load;
  }
  RollingInput rolling = input.rolling;
  rolling.validate();
  rolling.spin *= h;
  MimResult r = rolling_on(op, entry->normal, rolling, options_, workspace_);

  // Back to SI.
  const double g = m.shear_modulus;
  r.grid = grid;
  r.normal_force *= g * h * h;
  r.force_x *= g * h * h;
  r.force_y *= g * h * h;
  r.moment_z *= g * h * h * h;
  r.approach *= h;
  for (Field* f : {&r.pressure, &r.traction_x, &r.traction_y}) {
    for (double& v : *f) v *= g;
  }
  return r;
}

MimResult solve_hertz_rolling(const HertzRollingInput& input, const MimOptions& options) {
  HertzMimSolver solver(options, 1);
  return solver.solve(input);
}

}  // namespace ferro::contact::mim
