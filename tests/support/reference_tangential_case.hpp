#pragma once
// Test support: the tangential models' reference set (F_n = 82 kN, G = 82 GPa, nu = 0.28,
// mu = 0.3, both bodies alike) and one Hertzian case of it: an elliptic patch and the tangential
// problem on it. Shared by the tangential-model accuracy tests.
#include "ferro/contact/material.hpp"
#include "ferro/contact/normal/contact_patch.hpp"
#include "ferro/contact/tangential/tangential_model.hpp"

namespace ferro::test {

inline constexpr double kRefNormalForce = 82.0e3;  // [N]
inline constexpr double kRefFriction = 0.3;        // [-]
inline constexpr double kRefShearModulus = 82.0e9;  // [Pa]
inline constexpr double kRefPoisson = 0.28;        // [-]

inline contact::Material reference_material() {
  return contact::Material::from_young(2.0 * kRefShearModulus * (1.0 + kRefPoisson), kRefPoisson);
}

/// The patch a x b [m] under kRefNormalForce and the problem on it at creepage `c`.
struct ReferenceCase {
  contact::ContactPatch patch;
  contact::TangentialProblem problem;
  ReferenceCase(double a, double b, contact::Creepage c) {
    patch = contact::elliptic_patch(a, b, kRefNormalForce);
    problem.patch = &patch;
    problem.creepage = c;
    problem.friction = kRefFriction;
    problem.body1 = problem.body2 = reference_material();
  }
  ReferenceCase(const ReferenceCase&) = delete;  // the problem points at the patch
  ReferenceCase& operator=(const ReferenceCase&) = delete;
};

}  // namespace ferro::test
