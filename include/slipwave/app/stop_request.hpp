// SIGTERM (a batch system's time limit, kill) and SIGINT (Ctrl-C; a second Ctrl-C stops at once): instead of
// dying mid-write, the run notes the request, and the monitor stops at the end of a step on
// every rank together, after flushing the stations and energy.csv, with one line.
// The ranks agree on it with one MPI_Allreduce, not at every step (on 2 ranks of a small 2D box
// that reduction was 12-17 % of the run's wall time, -log_view, 80 x 40 cells, 4000 steps)
// but about every kStopAgreementSeconds of wall time: a stop then comes at most that long (and
// one step) after the signal, well inside a batch system's grace period before its SIGKILL
// and the 1 s mpiexec leaves between the SIGTERM it passes on and its own SIGKILL.
#pragma once
#include <petscsys.h>

namespace slipwave::app {

inline constexpr double   kStopAgreementSeconds  = 0.1;
inline constexpr PetscInt kStopAgreementMaxSteps = 100000; // bounds the wait when steps slow down

// Replaces PETSc's SIGTERM and SIGINT handlers (which abort at once) with one that only notes
// the request.
PetscErrorCode StopRequestInstall();
// Collective (every rank calls it at every step, steps increasing): the signal any rank has
// received (SIGTERM or SIGINT; the larger number where ranks got both), known at the steps
// where the ranks agree (the first call is one; rank 0 picks the next from the step rate it
// measured); 0 in between and without a signal.
PetscErrorCode StopRequested(MPI_Comm comm, PetscInt step, int *signal);
// "SIGTERM" or "SIGINT (Ctrl-C)", for the message that ends the run.
const char *StopSignalName(int signal);

} // namespace slipwave::app
