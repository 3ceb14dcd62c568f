#pragma once
// The thesis's chapter 3 contact (Toumi 2016 Tables 3.1, 3.7): 7.5 t wheel load, Hertz
// a = 6.66 mm, b = 5.05 mm, steel E = 210 GPa, nu = 0.28, mu = 0.2, as the FE tests use it.

#include "ferro/contact/material.hpp"
#include "ferro/fe_contact/hertz_case.hpp"

namespace ferro::test {

inline fe_contact::HertzCase thesis_hertz_case(int elements_minor, double margin) {
  fe_contact::HertzCase c;
  c.reference_force = 7.5e3 * 9.81;
  c.reference_semi_axis_x = 6.66e-3;
  c.reference_semi_axis_y = 5.05e-3;
  c.normal_force = c.reference_force;
  c.body = contact::Material::from_young(210.0e9, 0.28);
  c.friction = 0.2;
  c.elements_minor = elements_minor;
  c.margin = margin;
  return c;
}

}  // namespace ferro::test
