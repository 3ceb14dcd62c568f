// Tabulated MIM creep forces: build (MIM solves), HDF5 I/O (the io layer), tensor-product cubic
// Hermite interpolation, and the tangential model "mim_table".
//
// References: see mim_table.hpp (Toumi 2016 ch. 2, eqs. 38-40, annex A.2; Kalker 1990 ch. 2).
// Known deviations: see mim_table.hpp (fixed nu, clamping outside the table, interpolation).
#include "ferro/contact/tangential/mim_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <exception>
#include <limits>
#include <mutex>
#include <random>
#include <stdexcept>
#include <thread>

#include "ferro/contact/mim/mim.hpp"
#include "ferro/contact/tangential/kalker_coefficients.hpp"
#include "ferro/io/hdf5.hpp"
#include "ferro/numerics/interpolation.hpp"

namespace ferro::contact {

namespace {

constexpr int kFormatVersion = 2;  // 2: spin axis in psi = phi* kappa(a/b) / kappa(1)

void check_axis(const std::vector<double>& v, const char* name, bool starts_at_zero,
                bool positive) {
  if (v.size() < 3) {
    throw std::invalid_argument(fmt::format("mim table axis '{}': needs >= 3 nodes", name));
  }
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i]) || (positive && !(v[i] > 0.0)) || (i > 0 && !(v[i] > v[i - 1]))) {
      throw std::invalid_argument(fmt::format(
          "mim table axis '{}': nodes must be finite{} and strictly increasing (node {} = {})",
          name, positive ? ", > 0" : "", i, v[i]));
    }
  }
  if (starts_at_zero && v.front() != 0.0) {
    throw std::invalid_argument(fmt::format("mim table axis '{}': first node must be 0", name));
  }
}

// Weights of the cubic Hermite interpolant on nodes t at q (clamped): value = sum w[k] f[k].
// Node derivatives: three-point (non-uniform) formulas, one-sided second order at the ends.
struct AxisWeights {
  int first = 0;  // index of w[0]
  int count = 0;  // <= 4
  double w[4] = {0, 0, 0, 0};
};

AxisWeights axis_weights(const std::vector<double>& t, double q) {
  const int n = static_cast<int>(t.size());
  const numerics::AxisCell cell = numerics::locate(t, q);
  const int i = static_cast<int>(cell.index);
  const double h = t[i + 1] - t[i];
  const double u = cell.t;
  // Cubic Hermite value weights, factored (numerics::HermiteBasis holds the expanded form).
  const double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u);
  const double h01 = u * u * (3 - 2 * u), h11 = u * u * (u - 1);
  // Derivative at node j as coefficients on nodes (j0, j0+1, j0+2).
  const auto derivative = [&](int j, int& j0, double c[3]) {
    if (j == 0) {
      const double a = t[1] - t[0], b = t[2] - t[1];
      j0 = 0;
      c[0] = -(2 * a + b) / (a * (a + b));
      c[1] = (a + b) / (a * b);
      c[2] = -a / (b * (a + b));
    } else if (j == n - 1) {
      const double a = t[n - 2] - t[n - 3], b = t[n - 1] - t[n - 2];
      j0 = n - 3;
      c[0] = b / (a * (a + b));
      c[1] = -(a + b) / (a * b);
      c[2] = (2 * b + a) / (b * (a + b));
    } else {
      const double a = t[j] - t[j - 1], b = t[j + 1] - t[j];
      j0 = j - 1;
      c[0] = -b / (a * (a + b));
      c[1] = (b - a) / (a * b);
      c[2] = a / (b * (a + b));
    }
  };
  AxisWeights out;
  out.first = std::max(0, std::min(i - 1, n - 4));
  out.count = std::min(4, n);
  const auto add = [&](int node, double weight) { out.w[node - out.first] += weight; };
  add(i, h00);
  add(i + 1, h01);
  double c[3];
  int j0 = 0;
  derivative(i, j0, c);
  for (int k = 0; k < 3; ++k) add(j0 + k, h10 * h * c[k]);
  derivative(i + 1, j0, c);
  for (int k = 0; k < 3; ++k) add(j0 + k, h11 * h * c[k]);
  return out;
}

// Scales of a Hertzian problem: s = mu F_n, c = sqrt(ab), and the normalisation factors.
struct Scales {
  double s = 0.0, c = 0.0;
  double kx = 0.0, ky = 0.0, ks = 0.0;  // xi* = k xi
};

Scales scales(double a, double b, double normal_force, double mu, double shear_modulus,
              double poisson) {
  const KalkerCoefficients cij = kalker_coefficients_table(a, b, poisson);
  Scales sc;
  sc.s = mu * normal_force;
  sc.c = std::sqrt(a * b);
  sc.kx = shear_modulus * a * b * cij.c11 / sc.s;
  sc.ky = shear_modulus * a * b * cij.c22 / sc.s;
  sc.ks = shear_modulus * a * b * sc.c * cij.c23 / sc.s;
  return sc;
}

// Runs body(item, solver) for item = 0..count-1 on `threads` threads taking items in order, one
// MIM solver per thread (its operators are reused across that thread's items); the first
// exception stops the others and is rethrown.
template <class Body>
void for_each_item(int count, int threads, const Body& body) {
  std::atomic<int> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto worker = [&] {
    mim::HertzMimSolver solver;
    try {
      for (int item = next++; item < count; item = next++) body(item, solver);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next = count;
    }
  };
  std::vector<std::thread> pool;
  for (int k = 1; k < threads; ++k) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace

double mim_table_spin_scale(double ratio, double poisson) {
  const auto kappa = [&](double r) {
    const double a = std::sqrt(r), b = 1.0 / std::sqrt(r);  // c = sqrt(ab) = 1
    const KalkerCoefficients cij = kalker_coefficients_table(a, b, poisson);
    return std::max(cij.c11 * b, cij.c22 * a) / cij.c23;
  };
  return kappa(ratio) / kappa(1.0);
}

void MimTableSpec::validate() const {
  check_axis(ratio, "ratio", false, true);
  check_axis(xi_x, "xi_x", true, false);
  check_axis(xi_y, "xi_y", true, false);
  check_axis(spin, "spin", false, false);
  if (!(poisson >= 0.0 && poisson < 0.5)) {
    throw std::invalid_argument(
        fmt::format("mim table poisson: must be in [0, 0.5), got {}", poisson));
  }
  // The most elongated ellipse of the table sets the largest grid.
  int most = std::numeric_limits<int>::max();
  for (double r : {ratio.front(), ratio.back()}) {
    most = std::min(most, mim::max_elements_minor(r, 1.0));
  }
  if (elements < 6 || elements > most) {
    throw std::invalid_argument(fmt::format(
        "mim table elements: must lie in [6, {}] for a/b in [{}, {}] (at most {} grid elements "
        "per solve), got {}",
        most, ratio.front(), ratio.back(), mim::kMaxGridElements, elements));
  }
  if (grid != "minor" && grid != "patch" && grid != "patch_richardson") {
    throw std::invalid_argument(fmt::format(
        "mim table grid: unknown value '{}'; allowed: minor, patch, patch_richardson", grid));
  }
  if (grid == "patch_richardson" && elements < 12) {
    throw std::invalid_argument(
        fmt::format("mim table elements: grid patch_richardson needs >= 12, got {}", elements));
  }
  if (threads < 1) {
    throw std::invalid_argument(fmt::format("mim table threads: must be >= 1, got {}", threads));
  }
  if (density < 1 || density > 8) {
    throw std::invalid_argument(
        fmt::format("mim table density: must lie in [1, 8], got {}", density));
  }
}

MimTableSpec MimTableSpec::densified() const {
  MimTableSpec out = *this;
  const auto refine = [&](const std::vector<double>& v) {
    std::vector<double> r;
    for (std::size_t i = 0; i + 1 < v.size(); ++i) {
      for (int k = 0; k < density; ++k) r.push_back(v[i] + (v[i + 1] - v[i]) * k / density);
    }
    r.push_back(v.back());
    return r;
  };
  out.xi_x = refine(xi_x);
  out.xi_y = refine(xi_y);
  out.spin = refine(spin);
  out.density = 1;
  return out;
}

MimTableSpec MimTableSpec::default_spec() {
  MimTableSpec s;
  for (int k = -2; k <= 2; ++k) s.ratio.push_back(std::pow(5.0, k / 2.0));  // 0.2 ... 5
  s.xi_x = {0.0, 0.3, 0.6, 1.0, 1.5, 2.2, 3.2, 5.0};
  s.xi_y = s.xi_x;
  // Spin nodes: the force turns fastest below psi ~ 3 (measured against converged MIM over the
  // bench case set: 7 nodes per sign give 0.0039 mu F_n mean error, these 14 give 0.0030).
  const std::vector<double> half = {0.12, 0.25, 0.4, 0.6, 0.8, 1.0, 1.3,
                                    1.6,  2.0,  2.6, 3.4, 4.5, 6.0, 9.0};
  for (auto it = half.rbegin(); it != half.rend(); ++it) s.spin.push_back(-*it);
  s.spin.push_back(0.0);
  for (double v : half) s.spin.push_back(v);
  // 20 x 20 elements over the patch, extrapolated with 10 x 10: 0.002 mu F_n mean error against
  // converged MIM at 2.4 ms per node (16 square elements across the shorter axis: 0.0066 with a
  // 16 x 80 grid at a/b = 5).
  s.elements = 20;
  s.grid = "patch_richardson";
  return s;
}

void MimTable::init_axes() {
  log_ratio_.clear();
  spin_scale_.clear();
  for (double r : spec_.ratio) {
    log_ratio_.push_back(std::log(r));
    spin_scale_.push_back(mim_table_spin_scale(r, spec_.poisson));
  }
}

std::size_t MimTable::index(int ir, int ix, int iy, int is) const {
  const std::size_t nx = spec_.xi_x.size(), ny = spec_.xi_y.size(), ns = spec_.spin.size();
  return ((static_cast<std::size_t>(ir) * nx + ix) * ny + iy) * ns + is;
}

MimTableValue MimTable::node(int ir, int ix, int iy, int is) const {
  const std::size_t k = index(ir, ix, iy, is);
  return {fx_[k], fy_[k], mz_[k]};
}

MimTable MimTable::build(const MimTableSpec& requested) {
  requested.validate();
  const MimTableSpec spec = requested.densified();
  MimTable t;
  t.spec_ = spec;
  t.init_axes();
  const std::size_t n = spec.ratio.size() * spec.xi_x.size() * spec.xi_y.size() * spec.spin.size();
  t.fx_.assign(n, 0.0);
  t.fy_.assign(n, 0.0);
  t.mz_.assign(n, 0.0);
  const Material steel = Material::from_young(210.0e9, spec.poisson);
  const double g = combine(steel, steel).shear_modulus;
  const double b = 5.0e-3, normal_force = 100.0e3, mu = 0.3;
  const int nx = static_cast<int>(spec.xi_x.size()), ny = static_cast<int>(spec.xi_y.size());
  const int ns = static_cast<int>(spec.spin.size());
  // Work item = (ratio, xi_x) line; threads take lines in order (one MIM solver each, so the
  // unit-grid operators are reused along a ratio).
  const int lines = static_cast<int>(spec.ratio.size()) * nx;
  for_each_item(lines, spec.threads, [&](int line, mim::HertzMimSolver& solver) {
    const int ir = line / nx, ix = line % nx;
    const double a = spec.ratio[ir] * b;
    const Scales sc = scales(a, b, normal_force, mu, g, spec.poisson);
    for (int iy = 0; iy < ny; ++iy) {
      for (int is = 0; is < ns; ++is) {
        if (spec.xi_x[ix] == 0.0 && spec.xi_y[iy] == 0.0 && spec.spin[is] == 0.0) continue;
        mim::HertzRollingInput in;
        in.semi_axis_x = a;
        in.semi_axis_y = b;
        in.normal_force = normal_force;
        in.rolling = mim::RollingInput{spec.xi_x[ix] / sc.kx, spec.xi_y[iy] / sc.ky,
                                       spec.spin[is] / t.spin_scale_[ir] / sc.ks, mu};
        in.body1 = in.body2 = steel;
        in.elements_minor = spec.elements;
        in.grid_over_patch = spec.grid != "minor";
        in.extrapolate = spec.grid == "patch_richardson";
        const mim::MimResult r = solver.solve(in);
        if (!r.converged) {
          throw std::runtime_error(
              fmt::format("mim table: MIM did not converge at a/b = {}, xi* = ({}, {}, {})",
                          spec.ratio[ir], spec.xi_x[ix], spec.xi_y[iy], spec.spin[is]));
        }
        const std::size_t k = t.index(ir, ix, iy, is);
        t.fx_[k] = r.force_x / sc.s;
        t.fy_[k] = r.force_y / sc.s;
        t.mz_[k] = r.moment_z / (sc.s * sc.c);
      }
    }
  });
  return t;
}

void MimTable::write_hdf5(const std::string& path) const {
  io::H5File file = io::H5File::create(path);
  file.set_attribute("/", "format_version", static_cast<double>(kFormatVersion));
  file.set_attribute("/", "poisson", spec_.poisson);
  file.set_attribute("/", "elements", static_cast<double>(spec_.elements));
  file.set_attribute("/", "grid", spec_.grid);
  const auto axis = [&](const char* name, const std::vector<double>& v) {
    file.write_array(name, v, {v.size()});
  };
  axis("/ratio", spec_.ratio);
  axis("/xi_x", spec_.xi_x);
  axis("/xi_y", spec_.xi_y);
  axis("/spin", spec_.spin);
  const io::Dims dims = {spec_.ratio.size(), spec_.xi_x.size(), spec_.xi_y.size(),
                         spec_.spin.size()};
  file.write_array("/f_x", fx_, dims);
  file.write_array("/f_y", fy_, dims);
  file.write_array("/m_z", mz_, dims);
  file.close();
}

MimTable MimTable::read_hdf5(const std::string& path) {
  const io::H5File file = io::H5File::open_input(path, "MIM table");
  const auto attribute = [&](const char* name) {
    if (!file.has_attribute("/", name))
      throw std::invalid_argument(fmt::format("{}: missing attribute '{}'", path, name));
    return file.number_attribute("/", name);
  };
  const auto dataset = [&](const std::string& name, io::Dims* dims = nullptr) {
    if (!file.exists(name))
      throw std::invalid_argument(fmt::format("{}: missing dataset '{}'", path, name));
    return file.read_array(name, dims);
  };
  const double version = attribute("format_version");
  if (version != kFormatVersion) {
    throw std::invalid_argument(
        fmt::format("{}: format_version {} (expected {}; rebuild it with `ferrodyn contact "
                    "mim-table`)",
                    path, version, kFormatVersion));
  }
  MimTable t;
  t.spec_.poisson = attribute("poisson");
  t.spec_.elements = static_cast<int>(attribute("elements"));
  // Tables written before the grid choice existed were built on square elements.
  t.spec_.grid = file.has_attribute("/", "grid") ? file.string_attribute("/", "grid") : "minor";
  t.spec_.ratio = dataset("ratio");
  t.spec_.xi_x = dataset("xi_x");
  t.spec_.xi_y = dataset("xi_y");
  t.spec_.spin = dataset("spin");
  try {
    t.spec_.validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format("{}: {}", path, e.what()));
  }
  t.init_axes();
  const io::Dims expect = {t.spec_.ratio.size(), t.spec_.xi_x.size(), t.spec_.xi_y.size(),
                           t.spec_.spin.size()};
  for (const char* name : {"f_x", "f_y", "m_z"}) {
    io::Dims dims;
    std::vector<double> v = dataset(name, &dims);
    if (dims != expect) {
      throw std::invalid_argument(fmt::format(
          "{}: dataset '{}' must have dims [ratio][xi_x][xi_y][spin] = [{}][{}][{}][{}]", path,
          name, expect[0], expect[1], expect[2], expect[3]));
    }
    (name[0] == 'f' ? (name[2] == 'x' ? t.fx_ : t.fy_) : t.mz_) = std::move(v);
  }
  return t;
}

MimTableValue MimTable::at(double ratio, MimTablePoint p) const {
  // Symmetries: y-mirror for xi_y < 0, reversal of xi_x (see the header).
  double sign_fx = 1.0, sign_fy = 1.0;
  if (p.xi_y < 0.0) {
    p.xi_y = -p.xi_y;
    p.spin = -p.spin;
    sign_fy = -1.0;
  }
  if (p.xi_x < 0.0) {
    p.xi_x = -p.xi_x;
    sign_fx = -1.0;
  }
  // Outside the box: scale the creepage vector down onto it (spin in psi at the query a/b, its
  // scale interpolated linearly in log a/b between the ratio nodes).
  const AxisWeights wr = axis_weights(log_ratio_, std::log(ratio));
  const numerics::AxisCell ratio_cell = numerics::locate(log_ratio_, std::log(ratio));
  const double psi_scale = numerics::lerp(spin_scale_[ratio_cell.index],
                                          spin_scale_[ratio_cell.index + 1], ratio_cell.t);
  const double psi = p.spin * psi_scale;
  const double over = std::max({p.xi_x / spec_.xi_x.back(), p.xi_y / spec_.xi_y.back(),
                                psi / spec_.spin.back(), psi / spec_.spin.front()});
  if (over > 1.0) {
    p.xi_x /= over;
    p.xi_y /= over;
    p.spin /= over;
  }
  const AxisWeights wx = axis_weights(spec_.xi_x, p.xi_x);
  const AxisWeights wy = axis_weights(spec_.xi_y, p.xi_y);
  MimTableValue v;
  // Flat index ((ir nx + ix) ny + iy) ns + is (index()), built up loop by loop.
  const std::size_t nxs = spec_.xi_x.size(), nys = spec_.xi_y.size(), nss = spec_.spin.size();
  for (int a = 0; a < wr.count; ++a) {
    // Spin in each ratio node's own saturation scale.
    const AxisWeights ws = axis_weights(spec_.spin, p.spin * spin_scale_[wr.first + a]);
    const std::size_t row_r = static_cast<std::size_t>(wr.first + a) * nxs;
    for (int b = 0; b < wx.count; ++b) {
      const double wab = wr.w[a] * wx.w[b];
      if (wab == 0.0) continue;
      const std::size_t row_x = (row_r + static_cast<std::size_t>(wx.first + b)) * nys;
      for (int c = 0; c < wy.count; ++c) {
        const double wabc = wab * wy.w[c];
        if (wabc == 0.0) continue;
        const std::size_t base = (row_x + static_cast<std::size_t>(wy.first + c)) * nss +
                                 static_cast<std::size_t>(ws.first);
        for (int d = 0; d < ws.count; ++d) {
          const double w = wabc * ws.w[d];
          v.f_x += w * fx_[base + d];
          v.f_y += w * fy_[base + d];
          v.m_z += w * mz_[base + d];
        }
      }
    }
  }
  v.f_x *= sign_fx;
  v.f_y *= sign_fy;
  v.m_z *= sign_fy;
  // Coulomb bound: the interpolant may overshoot mu F_n near full slip; |f| <= 1.
  // The scale sits 4 ulp below 1/f so that the rounding of the division and of hypot (each
  // within 1 ulp) cannot leave |f| a hair above 1.
  const double f = std::hypot(v.f_x, v.f_y);
  if (f > 1.0) {
    const double scale = (1.0 - 4.0 * std::numeric_limits<double>::epsilon()) / f;
    v.f_x *= scale;
    v.f_y *= scale;
  }
  return v;
}

MimTablePoint MimTable::normalise(const TangentialProblem& problem) const {
  const CombinedMaterial m = combine(problem.body1, problem.body2);
  const ContactPatch& patch = *problem.patch;
  const Scales sc = scales(patch.semi_axis_x, patch.semi_axis_y, patch.normal_force,
                           problem.friction, m.shear_modulus, spec_.poisson);
  // K_ij: the reduced coefficients K_ij C_ij enter the normalisation (linear slopes K_ij C_ij,
  // the same saturation to mu F_n).
  const ReductionFactors& k = problem.reduction;
  return {problem.creepage.longitudinal * sc.kx * k.k11, problem.creepage.lateral * sc.ky * k.k22,
          problem.creepage.spin * sc.ks * k.k23};
}

TangentialSolution MimTable::forces(const TangentialProblem& problem) const {
  problem.validate();
  const CombinedMaterial m = combine(problem.body1, problem.body2);
  if (std::abs(m.poisson - spec_.poisson) > 0.02) {
    throw std::invalid_argument(fmt::format(
        "tangential problem.body1/body2: combined nu = {} but the mim table was built for nu = {}",
        m.poisson, spec_.poisson));
  }
  TangentialSolution s;
  if (problem.friction == 0.0) return s;
  const ContactPatch& patch = *problem.patch;
  const double mu_fn = problem.friction * patch.normal_force;
  const MimTableValue v = at(patch.semi_axis_x / patch.semi_axis_y, normalise(problem));
  s.force_x = v.f_x * mu_fn;
  s.force_y = v.f_y * mu_fn;
  s.moment_z = v.m_z * mu_fn * std::sqrt(patch.semi_axis_x * patch.semi_axis_y);
  return s;
}

std::vector<MimTableErrorPoint> mim_table_error_map(const MimTable& table, int points,
                                                    unsigned seed, int threads) {
  if (points < 1 || threads < 1) {
    throw std::invalid_argument(fmt::format(
        "mim table error map: points and threads must be >= 1, got {} and {}", points, threads));
  }
  const MimTableSpec& spec = table.spec();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<MimTableErrorPoint> out(static_cast<std::size_t>(points));
  const double lr0 = std::log(spec.ratio.front()), lr1 = std::log(spec.ratio.back());
  const double psi_max = std::min(spec.spin.back(), -spec.spin.front());
  for (MimTableErrorPoint& e : out) {  // drawn in order: the map depends on the seed only
    e.ratio = std::exp(lr0 + (lr1 - lr0) * unit(rng));
    e.xi_x = kErrorMapCreepMax * unit(rng);
    e.xi_y = kErrorMapCreepMax * unit(rng);
    e.spin = (2.0 * unit(rng) - 1.0) * std::min(psi_max, kErrorMapCreepMax) /
             mim_table_spin_scale(e.ratio, spec.poisson);
  }
  const Material steel = Material::from_young(210.0e9, spec.poisson);
  const double g = combine(steel, steel).shear_modulus;
  const double b = 5.0e-3, normal_force = 100.0e3, mu = 0.3;
  for_each_item(points, threads, [&](int k, mim::HertzMimSolver& solver) {
    MimTableErrorPoint& e = out[static_cast<std::size_t>(k)];
    const double a = e.ratio * b;
    const Scales sc = scales(a, b, normal_force, mu, g, spec.poisson);
    mim::HertzRollingInput in;
    in.semi_axis_x = a;
    in.semi_axis_y = b;
    in.normal_force = normal_force;
    in.rolling = mim::RollingInput{e.xi_x / sc.kx, e.xi_y / sc.ky, e.spin / sc.ks, mu};
    in.body1 = in.body2 = steel;
    in.elements_minor = spec.elements;
    in.grid_over_patch = spec.grid != "minor";
    in.extrapolate = spec.grid == "patch_richardson";
    const mim::MimResult r = solver.solve(in);
    e.direct = {r.force_x / sc.s, r.force_y / sc.s, r.moment_z / (sc.s * sc.c)};
    e.table = table.at(e.ratio, {e.xi_x, e.xi_y, e.spin});
    e.error = std::hypot(e.table.f_x - e.direct.f_x, e.table.f_y - e.direct.f_y);
  });
  return out;
}

TangentialSolution MimTableModel::solve(const TangentialProblem& problem) const {
  return table_.forces(problem);
}

std::unique_ptr<TangentialModel> MimTableModel::from_options(const ModelOptions& options) {
  check_option_keys("mim_table", options, {"table"});
  const std::string path = option_string(options, "table", "");
  if (path.empty()) {
    throw std::invalid_argument(
        "mim_table option 'table': give the HDF5 table path (table=PATH; build one with "
        "`ferrodyn contact mim-table -o PATH`)");
  }
  return std::make_unique<MimTableModel>(MimTable::read_hdf5(path));
}

}  // namespace ferro::contact
