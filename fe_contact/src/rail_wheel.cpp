// Rail segment and wheel as structured finite-element bodies.
//
// References: see rail_wheel.hpp.
// Known deviations: see rail_wheel.hpp (simplified rail section below the crown, flangeless
// wheel rim with a straight web).

#include "ferro/fe_contact/rail_wheel.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "ferro/contact/geometry/profile.hpp"

namespace ferro::fe_contact {

namespace {

void positive(const std::string& where, const char* name, double v) {
  if (!(v > 0.0) || !std::isfinite(v)) {
    throw std::invalid_argument(fmt::format("{}.{}: must be finite and > 0, got {}", where, name, v));
  }
}

// Half-extent of the grid rows and their centre.
struct RowSpan {
  double lo, hi;
};
RowSpan rows(const contact::mim::Grid& g) {
  return {g.y0 - 0.5 * g.dy, g.y0 + (g.ny - 0.5) * g.dy};
}

// Mesh spacing at the loaded column of a body: element sizes hx, hy (grid element over the
// level's subdivisions), the half-length `near` kept at that size along s, the grid's rows.
struct LoadedColumn {
  double hx, hy, near;
  RowSpan r;
};
LoadedColumn loaded_column(const contact::mim::Grid& g, const FeMeshLevel& lv) {
  return {g.dx / lv.subdivisions, g.dy / lv.subdivisions, (lv.near_columns + 0.5) * g.dx,
          rows(g)};
}

// Crown height above the crown top (<= 0) of the 60E1 head at lateral position y, from the
// profile's arcs, held constant beyond |y| = 30 mm.
class Crown {
 public:
  Crown() : p_(contact::make_60e1_rail()) {}
  [[nodiscard]] double height(double y) const {
    y = std::clamp(y, -kLimit, kLimit);
    const auto it = std::lower_bound(p_.y.begin(), p_.y.end(), y);
    const std::size_t i = std::clamp<std::size_t>(static_cast<std::size_t>(it - p_.y.begin()), 1,
                                                  p_.y.size() - 1);
    const double f = (y - p_.y[i - 1]) / (p_.y[i] - p_.y[i - 1]);
    return -((1.0 - f) * p_.z[i - 1] + f * p_.z[i]);  // profile z is positive downwards
  }

 private:
  static constexpr double kLimit = 0.030;
  contact::Profile p_;
};

}  // namespace

void RailSpec::validate(const std::string& where) const {
  grid.validate(where + ".grid");
  material.validate(where + ".material");
  mesh.validate(where + ".mesh");
  positive(where, "length", length);
  positive(where, "height", height);
  positive(where, "head_width", head_width);
  positive(where, "head_depth", head_depth);
  positive(where, "web_thickness", web_thickness);
  positive(where, "foot_width", foot_width);
  positive(where, "foot_thickness", foot_thickness);
  const RowSpan r = rows(grid);
  if (head_depth + foot_thickness >= height || web_thickness >= head_width ||
      -r.lo >= 0.5 * head_width || r.hi >= 0.5 * head_width || grid.nx * grid.dx >= 0.5 * length) {
    throw std::invalid_argument(fmt::format(
        "{}: inconsistent section (head + foot deeper than the rail, web wider than the head) or "
        "contact grid wider than the head / longer than half the segment",
        where));
  }
}

void WheelSpec::validate(const std::string& where) const {
  grid.validate(where + ".grid");
  material.validate(where + ".material");
  mesh.validate(where + ".mesh");
  positive(where, "radius", radius);
  if (!(conicity >= 0.0 && conicity < 1.0)) {
    throw std::invalid_argument(
        fmt::format("{}.conicity: must be in [0, 1), got {}", where, conicity));
  }
  positive(where, "rim_field_side", rim_field_side);
  positive(where, "rim_flange_side", rim_flange_side);
  positive(where, "rim_depth", rim_depth);
  positive(where, "web_thickness", web_thickness);
  positive(where, "hub_radius", hub_radius);
  const RowSpan r = rows(grid);
  if (hub_radius + rim_depth >= radius || web_thickness >= rim_field_side + rim_flange_side ||
      -r.lo >= rim_flange_side || r.hi >= rim_field_side) {
    throw std::invalid_argument(fmt::format(
        "{}: inconsistent wheel (hub inside the rim, web wider than the rim) or contact grid "
        "wider than the rim",
        where));
  }
}

StructuredBody rail_body(const RailSpec& spec) {
  spec.validate();
  const contact::mim::Grid& g = spec.grid;
  const FeMeshLevel& lv = spec.mesh;
  const auto [hx, hy, near, r] = loaded_column(g, lv);
  const double foot_top = -(spec.height - spec.foot_thickness);
  StructuredBody b;
  b.s = graded_lines(-near, near, hx, lv.growth, -0.5 * spec.length, 0.5 * spec.length);
  b.t = graded_lines(r.lo, r.hi, hy, lv.growth, -0.5 * spec.foot_width, 0.5 * spec.foot_width,
                     {-0.5 * spec.head_width, -0.5 * spec.web_thickness, 0.5 * spec.web_thickness,
                      0.5 * spec.head_width});
  b.w = graded_lines(-std::max(g.dx, g.dy), 0.0, std::min(hx, hy), lv.growth, -spec.height, 0.0,
                     {foot_top, -spec.head_depth});
  const std::vector<double> t = b.t, w = b.w;
  const double head = 0.5 * spec.head_width, web = 0.5 * spec.web_thickness,
               foot = 0.5 * spec.foot_width, head_depth = spec.head_depth;
  b.active = [t, w, head, web, foot, head_depth, foot_top](std::size_t, std::size_t j,
                                                           std::size_t k) {
    const double tc = 0.5 * (t[j] + t[j + 1]), wc = 0.5 * (w[k] + w[k + 1]);
    const double half = wc > -head_depth ? head : (wc > foot_top ? web : foot);
    return std::abs(tc) < half;
  };
  const auto crown = std::make_shared<Crown>();
  b.map = [crown, head_depth](double sv, double tv, double wv) {
    const double lift = wv > -head_depth ? crown->height(tv) * (1.0 + wv / head_depth) : 0.0;
    return Point3{sv, tv, wv + lift};
  };
  const double bottom = -spec.height, tol = 1e-9;
  b.clamped = [bottom, tol](const Point3& p) { return p[2] <= bottom + tol; };
  return b;
}

StructuredBody wheel_body(const WheelSpec& spec) {
  spec.validate();
  const contact::mim::Grid& g = spec.grid;
  const FeMeshLevel& lv = spec.mesh;
  const auto [hx, hy, near, r] = loaded_column(g, lv);
  const double R = spec.radius, half_turn = std::numbers::pi * R;
  const double web_lo = -0.5 * spec.web_thickness, web_hi = 0.5 * spec.web_thickness;
  const double web_c = 0.5 * (spec.rim_field_side - spec.rim_flange_side);
  StructuredBody b;
  b.periodic_s = true;
  b.s = graded_lines(-near, near, hx, lv.growth, -half_turn, half_turn);
  b.t = graded_lines(r.lo, r.hi, hy, lv.growth, -spec.rim_flange_side, spec.rim_field_side,
                     {web_c + web_lo, web_c + web_hi});
  b.w = graded_lines(-std::max(g.dx, g.dy), 0.0, std::min(hx, hy), lv.growth,
                     -(R - spec.hub_radius), 0.0, {-spec.rim_depth});
  const std::vector<double> t = b.t, w = b.w;
  const double rim = spec.rim_depth;
  b.active = [t, w, rim, web_c, web_lo, web_hi](std::size_t, std::size_t j, std::size_t k) {
    const double tc = 0.5 * (t[j] + t[j + 1]), wc = 0.5 * (w[k] + w[k + 1]);
    return wc > -rim || (tc > web_c + web_lo && tc < web_c + web_hi);
  };
  // t runs along the cone's generator (y = t cos beta); the tread radius R - t sin beta blends
  // into a cylinder at the rim's inner radius, so the hub is the circle r = hub_radius.
  const double beta = std::atan(spec.conicity), cb = std::cos(beta), sb = std::sin(beta);
  b.map = [R, cb, sb, rim](double s, double tv, double wv) {
    const double rr = R + wv - tv * sb * std::max(0.0, 1.0 + wv / rim);
    const double theta = s / R;
    return Point3{rr * std::sin(theta), tv * cb, rr * std::cos(theta) - R};
  };
  const double hub = spec.hub_radius, tol = 1e-9;
  b.clamped = [R, hub, tol](const Point3& p) {
    return std::hypot(p[0], p[2] + R) <= hub + tol;
  };
  b.rolling = {1.0, 0.0, 0.0};
  b.lateral = {0.0, cb, -sb};
  b.normal = {0.0, sb, cb};
  return b;
}

WheelRailInfluence wheel_rail_influence(const RailSpec& rail, const WheelSpec& wheel) {
  WheelRailInfluence out;
  out.rail = surface_influence(rail_body(rail), rail.grid, rail.material, rail.mesh.degree);
  out.wheel = surface_influence(wheel_body(wheel), wheel.grid, wheel.material, wheel.mesh.degree);
  out.pair = pair_of_bodies(out.rail.single_body, out.wheel.single_body);
  return out;
}

}  // namespace ferro::fe_contact
