// PETSc log events and stages of slipwave in one place, so -log_view explains where a step's
// time goes: class "slipwave", events SW:<Module>:<Phase>, stages per run phase.
#pragma once
#include <petscsys.h>

namespace slipwave::core {

extern PetscLogEvent event_bulk_force;  // SW:Bulk:Force      element loop + ghost exchange
extern PetscLogEvent event_boundary;    // SW:Boundary:Apply  loads, incident wave, held dofs
extern PetscLogEvent event_interface;   // SW:Interface:Update  gather, law per pair, scatter
extern PetscLogEvent event_energy;      // SW:Energy:Ledger
extern PetscLogEvent event_stations;    // SW:IO:Stations
extern PetscLogEvent event_output;      // SW:IO:Fields
extern PetscLogEvent event_guard;       // SW:Guard:Check     divergence detection
extern PetscLogEvent event_fourth_order; // SW:Time:Order4    the fourth-order correction: K a* (its second bulk-force pass), the loads' second difference
extern PetscLogStage stage_setup, stage_geostatic, stage_solve;

PetscErrorCode LogEventsRegister();

} // namespace slipwave::core
