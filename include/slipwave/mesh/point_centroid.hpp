// The vertex average of a mesh point (cell or face): where a cell lies (region boxes), which
// side of a face its cell is on (outward normals), where a face lies (box sides).
#pragma once
#include <petscdmplex.h>

namespace slipwave::mesh {

// x receives the coordinate dimension's worth of components.
PetscErrorCode MeshPointCentroid(DM dm, PetscInt point, PetscReal *x);

} // namespace slipwave::mesh
