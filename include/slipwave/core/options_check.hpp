// PETSc runs a whole job with a misspelled option and only mentions it at exit. Call
// OptionsErrorIfUnused after every *SetFromOptions and options block, before the first
// step, so a typo stops the run at once.
#pragma once
#include <petscsys.h>

namespace slipwave::core {

// Stops with PETSC_ERR_USER_INPUT naming every option given but never read.
PetscErrorCode OptionsErrorIfUnused(MPI_Comm comm);

} // namespace slipwave::core
