// The divergence guard, run after every step: stops the run when the energy grows beyond a
// multiple of the energy put in, or when it is not finite, and then says in one line where the
// first non-finite value is (field, node with its coordinates, component), which input caused
// it if one did (a material, gravity or tractions, the incident wave), and the stable step.
#pragma once
#include <petscvec.h>

#include "slipwave/problem/elastodynamics.hpp"
#include "slipwave/problem/energy_ledger.hpp"
#include "slipwave/problem/integrator_step.hpp"

namespace slipwave::app {

// ledger: updated for this step (its global sums cover every dof of u, v and the force parts);
// growth_limit: -energy_growth_limit; limit: the order's stable step, named in the messages; h: this
// step's size; u, v, a: the state after the step.
PetscErrorCode DivergenceGuard(const problem::Elastodynamics &model, const problem::EnergyLedger &ledger, PetscReal growth_limit, const problem::IntegratorStep &limit, PetscReal h,
                               PetscInt step, PetscReal t, Vec u, Vec v, Vec a);

} // namespace slipwave::app
