// The mesh check run once after the bulk operator is set up, before the mass and the
// stiffness are assembled: an inverted or degenerate cell stops the run, and a distorted
// one too unless -mesh_quality_check warn (or off) is given. The message names the first
// such cell (global cell number, 0-based in the order of the mesh file's cells on one rank)
// and its node coordinates.
// Options: -mesh_quality_check error|warn|off (default error; what a distorted cell does),
//          -mesh_quality_max_aspect (default 50), -mesh_quality_min_jacobian_ratio (default 0.1).
#pragma once
#include <petscdmplex.h>

#include "slipwave/fem/bulk_operator.hpp"

namespace slipwave::fem {

PetscErrorCode CellQualityCheck(DM dm, const BulkOperator &bulk);

} // namespace slipwave::fem
