#include "slipwave/mesh/point_centroid.hpp"

namespace slipwave::mesh {

PetscErrorCode MeshPointCentroid(DM dm, PetscInt point, PetscReal *x) {
  PetscInt     dim, nv = 0, *closure = nullptr, nclosure, c_start, c_end;
  PetscSection cell_section, section;
  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinateDim(dm, &dim));
  // Cellwise (periodic) coordinates: PETSc's own reading of them.
  PetscCall(DMGetCellCoordinateSection(dm, &cell_section));
  if (cell_section) {
    PetscInt           n;
    PetscBool          is_dg;
    const PetscScalar *array;
    PetscScalar       *coords = nullptr;
    PetscCall(DMPlexGetCellCoordinates(dm, point, &is_dg, &n, &array, &coords));
    nv = n / dim;
    for (PetscInt d = 0; d < dim; ++d) {
      x[d] = 0;
      for (PetscInt v = 0; v < nv; ++v) x[d] += PetscRealPart(coords[v * dim + d]) / nv;
    }
    PetscCall(DMPlexRestoreCellCoordinates(dm, point, &is_dg, &n, &array, &coords));
    PetscFunctionReturn(0);
  }
  // The vertices of its closure, summed in closure order as DMPlexGetCellCoordinates lists
  // them (the same sums), without gathering a closure vector (a third of the cost).
  Vec                coordinates;
  const PetscScalar *a;
  PetscCall(DMGetCoordinateSection(dm, &section));
  PetscCall(PetscSectionGetChart(section, &c_start, &c_end));
  PetscCall(DMGetCoordinatesLocalNoncollective(dm, &coordinates));
  PetscCall(VecGetArrayRead(coordinates, &a));
  PetscCall(DMPlexGetTransitiveClosure(dm, point, PETSC_TRUE, &nclosure, &closure));
  PetscInt at[27];
  for (PetscInt i = 0; i < nclosure; ++i) {
    const PetscInt p = closure[2 * i];
    PetscInt       dof = 0, off;
    if (p >= c_start && p < c_end) PetscCall(PetscSectionGetDof(section, p, &dof));
    if (!dof) continue;
    PetscCheck(nv < 27, PETSC_COMM_SELF, PETSC_ERR_SUP, "MeshPointCentroid: point %" PetscInt_FMT " has more than 27 vertices", point);
    PetscCall(PetscSectionGetOffset(section, p, &off));
    at[nv++] = off;
  }
  PetscCall(DMPlexRestoreTransitiveClosure(dm, point, PETSC_TRUE, &nclosure, &closure));
  for (PetscInt d = 0; d < dim; ++d) {
    x[d] = 0;
    for (PetscInt v = 0; v < nv; ++v) x[d] += PetscRealPart(a[at[v] + d]) / nv;
  }
  PetscCall(VecRestoreArrayRead(coordinates, &a));
  PetscFunctionReturn(0);
}

} // namespace slipwave::mesh
