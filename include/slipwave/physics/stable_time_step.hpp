// Critical time step of the explicit central-difference scheme.
#pragma once

namespace slipwave::physics {

// Largest stable step for the highest angular frequency omega_max [rad/s] when the
// stiffness-proportional damping beta K is evaluated with the lagged half-step velocity:
//   dt = (2/omega) (sqrt(1 + xi^2) - xi),  xi = beta omega / 2.
// Without damping this is the classic 2/omega. See the derivation in the source.
double centralDifferenceStableStep(double omega_max, double beta_stiffness_damping);

// The same bound for one Gershgorin row of a damping that is not proportional to K (contact
// dashpots, possibly with beta K): stiffness row sum over mass omega2 = sum_j |K_ij| / m_i
// [1/s^2] and damping row sum over mass rate = sum_j |C_ij| / m_i [1/s]. The lagged scheme
// is stable when M - (h/2) C - (h^2/4) K is positive definite (it is the centred scheme for
// the mass M - (h/2) C); Gershgorin makes that (h/2) rate + (h^2/4) omega2 <= 1 per row:
//   dt = 2 / (sqrt(omega2 + rate^2/4) + rate/2),
// which is the bound above when rate = beta omega2 (a single mode).
double centralDifferenceStableStepOfRow(double omega2, double rate);

} // namespace slipwave::physics
