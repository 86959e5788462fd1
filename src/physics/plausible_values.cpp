#include "slipwave/physics/plausible_values.hpp"

#include "slipwave/physics/message_format.hpp"

#include <cstdio>

namespace slipwave::physics {
namespace {

bool inside(double x, double lo, double hi) { return x >= lo && x <= hi; }

} // namespace

std::string ShearSpeedImplausible(double vs) {
  if (inside(vs, kPlausibleVsMin, kPlausibleVsMax)) return "";
  if (vs < kPlausibleVsMin)
    return inside(vs * 1e3, kPlausibleVsMin, kPlausibleVsMax)
             ? formatMessage("%g m/s is below any soil (30 m/s) and looks like km/s: %g km/s is %g m/s", vs, vs, vs * 1e3)
             : formatMessage("%g m/s is below any soil (30 m/s); the value is in m/s", vs);
  const double ft = 0.3048;
  return inside(vs * ft, kPlausibleVsMin, kPlausibleVsMax)
           ? formatMessage("%g m/s is above any rock (5000 m/s); ft/s? %g ft/s is %g m/s", vs, vs, vs * ft)
           : formatMessage("%g m/s is above any rock (5000 m/s); the value is in m/s", vs);
}

std::string DensityImplausible(double rho) {
  if (inside(rho, kPlausibleRhoMin, kPlausibleRhoMax)) return "";
  if (rho < kPlausibleRhoMin)
    return inside(rho * 1e3, kPlausibleRhoMin, kPlausibleRhoMax)
             ? formatMessage("%g kg/m^3 is below any soil (500 kg/m^3) and looks like g/cm^3 (t/m^3): %g g/cm^3 is %g kg/m^3", rho, rho, rho * 1e3)
             : formatMessage("%g kg/m^3 is below any soil (500 kg/m^3); the value is in kg/m^3", rho);
  return formatMessage("%g kg/m^3 is above soils, rocks and concrete (5000 kg/m^3; steel is 7850); the value is in kg/m^3", rho);
}

std::string PgaImplausible(double pga_g) {
  if (inside(pga_g, kPlausiblePgaMin, kPlausiblePgaMax)) return "";
  if (pga_g > kPlausiblePgaMax)
    return formatMessage("PGA %.4g g is above any recorded earthquake (about 3 g): a unit mistake? (cm/s^2 taken for m/s^2: %.4g g; m/s^2 taken for g: %.4g g)", pga_g,
                  pga_g * 0.01, pga_g / 9.80665);
  return formatMessage("PGA %.4g g is below 1e-4 g (ambient vibration): a unit or scale mistake? (g taken for m/s^2: %.4g g)", pga_g, pga_g * 9.80665);
}

} // namespace slipwave::physics
