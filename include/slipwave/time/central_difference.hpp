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

// Evaluates a_0 from the current u, v and time; TSSolve calls it on the first step when
// needed. Call it again after changing u or v by hand (restart).
PetscErrorCode CentralDifferenceComputeInitialAcceleration(TS ts);

// Sets a_n from a saved state (restart), so the next step continues exactly.
PetscErrorCode CentralDifferenceSetAcceleration(TS ts, Vec a);

} // namespace slipwave::time
