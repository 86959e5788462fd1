// Point forces (3D) or line loads per unit thickness (2D plane strain) at given points:
//   -point_forces a,b                    names of the forces
//   -point_force_<n>_location x,y[,z]    [m], inside the mesh's bounding box
//   -point_force_<n>_force fx,fy[,fz]    [N in 3D, N/m in 2D]
//   -point_force_<n>_stf ...             its factor history (TimeFunction, HistoryRole::Load;
//                                        none: a constant load)
// The force acts on the mesh node nearest to the location (lumped: the exact load when the
// point is a node, as it is on a mesh built for it). Ties are broken by the node's
// coordinates (smallest x, then y, then z), and the node is picked among owned nodes over
// all ranks, so the choice does not depend on the partition.
#pragma once
#include <petscdmplex.h>

#include "slipwave/input/boundary_conditions.hpp"

namespace slipwave::input {

PetscErrorCode PointForcesCreate(DM dm, BoundaryConditions *bc);

} // namespace slipwave::input
