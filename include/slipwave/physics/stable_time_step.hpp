// Critical time step of the explicit central-difference scheme and of its fourth-order
// modified-equation variant (time/central_difference.hpp, -ts_cd_order 4).
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

// The smallest lumped mass m [kg] with which one row, stiffness row sum K [N/m] and damping
// row sum C [N s/m], is stable at the step dt [s]: the row condition above,
// (dt/2) C/m + (dt^2/4) K/m <= 1, solved for m: m = dt^2 K/4 + dt C/2. For a spring alone it
// is the mass Newmark's average acceleration (beta = 1/4) adds to the node when the spring
// is taken implicitly: m + dt^2 k/4 (problem/interface_mass_scaling.hpp).
double massForStableStep(double stiffness_row, double damping_row, double dt);

// The fourth-order scheme u_{n+1} - 2 u_n + u_{n-1} = h^2 (1 - h^2 w^2 / 12) a*_n on the
// mode of omega_max with the lagged damping beta K: central differences for the mode
// w~^2 = w^2 (1 - W^2/12), 2 xi~ w~ = 2 xi w (1 - W^2/12) (W = w h, xi = beta w / 2), so the
// Jury condition above becomes (1 - W^2/12)(W^2/4 + xi W) <= 1 with W < sqrt(12)
// (1 - W^2/12 > 0). Without damping every W < sqrt(12) passes: dt = sqrt(12)/omega,
// sqrt(3) times central differences' 2/omega. With it, dt is the smallest W where the
// condition fails, over omega; never below centralDifferenceStableStep.
double fourthOrderStableStep(double omega_max, double beta_stiffness_damping);

} // namespace slipwave::physics
