#include "slipwave/app/divergence_guard.hpp"

#include <cmath>

#include "slipwave/core/log_events.hpp"

namespace slipwave::app {

PetscErrorCode DivergenceGuard(MPI_Comm comm, PetscInt dim, const model::EnergyLedger &e, PetscReal growth_limit, const model::StableStep &limit, PetscReal h,
                               PetscInt step, PetscReal t, Vec u, Vec v) {
  PetscFunctionBeginUser;
  // The ledger's global sums run over every dof of u and v: a NaN or Inf anywhere makes
  // them non-finite, so no extra pass is needed to detect it, only to locate it.
  if (std::isfinite(e.kinetic) && std::isfinite(e.strain) && std::isfinite(e.shadow)) {
    // Net work the interfaces did on the bulk is energy put in too: an interface started under
    // a normal traction (-interface_<name>_sigma_N0) stores energy and releases it at once.
    // External loads count with their gross work: a Ricker force takes back much of what it
    // put in, and its net work passes near zero while the model still moves.
    const double put_in = std::fabs(e.shadow_start) + std::fabs(e.input) + e.external_gross + std::fabs(e.reactions) + std::fmax(e.interface_work, 0.0);
    const double energy = e.kinetic + std::fabs(e.strain);
    PetscCheck(!(put_in > 0 && energy > growth_limit * put_in), comm, PETSC_ERR_NOT_CONVERGED,
               "diverged at step %" PetscInt_FMT ", t = %g s: kinetic + strain energy %g J exceeds %g x the energy put in (%g J); the time step %g s may be above the stable limit %g s",
               step, (double)t, energy, (double)growth_limit, put_in, (double)h, limit.dt_limit);
    PetscFunctionReturn(0);
  }
  PetscCall(PetscLogEventBegin(core::event_guard, 0, 0, 0, 0));
  // Locate: the lowest global dof that is not finite, in u first, then v.
  const char *names[2] = {"displacement", "velocity"};
  Vec         vecs[2]  = {u, v};
  for (int f = 0; f < 2; ++f) {
    PetscInt           n, lo, bad = PETSC_MAX_INT;
    const PetscScalar *x;
    PetscCall(VecGetOwnershipRange(vecs[f], &lo, nullptr));
    PetscCall(VecGetLocalSize(vecs[f], &n));
    PetscCall(VecGetArrayRead(vecs[f], &x));
    for (PetscInt i = 0; i < n && bad == PETSC_MAX_INT; ++i)
      if (!std::isfinite(PetscRealPart(x[i]))) bad = lo + i;
    PetscCall(VecRestoreArrayRead(vecs[f], &x));
    PetscInt first;
    PetscCallMPI(MPI_Allreduce(&bad, &first, 1, MPIU_INT, MPI_MIN, comm));
    if (first == PETSC_MAX_INT) continue;
    SETERRQ(comm, PETSC_ERR_NOT_CONVERGED,
            "diverged at step %" PetscInt_FMT ", t = %g s: %s is not finite at node %" PetscInt_FMT " (global numbering of the output), component %c; stable step limit %g s (%s)",
            step, (double)t, names[f], first / dim, "xyz"[first % dim], limit.dt_limit, limit.governing.c_str());
  }
  PetscCall(PetscLogEventEnd(core::event_guard, 0, 0, 0, 0));
  SETERRQ(comm, PETSC_ERR_NOT_CONVERGED, "diverged at step %" PetscInt_FMT ", t = %g s: the energy is not finite but u and v are; the forces are", step, (double)t);
}

} // namespace slipwave::app
