// What a run tells its user: the setup report before the first step (mesh, materials and
// resolution, boundaries and their warnings, input, damping and attenuation, interfaces,
// station notes, the stable step and the step chosen, memory and a run-time estimate),
// OUTPUT_DIR/run_info.json for the plotting script, and the summary after the last step.
#pragma once
#include <petscsys.h>

#include <string>

#include "slipwave/io/stations.hpp"
#include "slipwave/problem/elastodynamics.hpp"
#include "slipwave/problem/energy_ledger.hpp"
#include "slipwave/problem/integrator_step.hpp"
#include "slipwave/problem/stable_step.hpp"

namespace slipwave::app {

// integrator: the order and the step's choice; dt: the time step chosen; max_time: -ts_max_time [s]; output_interval: between frames [s].
// Compact by default (mesh, materials and their damping, resolution, input, interfaces, the
// step and what governs it, output, memory and the run-time estimate, every warning);
// verbose (-report_verbose) adds the details: boundaries, loads, damping fits, rigid bodies,
// interface penalties and dashpots, pore-pressure stepping, stations on interfaces.
PetscErrorCode ReportSetup(const problem::Elastodynamics &model, const problem::StableStep &limit, const problem::IntegratorStep &integrator, const io::Stations &stations, PetscReal dt,
                           PetscReal max_time, const std::string &output_dir, PetscReal output_interval, bool verbose);

// Rank 0: OUTPUT_DIR/run_info.json (resolved frequency, h_min, input top frequency, dt; with
// hysteretic soil, each region's backbone and the parameters it was built from; with mass
// scaling, what it added); answers: a
// JSON object for its "answers" (app/run_answers.hpp; written again at the end of the run).
void WriteRunInfo(const problem::Elastodynamics &model, const problem::StableStep &step, const std::string &output_dir, double dt, const std::string &answers = "");

// The corner of the low-passed peaks: p vs_min / (8 h), h the largest element of the region
// that resolves least (what scripts/scene_metrics.py calls the resolved frequency; the
// report's own resolved frequency asks for 10 nodes per wavelength at p = 1, this for 8).
double LowPassCornerFrequency(const problem::Elastodynamics &model);

// The interfaces' final states (and a warning when pairs opened or closed while the step, dt of the limit
// `step`, was above kSafetyInterfaces of it), the contact dashpots' work, steps and wall time,
// the energy balance error and where the output is: files, the names of the run's files in it.
PetscErrorCode ReportEnd(const problem::Elastodynamics &model, const problem::EnergyLedger &ledger, const problem::StableStep &step, double dt, const std::vector<std::string> &files,
                         PetscInt steps, double wall, const std::string &output_dir);

} // namespace slipwave::app
