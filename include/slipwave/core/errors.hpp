// User-facing errors: bad input stops the run with one line that names the option, the
// value and what is allowed, instead of PETSc's traceback. Raise them with
//   PetscCheck(cond, comm, PETSC_ERR_USER_INPUT, "-option = value ...; allowed ...");
// (or PETSC_ERR_FILE_OPEN for files). Every other error keeps PETSc's full traceback.
#pragma once
#include <petscsys.h>

namespace slipwave::core {

// Installs the handler that prints user-input errors as one line "<program>: error: <message>".
PetscErrorCode ErrorsPushUserInputHandler(const char *program_name);
// Collective: prints the user-facing line of an error now, before the work that precedes
// raising it with the same message (which then prints nothing): a stop by SIGTERM says so
// before it flushes the series, since mpiexec's SIGKILL follows its SIGTERM by 1 s.
PetscErrorCode ErrorsSayNow(MPI_Comm comm, const char *message);

} // namespace slipwave::core
