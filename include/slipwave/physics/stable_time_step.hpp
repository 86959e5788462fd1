// Critical time step of the explicit central-difference scheme.
#pragma once

namespace slipwave::physics {

// Largest stable step for the highest angular frequency omega_max [rad/s] when the
// stiffness-proportional damping beta K is evaluated with the lagged half-step velocity:
//   dt = (2/omega) (sqrt(1 + xi^2) - xi),  xi = beta omega / 2.
// Without damping this is the classic 2/omega. See the derivation in the source.
double centralDifferenceStableStep(double omega_max, double beta_stiffness_damping);

} // namespace slipwave::physics
