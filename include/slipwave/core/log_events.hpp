// PETSc log events and stages of slipwave in one place, so -log_view explains where a step's
// time goes: class "slipwave", events SW:<Module>:<Phase>, stages per run phase.
#pragma once
#include <petscsys.h>

namespace slipwave::core {

extern PetscLogEvent event_bulk_force;  // SW:Bulk:Force      element loop + ghost exchange
extern PetscLogEvent event_boundary;    // SW:Boundary:Apply  loads, incident wave, free-field columns, DRM forces
extern PetscLogEvent event_acceleration; // SW:Accel:Assemble a = M^-1 (the forces), held dofs, ties, rigid bodies: a pass over every dof
extern PetscLogEvent event_interface;   // SW:Interface:Update  gather, law per pair, scatter
extern PetscLogEvent event_energy;      // SW:Energy:Ledger
extern PetscLogEvent event_stations;    // SW:IO:Stations
extern PetscLogEvent event_output;      // SW:IO:Fields
extern PetscLogEvent event_guard;       // SW:Guard:Check     divergence detection
extern PetscLogEvent event_fourth_order; // SW:Time:Order4    the fourth-order correction: K a* (its second bulk-force pass), the loads' second difference
// Set-up (stage Setup): where a small run's fixed time goes.
extern PetscLogEvent event_mesh;        // SW:Mesh:Build      the distributed, labelled mesh (meshing/mesh_builder.hpp)
extern PetscLogEvent event_bulk_setup;  // SW:Bulk:Setup      element tables, matrices, spectral layout
extern PetscLogEvent event_boundary_setup; // SW:Boundary:Setup boundary faces, dashpots, input loads
extern PetscLogEvent event_output_open; // SW:IO:Open         output folder, run_info.json, first frame
// Stages: set-up, the geostatic stage, the time loop (TSSolve), the final output (the series
// flushed, the closing report).
extern PetscLogStage stage_setup, stage_geostatic, stage_solve, stage_output;

PetscErrorCode LogEventsRegister();

} // namespace slipwave::core
