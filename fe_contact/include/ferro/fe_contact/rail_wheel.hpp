#pragma once
// Finite elastic bodies of the thesis's chapter-3 contact: a UIC60 (60E1) rail segment with a
// clamped foot and a 920 mm wheel with a 1/10 conical tread, as structured bodies for the
// finite-element influence coefficients (fe_body.hpp). Rail inclined 1:10 and wheel cone 1/10
// put the contact on the crown top of the rail, on its axis of symmetry, so each body is meshed
// in its own frame with the contact point at the origin of the parametric surface.
//
// References: Toumi (2016) Table 3.1 (UIC60 inclined 1:10, 250 mm segment, clamped foot; wheel
// 920 mm, conicity 1/10), section 3.1; EN 13674-1 (60E1: height 172 mm, head width 72 mm, web
// 16.5 mm, foot width 150 mm, section area 76.70 cm^2; crown radii R300/R80/R13 via
// contact::make_60e1_rail); EN 13262 / EN 13979-1 (solid wheel: rim width 135 mm).
// Known deviations: the rail section is simplified below the crown: a rectangular head 72 mm
// wide and 49 mm deep whose top follows the 60E1 crown over |y| <= 30 mm (the R13 corners
// beyond are replaced by the crown height at 30 mm), a 16.5 mm web and a 150 mm x 16 mm foot
// (area 76.9 cm^2 against 76.7 cm^2); the segment's ends are free. The wheel is a solid of
// revolution: a rim 135 mm wide and 65 mm deep with the conical tread across its whole width
// (no flange), a straight web 30 mm thick under the rim's centre, clamped at the hub radius
// 130 mm; the web's curvature and the hub are not modelled.

#include <string>

#include "ferro/contact/material.hpp"
#include "ferro/contact/mim/grid.hpp"
#include "ferro/fe_contact/fe_body.hpp"

namespace ferro::fe_contact {

struct RailSpec {
  contact::mim::Grid grid;  ///< contact grid (rows centred on the rail axis)
  contact::Material material;
  FeMeshLevel mesh;
  double length = 0.250;          ///< segment length [m]
  double height = 0.172;          ///< crown top to foot bottom [m]
  double head_width = 0.072;      ///< [m]
  double head_depth = 0.049;      ///< crown top to the underside of the head [m]
  double web_thickness = 0.0165;  ///< [m]
  double foot_width = 0.150;      ///< [m]
  double foot_thickness = 0.016;  ///< [m]
  void validate(const std::string& where = "RailSpec") const;
};

struct WheelSpec {
  contact::mim::Grid grid;  ///< contact grid (rows centred on the contact point)
  contact::Material material;
  FeMeshLevel mesh;
  double radius = 0.460;             ///< rolling radius at the contact point [m]
  double conicity = 0.1;             ///< tread cone slope [-]
  double rim_field_side = 0.065;     ///< rim edge beyond the contact point, field side [m]
  double rim_flange_side = 0.070;    ///< rim edge before the contact point, flange side [m]
  double rim_depth = 0.065;          ///< radial rim thickness [m]
  double web_thickness = 0.030;      ///< [m]
  double hub_radius = 0.130;         ///< clamped radius [m]
  void validate(const std::string& where = "WheelSpec") const;
};

[[nodiscard]] StructuredBody rail_body(const RailSpec& spec);
[[nodiscard]] StructuredBody wheel_body(const WheelSpec& spec);

/// Pair coefficients of the wheel on the rail for the contact grid: rail + wheel turned by pi
/// about the rolling axis (pair_of_bodies); the CPU time, elements and DOFs are those of both
/// models.
struct WheelRailInfluence {
  FeInfluence rail;
  FeInfluence wheel;
  contact::mim::ColumnInfluence pair;
};
[[nodiscard]] WheelRailInfluence wheel_rail_influence(const RailSpec& rail,
                                                      const WheelSpec& wheel);

}  // namespace ferro::fe_contact
