// Full wheel-rail contact of prescribed wheelset positions (see the header for the method,
// references and known deviations).
#include "ferro/contact/geometry/wheelset_contact.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "ferro/contact/geometry/wheelset_pose.hpp"
#include "ferro/contact/mim/influence_operator.hpp"
#include "ferro/contact/mim/mim.hpp"
#include "ferro/contact/normal/hertz.hpp"
#include "ferro/io/hdf5.hpp"
#include "ferro/io/text_writer.hpp"

namespace ferro::contact {
namespace {

namespace fm = mim;

// --- geometry of a contact plane -----------------------------------------------------------

// Tangent plane of the rail at rail-profile coordinate rail_y: point, outward normal (0, ny, nz)
// and lateral tangent towards the field side (0, ty, tz), track frame (z down).
struct RailPlane {
  double y = 0.0, z = 0.0;
  double ny = 0.0, nz = 0.0, ty = 0.0, tz = 0.0;
  double contact_angle = 0.0;
};

RailPlane rail_plane(const WheelRailPair& pair, Side side, double rail_y) {
  const double sgn = side_sign(side);
  double zr = 0.0, dzr = 0.0;
  pair.rail().eval(rail_y, zr, dzr);
  const double f1 = sgn * dzr;
  const double nn = std::sqrt(1.0 + f1 * f1);
  RailPlane p;
  p.y = sgn * (rail_y + pair.rail_offset());
  p.z = zr - pair.rail_reference().top_z;
  p.ny = f1 / nn;
  p.nz = -1.0 / nn;
  p.ty = sgn / nn;
  p.tz = sgn * f1 / nn;
  p.contact_angle = -std::atan(dzr);
  return p;
}

// Normal and lateral tangent of a plane inclined by contact angle `angle` (rail_plane's
// convention), track frame.
RailPlane plane_frame(Side side, double angle) {
  const double sgn = side_sign(side);
  const double f1 = -sgn * std::tan(angle);
  const double nn = std::sqrt(1.0 + f1 * f1);
  RailPlane p;
  p.ny = f1 / nn;
  p.nz = -1.0 / nn;
  p.ty = sgn / nn;
  p.tz = sgn * f1 / nn;
  p.contact_angle = angle;
  return p;
}

// Rail-profile coordinate where the line (qy, qz) + t (ny, nz) meets the rail (Newton on t).
double rail_along(const WheelRailPair& pair, Side side, double qy, double qz, double ny,
                  double nz) {
  const double sgn = side_sign(side);
  const double top = pair.rail_reference().top_z;
  double t = 0.0;
  for (int it = 0; it < 40; ++it) {
    const double yr = sgn * (qy + t * ny) - pair.rail_offset();
    if (!pair.rail().contains(yr)) {
      throw std::runtime_error("wheelset contact: the patch centre lies beyond the rail profile");
    }
    double z = 0.0, dz = 0.0;
    pair.rail().eval(yr, z, dz);
    const double h = (z - top) - (qz + t * nz);
    const double step = h / (sgn * dz * ny - nz);
    t -= step;
    if (std::abs(step) < 1e-13) break;
  }
  return sgn * (qy + t * ny) - pair.rail_offset();
}

// Wheel-profile coordinate of the wheel section through track point p.
double wheel_y_at(const WheelRailPair& pair, const WheelsetPose& pose, Side side,
                  const Eigen::Vector3d& p) {
  const WheelsetFrame frame(pose, pair.params().nominal_radius);
  return side_sign(side) * frame.point_to_wheelset(p).y() - pair.wheel_offset();
}

// --- one patch -----------------------------------------------------------------------------

// Sampled gap around a point, with the lateral rows grouped into one patch: the run of
// penetrated rows containing `centre_row` and every run closer than kPatchSeparationDistance.
struct PatchWindow {
  GapGrid grid;
  double angle = 0.0;           // contact angle of the sampling plane [rad]
  int row_lo = 0, row_hi = -1;  // penetrated rows of the patch (inclusive)
  int col_lo = 0, col_hi = -1;  // penetrated columns of the patch (inclusive)
  bool touches_edge = false;
};

PatchWindow group_rows(GapGrid grid, int centre_row, double ds) {
  PatchWindow w;
  const int nx = grid.nx, ny = grid.ny;
  std::vector<char> hit(static_cast<std::size_t>(ny), 0);
  for (int iy = 0; iy < ny; ++iy) {
    for (int ix = 0; ix < nx; ++ix) {
      if (grid.at(ix, iy) < 0.0) hit[static_cast<std::size_t>(iy)] = 1;
    }
  }
  const int merge_rows = static_cast<int>(std::ceil(kPatchSeparationDistance / ds));
  int lo = centre_row, hi = centre_row;
  if (!hit[static_cast<std::size_t>(centre_row)]) {
    w.grid = std::move(grid);
    return w;  // empty
  }
  // Grow while another penetrated row lies within the combine distance.
  for (bool grown = true; grown;) {
    grown = false;
    for (int k = 1; k <= merge_rows + 1 && lo - k >= 0; ++k) {
      if (hit[static_cast<std::size_t>(lo - k)]) {
        lo -= k;
        grown = true;
        break;
      }
    }
    for (int k = 1; k <= merge_rows + 1 && hi + k < ny; ++k) {
      if (hit[static_cast<std::size_t>(hi + k)]) {
        hi += k;
        grown = true;
        break;
      }
    }
  }
  w.row_lo = lo;
  w.row_hi = hi;
  w.col_lo = nx;
  w.col_hi = -1;
  for (int iy = lo; iy <= hi; ++iy) {
    for (int ix = 0; ix < nx; ++ix) {
      if (grid.at(ix, iy) < 0.0) {
        w.col_lo = std::min(w.col_lo, ix);
        w.col_hi = std::max(w.col_hi, ix);
      }
    }
  }
  w.touches_edge = lo == 0 || hi == ny - 1 || w.col_lo == 0 || w.col_hi == nx - 1;
  w.grid = std::move(grid);
  return w;
}

// Penetration-weighted centre (x, s) of the patch rows, relative to the grid's point [m]:
// every element of the interpenetration weighted by its penetration squared (the benchmark's
// reference solutions weight by the square, which favours the deeper lobe of a two-lobe patch).
std::pair<double, double> weighted_centre(const PatchWindow& w) {
  double sw = 0.0, sx = 0.0, ss = 0.0;
  for (int iy = w.row_lo; iy <= w.row_hi; ++iy) {
    for (int ix = 0; ix < w.grid.nx; ++ix) {
      const double g = w.grid.at(ix, iy);
      if (!(g < 0.0)) continue;
      const double weight = g * g;
      sw += weight;
      sx += weight * w.grid.x(ix);
      ss += weight * w.grid.s(iy);
    }
  }
  return {sx / sw, ss / sw};
}

ContactPoint plane_point(const WheelRailPair& pair, Side side, double x, double rail_y) {
  const RailPlane rp = rail_plane(pair, side, rail_y);
  ContactPoint pt;
  pt.side = side;
  pt.x = x;
  pt.y = rp.y;
  pt.z = rp.z;
  pt.rail_y = rail_y;
  pt.contact_angle = rp.contact_angle;
  return pt;
}

// Samples the gap in the plane of `pt` over a window of half-sizes (hx, hs) centred at
// (xc, sc) relative to the point, enlarging it while the interpenetration reaches its edge.
PatchWindow patch_window(const WheelRailPair& pair, const WheelsetPose& pose,
                         const ContactPoint& pt, double angle, double hx, double hs, double xc,
                         double sc, const WheelsetContactSpec& in) {
  PatchWindow w;
  for (int attempt = 0; attempt < 4; ++attempt) {
    const int nx = 2 * static_cast<int>(std::ceil(hx / in.dx)) + 1;
    const int ny = 2 * static_cast<int>(std::ceil(hs / in.ds)) + 1;
    GapGrid g = sample_gap(pair, pose, pt, nx, ny, in.dx, in.ds, xc, sc, angle);
    // Row nearest to the point itself (s = 0) holds the deepest section of the candidate.
    int centre_row = static_cast<int>(std::lround((0.0 - (sc - 0.5 * (ny - 1) * in.ds)) / in.ds));
    centre_row = std::clamp(centre_row, 0, ny - 1);
    // Start from the deepest row near the point (the point's own row may miss by a sample).
    int best = centre_row;
    double best_gap = 1.0;
    for (int iy = std::max(0, centre_row - 3); iy <= std::min(ny - 1, centre_row + 3); ++iy) {
      for (int ix = 0; ix < nx; ++ix) {
        const double v = g.at(ix, iy);
        if (v < best_gap) {
          best_gap = v;
          best = iy;
        }
      }
    }
    w = group_rows(std::move(g), best, in.ds);
    w.angle = angle;
    if (w.row_hi < w.row_lo || !w.touches_edge) return w;
    hx *= 1.6;
    hs *= 1.6;
  }
  return w;
}

// Rolling input: creepages at track point p (on the wheel at its rolling radius), in the
// contact frame of normal n, the rail at rest and the wheelset rolling at c.pitch_rate.
Creepage creepages_at(const WheelRailPair& pair, const WheelsetPose& pose,
                      const WheelsetContactSpec& in, const WheelsetCase& c,
                      const Eigen::Vector3d& p, const ContactFrame& frame, double rolling_radius) {
  const WheelsetFrame wheelset(pose, pair.params().nominal_radius);
  const Eigen::Vector3d omega = c.pitch_rate * wheelset.axle();
  const Eigen::Vector3d arm = wheel_point_arm(p - wheelset.centre(), wheelset.axle(),
                                              rolling_radius, Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d wheel_point_velocity =
      Eigen::Vector3d(in.forward_speed, 0.0, 0.0) + omega.cross(arm);
  return creepage(wheel_point_velocity, omega, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                  frame, in.forward_speed);
}

// Solves one patch found around candidate `cand`; `covered` receives its rail extent.
PatchContact solve_patch(const WheelRailPair& pair, const WheelsetPose& pose,
                         const WheelsetContactSpec& in, const WheelsetCase& c,
                         const ContactPoint& cand, double& covered_lo, double& covered_hi) {
  const Side side = cand.side;
  // Window around the candidate: half-length from its penetration and longitudinal curvature,
  // half-width 12 mm (grown if the interpenetration reaches the edge).
  const double pen = std::max(cand.penetration, 1e-7);
  const double half_length = 1.3 * std::sqrt(pen / std::max(cand.curvature_a, 0.05)) + 4.0 * in.dx;
  PatchWindow w =
      patch_window(pair, pose, cand, cand.contact_angle, half_length, 12.0e-3, 0.0, 0.0, in);
  if (w.row_hi < w.row_lo) {
    throw std::runtime_error("wheelset contact: a penetrating candidate has no sampled overlap");
  }
  // Reference point: the penetration-weighted centre, projected on the rail along the plane
  // normal; contact angle: the same weighted average of the rail inclination of every row. The
  // gap is then sampled again in the plane of that point and angle, until the centre stays put
  // (0.01 mm) and the angle too (10 urad).
  ContactPoint ref = cand;
  double x_ref = cand.x;
  for (int it = 0; it < 6; ++it) {
    const auto [xc, sc] = weighted_centre(w);
    const RailPlane fr = plane_frame(side, w.angle);
    auto rail_y_of_s = [&](double s) {
      return rail_along(pair, side, ref.y + s * fr.ty, ref.z + s * fr.tz, fr.ny, fr.nz);
    };
    double sw = 0.0, sa = 0.0;
    for (int iy = w.row_lo; iy <= w.row_hi; ++iy) {
      double row = 0.0;
      for (int ix = 0; ix < w.grid.nx; ++ix) {
        const double g = w.grid.at(ix, iy);
        if (g < 0.0) row += g * g;
      }
      if (row <= 0.0) continue;
      sw += row;
      sa += row * rail_plane(pair, side, rail_y_of_s(w.grid.s(iy))).contact_angle;
    }
    const double angle = sa / sw;
    x_ref += xc;
    ref = plane_point(pair, side, x_ref, rail_y_of_s(sc));
    const bool settled =
        std::abs(sc) < 1e-5 && std::abs(xc) < 1e-5 && std::abs(angle - w.angle) < 1e-5;
    const double s_lo = w.grid.s(w.row_lo) - sc, s_hi = w.grid.s(w.row_hi) - sc;
    const double x_lo = w.grid.x(w.col_lo) - xc, x_hi = w.grid.x(w.col_hi) - xc;
    const double hs = 0.5 * (s_hi - s_lo) + 3.0 * in.ds;
    const double hx = 0.5 * (x_hi - x_lo) + 3.0 * in.dx;
    w = patch_window(pair, pose, ref, angle, hx, hs, 0.5 * (x_lo + x_hi), 0.5 * (s_lo + s_hi), in);
    if (w.row_hi < w.row_lo) {
      throw std::runtime_error("wheelset contact: the patch vanished in its own plane");
    }
    if (settled) break;
  }

  const RailPlane rp = plane_frame(side, w.angle);
  const double sgn = side_sign(side);
  PatchContact out;
  out.x = ref.x;
  out.rail_y = ref.rail_y;
  out.contact_angle = w.angle;
  const Eigen::Vector3d p(ref.x, ref.y, ref.z);
  out.wheel_y = wheel_y_at(pair, pose, side, p);
  out.rolling_radius = pair.wheel_radius(out.wheel_y);
  auto rail_y_of_s = [&](double s) {
    return rail_along(pair, side, ref.y + s * rp.ty, ref.z + s * rp.tz, rp.ny, rp.nz);
  };

  // Deepest interpenetration and the patch rows' extent for the coverage test.
  double gmin = 0.0;
  int deep_row = w.row_lo;
  for (int iy = w.row_lo; iy <= w.row_hi; ++iy) {
    for (int ix = 0; ix < w.grid.nx; ++ix) {
      const double g = w.grid.at(ix, iy);
      if (g < gmin) {
        gmin = g;
        deep_row = iy;
      }
    }
  }
  out.deepest_rail_y = rail_y_of_s(w.grid.s(deep_row));
  covered_lo = rail_y_of_s(w.grid.s(w.row_lo));
  covered_hi = rail_y_of_s(w.grid.s(w.row_hi));

  // MIM grid: x = t1, y = t2 = -sgn s (rows reversed on the right wheel); origin at the point.
  const int nx = w.grid.nx, ny = w.grid.ny;
  fm::Grid grid;
  grid.nx = nx;
  grid.ny = ny;
  grid.dx = in.dx;
  grid.dy = in.ds;
  grid.x0 = w.grid.x(0);
  grid.y0 = sgn > 0.0 ? -w.grid.s(ny - 1) : w.grid.s(0);
  constexpr double kFar = 1.0;  // gap where a profile ends: never in contact [m]
  fm::Field gap(grid.size());
  for (int j = 0; j < ny; ++j) {
    const int iy = sgn > 0.0 ? ny - 1 - j : j;
    for (int ix = 0; ix < nx; ++ix) {
      const bool in_patch = iy >= w.row_lo - 2 && iy <= w.row_hi + 2;
      const double g = w.grid.at(ix, iy);
      gap[grid.index(ix, j)] = (std::isfinite(g) && in_patch) ? g - gmin : kFar;
    }
  }
  const CombinedMaterial mat = combine(in.material, in.material);
  fm::InfluenceOperator op(grid, mat);
  fm::NormalLoad load;
  load.approach = -gmin;
  const ContactFrame frame = ContactFrame::from_normal(Eigen::Vector3d(0.0, rp.ny, rp.nz));
  out.creepage = creepages_at(pair, pose, in, c, p, frame, out.rolling_radius);
  const fm::RollingInput rolling{out.creepage.longitudinal, out.creepage.lateral, out.creepage.spin,
                                 in.friction};
  const fm::MimResult r = fm::solve_rolling_contact(op, gap, load, rolling);
  out.converged = r.converged;
  out.normal_force = r.normal_force;
  out.force_x = r.force_x;
  out.force_y = r.force_y;
  out.moment_z = r.moment_z;
  out.approach = r.approach;
  double pmax = 0.0, ylo = 1e300, yhi = -1e300;
  std::size_t loaded = 0, stick = 0;
  for (int j = 0; j < ny; ++j) {
    for (int ix = 0; ix < nx; ++ix) {
      const std::size_t k = grid.index(ix, j);
      if (!(r.pressure[k] > 0.0)) continue;
      pmax = std::max(pmax, r.pressure[k]);
      ++loaded;
      if (r.state[k] == fm::ElementState::stick) ++stick;
      const double s = -sgn * grid.y(j);
      ylo = std::min(ylo, s);
      yhi = std::max(yhi, s);
    }
  }
  out.peak_pressure = pmax;
  out.area = static_cast<double>(loaded) * grid.element_area();
  out.adhesion_fraction = loaded > 0 ? static_cast<double>(stick) / static_cast<double>(loaded) : 0;
  out.rail_y_min = loaded > 0 ? rail_y_of_s(ylo) : ref.rail_y;
  out.rail_y_max = loaded > 0 ? rail_y_of_s(yhi) : ref.rail_y;
  if (out.rail_y_min > out.rail_y_max) std::swap(out.rail_y_min, out.rail_y_max);
  out.regions = fm::count_positive_regions(grid, r.pressure);
  // Force on the wheel F = F_n n + F_x t1 + F_y t2; on the rail -F (track frame, z down).
  const Eigen::Vector3d f_wheel =
      out.normal_force * frame.n + out.force_x * frame.t1 + out.force_y * frame.t2;
  out.force_vertical = -f_wheel.z();
  out.force_lateral = -f_wheel.y();
  return out;
}

}  // namespace

// --- public --------------------------------------------------------------------------------

WheelContact wheel_contact_at(const WheelRailPair& pair, const WheelsetContactSpec& in,
                              const WheelsetCase& c, Side side, double vertical) {
  const WheelsetPose pose{c.lateral, vertical, c.roll, c.yaw};
  WheelContact out;
  out.side = side;
  out.vertical = vertical;
  std::vector<ContactPoint> cands = candidate_points(pair, pose, side, 0.0);
  std::sort(cands.begin(), cands.end(),
            [](const auto& a, const auto& b) { return a.vertical_gap < b.vertical_gap; });
  std::vector<std::pair<double, double>> covered;
  for (const ContactPoint& cand : cands) {
    if (!(cand.vertical_gap < 0.0)) continue;
    bool inside = false;
    for (const auto& [lo, hi] : covered) {
      if (cand.rail_y >= lo - kPatchSeparationDistance &&
          cand.rail_y <= hi + kPatchSeparationDistance) {
        inside = true;
      }
    }
    if (inside) continue;
    double lo = 0.0, hi = 0.0;
    PatchContact patch = solve_patch(pair, pose, in, c, cand, lo, hi);
    covered.emplace_back(lo, hi);
    out.vertical_load += patch.force_vertical;
    out.lateral_force += patch.force_lateral;
    out.patches.push_back(patch);
  }
  std::sort(out.patches.begin(), out.patches.end(),
            [](const auto& a, const auto& b) { return a.rail_y < b.rail_y; });
  return out;
}

WheelContact solve_wheel_contact(const WheelRailPair& pair, const WheelsetContactSpec& in,
                                 const WheelsetCase& c, Side side) {
  const double target = in.load_per_wheel;
  // Touching height (vertical gaps are affine in the height), then a Hertz estimate of the
  // approach at the deepest candidate.
  const WheelsetPose pose0{c.lateral, 0.0, c.roll, c.yaw};
  const double v_touch = min_vertical_gap(pair, pose0, side);
  const WheelsetPose touch{c.lateral, v_touch, c.roll, c.yaw};
  const ContactPoint deep = deepest_candidate(candidate_points(pair, touch, side));
  const double cos_g = std::max(std::cos(deep.contact_angle), 0.2);
  const double estar = combine(in.material, in.material).contact_modulus;
  double a_curv = std::max(deep.curvature_a, 0.05), b_curv = deep.curvature_b;
  if (!(b_curv > 0.05)) b_curv = 0.05;
  const double delta0 = hertz_solve(a_curv, b_curv, target / cos_g, estar).approach;

  // Secant on the load, kept inside a bracket once one is known.
  double v_lo = v_touch, q_lo = 0.0;  // load below target
  double v_hi = std::numeric_limits<double>::quiet_NaN(), q_hi = 0.0;
  double v = v_touch + delta0 / cos_g;
  WheelContact best;
  double best_err = std::numeric_limits<double>::infinity();
  for (int it = 1; it <= 40; ++it) {
    WheelContact w = wheel_contact_at(pair, in, c, side, v);
    w.iterations = it;
    const double q = w.vertical_load;
    const double err = std::abs(q - target);
    if (err < best_err) {
      best_err = err;
      best = w;
    }
    if (err <= kVerticalLoadTolerance * target) return w;
    if (q < target) {
      v_lo = v;
      q_lo = q;
    } else {
      v_hi = v;
      q_hi = q;
    }
    double next;
    if (std::isfinite(v_hi)) {
      next = v_lo + (target - q_lo) * (v_hi - v_lo) / (q_hi - q_lo);
      // Keep well inside the bracket (regula falsi with a bisection guard).
      const double span = v_hi - v_lo;
      next = std::clamp(next, v_lo + 0.05 * span, v_hi - 0.05 * span);
    } else {
      // Hertz-like growth: load ~ approach^1.5.
      const double d = v - v_touch;
      next = v_touch + d * std::pow(target / std::max(q, 1e-3 * target), 2.0 / 3.0);
      if (!(next > v)) next = v + d;
    }
    v = next;
  }
  throw std::runtime_error(fmt::format(
      "wheelset contact: case {} {} wheel: the height solve did not reach the load {:.1f} N "
      "(best {:.1f} N)",
      c.id, side == Side::left ? "left" : "right", target, best.vertical_load));
}

std::vector<WheelsetContact> solve_wheelset_contacts(const WheelRailPair& pair,
                                                     const WheelsetContactSpec& in,
                                                     const std::vector<WheelsetCase>& cases) {
  std::vector<WheelsetContact> out;
  for (const WheelsetCase& c : cases) {
    WheelsetContact r;
    r.input = c;
    r.wheels[0] = solve_wheel_contact(pair, in, c, Side::left);
    r.wheels[1] = solve_wheel_contact(pair, in, c, Side::right);
    out.push_back(std::move(r));
  }
  return out;
}

void write_wheelset_contacts(const std::vector<WheelsetContact>& results,
                             const WheelsetContactSpec& in, const std::string& pair_file,
                             const std::string& h5_path, const std::string& csv_path) {
  struct Column {
    std::string name, unit, description;
    std::vector<double> values;
  };
  std::vector<Column> cols = {
      {"case", "-", "case id", {}},
      {"y_mm", "mm", "wheelset lateral shift", {}},
      {"roll_rad", "rad", "wheelset roll", {}},
      {"yaw_rad", "rad", "wheelset yaw", {}},
      {"side", "-", "0 left, 1 right", {}},
      {"patch", "-", "patch index on the wheel", {}},
      {"patches", "-", "patches on the wheel", {}},
      {"height_mm", "mm", "solved axle drop below the nominal height (+ down)", {}},
      {"x_mm", "mm", "reference point along the track (track frame)", {}},
      {"rail_y_mm", "mm", "reference point on the rail profile", {}},
      {"wheel_y_mm", "mm", "reference point on the wheel profile", {}},
      {"contact_angle_deg", "deg", "contact angle (+ towards the track centre)", {}},
      {"rolling_radius_mm", "mm", "wheel radius at the reference point", {}},
      {"rail_y_min_mm", "mm", "loaded area, rail lateral minimum", {}},
      {"rail_y_max_mm", "mm", "loaded area, rail lateral maximum", {}},
      {"deepest_rail_y_mm", "mm", "deepest interpenetration on the rail", {}},
      {"regions", "-", "connected parts of the loaded area", {}},
      {"creepage_x", "-", "longitudinal creepage", {}},
      {"creepage_y", "-", "lateral creepage", {}},
      {"spin_per_m", "1/m", "spin creepage", {}},
      {"normal_force_n", "N", "normal force", {}},
      {"force_x_n", "N", "longitudinal creep force on the wheel", {}},
      {"force_y_n", "N", "lateral creep force on the wheel (t2 = n x t1)", {}},
      {"moment_z_nm", "N m", "spin moment on the wheel about n", {}},
      {"approach_um", "um", "rigid approach along n", {}},
      {"peak_pressure_mpa", "MPa", "peak pressure", {}},
      {"area_mm2", "mm^2", "loaded area", {}},
      {"adhesion_fraction", "-", "stick area / loaded area", {}},
      {"rail_vertical_n", "N", "vertical force on the rail from this patch (+ down)", {}},
      {"rail_lateral_n", "N", "lateral force on the rail from this patch (track y)", {}},
      {"wheel_vertical_n", "N", "vertical force on the rail, whole wheel", {}},
  };
  for (const WheelsetContact& r : results) {
    for (const WheelContact& w : r.wheels) {
      for (std::size_t k = 0; k < w.patches.size(); ++k) {
        const PatchContact& p = w.patches[k];
        const double v[] = {static_cast<double>(r.input.id),
                            r.input.lateral * 1e3,
                            r.input.roll,
                            r.input.yaw,
                            w.side == Side::left ? 0.0 : 1.0,
                            static_cast<double>(k),
                            static_cast<double>(w.patches.size()),
                            w.vertical * 1e3,
                            p.x * 1e3,
                            p.rail_y * 1e3,
                            p.wheel_y * 1e3,
                            p.contact_angle * 180.0 / std::numbers::pi,
                            p.rolling_radius * 1e3,
                            p.rail_y_min * 1e3,
                            p.rail_y_max * 1e3,
                            p.deepest_rail_y * 1e3,
                            static_cast<double>(p.regions),
                            p.creepage.longitudinal,
                            p.creepage.lateral,
                            p.creepage.spin,
                            p.normal_force,
                            p.force_x,
                            p.force_y,
                            p.moment_z,
                            p.approach * 1e6,
                            p.peak_pressure * 1e-6,
                            p.area * 1e6,
                            p.adhesion_fraction,
                            p.force_vertical,
                            p.force_lateral,
                            w.vertical_load};
        for (std::size_t i = 0; i < cols.size(); ++i) cols[i].values.push_back(v[i]);
      }
    }
  }
  io::H5File f = io::H5File::create(h5_path);
  f.set_attribute("/", "kind", "wheelset_contact");
  f.set_attribute("/", "pair_file", pair_file);
  f.set_attribute("/", "load_per_wheel_n", in.load_per_wheel);
  f.set_attribute("/", "friction", in.friction);
  f.set_attribute("/", "forward_speed_m_s", in.forward_speed);
  for (const Column& c : cols) {
    f.write_vector("/patches/" + c.name, c.values, c.unit, c.description);
  }
  f.close();
  if (csv_path.empty()) return;
  io::TextWriter csv(csv_path);
  std::string header;
  for (std::size_t i = 0; i < cols.size(); ++i) header += (i ? "," : "") + cols[i].name;
  csv.write(header + "\n");
  const std::size_t rows = cols.front().values.size();
  for (std::size_t r = 0; r < rows; ++r) {
    std::string line;
    for (std::size_t i = 0; i < cols.size(); ++i) {
      line += fmt::format("{}{:.10g}", i ? "," : "", cols[i].values[r]);
    }
    csv.write(line + "\n");
  }
  csv.close();
}

}  // namespace ferro::contact
