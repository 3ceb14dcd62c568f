// Uses the installed libraries: Kalker's table (ferro::contact) and the wheelset closed form
// (ferro::vehicle). Prints C11 for a circular contact at nu = 1/4 (table value 4.12).
#include <cstdio>

#include "ferro/contact/tangential/kalker_coefficients.hpp"
#include "ferro/vehicle/suspended_wheelset.hpp"

int main() {
  const auto c = ferro::contact::kalker_coefficients_table(1.0, 1.0, 0.25);
  std::printf("C11 %.2f\n", c.c11);
  return c.c11 == 4.12 ? 0 : 1;
}
