#include "slipwave/app/errors.hpp"

#include <cstdio>

namespace slipwave::app {
namespace {

const char *g_program = "slipwave";

bool isUserInputError(PetscErrorCode code) {
  return code == PETSC_ERR_USER_INPUT || code == PETSC_ERR_FILE_OPEN || code == PETSC_ERR_ARG_OUTOFRANGE || code == PETSC_ERR_NOT_CONVERGED;
}

PetscErrorCode userInputHandler(MPI_Comm comm, int line, const char *func, const char *file, PetscErrorCode code,
                                PetscErrorType type, const char *mess, void *ctx) {
  static bool reported = false;
  if (!isUserInputError(code) && !reported) return PetscTraceBackErrorHandler(comm, line, func, file, code, type, mess, ctx);
  // The first call carries the message; the calls that follow are the unwinding stack.
  if (type == PETSC_ERROR_INITIAL && !reported) {
    reported = true;
    PetscMPIInt rank = 0;
    if (comm != PETSC_COMM_SELF) MPI_Comm_rank(comm, &rank);
    if (rank == 0) {
      std::fprintf(stderr, "%s: error: %s\n", g_program, mess ? mess : "(no message)");
      std::fflush(stderr);
    }
  }
  return code;
}

} // namespace

PetscErrorCode ErrorsPushUserInputHandler(const char *program_name) {
  PetscFunctionBeginUser;
  g_program = program_name;
  PetscCall(PetscPushErrorHandler(userInputHandler, nullptr));
  PetscFunctionReturn(0);
}

} // namespace slipwave::app
