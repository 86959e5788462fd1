#include "slipwave/app/simulation.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "slipwave/app/checkpoint.hpp"
#include "slipwave/app/divergence_guard.hpp"
#include "slipwave/app/energy_csv.hpp"
#include "slipwave/app/initial_conditions.hpp"
#include "slipwave/app/output_dir.hpp"
#include "slipwave/app/output_frames.hpp"
#include "slipwave/app/rigid_histories.hpp"
#include "slipwave/app/run_answers.hpp"
#include "slipwave/app/run_report.hpp"
#include "slipwave/app/setup_cost.hpp"
#include "slipwave/app/stop_request.hpp"
#include "slipwave/core/errors.hpp"
#include "slipwave/core/log_events.hpp"
#include "slipwave/core/options_check.hpp"
#include "slipwave/input/record_files_check.hpp"
#include "slipwave/io/input_motion_csv.hpp"
#include "slipwave/io/stations.hpp"
#include "slipwave/medium/hysteresis.hpp"
#include "slipwave/porous/pore_pressure.hpp"
#include "slipwave/problem/elastodynamics.hpp"
#include "slipwave/problem/energy_ledger.hpp"
#include "slipwave/problem/geostatic.hpp"
#include "slipwave/problem/integrator_step.hpp"
#include "slipwave/problem/rigid_bodies.hpp"
#include "slipwave/problem/stable_step.hpp"
#include "slipwave/time/central_difference.hpp"

namespace slipwave::app {
using namespace core;  // the ground floor: log events and stages, the unused-option check
namespace {

struct RunOptions {
  char      output_dir[PETSC_MAX_PATH_LEN] = "output";
  PetscReal output_interval                = -1; // [s]; <0: 50 frames over the run
  PetscReal progress_interval              = 5.0; // wall seconds
  PetscReal energy_growth_limit            = 2.0;
  PetscBool dry_run                        = PETSC_FALSE;
  PetscBool report_verbose                 = PETSC_FALSE;
  PetscBool fields                         = PETSC_TRUE;
  PetscBool overwrite                      = PETSC_FALSE;
  PetscReal initial_velocity[3]            = {0, 0, 0};
  PetscInt  checkpoint_interval            = 0;
  // The ledger's stored energies sweep every dof (about a third of a bulk-force pass): every
  // 10th step keeps that under 5 % of a step. The work is booked every step regardless.
  PetscInt  energy_interval                = 10;
  char      restart[PETSC_MAX_PATH_LEN]    = "";
};

struct Run {
  RunOptions              opt;
  problem::Elastodynamics   model;
  problem::StableStep       step;
  problem::TimeStepOptions  time_step;
  problem::IntegratorStep   integrator;
  problem::EnergyLedger     ledger;
  problem::GeostaticOptions geostatic;
  io::Stations            stations;
  RigidHistories          rigid_histories;
  RunAnswers              answers;
  std::vector<double>     motion;           // the rigid bodies' motion at this step (RigidBodiesMotion)
  RegionVelocities        region_velocity;
  OutputFrames            frames;
  EnergyCsv               energy_csv;
  PetscReal               max_time = 0;
  PetscLogDouble          wall_start = 0, wall_last_progress = 0;
  PetscMPIInt             rank = 0;
  bool                    resumed = false; // TSSolve repeats the monitor of the restart step: skip it
  PetscReal               t_first  = NAN;  // the first step's time in this process (the progress line's speed)
  PetscInt                restart_step = 0;
  PetscReal               dt = 0;           // the time step chosen (run_info.json)
};

CheckpointState checkpointState(Run *r, TS ts) {
  return CheckpointState{&r->model, ts, &r->ledger, &r->stations, r->frames.times(), r->frames.nextOutput()};
}

PetscErrorCode readRunOptions(MPI_Comm comm, RunOptions *o) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "Run control and output", "slipwave");
  PetscCall(PetscOptionsString("-output_dir", "directory for volume.xmf/h5, stations, energy.csv", "SimulationRun", o->output_dir, o->output_dir, sizeof o->output_dir,
                               nullptr));
  PetscCall(PetscOptionsReal("-output_interval", "time between field outputs [s], > 0 (default: 50 frames over -ts_max_time)", "SimulationRun", o->output_interval,
                             &o->output_interval, nullptr));
  PetscCall(PetscOptionsBool("-output_overwrite", "delete an earlier run's files in -output_dir first (without it such a folder is refused)", "SimulationRun",
                             o->overwrite, &o->overwrite, nullptr));
  PetscCall(PetscOptionsBool("-output_fields", "write volume fields (HDF5 + XDMF)", "SimulationRun", o->fields, &o->fields, nullptr));
  PetscCall(PetscOptionsReal("-progress_interval", "wall-clock time between progress lines [s], >= 0 (0: every step)", "SimulationRun", o->progress_interval,
                             &o->progress_interval, nullptr));
  PetscCall(PetscOptionsReal("-energy_growth_limit", "stop when kinetic+strain energy exceeds this multiple of the energy put in [-], > 0 (divergence guard)", "SimulationRun",
                             o->energy_growth_limit, &o->energy_growth_limit, nullptr));
  PetscCall(PetscOptionsBool("-dry_run", "print the setup report (stable step, what governs it, points per wavelength) and stop", "SimulationRun", o->dry_run,
                             &o->dry_run, nullptr));
  PetscCall(PetscOptionsBool("-report_verbose", "the setup report in full (boundaries, loads, damping fits, rigid bodies, interface penalties, set-up cost); without it a compact summary",
                             "SimulationRun", o->report_verbose, &o->report_verbose, nullptr));
  PetscCall(PetscOptionsInt("-checkpoint_interval", "write the full state to OUTPUT_DIR/checkpoint.bin every N steps [steps], >= 0 (0: never)", "SimulationRun",
                            o->checkpoint_interval, &o->checkpoint_interval, nullptr));
  PetscCall(PetscOptionsString("-restart", "continue from this checkpoint file (same scene options and number of ranks)", "SimulationRun", o->restart, o->restart,
                               sizeof o->restart, nullptr));
  PetscCall(PetscOptionsInt("-energy_interval", "evaluate the energy balance (an energy.csv row, the divergence guard) every N steps, at output times and at the last [steps], 1 to 1e9", "SimulationRun",
                            o->energy_interval, &o->energy_interval, nullptr));
  PetscInt nv = 3;
  PetscCall(PetscOptionsRealArray("-initial_velocity", "uniform initial velocity vx,vy[,vz] of every free node [m/s]", "SimulationRun", o->initial_velocity, &nv,
                                  nullptr));
  PetscOptionsEnd();
  PetscCheck(o->checkpoint_interval >= 0, comm, PETSC_ERR_USER_INPUT, "-checkpoint_interval = %" PetscInt_FMT "; allowed: >= 0 steps", o->checkpoint_interval);
  PetscCheck(o->energy_interval >= 1, comm, PETSC_ERR_USER_INPUT, "-energy_interval = %" PetscInt_FMT "; allowed: 1 to 1e9 steps", o->energy_interval);
  PetscFunctionReturn(0);
}
// ---------------------------------------------------------------------------------------------
// The per-step monitor: its duties, one function each, in the order they run.

// The interfaces' stored and dissipated energy summed (collective).
PetscErrorCode sumInterfaceTotals(const problem::Elastodynamics &model, interface::InterfaceTotals *totals) {
  PetscFunctionBeginUser;
  for (const auto &iface : model.interfaces) {
    interface::InterfaceTotals one;
    PetscCall(iface.Totals(&one));
    totals->stored += one.stored;
    totals->dissipated += one.dissipated;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode appendEnergyRow(Run *r, PetscInt step, PetscReal t) {
  interface::InterfaceTotals totals;
  PetscFunctionBeginUser;
  PetscCall(sumInterfaceTotals(r->model, &totals));
  r->energy_csv.Append(step, t, r->ledger, totals);
  PetscFunctionReturn(0);
}

// At every output time and a SIGTERM (last): the rows sampled so far go to disk.
PetscErrorCode flushSeries(Run *r, bool last) {
  PetscFunctionBeginUser;
  r->energy_csv.Flush();
  PetscCall(r->stations.Flush(r->model.comm, r->opt.output_dir, last));
  PetscCall(r->rigid_histories.Flush());
  PetscFunctionReturn(0);
}

// A SIGTERM or SIGINT stops the run here, between steps, with everything sampled so far on
// disk, and says how the run can continue.
PetscErrorCode stopIfRequested(Run *r, PetscInt step, PetscReal t) {
  int signal;
  PetscFunctionBeginUser;
  PetscCall(StopRequested(r->model.comm, step, &signal));
  if (!signal) PetscFunctionReturn(0);
  const PetscInt every = r->opt.checkpoint_interval;
  char           resume[PETSC_MAX_PATH_LEN + 256];
  if (every > 0 && step >= every)
    std::snprintf(resume, sizeof resume, "to resume from the last checkpoint (step %ld): -restart %s/checkpoint.bin", (long)(step / every * every), r->opt.output_dir);
  else
    std::snprintf(resume, sizeof resume, "%s", every > 0 ? "no checkpoint yet (-checkpoint_interval steps not reached)" : "to be able to resume, run with -checkpoint_interval <steps>, then -restart <output_dir>/checkpoint.bin");
  char time_text[32]; // PETSc's own %g would print 0 as "0."
  std::snprintf(time_text, sizeof time_text, "%g", (double)t);
  char line[2 * PETSC_MAX_PATH_LEN + 512];
  std::snprintf(line, sizeof line,
                "stopped by %s after step %" PetscInt_FMT ", t = %s s; stations hold every sample up to it, energy.csv every -energy_interval-th, the fields every output time up to it (%s); %s",
                StopSignalName(signal), step, time_text, r->opt.output_dir, resume);
  // The line first, then the flush: mpiexec follows its SIGTERM with a SIGKILL 1 s later.
  PetscCall(core::ErrorsSayNow(r->model.comm, line));
  PetscCall(flushSeries(r, true));
  SETERRQ(r->model.comm, PETSC_ERR_USER_INPUT, "%s", line);
}

PetscErrorCode checkpointIfDue(Run *r, TS ts, PetscInt step) {
  PetscFunctionBeginUser;
  if (r->opt.checkpoint_interval > 0 && step > 0 && step % r->opt.checkpoint_interval == 0) {
    // The histories a restart copies from this folder hold every row up to the checkpoint.
    r->energy_csv.Flush();
    PetscCall(r->rigid_histories.Flush());
    PetscCall(CheckpointWrite(std::string(r->opt.output_dir) + "/checkpoint.bin", checkpointState(r, ts)));
  }
  PetscFunctionReturn(0);
}

// One progress line at the first and the last step and every -progress_interval wall seconds.
PetscErrorCode printProgressIfDue(Run *r, PetscInt step, PetscReal t, PetscReal h, bool last) {
  PetscLogDouble now;
  PetscFunctionBeginUser;
  PetscCall(PetscTime(&now));
  if (std::isnan(r->t_first)) r->t_first = t;
  if (step == 0 || last || now - r->wall_last_progress >= r->opt.progress_interval) {
    // The remaining time at the speed measured in this process so far (simulated s per wall s).
    const double elapsed = now - r->wall_start, done = t - r->t_first;
    char         eta[32] = "      -";
    if (done > 0) std::snprintf(eta, sizeof eta, "%7.1f", elapsed * (r->max_time - t) / done);
    std::string states;
    for (const InterfaceCounts &c : r->answers.counts()) {
      char cell[96];
      std::snprintf(cell, sizeof cell, "%s%.0f/%.0f/%.0f", states.empty() ? "  stick/slip/open " : " ", c.stick, c.slip, c.open);
      states += cell;
    }
    PetscCall(PetscPrintf(r->model.comm, "step %6" PetscInt_FMT "  t = %.4e s (%5.1f %%)  dt = %.3e s  wall %7.1f s  ETA %s s%s  energy kin %.3e strain %.3e  balance %.1e\n", step,
                          (double)t, 100 * t / r->max_time, (double)h, elapsed, eta, states.c_str(), r->ledger.kinetic, r->ledger.strain, r->ledger.relativeError()));
    r->wall_last_progress = now;
  }
  PetscFunctionReturn(0);
}

// At the stations' sample times: the stations' rows.
PetscErrorCode sampleSeries(Run *r, PetscReal t, Vec u, Vec v, Vec a) {
  PetscFunctionBeginUser;
  PetscCall(r->stations.Sample(r->model.dm, t, u, v, a));
  if (r->model.pore) PetscCall(r->stations.SamplePressure(r->model.pore->pdm, r->model.pore->p_total, r->model.pore->p));
  PetscCall(r->stations.SampleStress(r->model.bulk, r->model.initial_stress, r->model.hysteresis));
  if (r->model.rigid) r->rigid_histories.Sample(t, r->motion);
  PetscFunctionReturn(0);
}

PetscErrorCode monitor(TS ts, PetscInt step, PetscReal t, Vec u, void *ctx) {
  auto     *r = static_cast<Run *>(ctx);
  Vec       v, a;
  PetscReal h;
  PetscFunctionBeginUser;
  if (r->resumed) {
    r->resumed = false;
    PetscFunctionReturn(0);
  }
  PetscCall(TSGetTimeStep(ts, &h));
  const bool last = t >= r->max_time * (1 - 1e-12);
  // Evaluated at every output time too, so each frame has its energy row.
  const bool frame    = r->frames.Due(step, t, last);
  const bool evaluate = last || step % r->opt.energy_interval == 0 || frame;
  PetscCall(problem::EnergyLedgerUpdate(&r->model, ts, h, evaluate, &r->ledger));
  // The ledger and the guard read the integrator's own v and a; what is reported (stations,
  // answers, frames) is the velocity and acceleration of the motion (at order 2 the same).
  PetscCall(TS2GetSolution(ts, &u, &v));
  PetscCall(time::CentralDifferenceGetAcceleration(ts, &a));
  if (r->ledger.evaluated) PetscCall(DivergenceGuard(r->model, r->ledger, r->opt.energy_growth_limit, r->integrator, h, step, t, u, v, a));
  // Formed only when something reads them (at order 4 a pass over the dofs).
  if (r->answers.active() || r->stations.due(step) || frame) PetscCall(time::CentralDifferenceGetReportedState(ts, &v, &a));
  if (r->model.pore) PetscCall(porous::PorePressureTotal(r->model.pore)); // for the stations and the frames
  if (r->model.rigid) PetscCall(problem::RigidBodiesMotion(r->model.rigid, r->model.mass, u, &r->motion));
  // Every step (the interfaces' counts of the progress line too).
  if (r->answers.active()) PetscCall(r->answers.Update(r->model, r->stations, t, u, a, r->motion));
  if (r->stations.due(step)) PetscCall(sampleSeries(r, t, u, v, a));
  if (r->ledger.evaluated) PetscCall(appendEnergyRow(r, step, t));
  bool due;
  PetscCall(r->frames.WriteIfDue(r->model, step, t, last, u, v, a, &due));
  if (due) PetscCall(flushSeries(r, false));
  PetscCall(checkpointIfDue(r, ts, step));
  PetscCall(printProgressIfDue(r, step, t, h, last));
  PetscCall(stopIfRequested(r, step, t));
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------------------------------------
// SimulationRun's steps, in the order they run.

// Options, the model, its stable step, the stations.
PetscErrorCode setUp(MPI_Comm comm, Run *r) {
  PetscFunctionBeginUser;
  PetscCall(readRunOptions(comm, &r->opt));
  PetscBool help;
  PetscCall(PetscOptionsHasHelp(nullptr, &help));
  // The input files before anything is written or built (a malformed record fails in a second).
  PetscCall(input::RecordFilesCheck(comm));
  PetscCall(io::StationFileCheck(comm));
  if (!help) PetscCall(OutputDirPrepare(comm, {r->opt.output_dir, (bool)r->opt.overwrite, !r->opt.dry_run, r->opt.restart}));
  if (r->opt.restart[0]) PetscCall(CheckpointVerify(comm, r->opt.restart));
  PetscCall(problem::TimeStepOptionsRead(comm, &r->time_step));
  PetscCall(problem::ElastodynamicsCreate(comm, &r->model));
  PetscCall(problem::StableStepCompute(&r->model, r->time_step, &r->step));
  PetscCall(r->stations.Setup(r->model.dm, r->model.bulk, r->model.mesh));
  PetscCall(r->answers.Setup(r->model, r->stations));
  PetscCall(RegionVelocitiesRead(comm, r->model.dim, r->model.materials, &r->region_velocity));
  PetscCall(problem::GeostaticOptionsRead(comm, &r->geostatic));
  PetscFunctionReturn(0);
}

// The central-difference TS on the model's right-hand side.
PetscErrorCode createTimeStepper(Run *r, TS *out) {
  TS ts;
  PetscFunctionBeginUser;
  PetscCall(TSCreate(r->model.comm, &ts));
  PetscCall(TSSetType(ts, time::kTSCentralDifference));
  PetscCall(TSSetMaxTime(ts, 1.0));
  PetscCall(TSSetMaxSteps(ts, PETSC_MAX_INT));
  PetscCall(TSSetExactFinalTime(ts, TS_EXACTFINALTIME_MATCHSTEP));
  PetscCall(TSSetFromOptions(ts));
  PetscCall(problem::IntegratorStepChoose(r->model, r->step, r->time_step, ts, &r->integrator));
  PetscCall(problem::TimeStepChoose(ts, r->integrator));
  PetscCall(TSGetMaxTime(ts, &r->max_time));
  PetscCall(problem::ElastodynamicsSetUpTS(&r->model, ts));
  *out = ts;
  PetscFunctionReturn(0);
}

// Everything the geostatic stage and the steps so far produced comes from the file.
PetscErrorCode resumeFromCheckpoint(Run *r, TS ts, Vec u, Vec v) {
  PetscReal t;
  PetscFunctionBeginUser;
  PetscCall(TS2SetSolution(ts, u, v));
  PetscCall(CheckpointRead(r->opt.restart, checkpointState(r, ts)));
  PetscCall(TSGetStepNumber(ts, &r->restart_step));
  r->resumed = true;
  PetscCall(TSGetTime(ts, &t));
  PetscCall(PetscPrintf(r->model.comm, "restart: continuing from step %" PetscInt_FMT ", t = %g s (%s)\n", r->restart_step, (double)t, r->opt.restart));
  PetscFunctionReturn(0);
}

// The geostatic stage if asked for, then the initial velocities and the initial acceleration.
PetscErrorCode setInitialState(Run *r, TS ts, Vec u, Vec v) {
  PetscFunctionBeginUser;
  if (r->geostatic.enabled) {
    problem::GeostaticReport g;
    PetscReal              dt_geo;
    PetscCall(TSGetTimeStep(ts, &dt_geo));
    Vec u_geo;
    PetscCall(VecDuplicate(u, &u_geo));
    PetscCall(problem::GeostaticStage(&r->model, r->geostatic, dt_geo, &g, u_geo));
    PetscCall(r->answers.SetGeostatic(r->model, r->stations, u_geo));
    PetscCall(PetscPrintf(r->model.comm, "%s\n", problem::GeostaticReportLine(r->geostatic, g).c_str()));
    if (r->model.hysteresis) {
      // Darendeli regions whose sigma'_0 comes from this stage (the states are still virgin).
      Vec                      local;
      const PetscScalar       *a;
      std::vector<std::string> lines;
      PetscCall(DMGetLocalVector(r->model.dm, &local));
      PetscCall(DMGlobalToLocal(r->model.dm, u_geo, INSERT_VALUES, local));
      PetscCall(VecGetArrayRead(local, &a));
      PetscCall(medium::HysteresisSetGeostaticStress(r->model.hysteresis, r->model.comm, a, r->model.materials, &lines));
      PetscCall(VecRestoreArrayRead(local, &a));
      PetscCall(DMRestoreLocalVector(r->model.dm, &local));
      for (const std::string &line : lines) PetscCall(PetscPrintf(r->model.comm, "%s\n", line.c_str()));
    }
    PetscCall(VecDestroy(&u_geo));
  }
  PetscCall(InitialVelocitySet(r->model.dm, r->model.bulk, r->model.bc.free_mask, r->opt.initial_velocity, r->region_velocity, v));
  PetscCall(TS2SetSolution(ts, u, v));
  PetscCall(time::CentralDifferenceComputeInitialAcceleration(ts));
  PetscFunctionReturn(0);
}

// Between output frames [s]: -output_interval, by default 50 frames over the run.
PetscReal outputInterval(const Run *r) { return r->opt.output_interval > 0 ? r->opt.output_interval : r->max_time / 50; }

// OUTPUT_DIR with energy.csv, run_info.json and input_motion.csv (rank 0), and the output frames.
PetscErrorCode openOutputs(Run *r, TS ts) {
  const bool restarted = r->opt.restart[0];
  PetscFunctionBeginUser;
  if (r->rank == 0) {
    PetscReal dt;
    PetscCall(TSGetTimeStep(ts, &dt));
    r->energy_csv.SetFluid(r->model.pore != nullptr);
    r->energy_csv.SetHysteretic(r->model.hysteresis != nullptr);
    r->energy_csv.SetFourthOrder(r->integrator.order == 4);
    PetscCall(r->energy_csv.Open(r->opt.output_dir, restarted ? CheckpointFolder(r->opt.restart) + "/energy.csv" : "", r->restart_step));
    r->dt = dt;
    WriteRunInfo(r->model, r->step, r->opt.output_dir, dt);
    const input::BoundaryConditions &bc = r->model.bc;
    // Rank 0 alone: a failure warns (an error here would leave the other ranks waiting).
    // Up to where the run ends: -ts_max_time, or sooner -ts_max_steps steps of dt (a run
    // stopped by its step count may name no end time at all).
    PetscInt  max_steps;
    PetscReal t_start;
    PetscCall(TSGetMaxSteps(ts, &max_steps));
    PetscCall(TSGetTime(ts, &t_start));
    const double t_end = std::min((double)r->max_time, max_steps > 0 && max_steps < PETSC_MAX_INT ? (double)t_start + (double)max_steps * dt : 1e300);
    if (bc.input.active() && bc.input_wave != input::InputWave::None && !io::WriteInputMotion(r->opt.output_dir, bc.input, (int)bc.input_component, t_end))
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "warning: cannot write %s/input_motion.csv: the plots will not show the input motion\n", r->opt.output_dir));
  }
  PetscReal t;
  PetscCall(TSGetTime(ts, &t));
  PetscCall(r->rigid_histories.Open(r->model.rigid, r->rank, r->opt.output_dir, restarted ? CheckpointFolder(r->opt.restart) : "", t));
  PetscCall(r->frames.Open(r->model, r->opt.output_dir, outputInterval(r), r->opt.fields, restarted ? CheckpointFolder(r->opt.restart) : ""));
  PetscFunctionReturn(0);
}

PetscErrorCode closeOutputs(Run *r) {
  PetscFunctionBeginUser;
  r->energy_csv.Close();
  PetscCall(r->stations.Flush(r->model.comm, r->opt.output_dir, true));
  PetscCall(r->rigid_histories.Flush());
  PetscCall(r->frames.Close());
  PetscFunctionReturn(0);
}

// From the initial state (or the checkpoint) to -ts_max_time, then the outputs and the summary.
PetscErrorCode solve(Run *r, TS ts) {
  Vec            u, v;
  PetscLogDouble wall_end;
  PetscInt       steps;
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(r->model.dm, &u));
  PetscCall(VecDuplicate(u, &v));
  PetscCall(VecZeroEntries(u));
  // The initial state and the opened outputs are set-up too (-log_view's Setup stage).
  PetscCall(PetscLogStagePush(stage_setup));
  if (r->opt.restart[0]) PetscCall(resumeFromCheckpoint(r, ts, u, v));
  else PetscCall(setInitialState(r, ts, u, v));
  PetscCall(PetscLogEventBegin(event_output_open, 0, 0, 0, 0));
  PetscCall(openOutputs(r, ts));
  PetscCall(PetscLogEventEnd(event_output_open, 0, 0, 0, 0));
  PetscCall(PetscLogStagePop());
  PetscCall(TSMonitorSet(ts, monitor, r, nullptr));
  PetscCall(PetscTime(&r->wall_start));
  r->wall_last_progress = r->wall_start;
  PetscCall(PetscLogStagePush(stage_solve));
  PetscCall(TSSolve(ts, u));
  PetscCall(PetscLogStagePop());
  PetscCall(PetscTime(&wall_end));
  PetscCall(TSGetStepNumber(ts, &steps));
  PetscCall(PetscLogStagePush(stage_output));
  PetscCall(closeOutputs(r));
  // Listed from the folder itself: it held none of these files before the run (output_dir.hpp).
  // The steps this process ran (after a restart, not those before it).
  PetscReal dt;
  PetscCall(TSGetTimeStep(ts, &dt));
  PetscCall(ReportEnd(r->model, r->ledger, r->step, dt, OutputDirRunFiles(r->opt.output_dir), steps - r->restart_step, wall_end - r->wall_start, r->opt.output_dir));
  if (r->answers.active()) {
    std::string answers;
    PetscCall(r->answers.Finish(r->model, r->opt.restart[0] != 0, r->opt.output_dir, &answers));
    if (r->rank == 0 && !answers.empty()) WriteRunInfo(r->model, r->step, r->opt.output_dir, r->dt, answers);
  }
  PetscCall(PetscLogStagePop());
  PetscCall(VecDestroy(&u));
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode SimulationRun(MPI_Comm comm) {
  Run *r = new Run();
  TS   ts;
  PetscReal dt;
  PetscBool help;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &r->rank));
  PetscCall(LogEventsRegister());
  PetscCall(time::CentralDifferenceRegister());
  PetscCall(StopRequestInstall());
  PetscCall(PetscLogStagePush(stage_setup));
  PetscLogDouble setup_start;
  PetscCall(PetscTime(&setup_start));
  PetscCall(setUp(comm, r));
  PetscCall(createTimeStepper(r, &ts));
  PetscCall(OptionsErrorIfUnused(comm));
  PetscCall(TSGetTimeStep(ts, &dt));
  r->stations.setTimeStep(dt);
  PetscCall(ReportSetup(r->model, r->step, r->integrator, r->stations, dt, r->max_time, r->opt.output_dir, outputInterval(r), r->opt.report_verbose));
  if (r->opt.report_verbose) PetscCall(ReportSetupCost(comm, setup_start, r->model.mesh.build_seconds));
  PetscCall(PetscLogStagePop());
  PetscCall(PetscOptionsHasHelp(nullptr, &help));
  if (r->opt.dry_run || help) PetscCall(PetscPrintf(comm, "%s: stopping before the first step\n", help ? "-help" : "dry run"));
  else PetscCall(solve(r, ts));
  PetscCall(TSDestroy(&ts));
  PetscCall(problem::GeostaticOptionsDestroy(&r->geostatic));
  PetscCall(r->stations.Destroy());
  PetscCall(problem::ElastodynamicsDestroy(&r->model));
  delete r;
  PetscFunctionReturn(0);
}

} // namespace slipwave::app
