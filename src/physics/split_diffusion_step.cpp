#include "slipwave/physics/split_diffusion_step.hpp"

#include <cmath>

#include "slipwave/physics/biot.hpp"

namespace slipwave::physics {

int splitDiffusionSubsteps(double h, double dt_diffusion, bool subcycle) {
  const double step_rate = 2.0 * h / dt_diffusion; // h lambda_b
  if (!subcycle || step_rate <= 1) return 1;
  return 2 * (int)std::ceil(step_rate / (2 * 1.8));
}

double splitCouplingFactor(double h, double dt_diffusion, bool subcycle) {
  const double step_rate = 2.0 * h / dt_diffusion;
  if (splitDiffusionSubsteps(h, dt_diffusion, subcycle) > 1) return 2.0;
  return step_rate < 2 ? 2.0 / (2.0 - step_rate) : HUGE_VAL;
}

int diffusionSubstepsOfDegree(int degree, double h, double dt_diffusion, bool subcycle) {
  return degree > 1 ? splitDiffusionSubsteps(h, dt_diffusion, subcycle) : diffusionSubsteps(h, dt_diffusion, subcycle);
}

} // namespace slipwave::physics
