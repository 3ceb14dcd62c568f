#pragma once
// Surface influence coefficients of a finite elastic block by the finite-element method
// (GetFEM assembly, CHOLMOD sparse Cholesky): unit uniform traction on each surface element of
// one column of the potential contact area, displacement at the element centres of every
// column (translation invariance along x), for the dense compliance operator of the MIM.
//
// References: Toumi (2016) section 3.1 (FE wheel/rail, clamped foot), annex B.3 (the half-space
// coefficients these reproduce for a large block); Kalker (1990) section 5.2 (numerical
// influence coefficients); Renard & Poulios, "GetFEM: automated FE modeling with a
// high level generic assembly language", ACM TOMS 47 (2021); Chen, Davis, Hager & Rajamanickam,
// "CHOLMOD", ACM TOMS 35 (2008).
// Known deviations: a rectangular block (top face z = 0, clamped bottom, free sides), not the
// UIC60 rail or the S1002 wheel; structured hexahedral mesh of Lagrange degree 1 or 2, uniform
// inside the loaded area and graded geometrically outside; the normal-tangential coupling of
// the block (non-zero for a finite body) is not kept (quasi-identical bodies, as the MIM).

#include <string>

#include "ferro/contact/material.hpp"
#include "ferro/contact/mim/dense_operator.hpp"
#include "ferro/contact/mim/grid.hpp"

namespace ferro::fe_contact {

struct FeBlockSpec {
  contact::mim::Grid grid;   ///< surface grid of the potential contact area (top face z = 0)
  contact::Material material;
  int subdivisions = 2;      ///< FE elements per grid element side in the loaded area [-]
  int degree = 1;            ///< Lagrange degree of the hexahedra (1 or 2) [-]
  double growth = 1.4;       ///< size ratio of successive elements outside the loaded area [-]
  /// Block half-length, half-width and depth, in units of the loaded area's half-extent [-].
  double extent = 20.0;
  void validate(const std::string& where = "FeBlockSpec") const;
};

struct FeInfluence {
  /// Single-body coefficients (displacement of the block under the traction on it) [m/Pa].
  contact::mim::ColumnInfluence single_body;
  long elements = 0;
  long dofs = 0;
  double cpu_seconds = 0.0;  ///< mesh, assembly, factorisation and solves
};

/// FE influence coefficients of the block for the column of grid elements at x = 0 observed at
/// every offset (grid.nx columns each side). Throws std::runtime_error when the factorisation
/// fails.
[[nodiscard]] FeInfluence block_influence(const FeBlockSpec& spec);

/// Coefficients of a pair of identical bodies (relative displacement u1 - u2 = 2 u1).
[[nodiscard]] contact::mim::ColumnInfluence pair_of_identical(
    const contact::mim::ColumnInfluence& single_body);

}  // namespace ferro::fe_contact
