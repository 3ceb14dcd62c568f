// Polach's creep-force model. See polach.hpp for references and known deviations.
#include "ferro/contact/tangential/polach.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "ferro/contact/tangential/fastsim.hpp"
#include "ferro/contact/tangential/saturation_laws.hpp"

namespace ferro::contact {

namespace {
// FASTSIM grid of the fallback where Polach's spin term fails (about 1 us per evaluation).
constexpr int kSpinFallbackElements = 10;
}  // namespace

void PolachOptions::validate() const {
  if (!(k_a > 0.0 && k_a <= 1.0)) {
    throw std::invalid_argument(fmt::format("polach.k_a: must lie in (0, 1], got {}", k_a));
  }
  if (!(k_s > 0.0 && k_s <= 1.0)) {
    throw std::invalid_argument(fmt::format("polach.k_s: must lie in (0, 1], got {}", k_s));
  }

  if (!(friction_ratio > 0.0 && friction_ratio <= 1.0)) {
    throw std::invalid_argument(
        fmt::format("polach.friction_ratio: must lie in (0, 1], got {}", friction_ratio));
  }
  if (!(friction_decay >= 0.0) || !std::isfinite(friction_decay)) {
    throw std::invalid_argument(fmt::format(
        "polach.friction_decay: must be finite and >= 0 [s/m], got {}", friction_decay));
  }
}

PolachModel::PolachModel(PolachOptions options) : options_(options) {
  options_.validate();
}

TangentialSolution PolachModel::solve(const TangentialProblem& problem) const {
  problem.validate();
  constexpr double kPi = std::numbers::pi;
  const LinearCreepStiffness k = linear_creep_stiffness(problem, options_.source);
  TangentialSolution out;
  const double a = k.a, b = k.b, g = k.shear_modulus;
  const double sx = problem.creepage.longitudinal;
  const double sy = problem.creepage.lateral;
  const double phi = problem.creepage.spin;
  // Spin opposing the lateral creepage strongly enough to reverse s_y + phi a: the published
  // spin term divides by a small s_c and fails (F_yS alone can exceed mu Q with the wrong sign).
  // Fallback: FASTSIM (10 x 10, three flexibilities) with the same K_ij and friction.
  if (phi != 0.0 && sy * phi < 0.0 && std::abs(phi * a) > std::abs(sy)) {
    FastsimOptions fo;
    fo.mx = fo.my = kSpinFallbackElements;
    fo.source = options_.source;
    TangentialProblem fp = problem;
    fp.map = nullptr;
    if (options_.friction_decay > 0.0 && problem.rolling_speed > 0.0) {
      const double w = problem.rolling_speed * std::hypot(sx, sy);  // slip speed
      fp.friction *= (1.0 - options_.friction_ratio) * std::exp(-options_.friction_decay * w) +
                     options_.friction_ratio;
    }
    return FastsimModel(fo).solve(fp);
  }
  // Spin-corrected lateral creepage and total creepage.
  const double syc = std::abs(sy + phi * a) > std::abs(sy) ? sy + phi * a : sy;
  const double sc = std::hypot(sx, syc);
  if (sc == 0.0) return out;
  double mu = problem.friction;
  if (options_.friction_decay > 0.0) {
    const double v = problem.rolling_speed;
    if (!(v > 0.0) || !std::isfinite(v)) {
      throw std::invalid_argument(fmt::format(
          "polach: friction_decay > 0 needs tangential problem.rolling_speed > 0 [m/s], got {}",
          v));
    }
    const double w = v * sc;  // slip speed
    mu *= (1.0 - options_.friction_ratio) * std::exp(-options_.friction_decay * w) +
          options_.friction_ratio;
  }
  const double q_mu = mu * problem.patch->normal_force;
  if (!(q_mu > 0.0)) return out;
  // Longitudinal/lateral force from creepage.
  const double cjj = std::hypot(k.c.c11 * sx / sc, k.c.c22 * syc / sc);
  const double eps = g * kPi * a * b * cjj * sc / (4.0 * q_mu);
  const double ka_eps = options_.k_a * eps;
  const double f =
      2.0 * q_mu / kPi * (ka_eps / (1.0 + ka_eps * ka_eps) + std::atan(options_.k_s * eps));
  out.force_x = -f * sx / sc;
  out.force_y = -f * sy / sc;
  // Lateral force from spin.
  if (phi != 0.0) {
    const double shape = 1.0 + 6.3 * (1.0 - std::exp(-a / b));
    const double eps_psi = 8.0 / 3.0 * g * b * std::sqrt(a * b) / q_mu * k.c.c23 / shape * sc;
    const double e2 = eps_psi * eps_psi;
    const double delta = (e2 - 1.0) / (e2 + 1.0);
    const double one_m_d2 = 1.0 - delta * delta;
    const double km =
        std::abs(eps_psi) * (delta * delta * delta / 3.0 - delta * delta / 2.0 + 1.0 / 6.0) -
        std::sqrt(one_m_d2 * one_m_d2 * one_m_d2) / 3.0;
    out.force_y += 9.0 / 16.0 * a * q_mu * km * shape * phi / sc;
  }
  // Coulomb bound on the sum of the creep and spin terms.
  const double ft = std::hypot(out.force_x, out.force_y);
  if (ft > q_mu) {
    out.force_x *= q_mu / ft;
    out.force_y *= q_mu / ft;
  }
  // Moment: coupling term scaled like the creep force, spin term saturated on its full-slip
  // limit (saturation_laws.hpp).
  const double f_lin = g * a * b * cjj * sc;
  const double factor = f_lin > 0.0 ? f / f_lin : 1.0;
  // Creepage-only utilisation (Polach's function of s = |(s_x, s_y)|).
  double u = 0.0;
  if (const double s0 = std::hypot(sx, sy); s0 > 0.0) {
    const double e0 =
        g * kPi * a * b * std::hypot(k.c.c11 * sx / s0, k.c.c22 * sy / s0) * s0 / (4.0 * q_mu);
    const double ka0 = options_.k_a * e0;
    u = 2.0 / kPi * (ka0 / (1.0 + ka0 * ka0) + std::atan(options_.k_s * e0));
  }
  out.moment_z = saturated_spin_moment(k, problem.creepage, factor, q_mu, u);
  return out;
}

std::unique_ptr<TangentialModel> PolachModel::from_options(const ModelOptions& options) {
  check_option_keys("polach", options,
                    {"coefficients", "k_a", "k_s", "friction_ratio", "friction_decay"});
  PolachOptions o;
  o.source = coefficients_option(options);
  o.k_a = option_double(options, "k_a", o.k_a);
  o.k_s = option_double(options, "k_s", o.k_s);
  o.friction_ratio = option_double(options, "friction_ratio", o.friction_ratio);
  o.friction_decay = option_double(options, "friction_decay", o.friction_decay);
  return std::make_unique<PolachModel>(o);
}

}  // namespace ferro::contact
