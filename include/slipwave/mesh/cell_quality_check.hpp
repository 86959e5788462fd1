// The mesh check run once after the bulk operator is set up, before the mass and the
// stiffness are assembled: an inverted or degenerate cell stops the run, and a distorted
// one too unless -mesh_quality_check warn (or off) is given. The message names the first
// such cell (0-based number in the serial mesh: the order of the file's cells, or the box's;
// the same on any number of ranks) and its node coordinates.
// Options: -mesh_quality_check error|warn|off (default error; what a distorted cell does),
//          -mesh_quality_max_aspect (default 50), -mesh_quality_min_jacobian_ratio (default 0.1).
#pragma once
#include <petscdmplex.h>

#include <functional>
#include <vector>

#include "slipwave/numerics/reference_cell.hpp"

namespace slipwave::mesh {

// A cell's nodes in element-kernel order (nodes x dim, row-major).
using CellCoordinates = std::function<const double *(PetscInt cell)>;

// The ncell cells of one shape on this rank (the bulk operator's cells at degree 1);
// serial_cell (MeshDescription::serial_cell) numbers them in the message. Collective.
PetscErrorCode CellQualityCheck(DM dm, numerics::CellShape shape, PetscInt ncell, const CellCoordinates &cell_coords, const std::vector<PetscInt> &serial_cell);

// The same for the quadrilaterals or hexahedra of a serial mesh (all cells on rank 0; the
// message numbers them from 0): spectral elements are judged by their corners before they
// are subdivided into GLL sub-cells (mesh_builder.cpp), whose aspect ratios come from the
// GLL spacing by design. Collective.
PetscErrorCode CellQualityCheckSerialMesh(DM dm);

} // namespace slipwave::mesh
