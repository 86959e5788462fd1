// Normal viscous damping of a closed interface pair (contact damping), as explicit contact
// codes use it: a dashpot across the pair, sized as a fraction zeta of the critical damping
// of the two-mass oscillator that the pair's normal penalty spring forms with its two lumped
// nodal masses. It takes out the pair's own rattling at each impact (the highest mode of the
// mesh, far above what the cells resolve) and leaves slow motion almost untouched, because a
// dashpot's force grows with frequency.
#pragma once

namespace slipwave::physics {

// Critical damping fraction zeta [-] of the two-mass spring k [N/m] between masses m1, m2
// [kg] -> dashpot coefficient c [N s/m]:
//   c = 2 zeta sqrt(k m_eff),  m_eff = m1 m2 / (m1 + m2),
// so the relative motion w'' + (c/m_eff) w' + (k/m_eff) w = 0 has damping ratio zeta.
double contactDashpotCoefficient(double zeta, double k, double m1, double m2);

// Normal damping traction [Pa] (tension positive, like sigma_N) of a closed pair with
// dashpot c_per_area [Pa s/m] = c / A, normal jump rate w_dot [m/s] (opening positive) and
// spring traction sigma_N [Pa]. The dashpot resists closing without limit; while the pair
// opens it pulls at most until the total normal traction is zero (or stays at sigma_N if the
// spring is already in tension), so damping never glues the pair and never delays a lift-off
// that the spring alone allows. The result always opposes w_dot (it dissipates).
double contactDampingTraction(double c_per_area, double w_dot, double sigma_N);

} // namespace slipwave::physics
