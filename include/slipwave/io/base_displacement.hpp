// The displacement of a site model's base: the mean over the nodes at the lowest vertical
// coordinate (where the input wave enters), taken off the displacement in the volume and
// interface output (field displacement_relative). Warped by the relative displacement, a view
// shows the deformation and the structure's rocking, not the whole model drifting with the
// input motion (centimetres to decimetres in a record).
#pragma once
#include <petscdm.h>

#include "slipwave/fem/bulk_operator.hpp"

namespace slipwave::io {

class BaseDisplacement {
public:
  // Marks the base nodes from their coordinates (the same nodes on any partition).
  PetscErrorCode Setup(DM dm, const fem::BulkOperator &bulk);
  // base[0..dim) = mean over the base nodes of each component of the global vector u.
  PetscErrorCode Mean(Vec u, PetscScalar base[3]) const;
  PetscErrorCode Destroy();

private:
  Vec weight_ = nullptr;  // 1 / (number of base nodes) on the base nodes' dofs, 0 elsewhere
  Vec scratch_ = nullptr; // weight_ * u
};

} // namespace slipwave::io
