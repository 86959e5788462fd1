// SIGTERM (a batch system's time limit, kill, Ctrl-C is SIGINT and is left to PETSc): instead of
// dying mid-write, the run notes the request, and the monitor stops at the end of a step on
// every rank together, after flushing the stations and energy.csv, with one line.
// The ranks agree on it with one MPI_Allreduce, not at every step (on 2 ranks of a small 2D box
// that reduction was 12-17 % of the run's wall time, -log_view, 80 x 40 cells, 4000 steps)
// but about every kStopAgreementSeconds of wall time: a stop then comes at most that long (and
// one step) after the signal, well inside a batch system's grace period before its SIGKILL.
#pragma once
#include <petscsys.h>

namespace slipwave::app {

inline constexpr double   kStopAgreementSeconds  = 0.25;
inline constexpr PetscInt kStopAgreementMaxSteps = 100000; // bounds the wait when steps slow down

// Replaces PETSc's SIGTERM handler (which aborts at once) with one that only notes the request.
PetscErrorCode StopRequestInstall();
// Collective (every rank calls it at every step, steps increasing): whether any rank has
// received SIGTERM, known at the steps where the ranks agree (the first call is one; rank 0
// picks the next from the step rate it measured); false in between.
PetscErrorCode StopRequested(MPI_Comm comm, PetscInt step, bool *requested);

} // namespace slipwave::app
