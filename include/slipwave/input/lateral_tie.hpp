// Tied lateral boundaries (-bc_left_type tied -bc_left_tie_with right): each node of one
// side moves with the node facing it on the opposite side (same coordinates along the side),
// as in a periodic column. In the explicit scheme this is exact and costs nothing to solve:
// both nodes get the mass-weighted mean of their accelerations, (m_i a_i + m_j a_j)/(m_i + m_j),
// so if they start together they stay together, and the tie forces, equal and opposite on
// nodes with equal velocities, do no work. A node tied in two directions (3D: the vertical
// edges of a box tied left-right and front-back) joins the pairs it is in into one group, the
// four corner nodes at its height, which take their group's mass-weighted mean. The nodes of a
// group may live on different ranks: a VecScatter brings them to the rank that owns the
// first.
#pragma once
#include <petscdmplex.h>

#include <vector>

#include "slipwave/input/boundary_conditions.hpp"

namespace slipwave::input {

struct LateralTie {
  VecScatter            scatter = nullptr;
  Vec                   node_values = nullptr; // dim per node of this rank's groups, group after group
  std::vector<double>   mass;                  // per node
  std::vector<PetscInt> group_start;           // group g holds nodes group_start[g] .. group_start[g+1]-1
  PetscInt              dim = 0;
};

PetscErrorCode LateralTieCreate(DM dm, const BoundaryConditions &bc, Vec mass, LateralTie **tie);
// Replaces the accelerations of tied nodes by their group's mass-weighted mean.
PetscErrorCode LateralTieApply(LateralTie *tie, Vec accel);
PetscErrorCode LateralTieDestroy(LateralTie **tie);

} // namespace slipwave::input
