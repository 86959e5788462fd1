// The slipwave run: options, setup, the startup report, the time loop (TSSolve with the
// central-difference TS) and its per-step duties (energy ledger, divergence guard, stations,
// energy.csv, output frames, checkpoint, progress), and the final summary. Sequencing only:
// the duties live in app/run_report, initial_conditions, energy_csv, divergence_guard,
// output_frames and checkpoint; the physics and the numerics in problem/, input/, medium/, porous/, time/, fem/.
#pragma once
#include <petscsys.h>

namespace slipwave::app {

PetscErrorCode SimulationRun(MPI_Comm comm);

} // namespace slipwave::app
