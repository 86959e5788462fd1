// Stability of the pore pressure's split step (porous/pore_pressure.hpp) at element degree
// p > 1. Each step of size h first diffuses the pressure by m forward-Euler sub-steps,
// E = (I - (h/m) S^-1 H)^m, then adds the undrained response to the step's strain,
// p_{n+1} = E p_n - S^-1 alpha Q (u_{n+1} - u_n), while the skeleton steps by central
// differences under -K u + alpha Q^T p. With V = S^{1/2} p, B = S^{-1/2} alpha Q and the
// eigenvalues of E in [g, 1], g > -1, the quantity
//   G_{n+1/2} = W_{n+1/2} + V_n . V_{n+1} / 2 + V_n . (I - E) V_n / 4
// (W the central difference's shadow energy) never grows, and it is a norm of the state when
//   h^2 lambda_max(M^-1 (K + c B^T B)) < 4,   c = 2 / (1 + g)
// (docs/saturated-soil.md, "Stable step"): the undrained stiffening B^T B = alpha^2 Q^T S^-1 Q
// counts c times. Without diffusion E = I, c = 1: the undrained wave limit. A diffusion step
// that overshoots (g < 0, the forward Euler of a stiff mode past its half-way point) needs
// c > 2, and at g -> -1 no step is stable: the scalar model of one displacement mode and one
// pressure mode (tests/unit/test_split_diffusion_step.cpp) is unstable just above this bound.
// So the sub-steps are chosen to keep g >= 0 (c <= 2). lambda_b = 2 / dt_diffusion is the
// bound on the eigenvalues of S^-1 H that the explicit diffusion limit dt_diffusion comes from.
// Plain doubles, no PETSc.
#pragma once

namespace slipwave::physics {

// Sub-steps m for a step h: 1 when h lambda_b <= 1 (every factor 1 - h lambda in [0, 1]) or
// without sub-cycling (the caller keeps h within dt_diffusion); else the smallest even m with
// (h/m) lambda_b <= 1.8 (0.9 of forward Euler's limit, as at degree 1): factors in [-0.8, 1]
// raised to an even power lie in [0, 1].
int splitDiffusionSubsteps(double h, double dt_diffusion, bool subcycle);

// c = 2 / (1 + g) of that choice: g = 1 - h lambda_b with one sub-step (c = 1 without
// diffusion), g = 0 with an even count (c = 2). Non-decreasing in h; infinite past
// dt_diffusion with one sub-step (the diffusion itself is unstable there).
double splitCouplingFactor(double h, double dt_diffusion, bool subcycle);

// The sub-step rule of a u-p mesh of element degree p: splitDiffusionSubsteps at p > 1,
// physics::diffusionSubsteps (biot.hpp) at p = 1. The main mesh and the free-field columns
// share it, so they split a step alike.
int diffusionSubstepsOfDegree(int degree, double h, double dt_diffusion, bool subcycle);

} // namespace slipwave::physics
