// The vertices of every cell of a mesh in DMPlex's closure order, found once per DM and kept
// on it (a composed object), for the set-up passes that read every cell's vertices (the bulk
// operator's cell tables): a transitive closure per cell is a large part of a small run's
// set-up. A mesh builder that made the cells knows them and hands the table over
// (meshing/box_lattice.hpp); any other mesh gets it from the closures.
#pragma once
#include <petscdmplex.h>

#include <vector>

namespace slipwave::mesh {

struct CellVertices {
  PetscInt              per_cell = 0; // vertices of one cell (one cell type per mesh)
  std::vector<PetscInt> vertex;       // cell c (height-0 point c_start + c): vertex[c per_cell ...], closure order
  const PetscInt       *of(PetscInt c) const { return &vertex[(size_t)c * per_cell]; }
};

// The table of dm's cells. Not collective. Errors if the cells have different vertex counts.
PetscErrorCode CellVerticesOf(DM dm, const CellVertices **table);

// Keeps `table` on dm for CellVerticesOf: the one the closures give.
PetscErrorCode CellVerticesAttach(DM dm, CellVertices &&table);

} // namespace slipwave::mesh
