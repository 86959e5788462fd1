// The set-up's cost, printed after the setup report: wall time from the start of the set-up
// (and of it, building the mesh) and each rank's peak resident memory so far (getrusage
// ru_maxrss), as min / avg / max over ranks and rank 0's, the figures of issue 11's parallel
// set-up (rank 0 should not hold much more than the average rank).
#pragma once
#include <petscsys.h>

namespace slipwave::app {

// start: PetscTime at the start of the set-up; mesh_seconds: MeshDescription::build_seconds.
PetscErrorCode ReportSetupCost(MPI_Comm comm, PetscLogDouble start, double mesh_seconds);

} // namespace slipwave::app
