// Explicit central difference for M u'' + C u' + f_int(u) = f_ext(t) with lumped M, as a TS
// type "cd" (select with -ts_type cd). Written in its velocity-Verlet (kick-drift-kick) form,
// algebraically the classic central difference, so that u, v and a are all known at the
// end of every step for monitors, output and the energy ledger:
//   v_{n+1/2} = v_n + h/2 a_n;  u_{n+1} = u_n + h v_{n+1/2}
//   a*_{n+1}  = RHS(t_{n+1}, u_{n+1})          (everything except the nodal damping)
//   (I + h/2 D) v_{n+1} = v_{n+1/2} + h/2 a*_{n+1};   a_{n+1} = a*_{n+1} - D v_{n+1}
// D = M^{-1} C is nodal (a dim x dim block per node: Lysmer dashpots, mass-proportional
// damping) and treated centred, so it does not lower the stable step. Terms that are not
// nodal (stiffness-proportional damping) go into the RHS with the half-step velocity,
// available there through CentralDifferenceGetHalfStepVelocity.
// The TS solution is u; the velocity rides along through TS2SetSolution/TS2GetSolution.
//
// Order 4 (-ts_cd_order 4; docs/spectral-elements.md, "The fourth-order integrator"): the
// modified-equation (Lax-Wendroff, Dablain 1986) scheme u_{n+1} - 2 u_n + u_{n-1} = h^2 a~_n
// in the same kick-drift-kick form, the RHS result corrected before the kicks,
//   a~* = a* + c,   c = -(h^2/12) M^{-1} K_lin a* + (h^2/12) M^{-1} f_ext''   (the model's hook),
// so the linear bulk is integrated to fourth order (stable to omega h < sqrt(12)) at two
// operator applications per step, and everything else (nodal damping, the RHS's other forces)
// enters as in central differences. Its kick-drift-kick velocity is second order,
// v_n = u'(t_n) + h^2/6 u''' + O(h^4): CentralDifferenceGetReportedState removes that term
// (u''' from the last three accelerations) and the correction from the acceleration, for
// output; the TS's own v and a (the energy ledger's) stay those the kicks used.
#pragma once
#include <petscts.h>

namespace slipwave::time {

inline constexpr char kTSCentralDifference[] = "cd";

// Registers the type with TSRegister; call once after PetscInitialize.
PetscErrorCode CentralDifferenceRegister();

// Nodal damping blocks: a Vec laid out like u, holding for node i the bs x bs row-major block
// (M^{-1} C)_i in entries [i*bs*bs, (i+1)*bs*bs) of a Vec of local size nlocal_nodes*bs*bs.
// The TS keeps a reference. Pass nullptr to remove.
PetscErrorCode CentralDifferenceSetNodalDamping(TS ts, PetscInt bs, Vec blocks);

// commit(ctx) runs after every step (and after the initial acceleration at t_0): the state the
// last RHS evaluation reached is accepted, so the model makes its trial state (history
// variables the RHS advanced from the committed ones) the committed state. The RHS itself
// stays a function of (t, u, v_{n+1/2}) and the committed state.
PetscErrorCode CentralDifferenceSetCommit(TS ts, PetscErrorCode (*commit)(void *ctx), void *ctx);

// The half-step velocity v_{n+1/2} used by the step in progress (for the RHS function).
PetscErrorCode CentralDifferenceGetHalfStepVelocity(TS ts, Vec *v_half);

// The acceleration a_n at the current time (valid after the first step or after
// CentralDifferenceComputeInitialAcceleration).
PetscErrorCode CentralDifferenceGetAcceleration(TS ts, Vec *a);

// The order of the scheme, 2 (central difference, the default) or 4. Set it before
// TSSetFromOptions: -ts_cd_order then overrides it. Order 4 needs the correction hook.
PetscErrorCode CentralDifferenceSetOrder(TS ts, PetscInt order);
// The order in use, and whether -ts_cd_order gave it (false: the default or SetOrder).
PetscErrorCode CentralDifferenceGetOrder(TS ts, PetscInt *order, PetscBool *from_options);

// Order 4: correction(ctx, t, h, a_star, c) writes the correction c of the acceleration a* =
// RHS(t, u) (the dofs a constraint ties or holds treated as the RHS treats them).
PetscErrorCode CentralDifferenceSetCorrection(TS ts, PetscErrorCode (*correction)(void *ctx, PetscReal t, PetscReal h, Vec a_star, Vec c), void *ctx);
// Order 4: the correction c added at the current time (zero at order 2), for the energy
// ledger, which books its work.
PetscErrorCode CentralDifferenceGetCorrection(TS ts, Vec *c);

// The velocity and acceleration at the current time to report (stations, fields, answers).
// Order 2: the TS's v and a. Order 4: v - (h^2/6) u''' with u''' the backward difference of
// the last three accelerations (two after the first step, none at the start, where v is the
// initial velocity), and a - c. Valid until the next step.
PetscErrorCode CentralDifferenceGetReportedState(TS ts, Vec *v, Vec *a);

// Order 4: the accelerations of the two steps before the current one, which the reported
// velocity needs (a restart saves and restores them; count: how many of them the run has
// taken, at most 2).
PetscErrorCode CentralDifferenceGetHistory(TS ts, Vec *previous, Vec *before_previous);
PetscErrorCode CentralDifferenceSetHistory(TS ts, Vec previous, Vec before_previous, PetscInt count);

// Evaluates a_0 from the current u, v and time; TSSolve calls it on the first step when
// needed. Call it again after changing u or v by hand (restart).
PetscErrorCode CentralDifferenceComputeInitialAcceleration(TS ts);

// Sets a_n from a saved state (restart), so the next step continues exactly.
PetscErrorCode CentralDifferenceSetAcceleration(TS ts, Vec a);

} // namespace slipwave::time
