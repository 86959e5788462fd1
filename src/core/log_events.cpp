#include "slipwave/core/log_events.hpp"

namespace slipwave::core {

PetscLogEvent event_bulk_force, event_boundary, event_acceleration, event_interface, event_energy, event_stations, event_output, event_guard, event_fourth_order;
PetscLogEvent event_mesh, event_bulk_setup, event_boundary_setup, event_output_open;
PetscLogStage stage_setup, stage_geostatic, stage_solve, stage_output;

PetscErrorCode LogEventsRegister() {
  PetscClassId id;
  PetscFunctionBeginUser;
  PetscCall(PetscClassIdRegister("slipwave", &id));
  PetscCall(PetscLogEventRegister("SW:Bulk:Force", id, &event_bulk_force));
  PetscCall(PetscLogEventRegister("SW:Boundary:Apply", id, &event_boundary));
  PetscCall(PetscLogEventRegister("SW:Accel:Assemble", id, &event_acceleration));
  PetscCall(PetscLogEventRegister("SW:Interface:Update", id, &event_interface));
  PetscCall(PetscLogEventRegister("SW:Energy:Ledger", id, &event_energy));
  PetscCall(PetscLogEventRegister("SW:IO:Stations", id, &event_stations));
  PetscCall(PetscLogEventRegister("SW:IO:Fields", id, &event_output));
  PetscCall(PetscLogEventRegister("SW:Guard:Check", id, &event_guard));
  PetscCall(PetscLogEventRegister("SW:Mesh:Build", id, &event_mesh));
  PetscCall(PetscLogEventRegister("SW:Bulk:Setup", id, &event_bulk_setup));
  PetscCall(PetscLogEventRegister("SW:Boundary:Setup", id, &event_boundary_setup));
  PetscCall(PetscLogEventRegister("SW:IO:Open", id, &event_output_open));
  PetscCall(PetscLogEventRegister("SW:Time:Order4", id, &event_fourth_order));
  PetscCall(PetscLogStageRegister("Setup", &stage_setup));
  PetscCall(PetscLogStageRegister("Geostatic", &stage_geostatic));
  PetscCall(PetscLogStageRegister("Solve", &stage_solve));
  PetscCall(PetscLogStageRegister("Output", &stage_output));
  PetscFunctionReturn(0);
}

} // namespace slipwave::core
