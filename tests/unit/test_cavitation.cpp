// The cavitation floor of the pore pressure (physics/cavitation.hpp), one node alone: above
// the floor nothing changes; below it the pressure stops at the floor and the shortfall of
// fluid volume opens a cavity S (floor - p); a cavity closes first as the pore space
// shrinks, and the pressure rises only once it has closed; the cavity's work term is the
// trapezoid of -p dV, step by step.
#include "slipwave/physics/cavitation.hpp"

#include "unit_check.hpp"

#include <cmath>

using namespace slipwave::physics;

int main() {
  const double S = 4e-10, floor = -1.2e5; // storage [m^3/Pa] (1 m^3 of soil, M = 2.5e9 Pa), floor [Pa]
  {
    const CavitatedPressure r = cavitationFloor(-5e4, floor, S);
    unit::check(r.p == -5e4 && r.cavity == 0.0, "above the floor: the pressure as the storage equation gives it, no cavity");
  }
  {
    const CavitatedPressure r = cavitationFloor(floor, floor, S);
    unit::check(r.p == floor && r.cavity == 0.0, "at the floor: no cavity");
  }
  // A node expanded by dV = 1e-4 m^3 (volumetric strain 1e-4) from p = 0: without a floor
  // p = -dV / S = -2.5e5 Pa; with it the pressure stops at the floor and the fluid's missing
  // expansion, dV - S |floor| = 1e-4 - 4.8e-5, is the cavity.
  const double dV = 1e-4;
  const CavitatedPressure open = cavitationFloor(0.0 - dV / S, floor, S);
  unit::near(open.p, floor, 0, 0, "expanded past the floor: held at the floor");
  unit::near(open.cavity, dV - S * -floor, 1e-14, 0, "the cavity is the volume the fluid does not follow, dV - S |floor|");
  // Half of the expansion undone: the cavity closes by that much, the pressure stays.
  const double back = 0.5 * dV;
  const CavitatedPressure half = cavitationFloor(open.p + back / S - open.cavity / S, floor, S);
  unit::near(half.p, floor, 1e-14, 0, "contracting while a cavity is open: the pressure stays at the floor");
  unit::near(half.cavity, open.cavity - back, 1e-12, 0, "the cavity closes by the contraction");
  // All of it undone: the cavity is gone and the pressure is back where it started.
  const CavitatedPressure closed = cavitationFloor(half.p + back / S - half.cavity / S, floor, S);
  unit::check(closed.cavity == 0.0, "fully contracted: the cavity has closed");
  unit::near(closed.p, 0.0, 0, 1e-9, "and the pressure is back at its start");
  // The cavity's work over the three steps, -(p_n + p_{n+1})/2 (V_{n+1} - V_n) each: opening
  // from p = 0 to the floor, closing by `back` at the floor, closing the rest on the way up.
  const double w          = cavityWork(0.0, open.p, 0.0, open.cavity) + cavityWork(open.p, half.p, open.cavity, half.cavity) + cavityWork(half.p, closed.p, half.cavity, closed.cavity);
  const double w_expected = -0.5 * floor * open.cavity + floor * back + 0.5 * floor * half.cavity;
  unit::near(w, w_expected, 1e-12, 0, "cavity work: the trapezoid of -p dV over the three steps");
  unit::check(cavityWork(floor, floor, 0.0, 1e-5) > 0.0, "a cavity opening under suction takes work from the fluid");
  return unit::failures();
}
