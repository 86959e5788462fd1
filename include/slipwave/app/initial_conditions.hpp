// Initial conditions of a run that does not restart: a uniform initial velocity of every free
// node (-initial_velocity, read with the run options) and per-region velocities
// (-initial_velocity_<region>: every node of the region's cells, so that bodies separated by an
// interface can be launched against each other). Displacements start at zero.
#pragma once
#include <petscdm.h>

#include <vector>

#include "slipwave/fem/bulk_operator.hpp"
#include "slipwave/medium/materials.hpp"

namespace slipwave::app {

// One entry per region (in the order of the materials): its dim velocity components [m/s], or empty
// where -initial_velocity_<region> is not given.
using RegionVelocities = std::vector<std::vector<PetscReal>>;

// Read with the other options, before the run starts.
PetscErrorCode RegionVelocitiesRead(MPI_Comm comm, PetscInt dim, const std::vector<medium::RegionMaterialInfo> &materials, RegionVelocities *velocities);

// v = the uniform velocity on every free node, then each region's own velocity on the free
// nodes of its cells (free_mask: 1 on free dofs, 0 on held ones).
PetscErrorCode InitialVelocitySet(DM dm, const fem::BulkOperator &bulk, Vec free_mask, const PetscReal uniform[], const RegionVelocities &regions, Vec v);

} // namespace slipwave::app
