// Values outside what soils, rocks and structures have, most often a unit mistake (-vs 0.2
// meant as km/s, -rho 1.9 as g/cm^3, a record in cm/s^2 read as m/s^2). They run (a model
// may be odd on purpose) but the caller warns, once each, with what was probably meant.
// Each function returns "" for a plausible value, or the warning's text after the name.
#pragma once
#include <string>

namespace slipwave::physics {

inline constexpr double kPlausibleVsMin = 30, kPlausibleVsMax = 5000;       // m/s: peat to hard rock
inline constexpr double kPlausibleRhoMin = 500, kPlausibleRhoMax = 5000;    // kg/m^3: peat to dense rock and concrete
inline constexpr double kPlausiblePgaMin = 1e-4, kPlausiblePgaMax = 3;      // g: below ambient noise, above the largest recorded

// vs [m/s]: "... looks like km/s: 0.2 km/s is 200 m/s" below the range, ft/s above it.
std::string ShearSpeedImplausible(double vs);
// rho [kg/m^3]: g/cm^3 (t/m^3) below the range.
std::string DensityImplausible(double rho);
// The peak ground acceleration [g] of a record as applied (after its unit and scale).
std::string PgaImplausible(double pga_g);

} // namespace slipwave::physics
