#pragma once
// Regular grid of piecewise-constant rectangular boundary elements for the MIM solver.
//
// References: Toumi (2016) section 2.2.1, figure 2.2 (N rectangles dx x dy centred on (x_i, y_i)).
// Known deviations: none.

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace ferro::contact::mim {

/// Element (ix, iy) has its centre at (x0 + ix dx, y0 + iy dy). Fields on the grid are stored
/// row-major with x fastest: value(ix, iy) = field[iy * nx + ix]. x is the rolling direction;
/// the body rolls towards +x, so the leading edge of a patch is at its largest x.
struct Grid {
  int nx = 0;                                            ///< elements along x [-]
  int ny = 0;                                            ///< elements along y [-]
  double dx = std::numeric_limits<double>::quiet_NaN();  ///< element length along x [m]
  double dy = std::numeric_limits<double>::quiet_NaN();  ///< element length along y [m]
  double x0 = std::numeric_limits<double>::quiet_NaN();  ///< x of the centre of element (0, .) [m]
  double y0 = std::numeric_limits<double>::quiet_NaN();  ///< y of the centre of element (., 0) [m]

  /// Grid of nx x ny elements centred on the origin.
  static Grid centred(int nx, int ny, double dx, double dy);

  [[nodiscard]] std::size_t size() const {
    return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  }
  [[nodiscard]] double x(int ix) const { return x0 + ix * dx; }
  [[nodiscard]] double y(int iy) const { return y0 + iy * dy; }
  [[nodiscard]] double element_area() const { return dx * dy; }
  [[nodiscard]] std::size_t index(int ix, int iy) const {
    return static_cast<std::size_t>(iy) * static_cast<std::size_t>(nx) +
           static_cast<std::size_t>(ix);
  }
  /// Throws std::invalid_argument naming the offending field.
  void validate(const std::string& where = "grid") const;
};

/// A scalar field on a grid (row-major, x fastest).
using Field = std::vector<double>;

/// Number of connected parts (4-neighbourhood) of the elements where `field` > 0, e.g. the
/// lobes of a contact area from its pressure.
[[nodiscard]] int count_positive_regions(const Grid& grid, const Field& field);

/// Samples f(x, y) at every element centre.
template <class F>
[[nodiscard]] Field sample(const Grid& grid, F&& f) {
  Field out(grid.size());
  for (int iy = 0; iy < grid.ny; ++iy) {
    for (int ix = 0; ix < grid.nx; ++ix) {
      out[grid.index(ix, iy)] = f(grid.x(ix), grid.y(iy));
    }
  }
  return out;
}

}  // namespace ferro::contact::mim
