// The faces of a named boundary label on this rank, with what boundary terms need: vertex
// points, lumped nodal weights (∫ N_a dA), the outward unit normal and the region of the
// cell behind the face. Only faces with one supporting cell (true boundary faces) count;
// with no overlap each such face lives on exactly one rank, so nothing is counted twice.
#pragma once
#include <petscdmplex.h>

#include "slipwave/numerics/reference_cell.hpp"

#include <string>
#include <vector>

namespace slipwave::input {

struct BoundaryFace {
  PetscInt nvert = 0;
  PetscInt vertices[numerics::kMaxFaceNodes];
  double   weights[numerics::kMaxFaceNodes];
  double   normal[3] = {0, 0, 0};
  PetscInt region = -1;
};

// Faces of label `name` (any label value). Errors (user input) if the label does not exist.
PetscErrorCode BoundaryFacesGet(DM dm, const std::string &name, std::vector<BoundaryFace> *faces);

} // namespace slipwave::input
