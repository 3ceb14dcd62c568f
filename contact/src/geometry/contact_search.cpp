// 3D contact search of a wheelset on a track: section circles, Newton on the circle angle,
// local minima of the section gap, refinement, contact attributes.
//
// References: see wheel_rail_geometry.hpp (Shabana et al. 2008 ch. 4; Toumi 2016 eqs. 14-16).
// Known deviations: see wheel_rail_geometry.hpp (vertical interpenetration, A ignores yaw).

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ferro/contact/geometry/wheel_rail_geometry.hpp"

namespace ferro::contact {
namespace {

constexpr double kFar = 1.0;            // gap reported where the rail does not exist [m]
constexpr double kProminence = 1.0e-6;  // bumps lower than this merge two minima [m]
// The section-gap sample nearest a minimum lies above the refined minimum by up to ~0.1 mm on a
// flange flank (0.5 mm sections, slopes up to tan 70 deg: S1002 / UIC60 shows 73 um); minima
// are refined unless their sample exceeds max_gap by more than this [m].
constexpr double kEstimateMargin = 0.3e-3;

void require(bool ok, const char* field, const std::string& what) {
  if (!ok) throw std::invalid_argument(fmt::format("WheelRailPairParams.{}: {}", field, what));
}

// Everything the section solve needs, for one wheel at one pose.
struct SideContext {
  const WheelRailPair* pair;
  double sgn;  // +1 right, -1 left
  WheelsetFrame f;  // rotation and axle centre
  double wheel_offset, rail_offset, rail_top, r0, zw0;
};

SideContext make_context(const WheelRailPair& pair, const WheelsetPose& pose, Side side) {
  SideContext c{};
  c.pair = &pair;
  c.sgn = side_sign(side);
  c.r0 = pair.params().nominal_radius;
  c.f = WheelsetFrame(pose, c.r0);
  c.wheel_offset = pair.wheel_offset();
  c.rail_offset = pair.rail_offset();
  c.rail_top = pair.rail_reference().top_z;
  c.zw0 = pair.wheel_radius(0.0) - c.r0;
  return c;
}

struct Section {
  double gap = kFar;
  double theta = 0.0;
  double px = 0.0, py = 0.0, pz = 0.0;
  double radius = 0.0;
  double rail_y = 0.0;
  bool valid = false;
};

// Point of the wheel circle at wheel-profile coordinate yw with the smallest vertical gap.
Section section_min(const SideContext& c, double yw) {
  Section s;
  const ProfileCurve& wheel = c.pair->wheel();
  const ProfileCurve& rail = c.pair->rail();
  if (!wheel.contains(yw)) return s;
  const double r = c.r0 + wheel.z(yw) - c.zw0;
  const double Y = c.sgn * (c.wheel_offset + yw);
  const double ay = c.f.cos_yaw * c.f.cos_roll * Y, az = c.f.sin_roll * Y;
  // P_y = y_ws + ay + r (spsi sin th - cpsi sphi cos th);  P_z = z_c + az + cphi r cos th
  auto py_of = [&](double th) {
    return c.f.centre_y + ay +
           r * (c.f.sin_yaw * std::sin(th) - c.f.cos_yaw * c.f.sin_roll * std::cos(th));
  };
  double th = 0.0;
  double yr = c.sgn * py_of(th) - c.rail_offset;
  if (!rail.contains(yr)) return s;
  double zr, dzr, ddzr;
  rail.eval(yr, zr, dzr);
  double f1 = c.sgn * dzr;
  // Linearised first guess, then Newton on d(gap)/d(theta) = 0.
  th = -f1 * c.f.sin_yaw / (c.f.cos_roll + f1 * c.f.cos_yaw * c.f.sin_roll);
  for (int it = 0; it < 5; ++it) {
    const double st = std::sin(th), ct = std::cos(th);
    const double py = c.f.centre_y + ay + r * (c.f.sin_yaw * st - c.f.cos_yaw * c.f.sin_roll * ct);
    yr = c.sgn * py - c.rail_offset;
    if (!rail.contains(yr)) return s;
    rail.eval2(yr, zr, dzr, ddzr);
    const double f1n = c.sgn * dzr, f2 = ddzr;
    const double dpy = r * (c.f.sin_yaw * ct + c.f.cos_yaw * c.f.sin_roll * st);
    const double dpz = -c.f.cos_roll * r * st;
    const double ddpy = r * (-c.f.sin_yaw * st + c.f.cos_yaw * c.f.sin_roll * ct);
    const double ddpz = -c.f.cos_roll * r * ct;
    const double g1 = f1n * dpy - dpz;
    const double g2 = f2 * dpy * dpy + f1n * ddpy - ddpz;
    if (!(g2 > 0.0)) break;
    const double step = g1 / g2;
    th -= step;
    if (std::abs(step) < 1e-10) break;
  }
  const double st = std::sin(th), ct = std::cos(th);
  s.py = c.f.centre_y + ay + r * (c.f.sin_yaw * st - c.f.cos_yaw * c.f.sin_roll * ct);
  s.pz = c.f.centre_z + az + c.f.cos_roll * r * ct;
  s.px = c.f.cos_yaw * r * st - c.f.sin_yaw * (c.f.cos_roll * Y - c.f.sin_roll * r * ct);
  s.rail_y = c.sgn * s.py - c.rail_offset;
  if (!rail.contains(s.rail_y)) return s;
  s.gap = (rail.z(s.rail_y) - c.rail_top) - s.pz;
  s.theta = th;
  s.radius = r;
  s.valid = true;
  return s;
}

// Cheap estimate of a section's smallest gap for the scan: second-order expansion of the gap
// about the bottom of the circle (theta = 0), g0 - g1^2 / (2 g2); no trigonometry. Error is
// O(r theta^4) ~ 0.1 um for the largest lead on a yawed flange; minima are then refined with
// section_min.
double section_estimate(const SideContext& c, double yw) {
  const ProfileCurve& rail = c.pair->rail();
  const double r = c.r0 + c.pair->wheel().z(yw) - c.zw0;
  const double Y = c.sgn * (c.wheel_offset + yw);
  const double py = c.f.centre_y + c.f.cos_yaw * (c.f.cos_roll * Y - c.f.sin_roll * r);
  const double pz = c.f.centre_z + c.f.sin_roll * Y + c.f.cos_roll * r;
  const double yr = c.sgn * py - c.rail_offset;
  if (!rail.contains(yr)) return kFar;
  double z, dz, ddz;
  rail.eval2(yr, z, dz, ddz);
  const double f1 = c.sgn * dz;
  const double dpy = r * c.f.sin_yaw;
  const double g0 = (z - c.rail_top) - pz;
  const double g1 = f1 * dpy;
  const double g2 = ddz * dpy * dpy + f1 * r * c.f.cos_yaw * c.f.sin_roll + c.f.cos_roll * r;
  return g2 > 0.0 ? g0 - 0.5 * g1 * g1 / g2 : g0;
}

// Parabolic refinement of a section-gap extremum bracketed around yw with half-width h: a
// minimum (sense = +1, a candidate point) or a maximum (sense = -1, the barrier between two
// candidates). Fit a parabola through yw - h, yw, yw + h, move to its vertex, shrink h tenfold;
// four rounds bring h to 0.05 um for the 0.5 mm scan step. A section off the rail counts as the
// worst value.
double refine_extremum(const SideContext& c, double yw, double h, double sense) {
  const ProfileCurve& wheel = c.pair->wheel();
  auto value = [&](double y) {  // sense * gap: minimised
    const Section sec = section_min(c, y);
    return sec.valid ? sense * sec.gap : kFar;
  };
  double gm = value(yw);
  for (int it = 0; it < 4; ++it) {
    const double ya = std::max(yw - h, wheel.y_min()), yb = std::min(yw + h, wheel.y_max());
    const double ga = value(ya), gb = value(yb);
    double ynew = yw;
    const double denom = (ga - 2.0 * gm + gb);
    if (denom > 0.0 && ya < yw && yb > yw) {
      ynew = std::clamp(yw + 0.5 * h * (ga - gb) / denom, yw - h, yw + h);
    } else if (ga < gm || gb < gm) {
      ynew = ga < gb ? ya : yb;
    }
    if (ynew != yw) {
      const double gn = value(ynew);
      if (gn < gm) {
        yw = ynew;
        gm = gn;
      }
    }
    h *= 0.1;
  }
  return yw;
}

// The candidate point of the wheel section at yw, whose smallest gap is s (valid).
ContactPoint make_point(const SideContext& c, Side side, double yw, const Section& s) {
  ContactPoint p;
  p.side = side;
  p.x = s.px;
  p.y = s.py;
  p.z = s.pz + s.gap;  // on the rail surface
  p.wheel_y = yw;
  p.rail_y = s.rail_y;
  p.wheel_angle = s.theta;
  p.vertical_gap = s.gap;
  p.rolling_radius = s.radius;
  double zr, dzr, ddzr;
  c.pair->rail().eval2(s.rail_y, zr, dzr, ddzr);
  p.contact_angle = -std::atan(dzr);
  const double cg = std::cos(p.contact_angle);
  double zw, dzw, ddzw;
  c.pair->wheel().eval2(yw, zw, dzw, ddzw);
  const double kappa_rail = ddzr / std::pow(1.0 + dzr * dzr, 1.5);
  const double kappa_wheel = -ddzw / std::pow(1.0 + dzw * dzw, 1.5);
  p.curvature_a = 0.5 * cg / s.radius;
  p.curvature_b = 0.5 * (kappa_rail + kappa_wheel);
  p.penetration = std::max(0.0, -s.gap * cg);
  return p;
}

}  // namespace

void WheelRailPairParams::validate() const {
  require(std::isfinite(track_gauge) && track_gauge > 0.5 && track_gauge < 3.0, "track_gauge",
          fmt::format("must be a gauge in metres in (0.5, 3), got {}", track_gauge));
  require(std::isfinite(gauge_depth) && gauge_depth >= 0.0 && gauge_depth < 0.05, "gauge_depth",
          fmt::format("must be in [0, 0.05) m, got {}", gauge_depth));
  require(std::isfinite(flange_back_distance) && flange_back_distance > 0.5 &&
              flange_back_distance < track_gauge,
          "flange_back_distance",
          fmt::format("must be in (0.5 m, track_gauge), got {}", flange_back_distance));
  require(std::isnan(flange_back_y) || std::abs(flange_back_y) < 0.2, "flange_back_y",
          fmt::format("must be NaN or within +-0.2 m, got {}", flange_back_y));
  require(std::isfinite(nominal_radius) && nominal_radius > 0.1 && nominal_radius < 2.0,
          "nominal_radius", fmt::format("must be in (0.1, 2) m, got {}", nominal_radius));
  require(std::isfinite(rail_inclination) && std::abs(rail_inclination) < 0.2, "rail_inclination",
          fmt::format("must be within +-0.2 rad, got {}", rail_inclination));
  require(grid_step > 0.0 && grid_step < 1e-3, "grid_step",
          fmt::format("must be in (0, 1e-3) m, got {}", grid_step));
  require(section_step > 0.0 && section_step < 5e-3, "section_step",
          fmt::format("must be in (0, 5e-3) m, got {}", section_step));
}

WheelRailPair::WheelRailPair(const Profile& wheel, const Profile& rail,
                             const WheelRailPairParams& params)
    : params_(params), wheel_profile_(wheel) {
  params_.validate();
  if (wheel.kind != ProfileKind::wheel) {
    throw std::invalid_argument(fmt::format("{}: expected a wheel profile", wheel.source));
  }
  if (rail.kind != ProfileKind::rail) {
    throw std::invalid_argument(fmt::format("{}: expected a rail profile", rail.source));
  }
  rail_profile_ =
      params_.rail_inclination != 0.0 ? incline_rail(rail, params_.rail_inclination) : rail;
  wheel_ = ProfileCurve(wheel_profile_, params_.grid_step);
  rail_ = ProfileCurve(rail_profile_, params_.grid_step);
  rail_ref_ = ::ferro::contact::rail_reference(rail_profile_, params_.gauge_depth);
  if (!wheel_.contains(0.0)) {
    throw std::invalid_argument(
        fmt::format("{}: the wheel profile must contain the taping line y = 0", wheel.source));
  }
  wheel_z0_ = wheel_.z(0.0);
  const double fb =
      std::isnan(params_.flange_back_y) ? wheel_profile_.y.front() : params_.flange_back_y;
  wheel_offset_ = 0.5 * params_.flange_back_distance - fb;
  rail_offset_ = 0.5 * params_.track_gauge - rail_ref_.gauge_y;
}

const ContactPoint& deepest_candidate(const std::vector<ContactPoint>& candidates) {
  if (candidates.empty()) throw std::invalid_argument("deepest_candidate: no candidate point");
  return *std::min_element(candidates.begin(), candidates.end(),
                           [](const ContactPoint& a, const ContactPoint& b) {
                             return a.vertical_gap < b.vertical_gap;
                           });
}

std::vector<ContactPoint> candidate_points(const WheelRailPair& pair, const WheelsetPose& pose,
                                           Side side, double max_gap) {
  const SideContext c = make_context(pair, pose, side);
  const ProfileCurve& wheel = pair.wheel();
  const double h = pair.params().section_step;
  const auto n = static_cast<std::size_t>(std::floor((wheel.y_max() - wheel.y_min()) / h)) + 1;
  // Section gaps on the coarse grid (fixed-size stack buffer for the usual case).
  constexpr std::size_t kMaxStack = 1024;
  double gbuf[kMaxStack];
  std::vector<double> gheap;
  double* g = gbuf;
  if (n > kMaxStack) {
    gheap.resize(n);
    g = gheap.data();
  }
  // Only sections whose bottom point lies over the rail can touch it: invert the (nearly
  // linear) map y_w -> track y of the circle bottom, with a margin for the radius term and lead.
  const ProfileCurve& rail = pair.rail();
  const double a = c.f.cos_yaw * c.f.cos_roll * c.sgn;  // d(P_y)/d(y_w), ignoring r(y_w) sin(roll)
  const double b = c.f.centre_y + c.f.cos_yaw * c.f.cos_roll * c.sgn * c.wheel_offset -
                   c.f.cos_yaw * c.f.sin_roll * c.r0;
  // Rail y_r = sgn * P_y - rail_offset  =>  P_y range for each end of the rail.
  const double p1 = c.sgn * (rail.y_min() + c.rail_offset),
               p2 = c.sgn * (rail.y_max() + c.rail_offset);
  double w1 = (p1 - b) / a, w2 = (p2 - b) / a;
  if (w1 > w2) std::swap(w1, w2);
  const double margin = 2e-3 + 0.05 * std::abs(c.f.sin_roll) + 0.5 * std::abs(c.f.sin_yaw) * c.r0;
  const double kmin_d = std::floor((w1 - margin - wheel.y_min()) / h);
  const double kmax_d = std::ceil((w2 + margin - wheel.y_min()) / h);
  const std::size_t kmin = kmin_d < 0.0 ? 0 : std::min(n, static_cast<std::size_t>(kmin_d));
  const std::size_t kmax = kmax_d < 0.0 ? 0 : std::min(n, static_cast<std::size_t>(kmax_d) + 1);
  for (std::size_t k = 0; k < n; ++k) {
    g[k] = (k >= kmin && k < kmax) ? section_estimate(c, wheel.y_min() + h * static_cast<double>(k))
                                   : kFar;
  }
  // Local minima with prominence: a minimum survives unless the gap between it and the
  // previous kept minimum never rises more than kProminence above the higher of the two.
  struct Min {
    std::size_t k;
    double barrier;
    std::size_t k_barrier;  // scan section of the barrier (when finite)
  };
  std::vector<Min> mins;
  double run_max = -kFar;
  std::size_t k_run_max = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (g[k] > run_max) {
      run_max = g[k];
      k_run_max = k;
    }
    const bool left_ok = k == 0 || g[k] < g[k - 1];
    const bool right_ok = k + 1 == n || g[k] <= g[k + 1];
    if (!(left_ok && right_ok) || g[k] >= kFar) continue;
    if (!mins.empty()) {
      const double higher = std::max(g[mins.back().k], g[k]);
      if (run_max - higher < kProminence) {
        if (g[k] < g[mins.back().k]) mins.back().k = k;  // same valley: keep the deeper
        run_max = g[k];
        k_run_max = k;
        continue;
      }
      mins.push_back({k, run_max, k_run_max});
    } else {
      mins.push_back({k, std::numeric_limits<double>::infinity(), 0});
    }
    run_max = g[k];
    k_run_max = k;
  }
  std::vector<ContactPoint> out;
  out.reserve(mins.size());
  // Barrier carried over skipped candidates: its value and scan section.
  double pending = -kFar;
  std::size_t k_pending = 0;
  // A skipped candidate's barrier and gap estimate carry over to the next one's barrier.
  const auto skip = [&](const Min& m) {
    if (std::isfinite(m.barrier) && m.barrier > pending) {
      pending = m.barrier;
      k_pending = m.k_barrier;
    }
    if (g[m.k] > pending) {
      pending = g[m.k];
      k_pending = m.k;
    }
  };
  for (const Min& m : mins) {
    if (g[m.k] > max_gap + kEstimateMargin) {
      skip(m);
      continue;
    }
    const double y0 = wheel.y_min() + h * static_cast<double>(m.k);
    const double yw = refine_extremum(c, y0, h, 1.0);
    const Section section = section_min(c, yw);
    if (!section.valid) {
      // The section's nearest point lies past an end of the rail profile (a flange reaching
      // beyond the gauge face's last point under yaw, where the scan's estimate still found a
      // minimum): no surface to touch there.
      skip(m);
      continue;
    }
    ContactPoint p = make_point(c, side, yw, section);
    const bool from_pending = pending > m.barrier;
    if (std::isfinite(m.barrier) || from_pending) {
      // The barrier refined to the section-gap maximum near its scan section (the scan's
      // estimate samples it every section_step only).
      const std::size_t kb = from_pending ? k_pending : m.k_barrier;
      const double yb = refine_extremum(c, wheel.y_min() + h * static_cast<double>(kb), h, -1.0);
      const Section sb = section_min(c, yb);
      if (sb.valid) {
        double zr, dzr, ddzr;
        pair.rail().eval2(sb.rail_y, zr, dzr, ddzr);
        p.barrier = std::max(sb.gap, p.vertical_gap);
        p.barrier_x = sb.px;
        p.barrier_y = sb.py;
        p.barrier_z = sb.pz + sb.gap;
        p.barrier_angle = -std::atan(dzr);
      } else {
        p.barrier = from_pending ? pending : m.barrier;
      }
    }
    pending = -kFar;
    out.push_back(p);
  }
  return out;
}

void share_joined_runs(const RunMember* members, int count, double drop,
                       double* effective_gap) {
  // Depth of the submerged barrier between member i - 1 and i (0: not joined).
  auto joint = [&](int i) {
    if (i <= 0 || i >= count || members[i].side != members[i - 1].side) return 0.0;
    return std::max(0.0, drop - members[i].barrier);
  };
  int start = 0;
  while (start < count) {
    int end = start + 1;
    while (end < count && joint(end) > 0.0) ++end;
    if (end - start == 1) {
      effective_gap[start] = members[start].gap - drop;
    } else {
      // Barrier depth raised by the search's prominence (a minimum less than kProminence
      // below its barrier is merged into its neighbour by candidate_points()), so a member
      // appearing at that prominence starts with no excess, no weight and no depth.
      auto barrier_depth = [&](int i) {
        const double dmax = std::max(joint(i), joint(i + 1));
        return dmax + std::min(dmax, kProminence);
      };
      double sum = 0.0;
      for (int i = start; i < end; ++i) {
        const double d = drop - members[i].gap;
        effective_gap[i] = members[i].share * std::max(0.0, d - barrier_depth(i));  // excess
        sum += effective_gap[i];
      }
      const double n = static_cast<double>(end - start);
      for (int i = start; i < end; ++i) {
        const double d = drop - members[i].gap;
        const double dmax = std::min(d, barrier_depth(i));
        const double w = sum > 0.0 ? effective_gap[i] / sum : 1.0 / n;
        effective_gap[i] = d > 0.0 ? -(d - (1.0 - w) * dmax * dmax / d) : -d;
      }
    }
    start = end;
  }
}

std::vector<ContactPoint> contacts_from_candidates(const std::vector<ContactPoint>& candidates,
                                                   double extra_drop) {
  std::vector<RunMember> members(candidates.size());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    members[i] = {candidates[i].side, candidates[i].vertical_gap, candidates[i].barrier};
  }
  std::vector<double> gap(candidates.size());
  share_joined_runs(members.data(), static_cast<int>(members.size()), extra_drop, gap.data());
  std::vector<ContactPoint> out;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!(gap[i] < 0.0)) continue;
    ContactPoint p = candidates[i];
    p.vertical_gap = gap[i];
    p.penetration = -p.vertical_gap * std::cos(p.contact_angle);
    out.push_back(p);
  }
  return out;
}

std::vector<ContactPoint> search_contacts(const WheelRailPair& pair, const WheelsetPose& pose) {
  std::vector<ContactPoint> cands = candidate_points(pair, pose, Side::left, 0.0);
  std::vector<ContactPoint> right = candidate_points(pair, pose, Side::right, 0.0);
  cands.insert(cands.end(), right.begin(), right.end());
  return contacts_from_candidates(cands, 0.0);
}

double min_vertical_gap(const WheelRailPair& pair, const WheelsetPose& pose, Side side) {
  double best = kFar;
  for (const ContactPoint& p : candidate_points(pair, pose, side)) {
    best = std::min(best, p.vertical_gap);
  }
  return best;
}

}  // namespace ferro::contact
