// Node-based layouts on the mesh: a section with k dofs on every vertex. The displacement
// layout (k = dim) is the DM's own; other layouts (damping blocks, k = dim*dim) live on a
// clone so their global vectors list the owned vertices in the same order as the
// displacement's: node i of one is node i of the other.
#pragma once
#include <petscdmplex.h>

namespace slipwave::fem {

PetscErrorCode NodeFieldSetSection(DM dm, PetscInt dofs_per_vertex);
PetscErrorCode NodeFieldCreateDM(DM dm, PetscInt dofs_per_vertex, DM *node_dm);

} // namespace slipwave::fem
