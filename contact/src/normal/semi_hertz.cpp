// Semi-Hertzian normal contact (Ayasse & Chollet 2005), Toumi (2016) eqs. (17)-(23).
//
// References: Ayasse & Chollet, Vehicle System Dynamics 43 (2005) 161-172; Toumi (2016)
// eqs. (17)-(23).
// Known deviations: see semi_hertz.hpp (global reference curvature at the deepest sample,
// load-driven virtual penetration, lobes split into patches).
#include "ferro/contact/normal/semi_hertz.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "ferro/contact/normal/hertz.hpp"
#include "ferro/numerics/interpolation.hpp"

namespace ferro::contact {
namespace {

constexpr double kPi = std::numbers::pi;

// Piecewise-linear gap above its minimum, +inf outside the sampled range.
double relative_gap(const NormalProblem& p, double z_min, double y) {
  const auto& ys = p.gap_y;
  if (y < ys.front() || y > ys.back()) return INFINITY;
  const numerics::AxisCell c = numerics::locate(ys, y);
  return (1.0 - c.t) * p.gap_z[c.index] + c.t * p.gap_z[c.index + 1] - z_min;
}

struct StripGrid {
  double y0 = 0.0;  // first strip centre
  double dy = 0.0;  // strip width
  int count = 0;
  std::vector<double> gap;  // relative gap at the strip centres
};

void fill_grid(const NormalProblem& p, double z_min, double y_lo, double y_hi, int count,
               StripGrid& g) {
  g.count = count;
  g.dy = (y_hi - y_lo) / count;
  g.y0 = y_lo + 0.5 * g.dy;
  g.gap.resize(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i)
    g.gap[static_cast<std::size_t>(i)] = relative_gap(p, z_min, g.y0 + i * g.dy);
}

StripGrid make_grid(const NormalProblem& p, double z_min, double y_lo, double y_hi, int count) {
  StripGrid g;
  fill_grid(p, z_min, y_lo, y_hi, count, g);
  return g;
}

// Load carried by the strips for the virtual penetration h0 (eqs. 22-23 with p0_i = Kp a_i):
// F = (pi/2) Kp sum a_i^2 dy, a_i^2 = (h0 - z_i)/A_c.
// F(h0) = c sum_i max(h0 - z_i, 0) is piecewise linear and increasing in h0: sort the strip gaps
// and solve exactly on the right piece.
double solve_penetration(const StripGrid& g, double target, double compensated_curvature, double kp,
                         std::vector<double>& scratch) {
  const double c = 0.5 * kPi * kp / compensated_curvature * g.dy;
  scratch.clear();
  for (double z : g.gap) {
    if (std::isfinite(z)) scratch.push_back(z);
  }
  if (scratch.empty()) throw std::runtime_error("semi_hertz: no strip inside the sampled gap");
  std::sort(scratch.begin(), scratch.end());
  const double need = target / c;  // sum_i (h0 - z_i) over the penetrated strips
  double sum_z = 0.0;
  for (std::size_t k = 0; k < scratch.size(); ++k) {
    sum_z += scratch[k];
    const double n = static_cast<double>(k + 1);
    const double h = (need + sum_z) / n;  // h0 if exactly strips 0..k are penetrated
    if (k + 1 == scratch.size() || h <= scratch[k + 1]) return h;
  }
  return (need + sum_z) / static_cast<double>(scratch.size());
}

// Lateral span where the relative gap is below h0 (from the samples, linear crossings).
std::pair<double, double> penetrated_span(const NormalProblem& p, double z_min, double h0) {
  const auto& ys = p.gap_y;
  const auto& zs = p.gap_z;
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t i = 0; i + 1 < ys.size(); ++i) {
    const double z0 = zs[i] - z_min - h0, z1 = zs[i + 1] - z_min - h0;
    if (z0 < 0.0) {
      lo = std::min(lo, ys[i]);
      hi = std::max(hi, ys[i]);
    }
    if (z1 < 0.0) {
      lo = std::min(lo, ys[i + 1]);
      hi = std::max(hi, ys[i + 1]);
    }
    if ((z0 < 0.0) != (z1 < 0.0)) {
      const double yc = ys[i] + (ys[i + 1] - ys[i]) * z0 / (z0 - z1);
      lo = std::min(lo, yc);
      hi = std::max(hi, yc);
    }
  }
  return {lo, hi};
}

// Least-squares parabola z = c0 + c1 t + B t^2 (t = y - y[center]) through samples lo..hi;
// returns B (NaN if the system is singular).
// With `weight` (optional, one value per sample lo..hi), the weighted least-squares parabola.
double least_squares_curvature(const NormalProblem& p, std::size_t center, std::size_t lo,
                               std::size_t hi, const double* weight = nullptr) {
  double m[3][4] = {};  // normal equations [sum w t^(i+j) | sum w z t^i]
  for (std::size_t j = lo; j <= hi; ++j) {
    const double t = p.gap_y[j] - p.gap_y[center];
    const double z = p.gap_z[j] - p.gap_z[center];
    const double w = weight != nullptr ? weight[j - lo] : 1.0;
    const double pw[5] = {w, w * t, w * t * t, w * t * t * t, w * t * t * t * t};
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) m[r][c] += pw[r + c];
      m[r][3] += z * pw[r];
    }
  }
  // Gaussian elimination with partial pivoting.
  for (int c = 0; c < 3; ++c) {
    int piv = c;
    for (int r = c + 1; r < 3; ++r) {
      if (std::abs(m[r][c]) > std::abs(m[piv][c])) piv = r;
    }
    for (int k = 0; k < 4; ++k) std::swap(m[c][k], m[piv][k]);
    if (m[c][c] == 0.0) return std::numeric_limits<double>::quiet_NaN();
    for (int r = c + 1; r < 3; ++r) {
      const double f = m[r][c] / m[c][c];
      for (int k = c; k < 4; ++k) m[r][k] -= f * m[c][k];
    }
  }
  // Back substitution is only needed for the last unknown (B).
  return m[2][3] / m[2][2];
}

}  // namespace

void SemiHertzOptions::validate() const {
  if (curvature != Curvature::kFit && curvature != Curvature::kThreePoint) {
    throw std::invalid_argument("semi_hertz.curvature: must be fit or three_point");
  }
  if (strips < 4 || strips > 100000) {
    throw std::invalid_argument(
        fmt::format("semi_hertz.strips: must lie in [4, 100000], got {}", strips));
  }
}

namespace {

// The checked problem's deepest sample and the first estimate of the reference curvature B_ref.
struct GapMinimum {
  std::size_t jmin = 0;
  double z_min = 0.0;
  double b_ref = 0.0;
};

GapMinimum find_minimum(const NormalProblem& p, const SemiHertzOptions& options) {
  options.validate();
  if (!(p.curvature_x > 0.0) || !std::isfinite(p.curvature_x)) {
    throw std::invalid_argument(fmt::format(
        "semi_hertz: curvature_x (A) must be finite and > 0 [1/m], got {}", p.curvature_x));
  }
  if (p.gap_y.size() < 3 || p.gap_y.size() != p.gap_z.size()) {
    throw std::invalid_argument(
        fmt::format("semi_hertz: gap_y and gap_z must have the same size >= 3, got {} and {}",
                    p.gap_y.size(), p.gap_z.size()));
  }
  for (std::size_t i = 0; i + 1 < p.gap_y.size(); ++i) {
    if (!(p.gap_y[i + 1] > p.gap_y[i])) {
      throw std::invalid_argument(
          fmt::format("semi_hertz: gap_y must be strictly increasing (index {})", i + 1));
    }
  }
  GapMinimum g;
  g.jmin =
      static_cast<std::size_t>(std::min_element(p.gap_z.begin(), p.gap_z.end()) - p.gap_z.begin());
  const std::size_t jmin = g.jmin;
  if (jmin == 0 || jmin + 1 == p.gap_y.size()) {
    throw std::invalid_argument(
        "semi_hertz: the gap minimum lies on the first or last sample; widen gap_y");
  }
  g.z_min = p.gap_z[jmin];
  // Transverse curvature at the deepest point: second divided difference = coefficient of y^2.
  const double y0 = p.gap_y[jmin - 1], y1 = p.gap_y[jmin], y2 = p.gap_y[jmin + 1];
  const double z0 = p.gap_z[jmin - 1], z1 = p.gap_z[jmin], z2 = p.gap_z[jmin + 1];
  double b_ref = ((z2 - z1) / (y2 - y1) - (z1 - z0) / (y1 - y0)) / (y2 - y0);
  if (options.curvature == SemiHertzOptions::Curvature::kFit) {
    // First estimate from the 21 samples around the minimum (robust to sampling noise).
    const std::size_t lo = jmin >= 10 ? jmin - 10 : 0;
    const std::size_t hi = std::min(jmin + 10, p.gap_y.size() - 1);
    const double b_window = least_squares_curvature(p, jmin, lo, hi);
    if (b_window > 0.0 && std::isfinite(b_window)) b_ref = b_window;
  }
  if (!(b_ref > 0.0)) {
    throw std::invalid_argument(fmt::format(
        "semi_hertz: the gap has no positive transverse curvature at its minimum (B = {} 1/m)",
        b_ref));
  }
  g.b_ref = b_ref;
  return g;
}

// Least-squares parabola z = c0 + c1 t + B t^2 (t = y - y_min) over the samples of the deepest
// lobe (z - z_min < h0); NaN when the lobe has fewer than 5 samples or B is not positive.
double lobe_curvature(const NormalProblem& p, const GapMinimum& g, double h0) {
  std::size_t lo = g.jmin, hi = g.jmin;
  while (lo > 0 && p.gap_z[lo - 1] - g.z_min < h0) --lo;
  while (hi + 1 < p.gap_z.size() && p.gap_z[hi + 1] - g.z_min < h0) ++hi;
  if (hi - lo + 1 >= 5) {
    const double b_fit = least_squares_curvature(p, g.jmin, lo, hi);
    if (b_fit > 0.0 && std::isfinite(b_fit)) return b_fit;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

// Least-squares parabola over the deepest lobe at h0 with the weights (h0 - (z - z_min)) / h0,
// which fall to zero at the lobe's edge: B is continuous in h0 and in the gap samples (a sample
// entering or leaving the lobe carries no weight), as a right-hand side of an integrator must be.
// NaN when fewer than 5 samples carry weight or B is not positive.
double tapered_lobe_curvature(const NormalProblem& p, const GapMinimum& g, double h0,
                              std::vector<double>& weight) {
  std::size_t lo = g.jmin, hi = g.jmin;
  while (lo > 0 && p.gap_z[lo - 1] - g.z_min < h0) --lo;
  while (hi + 1 < p.gap_z.size() && p.gap_z[hi + 1] - g.z_min < h0) ++hi;
  if (hi - lo + 1 < 5) return std::numeric_limits<double>::quiet_NaN();
  weight.resize(hi - lo + 1);
  for (std::size_t j = lo; j <= hi; ++j) weight[j - lo] = (h0 - (p.gap_z[j] - g.z_min)) / h0;
  const double b_fit = least_squares_curvature(p, g.jmin, lo, hi, weight.data());
  return b_fit > 0.0 && std::isfinite(b_fit) ? b_fit : std::numeric_limits<double>::quiet_NaN();
}

// Eq. (21) factors r (1 + lambda) and n^2 (n: the Hertz coefficient of the lateral semi-axis,
// b = n c when B is the larger curvature), lambda = A / B_ref: delta = h0 r (1 + lambda) / n^2.
struct ApproachFactors {
  double r_one_plus_lambda = 0.0;
  double n_squared = 0.0;
  bool defined = false;
};

ApproachFactors approach_factors(double curvature_x, double b_ref) {
  ApproachFactors f;
  const double lambda = curvature_x / b_ref;
  const double theta = std::acos(std::abs(curvature_x - b_ref) / (curvature_x + b_ref));
  if (!(theta > 0.0)) return f;
  const HertzCoefficients c = hertz_coefficients(theta);
  const double n_lat = curvature_x <= b_ref ? c.n : c.m;
  f.r_one_plus_lambda = c.r * (1.0 + lambda);
  f.n_squared = n_lat * n_lat;
  f.defined = true;
  return f;
}

// Strips of the grid penetrated at the virtual penetration h0 (eqs. 22-23), one patch per
// connected lobe with its equivalent ellipse: a = max a_i, b = half the lateral extent, centred
// on the lobe. The storage of sol.patches (and of their strips) is reused.
void build_patches(const StripGrid& grid, double h0, double ac, double kp, double curvature_x,
                   double b_ref, NormalSolution& sol) {
  std::size_t count = 0;
  ContactPatch* current = nullptr;
  auto flush = [&]() {
    if (current == nullptr) return;
    double load = 0.0, amax = 0.0, pmax = 0.0;
    for (const auto& s : current->strips) {
      load += 0.5 * kPi * s.peak_pressure * s.half_length * s.width;
      amax = std::max(amax, s.half_length);
      pmax = std::max(pmax, s.peak_pressure);
    }
    const double ylo = current->strips.front().y - 0.5 * current->strips.front().width;
    const double yhi = current->strips.back().y + 0.5 * current->strips.back().width;
    current->y_center = 0.5 * (ylo + yhi);
    for (auto& s : current->strips) s.y -= current->y_center;
    current->semi_axis_x = amax;
    current->semi_axis_y = 0.5 * (yhi - ylo);
    current->normal_force = load;
    current->peak_pressure = pmax;
    current->curvature_x = curvature_x;
    current->curvature_y = b_ref;
    current = nullptr;
  };
  for (int i = 0; i < grid.count; ++i) {
    const double h = h0 - grid.gap[static_cast<std::size_t>(i)];
    if (h <= 0.0) {
      flush();
      continue;
    }
    if (current == nullptr) {
      if (count == sol.patches.size()) sol.patches.emplace_back();
      current = &sol.patches[count++];
      current->strips.clear();
      current->approach = ContactPatch::kNaN;
    }
    PatchStrip s;
    s.y = grid.y0 + i * grid.dy;
    s.width = grid.dy;
    s.half_length = std::sqrt(h / ac);     // eq. (22)
    s.peak_pressure = kp * s.half_length;  // eq. (23) along the strip
    current->strips.push_back(s);
  }
  flush();
  sol.patches.resize(count);
}

}  // namespace

NormalSolution semi_hertz_solve(const NormalProblem& p, const SemiHertzOptions& options) {
  const GapMinimum g = find_minimum(p, options);
  const CombinedMaterial mat = combine(p.body1, p.body2);
  const double z_min = g.z_min;
  double b_ref = g.b_ref;
  NormalSolution sol;
  if (p.normal_force == 0.0) return sol;

  // Reference Hertz ellipse and compensation (eqs. 18-21), then the virtual penetration h0 from
  // the load on strips refined over the penetrated span.
  double ac = 0.0, kp = 0.0, h0 = 0.0;
  StripGrid grid;
  std::vector<double> scratch;
  auto solve_with = [&](double b) {
    const HertzSolution ref = hertz_solve(p.curvature_x, b, p.normal_force, mat.contact_modulus);
    const double l = ref.semi_axis_y / ref.semi_axis_x;
    ac = b * l * l;                            // A_c (eq. 19)
    kp = ref.peak_pressure / ref.semi_axis_x;  // p0_i / a_i
    // h0 = b^2 B (eq. 21) for a quadric gap; in general h0 follows from the load:
    grid = make_grid(p, z_min, p.gap_y.front(), p.gap_y.back(), options.strips);
    h0 = solve_penetration(grid, p.normal_force, ac, kp, scratch);
    for (int pass = 0; pass < 2; ++pass) {
      const auto [lo, hi] = penetrated_span(p, z_min, h0 * 1.0000001);
      if (!(hi > lo)) break;
      grid = make_grid(p, z_min, lo, hi, options.strips);
      h0 = solve_penetration(grid, p.normal_force, ac, kp, scratch);
    }
  };
  solve_with(b_ref);
  if (options.curvature == SemiHertzOptions::Curvature::kFit) {
    // Least-squares curvature over the deepest lobe at this h0, then solve again with it.
    const double b_fit = lobe_curvature(p, g, h0);
    if (std::isfinite(b_fit)) {
      b_ref = b_fit;
      solve_with(b_ref);
    }
  }
  build_patches(grid, h0, ac, kp, p.curvature_x, b_ref, sol);
  // Rigid approach from eq. (21): delta = h0 r (1 + lambda) / n^2, lambda = A/B_ref.
  const ApproachFactors f = approach_factors(p.curvature_x, b_ref);
  if (f.defined) sol.approach = h0 * f.r_one_plus_lambda / f.n_squared;
  return sol;
}

// Passes of the tapered lobe fit after the first estimate: the lobe's width goes as B^(-1/2),
// so each pass moves B by a fraction of the previous change; two passes settle B on the S1002 /
// UIC60 gap within 1e-3 (tests/vehicle/semi_hertz_vehicle_test.cpp).
constexpr int kApproachFitPasses = 2;

void semi_hertz_solve_from_approach(const NormalProblem& p, double approach,
                                    const SemiHertzOptions& options, SemiHertzWorkspace& work,
                                    NormalSolution& out) {
  const GapMinimum g = find_minimum(p, options);
  if (!(approach >= 0.0) || !std::isfinite(approach)) {
    throw std::invalid_argument(
        fmt::format("semi_hertz: the approach must be finite and >= 0 m, got {}", approach));
  }
  const CombinedMaterial mat = combine(p.body1, p.body2);
  out.approach = approach;
  if (approach == 0.0) {
    out.patches.clear();
    return;
  }
  // Reference Hertz ellipse of the same approach and compensation (eqs. 18-20); the virtual
  // penetration from eq. (21) read backwards, h0 = delta n^2 / (r (1 + lambda)).
  double b_ref = g.b_ref, ac = 0.0, kp = 0.0, h0 = 0.0;
  auto solve_with = [&](double b) {
    const ApproachFactors f = approach_factors(p.curvature_x, b);
    if (!f.defined) {
      throw std::invalid_argument(fmt::format(
          "semi_hertz: eq. (21) undefined for A = {} 1/m, B_ref = {} 1/m", p.curvature_x, b));
    }
    h0 = approach * f.n_squared / f.r_one_plus_lambda;
    const HertzSolution ref =
        hertz_solve_from_approach(p.curvature_x, b, approach, mat.contact_modulus);
    const double l = ref.semi_axis_y / ref.semi_axis_x;
    ac = b * l * l;                            // A_c (eq. 19)
    kp = ref.peak_pressure / ref.semi_axis_x;  // p0_i / a_i, independent of the load
  };
  // First estimate: the larger of the caller's curvature_y (a geometry source's point curvature,
  // continuous in the pose) and the one of the samples around the minimum. The larger, not the
  // caller's alone: where the point's curvature passes through zero (a nearly conformal point)
  // the samples' curvature takes over continuously instead of replacing it at B = 0.
  if (std::isfinite(p.curvature_y)) b_ref = std::max(b_ref, p.curvature_y);
  solve_with(b_ref);
  if (options.curvature == SemiHertzOptions::Curvature::kFit) {
    for (int pass = 0; pass < kApproachFitPasses; ++pass) {
      const double b_fit = tapered_lobe_curvature(p, g, h0, work.weight);
      if (!std::isfinite(b_fit)) break;
      b_ref = b_fit;
      solve_with(b_ref);
    }
  }
  const auto [lo, hi] = penetrated_span(p, g.z_min, h0 * 1.0000001);
  if (!(hi > lo)) {
    out.patches.clear();
    return;
  }
  StripGrid grid;
  std::swap(grid.gap, work.strip_gap);  // reuse the workspace's storage
  fill_grid(p, g.z_min, lo, hi, options.strips, grid);
  build_patches(grid, h0, ac, kp, p.curvature_x, b_ref, out);
  std::swap(grid.gap, work.strip_gap);
}

}  // namespace ferro::contact
