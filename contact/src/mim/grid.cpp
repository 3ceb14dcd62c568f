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

}  // namespace ferro::contact::mim
