#pragma once
// Private factories of the integrator adapters.
#include <memory>

#include "ferro/vehicle/integrator.hpp"

namespace ferro::vehicle::detail {
std::unique_ptr<Integrator> make_cvode(const IntegratorSettings& settings);
std::unique_ptr<Integrator> make_arkode_erk(const IntegratorSettings& settings);
std::unique_ptr<Integrator> make_arkode_dirk(const IntegratorSettings& settings);
std::unique_ptr<Integrator> make_odeint(const IntegratorSettings& settings);
std::unique_ptr<Integrator> make_bdf2(const IntegratorSettings& settings);
}  // namespace ferro::vehicle::detail
