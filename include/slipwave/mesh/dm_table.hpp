// A C++ table kept on a DM (a composed PetscContainer that owns it) and found again by its key:
// what a pass over the mesh computes once per DM (the spectral layout, the cells' vertices).
#pragma once
#include <petscdm.h>

#include <utility>

namespace slipwave::mesh {

// Moves `table` onto dm under `key` (replacing any table there).
template <class T>
PetscErrorCode DMTableAttach(DM dm, const char *key, T &&table) {
  PetscContainer container;
  PetscFunctionBeginUser;
  PetscCall(PetscContainerCreate(PETSC_COMM_SELF, &container));
  PetscCall(PetscContainerSetPointer(container, new T(std::move(table))));
  PetscCall(PetscContainerSetUserDestroy(container, [](void *ctx) -> PetscErrorCode {
    delete static_cast<T *>(ctx);
    return 0;
  }));
  PetscCall(PetscObjectCompose((PetscObject)dm, key, (PetscObject)container));
  PetscCall(PetscContainerDestroy(&container));
  PetscFunctionReturn(0);
}

// The table under `key`, nullptr if dm has none.
template <class T>
PetscErrorCode DMTableFind(DM dm, const char *key, const T **table) {
  PetscContainer container = nullptr;
  void          *ctx       = nullptr;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectQuery((PetscObject)dm, key, (PetscObject *)&container));
  if (container) PetscCall(PetscContainerGetPointer(container, &ctx));
  *table = static_cast<const T *>(ctx);
  PetscFunctionReturn(0);
}

} // namespace slipwave::mesh
