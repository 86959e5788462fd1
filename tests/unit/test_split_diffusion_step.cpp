// The split u-p step's sub-steps and coupling factor (physics/split_diffusion_step.hpp): the
// rule itself, and the bound it rests on checked on the scalar model of one displacement
// mode and one pressure mode, stepped as porous/pore_pressure.cpp steps them:
//   u_{n+1} = (2 - a) u_n - u_{n-1} + r_n,   r_{n+1} = g r_n - b (u_{n+1} - u_n)
// (a = h^2 k/m, b = h^2 B^2/m, r the pressure's force times h^2/m, g the diffusion's
// amplification of the mode): bounded whenever a + c b < 4, c = 2/(1 + g), and growing just
// above it when the coupling carries the stiffness (a = 0), where the bound is sharp.
#include "slipwave/physics/split_diffusion_step.hpp"

#include "unit_check.hpp"

#include <algorithm>
#include <cmath>
#include <string>

using namespace slipwave::physics;

namespace {

// The largest |u| or |r| over `steps` steps from u_0 = 0, u_1 = 1, r_1 = 0.
double largest(double a, double b, double g, int steps) {
  double u0 = 0, u1 = 1, r = 0, top = 1;
  for (int n = 0; n < steps; ++n) {
    const double u2 = (2 - a) * u1 - u0 + r;
    r               = g * r - b * (u2 - u1);
    u0 = u1, u1 = u2;
    top = std::max({top, std::fabs(u1), std::fabs(r)});
    if (!(top < 1e30)) break;
  }
  return top;
}

} // namespace

int main() {
  // The rule.
  unit::check(splitDiffusionSubsteps(1.0, 1e300, true) == 1 && splitCouplingFactor(1.0, 1e300, true) == 1.0, "no diffusion: one sub-step, c = 1 (the undrained limit)");
  unit::near(splitCouplingFactor(0.25, 1.0, true), 2.0 / 1.5, 1e-15, 0, "h lambda_b = 0.5: one sub-step, c = 2/(2 - h lambda_b)");
  unit::check(splitDiffusionSubsteps(0.5, 1.0, true) == 1, "h lambda_b = 1: one sub-step (g = 0)");
  bool even = true, within = true, monotone = true;
  double previous[2] = {0, 0};
  for (int k = 1; k <= 4000; ++k) {
    const double h = 0.01 * k; // dt_diffusion = 1: h lambda_b = 2 h
    for (int cycle = 0; cycle < 2; ++cycle) {
      const bool subcycle = cycle == 0;
      if (!subcycle && h >= 1) continue; // without sub-steps the caller keeps h < dt_diffusion
      const int    m = splitDiffusionSubsteps(h, 1.0, subcycle);
      const double c = splitCouplingFactor(h, 1.0, subcycle);
      if (m > 1) even = even && m % 2 == 0, within = within && 2 * h / m <= 1.8 * (1 + 1e-15);
      monotone = monotone && c >= previous[cycle];
      previous[cycle] = c;
    }
  }
  unit::check(even && within, "several sub-steps: an even count, each within 0.9 of forward Euler's limit");
  unit::check(monotone, "c non-decreasing in h (with and without sub-cycling)");
  unit::check(splitCouplingFactor(0.8, 1.0, true) == 2.0, "sub-cycled: c = 2");
  unit::near(splitCouplingFactor(0.8, 1.0, false), 2.0 / (2.0 - 1.6), 1e-15, 0, "one sub-step past h lambda_b = 1: c = 2/(1 + g), g = 1 - h lambda_b < 0");

  // The bound on the scalar model: bounded at 0.98 of it over stiffness shares and diffusion
  // amplifications, growing at 1.02 of it where the coupling carries the stiffness.
  double worst_inside = 0, weakest_outside = HUGE_VAL;
  for (double g = -0.9; g <= 1.0 + 1e-12; g += 0.1)
    for (double share = 0; share <= 1.0 + 1e-12; share += 0.125) {
      const double c = 2 / (1 + g), total = 4 / (share + (1 - share) * c); // a + c b = 4
      const double a = share * total, b = (1 - share) * total;
      worst_inside = std::max(worst_inside, largest(0.98 * a, 0.98 * b, g, 20000));
      if (share == 0) weakest_outside = std::min(weakest_outside, largest(0, 1.02 * b, g, 20000));
    }
  unit::check(worst_inside < 1e3, "scalar model bounded at 0.98 of h^2 (k + c B^2)/m = 4 (largest " + std::to_string(worst_inside) + ")");
  unit::check(weakest_outside > 1e6, "scalar model grows at 1.02 of it when the coupling carries the stiffness (smallest " + std::to_string(weakest_outside) + ")");
  return unit::failures();
}
