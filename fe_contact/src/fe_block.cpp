// FE influence coefficients of a large elastic block.
//
// References: see fe_block.hpp.
// Known deviations: see fe_block.hpp (finite block).

#include "ferro/fe_contact/fe_block.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
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
  if (!(edge_refinement >= 0.0 && edge_refinement <= 0.3)) {
    throw std::invalid_argument(
        fmt::format("{}.edge_refinement: must be in [0, 0.3], got {}", where, edge_refinement));
  }
  if (!(layer_thickness >= 0.0 && layer_thickness < std::max(grid.dx, grid.dy))) {
    throw std::invalid_argument(fmt::format(
        "{}.layer_thickness: must be in [0, one grid element), got {} m", where, layer_thickness));
  }
  if (layer_thickness > 0.0) layer_material.validate(where + ".layer_material");
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
  // A surface layer adds its bottom as a node line; its cells take the layer's material.
  const double h = spec.layer_thickness;
  const double el = std::min(g.dx, g.dy);
  std::vector<double> depth_lines;
  if (h > 0.0) depth_lines.push_back(-h);
  b.w = graded_lines(-std::max(g.dx, g.dy), 0.0, std::min(hx, hy), lv.growth, -size, 0.0);
  // Load-edge refinement around the centre element (lines inside the refined zone).
  if (const double e = spec.edge_refinement; e > 0.0) {
    const double yc0 = g.y(g.ny / 2);
    for (double edge : {-0.5 * g.dx, 0.5 * g.dx})
      for (double side : {-1.0, 1.0}) b.s.push_back(edge + side * e * g.dx);
    for (double edge : {yc0 - 0.5 * g.dy, yc0 + 0.5 * g.dy})
      for (double side : {-1.0, 1.0}) b.t.push_back(edge + side * e * g.dy);
    for (double d : {e, 2.5 * e}) depth_lines.push_back(-d * el);
  }
  b.w.insert(b.w.end(), depth_lines.begin(), depth_lines.end());
  for (std::vector<double>* lines : {&b.s, &b.t, &b.w}) {
    std::sort(lines->begin(), lines->end());
    lines->erase(std::unique(lines->begin(), lines->end(),
                             [&](double x, double y) { return std::abs(x - y) < 1e-9 * el; }),
                 lines->end());
  }
  if (h > 0.0) {
    const auto layer = std::make_shared<const contact::Material>(spec.layer_material);
    const std::vector<double> w = b.w;
    b.cell_material = [layer, w, h](std::size_t, std::size_t, std::size_t k) {
      return w[k] >= -h * (1.0 + 1e-9) ? layer.get() : nullptr;
    };
  }
  const double bottom = b.w.front(), tol = 1e-9 * size;
  b.clamped = [bottom, tol](const Point3& p) { return std::abs(p[2] - bottom) <= tol; };
  return b;
}

FeInfluence block_influence(const FeBlockSpec& spec) {
  return surface_influence(block_body(spec), spec.grid, spec.material, spec.mesh.degree);
}

}  // namespace ferro::fe_contact
