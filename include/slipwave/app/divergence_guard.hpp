// The divergence guard, run after every step: stops the run when the energy grows beyond a
// multiple of the energy put in, or when it is not finite, and then says where the first
// non-finite value is (node, component) and what limits the stable step.
#pragma once
#include <petscvec.h>

#include "slipwave/model/elastodynamics.hpp"
#include "slipwave/model/stable_step.hpp"
#include "slipwave/model/energy_ledger.hpp"

namespace slipwave::app {

// ledger: updated for this step (its global sums cover every dof of u and v); growth_limit:
// -energy_growth_limit; limit: the stable step, named in the messages; h: this step's size.
PetscErrorCode DivergenceGuard(MPI_Comm comm, PetscInt dim, const model::EnergyLedger &ledger, PetscReal growth_limit, const model::StableStep &limit, PetscReal h,
                               PetscInt step, PetscReal t, Vec u, Vec v);

} // namespace slipwave::app
