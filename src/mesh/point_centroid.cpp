#include "slipwave/mesh/point_centroid.hpp"

namespace slipwave::mesh {

PetscErrorCode MeshPointCentroid(DM dm, PetscInt point, PetscReal *x) {
  PetscInt           dim, n;
  PetscBool          is_dg;
  const PetscScalar *array;
  PetscScalar       *coords = nullptr;
  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinateDim(dm, &dim));
  PetscCall(DMPlexGetCellCoordinates(dm, point, &is_dg, &n, &array, &coords));
  const PetscInt nv = n / dim;
  for (PetscInt d = 0; d < dim; ++d) {
    x[d] = 0;
    for (PetscInt v = 0; v < nv; ++v) x[d] += PetscRealPart(coords[v * dim + d]) / nv;
  }
  PetscCall(DMPlexRestoreCellCoordinates(dm, point, &is_dg, &n, &array, &coords));
  PetscFunctionReturn(0);
}

} // namespace slipwave::mesh
