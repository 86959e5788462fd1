#include "slipwave/app/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "slipwave/app/checkpoint.hpp"
#include "slipwave/app/log_events.hpp"
#include "slipwave/app/options_check.hpp"
#include "slipwave/io/interface_output.hpp"
#include "slipwave/io/stations.hpp"
#include "slipwave/io/volume_output.hpp"
#include "slipwave/model/attenuation.hpp"
#include "slipwave/model/elastodynamics.hpp"
#include "slipwave/model/energy_ledger.hpp"
#include "slipwave/model/geostatic.hpp"
#include "slipwave/time/central_difference.hpp"

namespace slipwave::app {
namespace {

// Default fractions of the stable step. With contact interfaces the open/close switching of a
// pair is not covered by the linear bound: in the two-bar impact (penalty factor 1) the energy
// grew by 2.5 % at 0.9 of the limit, 1.1 % at 0.7 and 0.5 % at 0.5 (the spec saw +0.09 % at
// half the limit and +180 % at it), so interfaces get 0.5.
constexpr PetscReal kSafetyBulk       = 0.9;
constexpr PetscReal kSafetyInterfaces = 0.5;

struct RunOptions {
  char      output_dir[PETSC_MAX_PATH_LEN] = "output";
  PetscReal output_interval                = -1; // [s]; <0: 50 frames over the run
  PetscReal safety                         = -1; // default: kSafetyBulk, or kSafetyInterfaces with interfaces
  PetscBool safety_set                     = PETSC_FALSE;
  PetscReal progress_interval              = 5.0; // wall seconds
  PetscReal energy_growth_limit            = 2.0;
  PetscBool dry_run                        = PETSC_FALSE;
  PetscBool fields                         = PETSC_TRUE;
  PetscReal initial_velocity[3]            = {0, 0, 0};
  PetscInt  checkpoint_interval            = 0;
  char      restart[PETSC_MAX_PATH_LEN]    = "";
};

struct Run {
  RunOptions           opt;
  model::Elastodynamics model;
  model::StableStep    step;
  model::EnergyLedger  ledger;
  model::GeostaticOptions geostatic;
  io::Stations         stations;
  io::VolumeOutput     volume;
  std::vector<std::unique_ptr<io::InterfaceOutput>> interface_outputs;
  FILE                *energy_csv = nullptr;
  PetscReal            next_output = 0, max_time = 0;
  PetscInt             frames = 0;
  PetscLogDouble       wall_start = 0, wall_last_progress = 0;
  PetscMPIInt          rank = 0;
  std::vector<std::vector<PetscReal>> region_velocity; // per region, empty if not given
  std::vector<PetscReal> frame_times; // times of the output frames written
  bool                   resumed = false; // TSSolve repeats the monitor of the restart step: skip it
  PetscInt               restart_step = 0;
};

CheckpointState checkpointState(Run *r, TS ts) {
  return CheckpointState{&r->model, ts, &r->ledger, &r->stations, &r->frame_times, &r->next_output};
}

PetscErrorCode readRunOptions(MPI_Comm comm, RunOptions *o) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "Run control and output", "slipwave");
  PetscCall(PetscOptionsString("-output_dir", "directory for volume.xmf/h5, stations, energy.csv", "SimulationRun", o->output_dir, o->output_dir, sizeof o->output_dir,
                               nullptr));
  PetscCall(PetscOptionsReal("-output_interval", "time between field outputs [s], > 0 (default: 50 frames over -ts_max_time)", "SimulationRun", o->output_interval,
                             &o->output_interval, nullptr));
  PetscCall(PetscOptionsBool("-output_fields", "write volume fields (HDF5 + XDMF)", "SimulationRun", o->fields, &o->fields, nullptr));
  PetscCall(PetscOptionsReal("-time_step_safety",
                             "time step as a fraction of the stable limit, used when -ts_dt is not given (0 < s <= 1; default 0.9, 0.5 with interfaces)", "SimulationRun",
                             o->safety, &o->safety, &o->safety_set));
  PetscCall(PetscOptionsReal("-progress_interval", "wall-clock time between progress lines [s], >= 0 (0: every step)", "SimulationRun", o->progress_interval,
                             &o->progress_interval, nullptr));
  PetscCall(PetscOptionsReal("-energy_growth_limit", "stop when kinetic+strain energy exceeds this multiple of the energy put in [-], > 0 (divergence guard)", "SimulationRun",
                             o->energy_growth_limit, &o->energy_growth_limit, nullptr));
  PetscCall(PetscOptionsBool("-dry_run", "print the setup report (stable step, what governs it, points per wavelength) and stop", "SimulationRun", o->dry_run,
                             &o->dry_run, nullptr));
  PetscCall(PetscOptionsInt("-checkpoint_interval", "write the full state to OUTPUT_DIR/checkpoint.bin every N steps [steps], >= 0 (0: never)", "SimulationRun",
                            o->checkpoint_interval, &o->checkpoint_interval, nullptr));
  PetscCall(PetscOptionsString("-restart", "continue from this checkpoint file (same scene options and number of ranks)", "SimulationRun", o->restart, o->restart,
                               sizeof o->restart, nullptr));
  PetscInt nv = 3;
  PetscCall(PetscOptionsRealArray("-initial_velocity", "uniform initial velocity vx,vy[,vz] of every free node [m/s]", "SimulationRun", o->initial_velocity, &nv,
                                  nullptr));
  PetscOptionsEnd();
  PetscCheck(o->checkpoint_interval >= 0, comm, PETSC_ERR_USER_INPUT, "-checkpoint_interval = %" PetscInt_FMT "; allowed: >= 0 steps", o->checkpoint_interval);
  PetscCheck(!o->safety_set || (o->safety > 0 && o->safety <= 1), comm, PETSC_ERR_USER_INPUT, "-time_step_safety = %g; allowed: 0 < s <= 1", (double)o->safety);
  PetscFunctionReturn(0);
}

// Where the first non-finite value is: rank, node, coordinates, field, component.
PetscErrorCode divergenceGuard(Run *r, PetscReal h, PetscInt step, PetscReal t, Vec u, Vec v) {
  MPI_Comm comm = r->model.comm;
  PetscFunctionBeginUser;
  // The ledger's global sums run over every dof of u and v: a NaN or Inf anywhere makes
  // them non-finite, so no extra pass is needed to detect it, only to locate it.
  const model::EnergyLedger &e = r->ledger;
  if (std::isfinite(e.kinetic) && std::isfinite(e.strain) && std::isfinite(e.shadow)) {
    // Net work the interfaces did on the bulk is energy put in too: an interface started under
    // a normal traction (-interface_<name>_sigma_N0) stores energy and releases it at once.
    const double put_in = std::fabs(r->ledger.shadow_start) + std::fabs(r->ledger.input) + std::fabs(r->ledger.external) + std::fabs(r->ledger.reactions) +
                          std::fmax(r->ledger.interface_work, 0.0);
    const double energy = r->ledger.kinetic + std::fabs(r->ledger.strain);
    PetscCheck(!(put_in > 0 && energy > r->opt.energy_growth_limit * put_in), comm, PETSC_ERR_NOT_CONVERGED,
               "diverged at step %" PetscInt_FMT ", t = %g s: kinetic + strain energy %g J exceeds %g x the energy put in (%g J); the time step %g s may be above the stable limit %g s",
               step, (double)t, energy, (double)r->opt.energy_growth_limit, put_in, (double)h, r->step.dt_limit);
    PetscFunctionReturn(0);
  }
  PetscCall(PetscLogEventBegin(event_guard, 0, 0, 0, 0));
  // Locate: the lowest global dof that is not finite, in u first, then v.
  const char *names[2] = {"displacement", "velocity"};
  Vec         vecs[2]  = {u, v};
  for (int f = 0; f < 2; ++f) {
    PetscInt           n, lo, bad = PETSC_MAX_INT;
    const PetscScalar *x;
    PetscCall(VecGetOwnershipRange(vecs[f], &lo, nullptr));
    PetscCall(VecGetLocalSize(vecs[f], &n));
    PetscCall(VecGetArrayRead(vecs[f], &x));
    for (PetscInt i = 0; i < n && bad == PETSC_MAX_INT; ++i)
      if (!std::isfinite(PetscRealPart(x[i]))) bad = lo + i;
    PetscCall(VecRestoreArrayRead(vecs[f], &x));
    PetscInt first;
    PetscCallMPI(MPI_Allreduce(&bad, &first, 1, MPIU_INT, MPI_MIN, comm));
    if (first == PETSC_MAX_INT) continue;
    const PetscInt dim = r->model.dim;
    SETERRQ(comm, PETSC_ERR_NOT_CONVERGED,
            "diverged at step %" PetscInt_FMT ", t = %g s: %s is not finite at node %" PetscInt_FMT " (global numbering of the output), component %c; stable step limit %g s (%s)",
            step, (double)t, names[f], first / dim, "xyz"[first % dim], r->step.dt_limit, r->step.governing.c_str());
  }
  PetscCall(PetscLogEventEnd(event_guard, 0, 0, 0, 0));
  SETERRQ(comm, PETSC_ERR_NOT_CONVERGED, "diverged at step %" PetscInt_FMT ", t = %g s: the energy is not finite but u and v are; the forces are", step, (double)t);
}

PetscErrorCode monitor(TS ts, PetscInt step, PetscReal t, Vec u, void *ctx) {
  auto *r = static_cast<Run *>(ctx);
  Vec   v, a;
  PetscReal h;
  PetscFunctionBeginUser;
  if (r->resumed) {
    r->resumed = false;
    PetscFunctionReturn(0);
  }
  PetscCall(TS2GetSolution(ts, &u, &v));
  PetscCall(time::CentralDifferenceGetAcceleration(ts, &a));
  PetscCall(TSGetTimeStep(ts, &h));
  PetscCall(model::EnergyLedgerUpdate(&r->model, ts, h, &r->ledger));
  PetscCall(divergenceGuard(r, h, step, t, u, v));
  PetscCall(r->stations.Sample(r->model.dm, t, u, v, a));
  interface::InterfaceTotals totals;
  for (const auto &iface : r->model.interfaces) {
    interface::InterfaceTotals one;
    PetscCall(iface.Totals(&one));
    totals.stored += one.stored;
    totals.dissipated += one.dissipated;
  }
  if (r->rank == 0 && r->energy_csv) {
    const model::EnergyLedger &e = r->ledger;
    std::fprintf(r->energy_csv, "%" PetscInt_FMT ",%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.3e\n", step, (double)t, e.kinetic,
                 e.strain, e.input, e.external + e.reactions, e.absorbed, e.damped, e.anelastic, e.interface_work, totals.stored, totals.dissipated, e.contact_damped,
                 e.shadow - e.shadow_start,
                 e.balance_error, e.relativeError());
  }
  const bool last = t >= r->max_time * (1 - 1e-12);
  if (r->opt.fields && (t >= r->next_output * (1 - 1e-12) || last || step == 0)) {
    PetscCall(r->volume.Write(r->model.dm, r->model.bulk, r->frames, t, u, v, a, r->model.initial_stress));
    for (size_t k = 0; k < r->interface_outputs.size(); ++k) PetscCall(r->interface_outputs[k]->Write(r->model.interfaces[k], r->frames, t));
    ++r->frames;
    r->frame_times.push_back(t);
    while (r->next_output <= t * (1 + 1e-12)) r->next_output += r->opt.output_interval;
  }
  if (r->opt.checkpoint_interval > 0 && step > 0 && step % r->opt.checkpoint_interval == 0) {
    if (r->energy_csv) std::fflush(r->energy_csv);
    PetscCall(CheckpointWrite(std::string(r->opt.output_dir) + "/checkpoint.bin", checkpointState(r, ts)));
  }
  PetscLogDouble now;
  PetscCall(PetscTime(&now));
  if (step == 0 || last || now - r->wall_last_progress >= r->opt.progress_interval) {
    const double elapsed = now - r->wall_start;
    const double eta     = t > 0 ? elapsed * (r->max_time - t) / t : 0;
    PetscCall(PetscPrintf(r->model.comm, "step %6" PetscInt_FMT "  t = %.4e s  dt = %.3e s  wall %7.1f s  ETA %7.1f s  energy kin %.3e strain %.3e  balance %.1e\n",
                          step, (double)t, (double)h, elapsed, eta, r->ledger.kinetic, r->ledger.strain, r->ledger.relativeError()));
    r->wall_last_progress = now;
  }
  PetscFunctionReturn(0);
}

// -initial_velocity_<region> vx,vy[,vz]: every node of the region's cells (after the split,
// bodies separated by an interface can be launched against each other). Read with the other
// options, applied when the run starts.
PetscErrorCode readRegionInitialVelocities(Run *r) {
  const PetscInt dim = r->model.dim;
  PetscFunctionBeginUser;
  r->region_velocity.assign(r->model.materials.size(), {});
  PetscOptionsBegin(r->model.comm, "", "Initial conditions", "slipwave");
  for (size_t reg = 0; reg < r->model.materials.size(); ++reg) {
    const std::string opt = "-initial_velocity_" + r->model.materials[reg].region;
    PetscReal         vel[3] = {0, 0, 0};
    PetscInt          n      = 3;
    PetscBool         set;
    PetscCall(PetscOptionsRealArray(opt.c_str(), "initial velocity vx,vy[,vz] of the region's nodes [m/s]", "SimulationRun", vel, &n, &set));
    if (!set) continue;
    PetscCheck(n == dim, r->model.comm, PETSC_ERR_USER_INPUT, "%s has %" PetscInt_FMT " values; allowed: %" PetscInt_FMT, opt.c_str(), n, dim);
    r->region_velocity[reg].assign(vel, vel + dim);
  }
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

PetscErrorCode setRegionInitialVelocities(Run *r, Vec v) {
  const PetscInt dim = r->model.dim;
  Vec            local;
  PetscFunctionBeginUser;
  bool any = false;
  for (const auto &vel : r->region_velocity) any = any || !vel.empty();
  if (!any) PetscFunctionReturn(0);
  PetscCall(DMGetLocalVector(r->model.dm, &local));
  PetscCall(DMGlobalToLocal(r->model.dm, v, INSERT_VALUES, local));
  PetscScalar *va;
  PetscCall(VecGetArray(local, &va));
  for (PetscInt c = 0; c < r->model.bulk.cellCount(); ++c) {
    const auto &vel = r->region_velocity[r->model.bulk.cellRegion(c)];
    if (vel.empty()) continue;
    for (PetscInt a = 0; a < r->model.bulk.nodesPerCell(); ++a)
      for (PetscInt d = 0; d < dim; ++d) va[r->model.bulk.cellNodeOffset(c, a) + d] = vel[d];
  }
  PetscCall(VecRestoreArray(local, &va));
  PetscCall(DMLocalToGlobal(r->model.dm, local, INSERT_VALUES, v));
  PetscCall(VecPointwiseMult(v, v, r->model.bc.free_mask));
  PetscCall(DMRestoreLocalVector(r->model.dm, &local));
  PetscFunctionReturn(0);
}

// energy.csv: a new file, or after a restart the rows up to the restart step, then appended.
PetscErrorCode openEnergyCsv(Run *r) {
  const std::string path = std::string(r->opt.output_dir) + "/energy.csv";
  const char *header = "step,time,kinetic,strain,input_work,external_work,absorbed,damped,anelastic,interface_work,interface_stored,interface_dissipated,contact_damped,stored_change,"
                       "balance_error,relative_balance_error\n";
  PetscFunctionBeginUser;
  std::string kept = header;
  if (r->opt.restart[0]) {
    PetscInt restart_step = r->restart_step;
    if (FILE *in = std::fopen(path.c_str(), "r")) {
      char line[4096];
      kept.clear();
      while (std::fgets(line, sizeof line, in)) {
        long step = 0;
        if (kept.empty() || (std::sscanf(line, "%ld,", &step) == 1 && step <= restart_step)) kept += line;
      }
      std::fclose(in);
    }
  }
  r->energy_csv = std::fopen(path.c_str(), "w");
  PetscCheck(r->energy_csv, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-output_dir = %s: cannot write energy.csv there", r->opt.output_dir);
  std::fputs(kept.c_str(), r->energy_csv);
  PetscFunctionReturn(0);
}

// Memory in use after setup (all ranks) and a run-time estimate: the element loop timed here
// times the ratio of a whole step to it (measured: 2.6 on a 512^2 mesh, docs/performance.md;
// 4.3 on the default scene, where the per-step vector work weighs more; 4 is used, so the
// estimate is good to a factor 2), doubled with stiffness-proportional damping (a second loop).
PetscErrorCode reportCost(Run *r, double steps) {
  constexpr double kStepOverLoop = 4.0;
  PetscLogDouble   memory, t0, t1;
  PetscFunctionBeginUser;
  PetscCall(PetscMemoryGetCurrentUsage(&memory));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &memory, 1, MPI_DOUBLE, MPI_SUM, r->model.comm));
  std::vector<PetscScalar> u, f;
  PetscInt                 n;
  PetscCall(VecGetLocalSize(r->model.u_local, &n));
  u.assign(n, 1e-6);
  f.assign(n, 0.0);
  PetscCall(PetscTime(&t0));
  const int repeats = 5;
  for (int k = 0; k < repeats; ++k) r->model.bulk.addStiffnessTimes(u.data(), f.data());
  PetscCall(PetscTime(&t1));
  double loop = (t1 - t0) / repeats;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &loop, 1, MPI_DOUBLE, MPI_MAX, r->model.comm));
  const double per_step = loop * kStepOverLoop * (r->model.rayleigh.beta > 0 ? 2 : 1);
  PetscCall(PetscPrintf(r->model.comm, "  memory in use after setup: %.1f MB (all ranks); estimated run time %.0f s (%.0f steps x %.3g ms; within a factor 2)\n",
                        memory / 1048576.0, steps * per_step, steps, 1e3 * per_step));
  PetscFunctionReturn(0);
}

// The highest frequency the mesh carries: 10 points per S wavelength in the slowest region
// (Kuhlemeyer & Lysmer 1973: elements of 1/8 to 1/10 of the shortest wavelength), with the
// smallest cell size of the mesh.
constexpr double kPointsPerWavelength = 10;

struct Resolution {
  double      frequency = 0; // Hz
  std::string region;
};

Resolution resolvedFrequency(const Run *r) {
  Resolution res;
  for (const auto &m : r->model.materials) {
    const double f = m.elastic.vs / (kPointsPerWavelength * r->model.bulk.minCellSize());
    if (res.region.empty() || f < res.frequency) res = {f, m.region};
  }
  return res;
}

// OUTPUT_DIR/run_info.json: what scripts/plot_results.py needs to label its plots.
void writeRunInfo(const Run *r, double dt) {
  const Resolution res  = resolvedFrequency(r);
  const std::string path = std::string(r->opt.output_dir) + "/run_info.json";
  if (FILE *f = std::fopen(path.c_str(), "w")) {
    std::fprintf(f, "{\"resolved_frequency_hz\": %.6g, \"points_per_wavelength\": %g, \"slowest_region\": \"%s\", \"h_min_m\": %.6g,\n", res.frequency,
                 kPointsPerWavelength, res.region.c_str(), r->model.bulk.minCellSize());
    std::fprintf(f, " \"input_top_frequency_hz\": %.6g, \"time_step_s\": %.10g}\n", r->model.bc.input.active() ? r->model.bc.input.topFrequency() : 0.0, dt);
    std::fclose(f);
  }
}

PetscErrorCode report(Run *r, TS ts) {
  MPI_Comm    comm = r->model.comm;
  PetscMPIInt size;
  PetscReal   dt;
  PetscInt    n_nodes, ncell_local = r->model.bulk.cellCount(), ncell;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(VecGetSize(r->model.mass, &n_nodes));
  PetscCallMPI(MPI_Allreduce(&ncell_local, &ncell, 1, MPIU_INT, MPI_SUM, comm));
  PetscCall(TSGetTimeStep(ts, &dt));
  PetscCall(PetscPrintf(comm, "slipwave: explicit elastodynamics, %" PetscInt_FMT "D %s, %d rank%s (partitioner %s)\n", r->model.dim,
                        r->model.dim == 2 ? "plane strain" : "", size, size > 1 ? "s" : "", r->model.mesh.partitioner.c_str()));
  PetscCall(PetscPrintf(comm, "  mesh: %s, %" PetscInt_FMT " cells, %" PetscInt_FMT " nodes, %" PetscInt_FMT " distinct element matrices on rank 0\n",
                        r->model.mesh.source.c_str(), ncell, n_nodes / r->model.dim, r->model.bulk.distinctMatrices()));
  const double fmax = r->model.bc.input.active() ? r->model.bc.input.topFrequency() : 0.0;
  for (const auto &m : r->model.materials) {
    PetscCall(PetscPrintf(comm, "  region %-10s rho %8.1f kg/m3  vp %8.1f m/s  vs %8.1f m/s", m.region.c_str(), m.elastic.rho, m.elastic.vp, m.elastic.vs));
    if (fmax > 0) PetscCall(PetscPrintf(comm, "  %5.1f points per S wavelength at %.2f Hz (h_min %.3g m)", m.elastic.vs / fmax / r->model.bulk.minCellSize(), fmax,
                                        r->model.bulk.minCellSize()));
    PetscCall(PetscPrintf(comm, "\n"));
  }
  const Resolution res = resolvedFrequency(r);
  PetscCall(PetscPrintf(comm, "  resolution: S waves up to %.3g Hz (%d points per wavelength in region %s, h_min %.3g m)\n", res.frequency, (int)kPointsPerWavelength,
                        res.region.c_str(), r->model.bulk.minCellSize()));
  std::string bcs;
  for (size_t i = 0; i < r->model.bc.names.size(); ++i) bcs += " " + r->model.bc.names[i] + "=" + model::boundaryTypeName(r->model.bc.types[i]);
  PetscCall(PetscPrintf(comm, "  boundaries:%s\n", bcs.c_str()));
  for (const std::string &w : r->model.bc.warnings) PetscCall(PetscPrintf(comm, "  warning: %s\n", w.c_str()));
  if (r->model.bc.input_wave != model::InputWave::None)
    PetscCall(PetscPrintf(comm, "  input: %s wave through '%s', %s\n", model::inputWaveName(r->model.bc.input_wave), r->model.bc.input_boundary.c_str(),
                          r->model.bc.input.describe().c_str()));
  if (r->model.damping_ratio > 0)
    PetscCall(PetscPrintf(comm, "  Rayleigh damping %.3g %% at %g and %g Hz: alpha %.4g 1/s, beta %.4g s\n", 100 * r->model.damping_ratio, r->model.damping_f1,
                          r->model.damping_f2, r->model.rayleigh.alpha, r->model.rayleigh.beta));
  if (r->model.rayleigh.beta > 0)
    PetscCall(PetscPrintf(comm, "    its stiffness-proportional part lowers the stable step from %.4e s (undamped) to %.4e s (-%.1f %%)\n",
                          r->step.dt_without_stiffness_damping, r->step.dt_bulk, 100 * (1 - r->step.dt_bulk / r->step.dt_without_stiffness_damping)));
  for (const std::string &line : model::AttenuationReport(r->model.attenuation, r->model.materials)) PetscCall(PetscPrintf(comm, "%s\n", line.c_str()));
  for (size_t k = 0; k < r->model.interfaces.size(); ++k) {
    const auto &iface = r->model.interfaces[k];
    const auto &p     = iface.params();
    PetscCall(PetscPrintf(comm, "  interface %s between %s (soil side) and %s: %" PetscInt_FMT " node pairs; phi %.4g deg, psi %.4g deg, c %.4g Pa, e_ini %.4g m\n",
                          iface.spec().name.c_str(), iface.spec().soil_region.c_str(), iface.spec().structure_region.c_str(), iface.pairs().n_global,
                          p.phi * 180 / PETSC_PI, p.psi * 180 / PETSC_PI, p.c, p.e_ini));
    PetscInt cut;
    PetscCall(iface.CountCutPairs(r->model.mass, &cut));
    PetscCall(PetscPrintf(comm, "    %s; %" PetscInt_FMT " pairs have their two nodes on different ranks\n", r->model.penalty_notes[k].c_str(), cut));
    double c_min, c_max;
    PetscCall(iface.DashpotRange(&c_min, &c_max));
    PetscCall(PetscPrintf(comm, "    contact damping %.3g of critical on closed pairs (normal dashpots %.4g .. %.4g N s/m)\n", iface.contactDamping(), c_min, c_max));
  }
  for (const std::string &line : r->stations.ambiguities()) PetscCall(PetscPrintf(comm, "  %s\n", line.c_str()));
  PetscCall(PetscPrintf(comm, "  stable step: %.4e s (%s); h_min/vp_max = %.4e s for comparison\n", r->step.dt_limit, r->step.governing.c_str(), r->step.dt_cfl));
  if (r->step.dt_limit < r->step.dt_without_interfaces * (1 - 1e-12))
    PetscCall(PetscPrintf(comm, "  warning: the interface penalty lowers the stable step from %.4e s (bulk alone) to %.4e s (-%.1f %%)\n", r->step.dt_without_interfaces,
                          r->step.dt_limit, 100 * (1 - r->step.dt_limit / r->step.dt_without_interfaces)));
  PetscCall(PetscPrintf(comm, "  time step %.4e s = %.3f of the limit; %.0f steps to t = %g s\n", (double)dt, dt / r->step.dt_limit, std::ceil(r->max_time / dt),
                        (double)r->max_time));
  PetscCall(PetscPrintf(comm, "  output: %s/\n", r->opt.output_dir));
  PetscCall(reportCost(r, std::ceil(r->max_time / dt)));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode SimulationRun(MPI_Comm comm) {
  Run *r = new Run();
  TS   ts;
  Vec  u, v;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &r->rank));
  PetscCall(LogEventsRegister());
  PetscCall(time::CentralDifferenceRegister());
  PetscCall(PetscLogStagePush(stage_setup));
  PetscCall(readRunOptions(comm, &r->opt));
  PetscCall(model::ElastodynamicsCreate(comm, &r->model));
  PetscCall(model::ElastodynamicsStableStep(&r->model, &r->step));
  PetscCall(r->stations.Setup(r->model.dm, r->model.bulk, r->model.mesh));
  PetscCall(readRegionInitialVelocities(r));
  PetscCall(model::GeostaticOptionsRead(comm, &r->geostatic));

  if (!r->opt.safety_set) r->opt.safety = r->model.interfaces.empty() ? kSafetyBulk : kSafetyInterfaces;
  PetscCall(TSCreate(comm, &ts));
  PetscCall(TSSetType(ts, time::kTSCentralDifference));
  PetscCall(TSSetRHSFunction(ts, nullptr, model::ElastodynamicsRHS, &r->model));
  PetscCall(TSSetMaxTime(ts, 1.0));
  PetscCall(TSSetMaxSteps(ts, PETSC_MAX_INT));
  PetscCall(TSSetExactFinalTime(ts, TS_EXACTFINALTIME_MATCHSTEP));
  PetscCall(TSSetTimeStep(ts, r->opt.safety * r->step.dt_limit));
  PetscCall(TSSetFromOptions(ts));
  PetscBool user_dt;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-ts_dt", &user_dt));
  PetscCall(TSGetMaxTime(ts, &r->max_time));
  if (!user_dt && r->max_time > 0) {
    // A whole number of equal steps: a shortened last step would break the constant-step
    // energy identity the ledger checks.
    PetscCall(TSSetTimeStep(ts, r->max_time / std::ceil(r->max_time / (r->opt.safety * r->step.dt_limit))));
  }
  r->model.ts = ts;
  PetscReal dt;
  PetscCall(TSGetTimeStep(ts, &dt));
  PetscCheck(dt <= r->step.dt_limit, comm, PETSC_ERR_USER_INPUT,
             "-ts_dt = %.6g s is above the stable limit %.6g s (%s); allowed: 0 < dt <= %.6g s (omit -ts_dt to use %.2f of the limit)", (double)dt, r->step.dt_limit,
             r->step.governing.c_str(), r->step.dt_limit, (double)r->opt.safety);
  PetscCheck(dt > 0, comm, PETSC_ERR_USER_INPUT, "-ts_dt = %g; allowed: 0 < dt <= %.6g s", (double)dt, r->step.dt_limit);
  PetscCheck(r->max_time > 0, comm, PETSC_ERR_USER_INPUT, "-ts_max_time = %g; allowed: > 0 s", (double)r->max_time);
  if (r->opt.output_interval <= 0) r->opt.output_interval = r->max_time / 50;
  PetscCall(time::CentralDifferenceSetNodalDamping(ts, r->model.dim, r->model.damping_blocks));
  PetscCall(OptionsErrorIfUnused(comm));
  PetscCall(report(r, ts));
  PetscCall(PetscLogStagePop());
  PetscBool help;
  PetscCall(PetscOptionsHasHelp(nullptr, &help));
  if (r->opt.dry_run || help) {
    PetscCall(PetscPrintf(comm, "%s: stopping before the first step\n", help ? "-help" : "dry run"));
  } else {
    PetscCall(DMCreateGlobalVector(r->model.dm, &u));
    PetscCall(VecDuplicate(u, &v));
    PetscCall(VecZeroEntries(u));
    std::vector<std::pair<PetscInt, PetscReal>> previous_frames;
    if (r->opt.restart[0]) {
      // Everything the geostatic stage and the steps so far produced comes from the file.
      PetscCall(TS2SetSolution(ts, u, v));
      PetscCall(CheckpointRead(r->opt.restart, checkpointState(r, ts)));
      PetscCall(TSGetStepNumber(ts, &r->restart_step));
      for (size_t k = 0; k < r->frame_times.size(); ++k) previous_frames.emplace_back((PetscInt)k, r->frame_times[k]);
      r->frames  = (PetscInt)r->frame_times.size();
      r->resumed = true;
      PetscReal t;
      PetscCall(TSGetTime(ts, &t));
      PetscCall(PetscPrintf(comm, "restart: continuing from step %" PetscInt_FMT ", t = %g s (%s)\n", r->restart_step, (double)t, r->opt.restart));
    } else {
      if (r->geostatic.enabled) {
        model::GeostaticReport g;
        PetscReal              dt_geo;
        PetscCall(TSGetTimeStep(ts, &dt_geo));
        PetscCall(model::GeostaticStage(&r->model, r->geostatic, dt_geo, &g));
        PetscCall(PetscPrintf(comm, "%s\n", model::GeostaticReportLine(r->geostatic, g).c_str()));
      }
      PetscInt           n;
      PetscScalar       *va;
      const PetscScalar *mask;
      PetscCall(VecGetLocalSize(v, &n));
      PetscCall(VecGetArray(v, &va));
      PetscCall(VecGetArrayRead(r->model.bc.free_mask, &mask));
      for (PetscInt i = 0; i < n; ++i) va[i] = mask[i] * r->opt.initial_velocity[i % r->model.dim];
      PetscCall(VecRestoreArrayRead(r->model.bc.free_mask, &mask));
      PetscCall(VecRestoreArray(v, &va));
      PetscCall(setRegionInitialVelocities(r, v));
      PetscCall(TS2SetSolution(ts, u, v));
      PetscCall(time::CentralDifferenceComputeInitialAcceleration(ts));
    }
    if (r->rank == 0) {
      std::filesystem::create_directories(r->opt.output_dir);
      PetscCall(openEnergyCsv(r));
      writeRunInfo(r, dt);
    }
    if (r->opt.fields) {
      const auto *previous = r->opt.restart[0] ? &previous_frames : nullptr;
      PetscCall(r->volume.Open(r->model.dm, r->model.bulk, r->opt.output_dir, previous));
      for (const auto &iface : r->model.interfaces) {
        r->interface_outputs.push_back(std::make_unique<io::InterfaceOutput>());
        PetscCall(r->interface_outputs.back()->Open(comm, r->model.dim, iface, r->opt.output_dir, previous));
      }
    }
    PetscCall(TSMonitorSet(ts, monitor, r, nullptr));
    PetscCall(PetscTime(&r->wall_start));
    r->wall_last_progress = r->wall_start;
    PetscCall(PetscLogStagePush(stage_solve));
    PetscCall(TSSolve(ts, u));
    PetscCall(PetscLogStagePop());
    PetscLogDouble wall_end;
    PetscCall(PetscTime(&wall_end));
    PetscInt steps;
    PetscCall(TSGetStepNumber(ts, &steps));
    if (r->energy_csv) std::fclose(r->energy_csv);
    PetscCall(r->stations.Write(comm, r->opt.output_dir));
    if (r->opt.fields) {
      PetscCall(r->volume.Close());
      for (auto &out : r->interface_outputs) PetscCall(out->Close());
    }
    for (const auto &iface : r->model.interfaces) {
      interface::InterfaceTotals t;
      PetscCall(iface.Totals(&t));
      PetscCall(PetscPrintf(comm, "interface %s: %" PetscInt_FMT " stick, %" PetscInt_FMT " slip, %" PetscInt_FMT " open at the end; dissipated %.4g J; largest yield-surface drift corrected %.3g Pa\n",
                            iface.spec().name.c_str(), t.n_stick, t.n_slip, t.n_open, t.dissipated, t.max_drift));
    }
    if (!r->model.interfaces.empty()) PetscCall(PetscPrintf(comm, "contact dashpots (all interfaces): took %.4g J\n", r->ledger.contact_damped));
    PetscCall(PetscPrintf(comm, "done: %" PetscInt_FMT " steps in %.2f s wall (%.3g s per step); energy balance error %.2e of the largest energy\n", steps,
                          wall_end - r->wall_start, (wall_end - r->wall_start) / std::max<PetscInt>(steps, 1), r->ledger.relativeError()));
    PetscCall(PetscPrintf(comm, "output in %s/: volume.xmf%s (open in ParaView), energy.csv%s\n", r->opt.output_dir, r->model.interfaces.empty() ? "" : ", interface_<name>.xmf", r->stations.empty() ? "" : ", stations/*.csv, stations.h5"));
    PetscCall(VecDestroy(&u));
    PetscCall(VecDestroy(&v));
  }
  PetscCall(TSDestroy(&ts));
  PetscCall(model::GeostaticOptionsDestroy(&r->geostatic));
  PetscCall(r->stations.Destroy());
  PetscCall(model::ElastodynamicsDestroy(&r->model));
  delete r;
  PetscFunctionReturn(0);
}

} // namespace slipwave::app
