#include "slipwave/app/stop_request.hpp"

#include <algorithm>
#include <cmath>
#include <csignal>

namespace slipwave::app {
namespace {

volatile std::sig_atomic_t g_requested = 0; // the signal received, 0: none

// A second Ctrl-C stops at once, as a user pressing it again expects.
extern "C" void noteRequest(int signal) {
  if (signal == SIGINT && g_requested == SIGINT) {
    std::signal(SIGINT, SIG_DFL);
    std::raise(SIGINT);
  }
  g_requested = signal;
}

// When the ranks next agree: the step, and rank 0's clock at the last agreement.
struct NextAgreement {
  PetscInt       step = 0;
  PetscInt       last_step = 0;
  PetscLogDouble last_wall = 0;
};
NextAgreement g_next;

} // namespace

PetscErrorCode StopRequestInstall() {
  struct sigaction action = {};
  PetscFunctionBeginUser;
  action.sa_handler = noteRequest;
  sigemptyset(&action.sa_mask);
  PetscCheck(sigaction(SIGTERM, &action, nullptr) == 0, PETSC_COMM_SELF, PETSC_ERR_SYS, "cannot install the SIGTERM handler");
  PetscCheck(sigaction(SIGINT, &action, nullptr) == 0, PETSC_COMM_SELF, PETSC_ERR_SYS, "cannot install the SIGINT handler");
  PetscFunctionReturn(0);
}

const char *StopSignalName(int signal) { return signal == SIGINT ? "SIGINT (Ctrl-C)" : "SIGTERM"; }

PetscErrorCode StopRequested(MPI_Comm comm, PetscInt step, int *requested) {
  PetscMPIInt    rank;
  PetscLogDouble now;
  PetscFunctionBeginUser;
  *requested = 0;
  if (step < g_next.step) PetscFunctionReturn(0);
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscTime(&now));
  // Rank 0 turns the last period's step rate into the steps that fill kStopAgreementSeconds;
  // the other ranks add 0, so the maximum is rank 0's count and every rank agrees on it.
  long agreed[2] = {g_requested, 1};
  if (rank == 0 && step > g_next.last_step && now > g_next.last_wall) {
    const double steps_per_second = (step - g_next.last_step) / (now - g_next.last_wall);
    agreed[1] = (long)std::clamp(std::floor(kStopAgreementSeconds * steps_per_second), 1.0, (double)kStopAgreementMaxSteps);
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, agreed, 2, MPI_LONG, MPI_MAX, comm));
  *requested       = (int)agreed[0];
  g_next.step      = step + agreed[1];
  g_next.last_step = step;
  g_next.last_wall = now;
  PetscFunctionReturn(0);
}

} // namespace slipwave::app
