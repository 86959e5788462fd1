// The normal traction an interface's friction sees, lagged behind the actual effective
// normal traction by a slip distance and a time: the Prakash-Clifton regularisation.
//
// Why: Coulomb friction whose strength follows the normal traction at once is ill-posed when
// slip changes that traction: between dissimilar bodies (Adams 1995, J. Appl. Mech. 62, 867;
// Martins, Guimaraes & Faria 1995, J. Vib. Acoust. 117, 445, for an elastic body against a
// rigid one) and, worse, on undrained soil, where slip changes the volumetric strain at the
// contact, hence the pore pressure, hence the effective normal traction (Rudnicki & Rice 2006,
// JGR 111, B10308). Perturbations then grow the faster the shorter their wavelength, so the
// slip depends on the mesh (measured on a rigid block pushed over undrained soil:
// docs/saturated-soil.md). Prakash & Clifton (1993) measured that the shear strength of a
// sliding contact follows a step of normal stress over a slip distance, not at once; Cochard
// & Rice (2000, JGR 105, 25891) and Ranjith & Rice (2001, JMPS 49, 341) showed that this lag
// makes the problem well-posed; Dunham & Rice (2008, JGR 113, B09304) used it for slip that
// changes the pore pressure:
//
//   d sigma*/dt = -(|V| + V*) / L (sigma* - sigma'),   sigma' = sigma_N + p,
//
// V the slip rate, L the slip over which the friction takes up a change of sigma', V* a
// reference velocity, so that a sticking pair follows sigma' over the time L / V*. The
// strength is then c - sigma* tan(phi). Over one step with the slip increment ds = |dw_T|
// and sigma' held at its end value (implicit: no step size overshoots):
//
//   sigma*(n+1) = sigma' + (sigma*(n) - sigma') exp(-(ds + V* dt) / L).
#pragma once

#include <cmath>

namespace slipwave::physics {

struct FrictionLag {
  double slip_length        = 0.0; // L [m]; 0: no lag (the friction sees sigma' at once)
  double reference_velocity = 0.0; // V* [m/s], >= 0
};

inline bool frictionLagged(const FrictionLag &lag) { return lag.slip_length > 0.0; }

// sigma* at the step's end from its value at the start (sigma_star), the effective normal
// traction at the end (target), the slip over the step (>= 0) and the step dt (>= 0).
inline double laggedNormalTraction(const FrictionLag &lag, double sigma_star, double target, double slip, double dt) {
  if (!frictionLagged(lag)) return target;
  return target + (sigma_star - target) * std::exp(-(slip + lag.reference_velocity * dt) / lag.slip_length);
}

} // namespace slipwave::physics
