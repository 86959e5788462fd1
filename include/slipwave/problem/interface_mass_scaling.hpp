// Mass scaling of the nodes of interface pairs (-time_step_mass_scaling interface): each such
// node takes the smallest lumped mass with which its Gershgorin row, the bulk's plus its
// penalty springs' and contact dashpots', is stable at the bulk's own step
// (physics::massForStableStep), so the penalty no longer lowers the step. For a spring alone
// the added mass is at most dt^2 k / 4, the mass Newmark's average acceleration (beta = 1/4)
// adds when the spring is taken implicitly: a consistent change of the scheme whose effect
// falls as dt^2, and whose total over an interface of cells h falls as h^2 (k ~ h per node,
// dt^2 ~ h^2, nodes ~ 1/h). The energy ledger takes the scaled mass as the mass, so it still
// closes; the weight (gravity) stays the physical mass's. Not scaled: nodes of rigid bodies
// (they move as wholes on their own bound), nodes with absorbing dashpots (their dashpot
// blocks were built with the physical mass) and held components.
#pragma once
#include <petscvec.h>

#include <string>

#include "slipwave/problem/elastodynamics.hpp"

namespace slipwave::problem {

struct MassScalingResult {
  double      added = 0;          // mass added, all ranks [kg; kg per metre of thickness in 2D]
  double      model_mass = 0;     // the model's physical mass, for comparison [kg]
  double      lightest_side = 0;  // the mass of the lightest region an interface separates [kg]: what the added inertia is measured against
  std::string lightest_region;    // its name
  double   largest_factor = 1; // largest (scaled / physical) nodal mass
  PetscInt nodes = 0;        // nodes that took mass
};

// bulk_rows: the bulk's Gershgorin rows (with the undrained rows of saturated regions), laid
// out like u; dt_target: the bulk's own limit from them. Adds the mass each interface node
// still needs to the model (ElastodynamicsAddMass); *nodes: how many took some (all ranks).
PetscErrorCode InterfaceMassScale(Elastodynamics *model, Vec bulk_rows, double dt_target, PetscInt *nodes);
// What the model's mass holds beyond physical_mass (a copy taken before the scaling).
PetscErrorCode MassScalingSummarize(const Elastodynamics *model, Vec physical_mass, MassScalingResult *result);

} // namespace slipwave::problem
