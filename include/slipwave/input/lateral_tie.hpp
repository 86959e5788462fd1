// Tied lateral boundaries (-bc_left_type tied -bc_left_tie_with right): each node of one
// side moves with the node facing it on the opposite side (same coordinates along the side),
// as in a periodic column. In the explicit scheme this is exact and costs nothing to solve:
// both nodes get the mass-weighted mean of their accelerations, (m_i a_i + m_j a_j)/(m_i + m_j),
// so if they start together they stay together, and the tie forces, equal and opposite on
// nodes with equal velocities, do no work. The pairs may live on different ranks: a
// VecScatter brings both nodes of each pair to the rank that owns the first.
#pragma once
#include <petscdmplex.h>

#include <vector>

#include "slipwave/input/boundary_conditions.hpp"

namespace slipwave::input {

struct LateralTie {
  VecScatter          scatter = nullptr;
  Vec                 pair_values = nullptr; // 2*dim per pair: node i then node j
  std::vector<double> mass;                  // 2 per pair
  PetscInt            dim = 0, npairs = 0, npairs_global = 0;
};

PetscErrorCode LateralTieCreate(DM dm, const BoundaryConditions &bc, Vec mass, LateralTie **tie);
// Replaces the accelerations of tied nodes by their pair's mass-weighted mean.
PetscErrorCode LateralTieApply(LateralTie *tie, Vec accel);
PetscErrorCode LateralTieDestroy(LateralTie **tie);

} // namespace slipwave::input
