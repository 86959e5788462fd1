// Plausibility warnings (plausible_values.hpp): the bounds by hand (30 and 5000 m/s, 500 and
// 5000 kg/m^3, 1e-4 and 3 g are plausible and give no text; just outside they warn) and the
// suggested reading of the value: 0.2 as km/s is 200 m/s, 1.9 as g/cm^3 is 1900 kg/m^3,
// 8000 as ft/s is 2438.4 m/s (0.3048 m per ft), a PGA of 34.83 g as cm/s^2 is 0.3483 g.
#include "slipwave/physics/plausible_values.hpp"

#include "unit_check.hpp"

using namespace slipwave::physics;

static bool says(const std::string &text, const std::string &part) { return text.find(part) != std::string::npos; }

int main() {
  unit::check(ShearSpeedImplausible(30).empty() && ShearSpeedImplausible(200).empty() && ShearSpeedImplausible(5000).empty(), "vs 30, 200, 5000 m/s: plausible");
  unit::check(says(ShearSpeedImplausible(0.2), "looks like km/s: 0.2 km/s is 200 m/s"), "vs 0.2: km/s, 200 m/s: " + ShearSpeedImplausible(0.2));
  unit::check(says(ShearSpeedImplausible(29.9), "below any soil") && !says(ShearSpeedImplausible(29.9), "km/s"), "vs 29.9: below, no km/s reading (29900 m/s is no rock)");
  unit::check(says(ShearSpeedImplausible(8000), "ft/s? 8000 ft/s is 2438.4 m/s"), "vs 8000: ft/s: " + ShearSpeedImplausible(8000));
  unit::check(says(ShearSpeedImplausible(1e6), "above any rock") && !says(ShearSpeedImplausible(1e6), "ft/s"), "vs 1e6: above, no ft/s reading");
  unit::check(DensityImplausible(500).empty() && DensityImplausible(2000).empty() && DensityImplausible(5000).empty(), "rho 500, 2000, 5000: plausible");
  unit::check(says(DensityImplausible(1.9), "g/cm^3 (t/m^3): 1.9 g/cm^3 is 1900 kg/m^3"), "rho 1.9: g/cm^3: " + DensityImplausible(1.9));
  unit::check(says(DensityImplausible(7850), "above soils, rocks and concrete"), "rho 7850 (steel): above the range");
  unit::check(PgaImplausible(1e-4).empty() && PgaImplausible(0.35).empty() && PgaImplausible(3).empty(), "PGA 1e-4, 0.35, 3 g: plausible");
  unit::check(says(PgaImplausible(34.83), "above any recorded earthquake") && says(PgaImplausible(34.83), "cm/s^2 taken for m/s^2: 0.3483 g"),
              "PGA 34.83 g: cm/s^2 reading 0.3483 g: " + PgaImplausible(34.83));
  unit::check(says(PgaImplausible(5e-5), "below 1e-4 g") && says(PgaImplausible(5e-5), "g taken for m/s^2: 0.0004903 g"), "PGA 5e-5 g: below: " + PgaImplausible(5e-5));
  return unit::failures();
}
