#include "slipwave/app/stop_request.hpp"

#include <csignal>

namespace slipwave::app {
namespace {

volatile std::sig_atomic_t g_requested = 0;

extern "C" void noteRequest(int) { g_requested = 1; }

} // namespace

PetscErrorCode StopRequestInstall() {
  struct sigaction action = {};
  PetscFunctionBeginUser;
  action.sa_handler = noteRequest;
  sigemptyset(&action.sa_mask);
  PetscCheck(sigaction(SIGTERM, &action, nullptr) == 0, PETSC_COMM_SELF, PETSC_ERR_SYS, "cannot install the SIGTERM handler");
  PetscFunctionReturn(0);
}

PetscErrorCode StopRequested(MPI_Comm comm, bool *requested) {
  int any = g_requested;
  PetscFunctionBeginUser;
  // Ranks may receive the signal at different steps: agreeing every step stops all at one.
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_MAX, comm));
  *requested = any != 0;
  PetscFunctionReturn(0);
}

} // namespace slipwave::app
