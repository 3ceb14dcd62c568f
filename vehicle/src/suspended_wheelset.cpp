#include "ferro/vehicle/suspended_wheelset.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "ferro/contact/tangential/kalker_coefficients.hpp"

namespace ferro::vehicle {
namespace {

void require_positive(double v, const std::string& where, const char* field, const char* unit) {
  if (!(v > 0.0) || !std::isfinite(v)) {
    throw std::invalid_argument(
        fmt::format("{}.{}: must be a finite positive value in {}, got {}", where, field, unit, v));
  }
}
void require_non_negative(double v, const std::string& where, const char* field, const char* unit) {
  if (!(v >= 0.0) || !std::isfinite(v)) {
    throw std::invalid_argument(
        fmt::format("{}.{}: must be a finite value >= 0 in {}, got {}", where, field, unit, v));
  }
}

}  // namespace

void SuspendedWheelsetParams::validate(const std::string& where) const {
  require_positive(mass, where, "mass", "kg");
  require_positive(yaw_inertia, where, "yaw_inertia", "kg m^2");
  require_positive(half_gauge, where, "half_gauge", "m");
  require_positive(rolling_radius, where, "rolling_radius", "m");
  require_positive(conicity, where, "conicity", "- (effective conicity)");
  require_non_negative(primary_stiffness_x, where, "primary_stiffness_x", "N/m");
  require_non_negative(primary_stiffness_y, where, "primary_stiffness_y", "N/m");
  require_non_negative(primary_damping_x, where, "primary_damping_x", "N s/m");
  require_non_negative(primary_damping_y, where, "primary_damping_y", "N s/m");
  if (!std::isnan(primary_semi_spacing)) {
    require_positive(primary_semi_spacing, where, "primary_semi_spacing", "m");
  }
}

double SuspendedWheelsetParams::spring_semi_spacing() const {
  return std::isnan(primary_semi_spacing) ? half_gauge : primary_semi_spacing;
}

void LinearCreepParams::validate(const std::string& where) const {
  require_positive(semi_axis_a, where, "semi_axis_a", "m");
  require_positive(semi_axis_b, where, "semi_axis_b", "m");
  wheel.validate(where + ".wheel");
  rail.validate(where + ".rail");
  reduction.validate(where.c_str());
  if (coefficients != "kalker_table" && coefficients != "equal") {
    throw std::invalid_argument(fmt::format(
        "{}.coefficients: unknown '{}'; allowed: kalker_table, equal", where, coefficients));
  }
}

CreepCoefficients creep_coefficients(const LinearCreepParams& creep) {
  creep.validate();
  const auto m = contact::combine(creep.wheel, creep.rail);
  const auto c =
      contact::kalker_coefficients_table(creep.semi_axis_a, creep.semi_axis_b, m.poisson);
  const double gab = m.shear_modulus * creep.semi_axis_a * creep.semi_axis_b;
  const double c22 = creep.coefficients == "equal" ? c.c11 : c.c22;
  return CreepCoefficients{gab * c.c11 * creep.reduction.k11, gab * c22 * creep.reduction.k22};
}

SuspendedWheelset::SuspendedWheelset(SuspendedWheelsetParams params, CreepCoefficients creep,
                                     double speed)
    : p_(params), creep_(creep), speed_(speed) {
  p_.validate();
  if (!(speed > 0.0) || !std::isfinite(speed)) {
    throw std::invalid_argument(fmt::format("speed: must be finite and > 0 m/s, got {}", speed));
  }
  if (!(creep.f11 > 0.0) || !(creep.f22 > 0.0)) {
    throw std::invalid_argument("creep coefficients f11, f22 must be positive");
  }
}

int SuspendedWheelset::rhs(double /*t*/, std::span<const double> x, std::span<double> xdot) const {
  const double y = x[0], psi = x[1], yd = x[2], psid = x[3];
  const double e = p_.half_gauge, d = p_.spring_semi_spacing(), V = speed_;
  // Creepages: lateral xi_y = y'/V - psi (both wheels); longitudinal on the left wheel
  // xi_x = -(e psi'/V + gamma y / R), opposite on the right (Toumi eqs. 24-25).
  const double xi_y = yd / V - psi;
  const double xi_x_left = -(e * psid / V + p_.conicity * y / p_.rolling_radius);
  const double lateral_force = -2.0 * creep_.f22 * xi_y;
  const double yaw_moment = 2.0 * e * creep_.f11 * xi_x_left;
  const double fy_susp = -2.0 * p_.primary_stiffness_y * y - 2.0 * p_.primary_damping_y * yd;
  const double mz_susp =
      -2.0 * d * d * (p_.primary_stiffness_x * psi + p_.primary_damping_x * psid);
  xdot[0] = yd;
  xdot[1] = psid;
  xdot[2] = (lateral_force + fy_susp) / p_.mass;
  xdot[3] = (yaw_moment + mz_susp) / p_.yaw_inertia;
  return std::isfinite(xdot[2]) && std::isfinite(xdot[3]) ? kRhsOk : kRhsFatal;
}

std::vector<SignalInfo> SuspendedWheelset::state_info() const {
  return {{"wheelset.y", "m", "lateral displacement"},
          {"wheelset.yaw", "rad", "yaw angle"},
          {"wheelset.y_dot", "m/s", "lateral velocity"},
          {"wheelset.yaw_dot", "rad/s", "yaw rate"}};
}

std::vector<SignalInfo> SuspendedWheelset::signal_info() const {
  return {{"contact.creepage_lateral", "-", "lateral creepage xi_y (both wheels)"},
          {"contact.creepage_long_left", "-", "longitudinal creepage xi_x, left wheel"},
          {"contact.lateral_force", "N", "total lateral creep force on the wheelset"},
          {"contact.yaw_moment", "N m", "yaw moment of the longitudinal creep forces"}};
}

void SuspendedWheelset::signals(double /*t*/, std::span<const double> x,
                                std::span<double> out) const {
  const double e = p_.half_gauge, V = speed_;
  const double xi_y = x[2] / V - x[1];
  const double xi_x_left = -(e * x[3] / V + p_.conicity * x[0] / p_.rolling_radius);
  out[0] = xi_y;
  out[1] = xi_x_left;
  out[2] = -2.0 * creep_.f22 * xi_y;
  out[3] = 2.0 * e * creep_.f11 * xi_x_left;
}

double analytic_critical_speed(const SuspendedWheelsetParams& p, const CreepCoefficients& creep) {
  p.validate();
  const double e = p.half_gauge, d = p.spring_semi_spacing(), R = p.rolling_radius;
  if (std::abs(creep.f11 - creep.f22) > 1e-12 * creep.f11) {
    throw std::invalid_argument("analytic_critical_speed: formula (151) needs f11 = f22");
  }
  if (std::abs(p.yaw_inertia - p.mass * e * e) > 1e-6 * p.yaw_inertia) {
    throw std::invalid_argument("analytic_critical_speed: formula (151) needs I_zz = m e^2");
  }
  if (p.primary_damping_x != 0.0 || p.primary_damping_y != 0.0) {
    throw std::invalid_argument("analytic_critical_speed: formula (151) has no primary damping");
  }
  const double f = creep.f11, m = p.mass, g = p.conicity;
  const double Ky = 2.0 * p.primary_stiffness_y;
  const double Kx = 2.0 * p.primary_stiffness_x * d * d / (e * e);
  const double den = m * (16.0 * f * f * g - e * R * (Ky - Kx) * (Ky - Kx));
  if (den <= 0.0) return std::numeric_limits<double>::infinity();
  return std::sqrt(8.0 * f * f * e * R * (Kx + Ky) / den);
}

}  // namespace ferro::vehicle
