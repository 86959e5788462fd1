#include "slipwave/physics/interface_params_check.hpp"

#include <cmath>
#include <cstdio>

namespace slipwave::physics {
namespace {

constexpr double kDegPerRad = 180.0 / M_PI;

std::string formatNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

InterfaceParamIssue issue(const char *name, double value, const char *unit, std::string allowed) {
  return InterfaceParamIssue{name, value, unit, std::move(allowed)};
}

} // namespace

std::optional<InterfaceParamIssue> interfaceParamsCheck(const InterfaceParams &p) {
  if (!(p.E > 0.0) || !std::isfinite(p.E)) return issue("E", p.E, "Pa/m", "E > 0 (normal penalty stiffness)");
  if (!(p.G > 0.0) || !std::isfinite(p.G)) return issue("G", p.G, "Pa/m", "G > 0 (tangential penalty stiffness)");
  const double phi_deg = p.phi * kDegPerRad, psi_deg = p.psi * kDegPerRad;
  if (!(phi_deg >= 0.0 && phi_deg < 90.0)) return issue("phi", phi_deg, "deg", "0 <= phi < 90");
  if (!(psi_deg >= 0.0 && p.psi <= p.phi))
    return issue("psi", psi_deg, "deg",
                 "0 <= psi <= phi = " + formatNumber(phi_deg) + " deg (dilatancy above friction creates energy)");
  if (!(p.c >= 0.0) || !std::isfinite(p.c)) return issue("c", p.c, "Pa", "c >= 0");
  if (!(p.e_ini >= 0.0) || !std::isfinite(p.e_ini)) return issue("e_ini", p.e_ini, "m", "e_ini >= 0");
  if (!(p.tensile_strength >= 0.0) || !std::isfinite(p.tensile_strength))
    return issue("tensile_strength", p.tensile_strength, "Pa", "tensile_strength >= 0");
  if (p.phi > 0.0) {
    // Beyond c / tan(phi) (the apex) no shear traction is admissible at all.
    const double apex = p.c / std::tan(p.phi);
    if (p.tensile_strength > apex * (1.0 + 1e-12))
      return issue("tensile_strength", p.tensile_strength, "Pa",
                   "0 <= tensile_strength <= c / tan(phi) = " + formatNumber(apex) + " Pa (c = " + formatNumber(p.c) +
                       " Pa, phi = " + formatNumber(phi_deg) + " deg)");
  }
  return std::nullopt;
}

std::optional<InterfaceParamIssue> interfaceInitialStressCheck(const InterfaceParams &p, double sigma_N0) {
  if (!(sigma_N0 <= p.tensile_strength) || !std::isfinite(sigma_N0))
    return issue("sigma_N0", sigma_N0, "Pa",
                 "sigma_N0 <= tensile_strength = " + formatNumber(p.tensile_strength) +
                     " Pa (tension positive: a compressive load is negative)");
  return std::nullopt;
}

} // namespace slipwave::physics
