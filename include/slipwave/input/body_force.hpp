// A uniform body force per unit mass b [m/s^2] on every cell, times a factor history:
//   -body_force bx,by[,bz]   [m/s^2] (force density rho b)
//   -body_force_stf ...      its factor (TimeFunction, HistoryRole::Load; none: constant)
// Nodal forces M b with the lumped mass M: the row sums of the consistent mass, which is
// exactly the consistent load of a uniform body force.
#pragma once
#include <petscdmplex.h>

#include "slipwave/input/boundary_conditions.hpp"

namespace slipwave::input {

PetscErrorCode BodyForceCreate(DM dm, Vec mass, BoundaryConditions *bc);

} // namespace slipwave::input
