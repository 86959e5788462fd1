#include "slipwave/mesh/cell_vertices.hpp"

#include "slipwave/mesh/dm_table.hpp"

#include <utility>

namespace slipwave::mesh {
namespace {

constexpr char kTableKey[] = "slipwave_cell_vertices";

} // namespace

PetscErrorCode CellVerticesAttach(DM dm, CellVertices &&table) {
  PetscFunctionBeginUser;
  PetscCall(DMTableAttach(dm, kTableKey, std::move(table)));
  PetscFunctionReturn(0);
}

PetscErrorCode CellVerticesOf(DM dm, const CellVertices **table) {
  PetscFunctionBeginUser;
  PetscCall(DMTableFind(dm, kTableKey, table));
  if (!*table) {
    CellVertices found;
    PetscInt     c_start, c_end, v_start, v_end;
    PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, &c_end));
    PetscCall(DMPlexGetDepthStratum(dm, 0, &v_start, &v_end));
    for (PetscInt c = c_start; c < c_end; ++c) {
      PetscInt *closure = nullptr, nclosure, n = 0;
      PetscCall(DMPlexGetTransitiveClosure(dm, c, PETSC_TRUE, &nclosure, &closure));
      for (PetscInt i = 0; i < nclosure; ++i)
        if (closure[2 * i] >= v_start && closure[2 * i] < v_end) found.vertex.push_back(closure[2 * i]), ++n;
      PetscCall(DMPlexRestoreTransitiveClosure(dm, c, PETSC_TRUE, &nclosure, &closure));
      if (c == c_start) found.per_cell = n;
      PetscCheck(n == found.per_cell, PETSC_COMM_SELF, PETSC_ERR_SUP, "CellVerticesOf: cell %" PetscInt_FMT " has %" PetscInt_FMT " vertices, cell %" PetscInt_FMT " %" PetscInt_FMT "; one cell type per mesh", c, n, c_start,
                 found.per_cell);
    }
    PetscCall(CellVerticesAttach(dm, std::move(found)));
    PetscCall(DMTableFind(dm, kTableKey, table));
  }
  PetscFunctionReturn(0);
}

} // namespace slipwave::mesh
