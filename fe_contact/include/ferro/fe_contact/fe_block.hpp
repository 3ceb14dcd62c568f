#pragma once
// Surface influence coefficients of a large elastic block (top face z = 0, clamped bottom, free
// sides) by the finite-element method: the half-space limit against which the finite-element
// route (fe_body.hpp) is checked with the Boussinesq-Cerruti coefficients of annex B.3.
//
// References: Toumi (2016) annex B.3 (the half-space coefficients these reproduce for a large
// block); Johnson, "Contact Mechanics" (1985) section 3.2 (point-load displacement below the
// surface, which sets the clamped-bottom error ~ (3 - 2 nu) r / (2 (1 - nu) H)).
// A bonded surface layer (thickness h, its own material) can cover the top face: the finite-element
// counterpart of the interfacial layer's local tangential compliance h / G3.
// Known deviations: the block is finite (extent x the loaded area's half-size in every direction),
// which lowers the coefficients by about the displacement the half-space has at the block's depth.

#include <string>

#include "ferro/contact/material.hpp"
#include "ferro/contact/mim/grid.hpp"
#include "ferro/fe_contact/fe_body.hpp"

namespace ferro::fe_contact {

struct FeBlockSpec {
  contact::mim::Grid grid;  ///< surface grid of the potential contact area (top face z = 0)
  contact::Material material;
  FeMeshLevel mesh;
  /// Block half-length, half-width and depth, in units of the loaded area's half-extent [-].
  double extent = 200.0;
  /// Refinement at the edges of the centre grid element, where the strain of a uniform load is
  /// singular (logarithmically): node lines at +-edge_refinement grid elements from its four
  /// edges and below the surface at depths edge_refinement and 2.5 edge_refinement grid
  /// elements; 0: none [-].
  double edge_refinement = 0.0;
  /// Bonded surface layer of another material over the whole top face (a third-body layer
  /// meshed with finite elements): its thickness (0: no layer) and material.
  double layer_thickness = 0.0;  ///< h [m]
  contact::Material layer_material;
  void validate(const std::string& where = "FeBlockSpec") const;
};

/// The block as a structured body (the loaded column at x = 0, rows along y).
[[nodiscard]] StructuredBody block_body(const FeBlockSpec& spec);

/// FE influence coefficients of the block for the column of grid elements at x = 0 observed at
/// every offset (grid.nx columns each side).
[[nodiscard]] FeInfluence block_influence(const FeBlockSpec& spec);

}  // namespace ferro::fe_contact
