// User-facing errors: bad input stops the run with one line that names the option, the
// value and what is allowed, instead of PETSc's traceback. Raise them with
//   PetscCheck(cond, comm, PETSC_ERR_USER_INPUT, "-option = value ...; allowed ...");
// (or PETSC_ERR_FILE_OPEN for files). Every other error keeps PETSc's full traceback.
#pragma once
#include <petscsys.h>

namespace slipwave::core {

// Installs the handler that prints user-input errors as one line "<program>: error: <message>".
PetscErrorCode ErrorsPushUserInputHandler(const char *program_name);

} // namespace slipwave::core
