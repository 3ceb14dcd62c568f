// Vertical-load solve with Hertzian springs, rigid two-wheel touching solve, and the undeformed
// gap sampled in the contact plane.
//
// References: Johnson, "Contact Mechanics" (1985) eq. (4.39): A = (p0/E*)(b/(e^2 a^2))(K - E),
// B = (p0/E*)(b/(e^2 a^2))((a/b)^2 E - K), delta = (p0/E*) b K, p0 = 3P/(2 pi a b);
// Toumi (2016) eqs. (1), (5)-(13) (gap z = z1 - z2, Hertz); EN 15302 (rigid wheelset for the
// rolling-radius difference: both wheels touching, roll free).
// Known deviations: the vertical equilibrium ignores tangential forces (sum N cos(gamma) = load);
// conformal points (B <= 0) are treated as hertz_curvatures() documents.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "ferro/contact/geometry/wheel_rail_geometry.hpp"
#include "ferro/contact/normal/hertz.hpp"

namespace ferro::contact {
namespace {

// Hertz stiffness c of F = c delta^(3/2) [N/m^1.5], from the exact solution under a unit load
// (curvatures treated by hertz_curvatures(): conformal floor, kink cap).
double hertz_stiffness(double ca, double cb, double estar) {
  return std::pow(hertz_solve(ca, cb, 1.0, estar).approach, -1.5);
}

}  // namespace

LoadedWheelset solve_vertical_load(const WheelRailPair& pair, const WheelsetPose& pose,
                                   double total_load, double estar) {
  if (!(total_load > 0.0) || !(estar > 0.0)) {
    throw std::invalid_argument(
        fmt::format("solve_vertical_load: load and contact modulus must be > 0, got {} N, {} Pa",
                    total_load, estar));
  }
  WheelsetPose base = pose;
  base.vertical = 0.0;
  std::vector<ContactPoint> cands = candidate_points(pair, base, Side::left);
  const std::vector<ContactPoint> right = candidate_points(pair, base, Side::right);
  cands.insert(cands.end(), right.begin(), right.end());
  if (cands.empty()) throw std::runtime_error("solve_vertical_load: no candidate contact point");
  std::vector<double> stiff(cands.size());
  for (std::size_t i = 0; i < cands.size(); ++i) {
    stiff[i] = hertz_stiffness(cands[i].curvature_a, cands[i].curvature_b, estar);
  }
  // Vertical load carried at drop v: each penetrating run loads at its deepest candidate.
  auto load_at = [&](double v, std::vector<ContactPoint>* pts) {
    std::vector<ContactPoint> c = contacts_from_candidates(cands, v);
    double total = 0.0;
    for (ContactPoint& p : c) {
      std::size_t idx = 0;
      for (std::size_t i = 0; i < cands.size(); ++i) {
        if (cands[i].side == p.side && cands[i].wheel_y == p.wheel_y) idx = i;
      }
      p.normal_force = stiff[idx] * std::pow(p.penetration, 1.5);
      total += p.normal_force * std::cos(p.contact_angle);
    }
    if (pts) *pts = std::move(c);
    return total;
  };
  double lo = 1.0;
  for (const ContactPoint& p : cands) lo = std::min(lo, p.vertical_gap);
  double hi = lo + 1e-5;
  while (load_at(hi, nullptr) < total_load) {
    hi = lo + 2.0 * (hi - lo);
    if (hi - lo > 0.05) throw std::runtime_error("solve_vertical_load: load not reached");
  }
  for (int it = 0; it < 80 && hi - lo > 1e-13; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (load_at(mid, nullptr) < total_load)
      lo = mid;
    else
      hi = mid;
  }
  LoadedWheelset out;
  out.pose = base;
  out.pose.vertical = 0.5 * (lo + hi);
  load_at(out.pose.vertical, &out.points);
  for (const ContactPoint& p : out.points) {
    out.vertical_load[static_cast<int>(p.side)] += p.normal_force * std::cos(p.contact_angle);
  }
  return out;
}

RigidContact solve_rigid_contact(const WheelRailPair& pair, double lateral, double yaw) {
  WheelsetPose pose;
  pose.lateral = lateral;
  pose.yaw = yaw;
  auto gaps = [&](double roll, std::vector<ContactPoint>* l, std::vector<ContactPoint>* r) {
    pose.roll = roll;
    std::vector<ContactPoint> cl = candidate_points(pair, pose, Side::left);
    std::vector<ContactPoint> cr = candidate_points(pair, pose, Side::right);
    double gl = 1.0, gr = 1.0;
    for (const auto& p : cl) gl = std::min(gl, p.vertical_gap);
    for (const auto& p : cr) gr = std::min(gr, p.vertical_gap);
    if (l) *l = std::move(cl);
    if (r) *r = std::move(cr);
    return std::pair<double, double>{gl, gr};
  };
  // f(roll) = gap_right - gap_left decreases with roll (+roll lowers the right wheel).
  auto f = [&](double roll) {
    const auto [gl, gr] = gaps(roll, nullptr, nullptr);
    return gr - gl;
  };
  double a = -0.01, b = 0.01;
  double fa = f(a), fb = f(b);
  for (int it = 0; it < 10 && fa * fb > 0.0; ++it) {
    a *= 2.0;
    b *= 2.0;
    fa = f(a);
    fb = f(b);
  }
  if (fa * fb > 0.0) throw std::runtime_error("solve_rigid_contact: roll not bracketed");
  // Illinois regula falsi.
  double x = 0.0;
  int side = 0;
  for (int it = 0; it < 100; ++it) {
    x = (a * fb - b * fa) / (fb - fa);
    const double fx = f(x);
    if (std::abs(fx) < 1e-12 || std::abs(b - a) < 1e-13) break;
    if (fx * fb > 0.0) {
      b = x;
      fb = fx;
      if (side == -1) fa *= 0.5;
      side = -1;
    } else {
      a = x;
      fa = fx;
      if (side == +1) fb *= 0.5;
      side = +1;
    }
  }
  std::vector<ContactPoint> cl, cr;
  const auto [gl, gr] = gaps(x, &cl, &cr);
  const double drop = std::min(gl, gr);
  RigidContact out;
  out.pose = pose;
  out.pose.roll = x;
  out.pose.vertical = drop;
  auto pick = [&](std::vector<ContactPoint>& c, int idx) {
    std::size_t best = 0;
    for (std::size_t i = 0; i < c.size(); ++i) {
      c[i].vertical_gap -= drop;
      if (c[i].vertical_gap < c[best].vertical_gap) best = i;
    }
    out.main[static_cast<std::size_t>(idx)] = c[best];
    // Report every candidate within 1 um of touching: two-point contact on one wheel.
    for (const auto& p : c) {
      if (p.vertical_gap < 1e-6) out.points.push_back(p);
    }
  };
  if (cl.empty() || cr.empty()) throw std::runtime_error("solve_rigid_contact: no contact");
  pick(cl, 0);
  pick(cr, 1);
  for (auto& p : out.points) p.penetration = 0.0;
  return out;
}

WheelsetPose touching_pose(const WheelRailPair& pair, const WheelsetPose& pose) {
  WheelsetPose p = pose;
  const double g =
      std::min(min_vertical_gap(pair, pose, Side::left), min_vertical_gap(pair, pose, Side::right));
  p.vertical += g;
  return p;
}

ContactPlaneGap::ContactPlaneGap(const WheelRailPair& pair, const WheelsetPose& pose,
                                 const ContactPoint& pt, double plane_angle)
    : pair_(&pair),
      sgn_(side_sign(pt.side)),
      px_(pt.x),
      py_(pt.y),
      pz_(pt.z),
      frame_(pose, pair.params().nominal_radius) {
  double dzr = 0.0;
  if (std::isfinite(plane_angle)) {
    dzr = -std::tan(plane_angle);  // contact_angle = -atan(dzr)
  } else {
    double zr = 0.0;
    pair.rail().eval(pt.rail_y, zr, dzr);
  }
  const double f1 = sgn_ * dzr;  // track-frame slope dz/dy of the sampling plane
  const double nn = std::sqrt(1.0 + f1 * f1);
  ny_ = f1 / nn;
  nz_ = -1.0 / nn;  // normal, out of the rail
  ty_ = sgn_ / nn;
  tz_ = sgn_ * f1 / nn;  // lateral tangent, to the field
  double mx = 0.0;
  frame_.to_wheelset(0.0, ny_, nz_, mx, my_, mz_);  // normal in the wheelset frame
  mx_ = mx;
}

double ContactPlaneGap::at(double x_rel, double s) const {
  const ProfileCurve& rail = pair_->rail();
  const ProfileCurve& wheel = pair_->wheel();
  const double top = pair_->rail_reference().top_z;
  const double ro = pair_->rail_offset(), wo = pair_->wheel_offset();
  const double x = px_ + x_rel;
  const double qy = py_ + s * ty_, qz = pz_ + s * tz_;
  // Rail along the normal line: f(qy + t ny) = qz + t nz.
  double t_r = 0.0;
  for (int it = 0; it < 30; ++it) {
    const double yr = sgn_ * (qy + t_r * ny_) - ro;
    if (!rail.contains(yr)) return std::numeric_limits<double>::quiet_NaN();
    double z, dz;
    rail.eval(yr, z, dz);
    const double h = (z - top) - (qz + t_r * nz_);
    const double dh = sgn_ * dz * ny_ - nz_;
    const double step = h / dh;
    t_r -= step;
    if (std::abs(step) < 1e-12) break;
  }
  // Wheel along the same line: rho(P) = r(y_w).
  double t_w = t_r;
  for (int it = 0; it < 30; ++it) {
    double lx, ly, lz;
    frame_.to_wheelset(x, qy + t_w * ny_ - frame_.centre_y, qz + t_w * nz_ - frame_.centre_z, lx,
                       ly, lz);
    const double yw = sgn_ * ly - wo;
    if (!wheel.contains(yw)) return std::numeric_limits<double>::quiet_NaN();
    double zw, dzw;
    wheel.eval(yw, zw, dzw);
    const double rho = std::hypot(lx, lz);
    const double g = rho - pair_->wheel_radius(yw);
    const double dg = (lx * mx_ + lz * mz_) / rho - dzw * sgn_ * my_;
    const double step = g / dg;
    t_w -= step;
    if (std::abs(step) < 1e-12) break;
  }
  return t_w - t_r;
}

GapGrid sample_gap(const WheelRailPair& pair, const WheelsetPose& pose, const ContactPoint& pt,
                   int nx, int ny, double dx, double ds, double x_centre, double s_centre,
                   double plane_angle) {
  if (nx < 1 || ny < 1 || !(dx > 0.0) || !(ds > 0.0)) {
    throw std::invalid_argument("sample_gap: need nx, ny >= 1 and dx, ds > 0 [m]");
  }
  const ContactPlaneGap plane(pair, pose, pt, plane_angle);
  GapGrid grid;
  grid.nx = nx;
  grid.ny = ny;
  grid.dx = dx;
  grid.ds = ds;
  grid.x_centre = x_centre;
  grid.s_centre = s_centre;
  grid.gap.assign(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny),
                  std::numeric_limits<double>::quiet_NaN());
  for (int iy = 0; iy < ny; ++iy) {
    for (int ix = 0; ix < nx; ++ix) {
      grid.gap[static_cast<std::size_t>(iy * nx + ix)] = plane.at(grid.x(ix), grid.s(iy));
    }
  }
  return grid;
}

}  // namespace ferro::contact
