#include "ferro/contact/material.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace ferro::contact {

void Material::validate(const std::string& where) const {
  if (!(shear_modulus > 0.0) || !std::isfinite(shear_modulus)) {
    throw std::invalid_argument(fmt::format(
        "{}.shear_modulus: must be a finite positive value in Pa, got {}", where, shear_modulus));
  }
  if (!(poisson >= 0.0 && poisson < 0.5)) {
    throw std::invalid_argument(
        fmt::format("{}.poisson: must lie in [0, 0.5), got {}", where, poisson));
  }
}

CombinedMaterial combine(const Material& body1, const Material& body2) {
  CombinedMaterial c;
  const double inv_g = 0.5 * (1.0 / body1.shear_modulus + 1.0 / body2.shear_modulus);
  c.shear_modulus = 1.0 / inv_g;
  c.poisson = 0.5 * (body1.poisson / body1.shear_modulus + body2.poisson / body2.shear_modulus) *
              c.shear_modulus;
  const double inv_estar = (1.0 - body1.poisson * body1.poisson) / body1.young() +
                           (1.0 - body2.poisson * body2.poisson) / body2.young();
  c.contact_modulus = 1.0 / inv_estar;
  return c;
}

}  // namespace ferro::contact
