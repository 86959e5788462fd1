#include "slipwave/io/base_displacement.hpp"

#include <algorithm>

namespace slipwave::io {

PetscErrorCode BaseDisplacement::Setup(DM dm, const fem::BulkOperator &bulk) {
  const PetscInt dim = bulk.dimension();
  Vec            x_local;
  PetscScalar   *x, *w;
  PetscReal      low, high;
  PetscInt       n, count_local = 0, count;
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(dm, &weight_));
  PetscCall(VecSetBlockSize(weight_, dim));
  PetscCall(VecDuplicate(weight_, &scratch_));
  PetscCall(DMGetLocalVector(dm, &x_local));
  PetscCall(VecGetArray(x_local, &x));
  bulk.nodeCoordinates(x);
  PetscCall(VecRestoreArray(x_local, &x));
  PetscCall(DMLocalToGlobal(dm, x_local, INSERT_VALUES, scratch_));
  PetscCall(DMRestoreLocalVector(dm, &x_local));
  PetscCall(VecStrideMin(scratch_, dim - 1, nullptr, &low));
  PetscCall(VecStrideMax(scratch_, dim - 1, nullptr, &high));
  // Within round-off of the model's height: a flat base is found whole.
  const PetscReal tol = 1e-9 * std::max(high - low, (PetscReal)1);
  PetscCall(VecGetLocalSize(weight_, &n));
  PetscCall(VecGetArray(scratch_, &x));
  PetscCall(VecGetArray(weight_, &w));
  for (PetscInt i = 0; i < n; i += dim) {
    const bool base = PetscRealPart(x[i + dim - 1]) <= low + tol;
    for (PetscInt k = 0; k < dim; ++k) w[i + k] = base ? 1.0 : 0.0;
    count_local += base;
  }
  PetscCallMPI(MPI_Allreduce(&count_local, &count, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  for (PetscInt i = 0; i < n; ++i) w[i] /= (PetscReal)count;
  PetscCall(VecRestoreArray(weight_, &w));
  PetscCall(VecRestoreArray(scratch_, &x));
  PetscFunctionReturn(0);
}

PetscErrorCode BaseDisplacement::Mean(Vec u, PetscScalar base[3]) const {
  PetscInt dim;
  PetscFunctionBeginUser;
  PetscCall(VecGetBlockSize(weight_, &dim));
  PetscCall(VecPointwiseMult(scratch_, weight_, u));
  for (PetscInt k = 0; k < 3; ++k) base[k] = 0;
  for (PetscInt k = 0; k < dim; ++k) PetscCall(VecStrideSum(scratch_, k, &base[k]));
  PetscFunctionReturn(0);
}

PetscErrorCode BaseDisplacement::Destroy() {
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&weight_));
  PetscCall(VecDestroy(&scratch_));
  PetscFunctionReturn(0);
}

} // namespace slipwave::io
