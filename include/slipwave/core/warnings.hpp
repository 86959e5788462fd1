// Warnings: one stderr line "slipwave: warning: <text>" from rank 0, for input that runs but
// is probably a mistake (physics/plausible_values.hpp). Errors stop the run instead (errors.hpp).
#pragma once
#include <petscsys.h>

#include <string>

namespace slipwave::core {

PetscErrorCode WarningPrint(MPI_Comm comm, const std::string &text);

} // namespace slipwave::core
