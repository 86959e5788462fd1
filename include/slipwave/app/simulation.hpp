// The slipwave run: options, setup, the startup report, the time loop (TSSolve with the
// central-difference TS) and its per-step duties (energy ledger, stations, field output,
// progress, divergence guard), and the final summary. Sequencing only; the physics and the
// numerics live in model/, time/, fem/.
#pragma once
#include <petscsys.h>

namespace slipwave::app {

PetscErrorCode SimulationRun(MPI_Comm comm);

} // namespace slipwave::app
