// Frequency-independent (constant-Q) viscoelasticity by a generalized Maxwell body: an elastic
// spring of the unrelaxed modulus M_U in parallel with N relaxation mechanisms, each a memory
// variable zeta_l driven towards Y_l M_U eps at relaxation angular frequency w_l:
//   sigma = M_U eps - sum_l zeta_l,   d zeta_l/dt = w_l (Y_l M_U eps - zeta_l).
// With exp(i w t) time dependence the complex modulus is
//   M(w)/M_U = 1 - sum_l Y_l w_l / (w_l + i w)
// (M_R = M_U (1 - sum Y_l) at w = 0, M_U at w -> infinity), and Q(w) = Re M / Im M.
// The fit (Emmerich & Korn 1987; Moczo & Kristek 2005, in the exact form): w_l log-spaced
// over the band [f_min, f_max] (both ends included), and Y_l from Q(w_k) = Q0 at 4N + 1
// log-spaced frequencies w_k of the band, which is linear in Y_l:
//   sum_l Y_l (w_l w_k + Q0^{-1} w_l^2) / (w_l^2 + w_k^2) = Q0^{-1},
// solved by least squares. Q0 = 1/(2 xi): the damping ratio xi of a complex modulus
// G(1 + 2 i xi) has Q^{-1} = 2 xi.
// A causal constant-Q material is dispersive (Kramers-Kronig): the phase speed grows with
// frequency, c(f)/c(f_r) ~ 1 + ln(f/f_r)/(pi Q) in the band, so material speeds are given at a
// reference frequency f_r and M_U follows from them.
#pragma once
#include <complex>
#include <vector>

namespace slipwave::physics {

struct ConstantQModel {
  double              damping_ratio = 0; // target xi [-]; Q0 = 1/(2 xi)
  std::vector<double> omega;             // relaxation angular frequencies w_l [rad/s]
  std::vector<double> weight;            // anelastic coefficients Y_l [-]
};

// The fit for 0 < xi < 0.5, 0 < f_min < f_max, 1 <= mechanisms <= 8 (checked by the caller).
ConstantQModel constantQFit(double damping_ratio, double f_min, double f_max, int mechanisms);

// M(w)/M_U at frequency f [Hz].
std::complex<double> constantQModulusRatio(const ConstantQModel &model, double f);
// Q(f) = Re M / Im M of the fitted body.
double constantQQuality(const ConstantQModel &model, double f);
// Phase speed at f over the unrelaxed speed sqrt(M_U/rho): 1 / Re[(M/M_U)^{-1/2}].
double constantQSpeedRatio(const ConstantQModel &model, double f);
// M_U / (rho c(f_r)^2): the factor on an elastic modulus rho c^2 whose speed c holds at f_r.
double constantQUnrelaxedFactor(const ConstantQModel &model, double f_reference);

// The lowest reference frequency f_r >= f_low at which the speeds may be given so that the
// unrelaxed moduli raise the highest natural frequency by at most 1/(1 - max_step_drop), i.e.
// the stable step drops by at most max_step_drop against an elastic model with the same speeds:
// 1/sqrt(constantQUnrelaxedFactor(f_r)) >= 1 - max_step_drop (the factor falls to 1 as f_r grows).
double constantQReferenceForStepDrop(const ConstantQModel &model, double f_low, double max_step_drop);

// Exact update of one memory variable over a step h, for a drive g(t) = Y M_U eps linear in t
// between g_0 (at the start) and g_1 (at the end):
//   zeta(h) = decay zeta(0) + end g_1 + start g_0,
//   decay = e^{-w h}, end = 1 - phi, start = phi - e^{-w h}, phi = (1 - e^{-w h})/(w h).
// |decay| < 1 for every h > 0, so the memory variables add no step limit; at h = 0 the update
// is the identity.
struct MemoryUpdate {
  double decay, end, start;
};
MemoryUpdate memoryUpdate(double omega, double h);

} // namespace slipwave::physics
