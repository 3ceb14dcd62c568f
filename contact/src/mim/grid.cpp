// Regular MIM grid: construction and validation.
//
// References: Toumi (2016) section 2.2.1 (figure 2.2).
// Known deviations: none.

#include "ferro/contact/mim/grid.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace ferro::contact::mim {

Grid Grid::centred(int nx, int ny, double dx, double dy) {
  Grid g;
  g.nx = nx;
  g.ny = ny;
  g.dx = dx;
  g.dy = dy;
  g.x0 = -0.5 * (nx - 1) * dx;
  g.y0 = -0.5 * (ny - 1) * dy;
  return g;
}

void Grid::validate(const std::string& where) const {
  if (nx < 2 || ny < 1) {
    throw std::invalid_argument(
        fmt::format("{}.nx/ny: need nx >= 2 and ny >= 1 elements, got {} x {}", where, nx, ny));
  }
  if (!(dx > 0.0) || !std::isfinite(dx)) {
    throw std::invalid_argument(fmt::format("{}.dx: must be finite and > 0 m, got {}", where, dx));
  }
  if (!(dy > 0.0) || !std::isfinite(dy)) {
    throw std::invalid_argument(fmt::format("{}.dy: must be finite and > 0 m, got {}", where, dy));
  }
  if (!std::isfinite(x0)) {
    throw std::invalid_argument(fmt::format("{}.x0: must be finite (m), got {}", where, x0));
  }
  if (!std::isfinite(y0)) {
    throw std::invalid_argument(fmt::format("{}.y0: must be finite (m), got {}", where, y0));
  }
}

int count_positive_regions(const Grid& grid, const Field& field) {
  std::vector<int> label(grid.size(), 0);
  int n = 0;
  for (std::size_t k0 = 0; k0 < grid.size(); ++k0) {
    if (!(field[k0] > 0.0) || label[k0] != 0) continue;
    ++n;
    std::vector<std::size_t> stack{k0};
    label[k0] = n;
    while (!stack.empty()) {
      const std::size_t k = stack.back();
      stack.pop_back();
      const int ix = static_cast<int>(k % static_cast<std::size_t>(grid.nx));
      const int iy = static_cast<int>(k / static_cast<std::size_t>(grid.nx));
      const int nb[4][2] = {{ix - 1, iy}, {ix + 1, iy}, {ix, iy - 1}, {ix, iy + 1}};
      for (const auto& q : nb) {
        if (q[0] < 0 || q[0] >= grid.nx || q[1] < 0 || q[1] >= grid.ny) continue;
        const std::size_t m = grid.index(q[0], q[1]);
        if (field[m] > 0.0 && label[m] == 0) {
          label[m] = n;
          stack.push_back(m);
        }
      }
    }
  }
  return n;
}

}  // namespace ferro::contact::mim
