// Read access to the coordinates of a DMPlex's vertices, for loops over vertices: the local
// coordinate vector is read through the coordinate DM's section (one offset per vertex).
// Open before the loop, Close after it; the vector's array is held in between.
#pragma once
#include <petscdmplex.h>

namespace slipwave::mesh {

class VertexCoordinates {
public:
  PetscErrorCode Open(DM dm);
  // x receives dimension() components of vertex v (a depth-0 point of the DM, ghosts included).
  PetscErrorCode Get(PetscInt v, double *x) const;
  PetscErrorCode Close();
  PetscInt       dimension() const { return dim_; }  // the coordinate dimension

private:
  Vec                coords_  = nullptr;
  PetscSection       section_ = nullptr;
  const PetscScalar *array_   = nullptr;
  PetscInt           dim_     = 0;
};

} // namespace slipwave::mesh
