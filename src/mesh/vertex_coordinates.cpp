#include "slipwave/mesh/vertex_coordinates.hpp"

namespace slipwave::mesh {

PetscErrorCode VertexCoordinates::Open(DM dm) {
  DM cdm;
  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinateDim(dm, &dim_));
  PetscCall(DMGetCoordinatesLocal(dm, &coords_));
  PetscCall(DMGetCoordinateDM(dm, &cdm));
  PetscCall(DMGetLocalSection(cdm, &section_));
  PetscCall(VecGetArrayRead(coords_, &array_));
  PetscFunctionReturn(0);
}

PetscErrorCode VertexCoordinates::Get(PetscInt v, double *x) const {
  PetscInt off;
  PetscFunctionBeginUser;
  PetscCall(PetscSectionGetOffset(section_, v, &off));
  for (PetscInt d = 0; d < dim_; ++d) x[d] = PetscRealPart(array_[off + d]);
  PetscFunctionReturn(0);
}

PetscErrorCode VertexCoordinates::Close() {
  PetscFunctionBeginUser;
  PetscCall(VecRestoreArrayRead(coords_, &array_));
  PetscFunctionReturn(0);
}

} // namespace slipwave::mesh
