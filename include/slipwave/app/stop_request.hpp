// SIGTERM (a batch system's time limit, kill, Ctrl-C is SIGINT and is left to PETSc): instead of
// dying mid-write, the run notes the request, and the monitor stops at the end of the step on
// every rank together, after flushing the stations and energy.csv, with one line.
#pragma once
#include <petscsys.h>

namespace slipwave::app {

// Replaces PETSc's SIGTERM handler (which aborts at once) with one that only notes the request.
PetscErrorCode StopRequestInstall();
// Collective: whether any rank has received SIGTERM.
PetscErrorCode StopRequested(MPI_Comm comm, bool *requested);

} // namespace slipwave::app
