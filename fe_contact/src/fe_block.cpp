// FE influence coefficients of a large elastic block.
//
// References: see fe_block.hpp.
// Known deviations: see fe_block.hpp (finite block).

#include "ferro/fe_contact/fe_block.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ferro::fe_contact {

void FeBlockSpec::validate(const std::string& where) const {
  grid.validate(where + ".grid");
  material.validate(where + ".material");
  mesh.validate(where + ".mesh");
  if (!(extent >= 2.0 && extent <= 10000.0)) {
    throw std::invalid_argument(
        fmt::format("{}.extent: must be in [2, 10000], got {}", where, extent));
  }
}

StructuredBody block_body(const FeBlockSpec& spec) {
  spec.validate();
  const contact::mim::Grid& g = spec.grid;
  const FeMeshLevel& lv = spec.mesh;
  const double ex = (g.nx + 0.5) * g.dx;
  const double y_lo = g.y0 - 0.5 * g.dy, y_hi = g.y0 + (g.ny - 0.5) * g.dy;
  const double ey = 0.5 * (y_hi - y_lo), yc = 0.5 * (y_hi + y_lo);
  const double size = spec.extent * std::max(ex, ey);
  const double hx = g.dx / lv.subdivisions, hy = g.dy / lv.subdivisions;
  const double near = (lv.near_columns + 0.5) * g.dx;
  StructuredBody b;
  b.s = graded_lines(-near, near, hx, lv.growth, -size, size);
  b.t = graded_lines(y_lo, y_hi, hy, lv.growth, yc - size, yc + size);
  // Depth: uniform layers over one grid element, then graded down to the clamped bottom.
  b.w = graded_lines(-std::max(g.dx, g.dy), 0.0, std::min(hx, hy), lv.growth, -size, 0.0);
  const double bottom = b.w.front(), tol = 1e-9 * size;
  b.clamped = [bottom, tol](const Point3& p) { return std::abs(p[2] - bottom) <= tol; };
  return b;
}

FeInfluence block_influence(const FeBlockSpec& spec) {
  return surface_influence(block_body(spec), spec.grid, spec.material, spec.mesh.degree);
}

}  // namespace ferro::fe_contact
