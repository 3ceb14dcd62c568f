#pragma once
// Surface influence coefficients of a finite elastic body by the finite-element method (GetFEM
// assembly, CHOLMOD sparse Cholesky). The body is a structured hexahedral mesh in parametric
// coordinates (s along the rolling direction, t across it, w <= 0 into the body; w = 0 is the
// loaded surface) mapped to physical space, with inactive cells cut out (rail web and foot,
// wheel web). A unit uniform traction (1 Pa along the rolling, lateral and inward normal
// directions) is integrated over each grid element of one column of the potential contact area
// (s in [-dx/2, dx/2]); the displacement of the finite-element solution is evaluated at the
// grid-element centres (s = ox dx, t = y(io), w = 0) of every column offset, as the
// Boussinesq-Cerruti coefficients of annex B.3 are (uniform load, centre value). Translation
// invariance along the rail and the wheel's axisymmetry make the coefficients of one loaded
// column those of every column.
//
// References: Toumi (2016) section 3.1 (FE wheel/rail), annex B.3 (centre values of uniformly
// loaded rectangles); Kalker (1990) section 5.2 (numerical influence coefficients);
// Renard & Poulios, "GetFEM: automated FE modeling with a high level generic assembly language",
// ACM TOMS 47 (2021); Chen, Davis, Hager & Rajamanickam, "CHOLMOD", ACM TOMS 35 (2008).
// Known deviations: the mapped mesh is trilinear (curved surfaces are facetted); the traction
// directions are those of the contact frame at the contact point for the whole loaded column
// (surface slopes over the patch below 0.04 rad); the normal-tangential coupling of the body is
// computed but not kept (the MIM operator, like the thesis's MIM, treats the pair as
// quasi-identical).

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "ferro/contact/material.hpp"
#include "ferro/contact/mim/dense_operator.hpp"
#include "ferro/contact/mim/grid.hpp"

namespace ferro::fe_contact {

using Point3 = std::array<double, 3>;

/// Mesh refinement of a finite-element influence computation.
struct FeMeshLevel {
  int degree = 2;         ///< Lagrange degree of the hexahedra (1 or 2) [-]
  int subdivisions = 1;   ///< elements per grid element side in the refined zone [-]
  double growth = 1.5;    ///< size ratio of successive elements outside the refined zone [-]
  int near_columns = 1;   ///< grid columns each side of the loaded one meshed finely [-]
  void validate(const std::string& where = "FeMeshLevel") const;
};

/// Structured body: node lines of the parametric box, active cells, the map to physical space,
/// the clamped nodes and the contact frame.
struct StructuredBody {
  std::vector<double> s;  ///< node lines along the rolling direction [m], increasing
  std::vector<double> t;  ///< node lines across [m], increasing
  std::vector<double> w;  ///< node lines into the body [m], increasing, w.back() == 0
  /// Whether cell (i, j, k) (between lines i..i+1, j..j+1, k..k+1) belongs to the body;
  /// empty: every cell.
  std::function<bool(std::size_t, std::size_t, std::size_t)> active;
  /// Physical position of a parametric point [m]; empty: identity.
  std::function<Point3(double, double, double)> map;
  /// Material of cell (i, j, k) where it differs from the body's (e.g. a bonded surface layer);
  /// empty, or nullptr for a cell: the material passed to surface_influence.
  std::function<const contact::Material*(std::size_t, std::size_t, std::size_t)> cell_material;
  /// Whether a node at a physical position is clamped (all components zero).
  std::function<bool(const Point3&)> clamped;
  /// The s lines close on themselves (node line s.back() is node line s.front(): a full ring).
  bool periodic_s = false;
  /// Contact frame in physical coordinates: rolling direction, lateral direction, outward normal.
  Point3 rolling{1.0, 0.0, 0.0};
  Point3 lateral{0.0, 1.0, 0.0};
  Point3 normal{0.0, 0.0, 1.0};
};

struct FeInfluence {
  /// Single-body coefficients in the contact frame (pressure pushes along -normal, u_z is the
  /// displacement along -normal) [m/Pa].
  contact::mim::ColumnInfluence single_body;
  long elements = 0;
  long dofs = 0;
  double cpu_seconds = 0.0;  ///< mesh, assembly, factorisation, solves and sampling [s]
};

/// Node lines: uniform steps of at most h on [a, b] (a and b are lines), then steps growing by
/// `growth` out to lo and hi (the last step absorbs a short remainder). Lines listed in
/// `required` inside (lo, hi) are inserted and lines outside [a, b] closer than a third of the
/// local step to them dropped.
[[nodiscard]] std::vector<double> graded_lines(double a, double b, double h, double growth,
                                               double lo, double hi,
                                               const std::vector<double>& required = {});

/// FE influence coefficients of `body` for the grid column centred on s = 0 (rows t = y(iy)),
/// observed at every column offset in [-grid.nx, grid.nx]. The edges s = +-dx/2 and the row
/// edges must be node lines. Throws std::invalid_argument for a grid the mesh does not carry and
/// std::runtime_error when the factorisation fails.
[[nodiscard]] FeInfluence surface_influence(const StructuredBody& body,
                                            const contact::mim::Grid& grid,
                                            const contact::Material& material, int degree);

/// Coefficients of a pair of identical bodies (relative displacement u1 - u2 = 2 u1).
[[nodiscard]] contact::mim::ColumnInfluence pair_of_identical(
    const contact::mim::ColumnInfluence& single_body);

/// Coefficients of a pair of bodies each computed in its own contact frame: body 2 (the rail)
/// in the contact frame, body 1 (the wheel) turned by pi about the rolling axis (lateral axis
/// and rows reversed, lateral coupling terms change sign); relative displacement u1 - u2 under
/// tractions +tau on body 1 and -tau on body 2 is the sum of the two.
[[nodiscard]] contact::mim::ColumnInfluence pair_of_bodies(
    const contact::mim::ColumnInfluence& lower, const contact::mim::ColumnInfluence& upper_turned);

}  // namespace ferro::fe_contact
