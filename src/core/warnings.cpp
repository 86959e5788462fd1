#include "slipwave/core/warnings.hpp"

namespace slipwave::core {

PetscErrorCode WarningPrint(MPI_Comm comm, const std::string &text) {
  PetscFunctionBeginUser;
  PetscCall(PetscFPrintf(comm, PETSC_STDERR, "slipwave: warning: %s\n", text.c_str()));
  PetscFunctionReturn(0);
}

} // namespace slipwave::core
