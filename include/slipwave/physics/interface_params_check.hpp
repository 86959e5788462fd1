// Validity of the interface law's parameters (spec section 3), as data: the options layer
// turns an issue into the user-facing error, the simulation reuses the same rules.
#pragma once

#include "slipwave/physics/mohr_coulomb_interface.hpp"

#include <optional>
#include <string>

namespace slipwave::physics {

struct InterfaceParamIssue {
  const char *name;    // option suffix: E, G, phi, psi, c, e_ini, tensile_strength, sigma_N0
  double value;        // in input units (degrees for angles)
  const char *unit;    // "deg", "Pa/m", "Pa", "m"
  std::string allowed; // the valid range, with the values it depends on
};

// First parameter out of its range, or nothing. Angles of params in radians.
std::optional<InterfaceParamIssue> interfaceParamsCheck(const InterfaceParams &params);

// An initial normal traction beyond the tension cut-off is not an admissible state.
std::optional<InterfaceParamIssue> interfaceInitialStressCheck(const InterfaceParams &params, double sigma_N0);

} // namespace slipwave::physics
