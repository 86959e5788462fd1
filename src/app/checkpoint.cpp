#include "slipwave/app/checkpoint.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "slipwave/app/checkpoint_seal.hpp"
#include "slipwave/app/scene_options.hpp"
#include "slipwave/input/drm.hpp"
#include "slipwave/input/free_field.hpp"
#include "slipwave/medium/attenuation.hpp"
#include "slipwave/medium/hysteresis.hpp"
#include "slipwave/porous/pore_pressure.hpp"
#include "slipwave/time/central_difference.hpp"

namespace slipwave::app {
namespace {

constexpr PetscInt kMagic   = 0x53574350; // "SWCP"
constexpr PetscInt kVersion = 15; // 2: ledger with `anelastic`, attenuation memory; 3: and `contact_damped`;
                                 // 4: state only (no RHS force parts, no attenuation trial);
                                 // 5: the scene options after the header, a seal at the end;
                                 // 6: the pore pressure state and the ledger's fluid terms;
                                 // 7: free-field columns keep constant-Q memory at every GLL
                                 //    point of a segment (both ends at p = 1)
                                 // 8: the hysteretic soil's state and the ledger's hysteretic work
                                 //    (a free-field column beside hysteretic soil appends its Iwan
                                 //    states to its record; a linear column's record is unchanged)
                                 // 9: the pore pressure's cavities and the ledger's cavitation work
                                 // 10: each hysteretic point's state opens with a header (its
                                 //    tail, physics/hysteretic_soil.hpp)
                                 // 11: each interface's count of open/closed switches after its drift
                                 // 12: the ledger's integrator_correction; at order 4 the two
                                 //    accelerations before the current one (the reported velocity)
                                 // 13: each interface pair's sigma* (the friction lag's normal traction)
                                 // 14: a free-field column beside saturated soil appends its pore
                                 //    pressure state (p, alpha Q u, cavities)
                                 // 15: DRM on a saturated site appends its pore pressure terms (G, r, W)
constexpr PetscInt kHeader  = 10;

// The ledger as a flat array, in a fixed order.
std::vector<double> ledgerArray(const problem::EnergyLedger &e) {
  return {e.kinetic, e.strain,        e.input,        e.external,      e.reactions, e.absorbed,          e.damped, e.interface_work,
          e.shadow,  e.shadow_start,  e.balance_error, e.scale,        e.h_prev,    e.started ? 1.0 : 0.0, e.anelastic, e.contact_damped,
          e.fluid_stored, e.darcy, e.fluid_inflow, e.hysteretic_work, e.hysteretic_dissipated, e.cavitation, e.integrator_correction};
}

void ledgerFromArray(const double *a, problem::EnergyLedger *e) {
  e->kinetic = a[0], e->strain = a[1], e->input = a[2], e->external = a[3], e->reactions = a[4], e->absorbed = a[5], e->damped = a[6];
  e->interface_work = a[7], e->shadow = a[8], e->shadow_start = a[9], e->balance_error = a[10], e->scale = a[11], e->h_prev = a[12];
  e->started = a[13] != 0, e->anelastic = a[14], e->contact_damped = a[15];
  e->fluid_stored = a[16], e->darcy = a[17], e->fluid_inflow = a[18];
  e->hysteretic_work = a[19], e->hysteretic_dissipated = a[20];
  e->cavitation = a[21];
  e->integrator_correction = a[22];
  e->external_gross = std::fabs(e->external); // not stored: the net work bounds it from below
}
constexpr PetscInt kLedgerSize = 23;

std::vector<Vec> stateVectors(const CheckpointState &s) {
  Vec u, v, a, a_previous, a_before;
  TS2GetSolution(s.ts, &u, &v);
  time::CentralDifferenceGetAcceleration(s.ts, &a);
  // The force parts of the last RHS evaluation are not state: the next step recomputes them
  // before the ledger reads them (the monitor of the restart step itself is skipped). At
  // order 4 the accelerations of the two steps before are (the reported velocity's).
  time::CentralDifferenceGetHistory(s.ts, &a_previous, &a_before);
  if (a_previous) return {u, v, a, s.model->bc.constant_force, a_previous, a_before};
  return {u, v, a, s.model->bc.constant_force};
}

// The committed pore pressure state of a saturated scene (porous/pore_pressure.hpp): p_n,
// alpha Q u_n (the reference of the next strain increment), H p_n (the first diffusion
// sub-step of the next step), the step before's mean H p (the ledger's Darcy term) and the
// cavities' volumes; with DRM its committed G, r and the last step's volume source W
// (porous/pore_pressure_drm.hpp).
std::vector<Vec> poreStateVectors(const CheckpointState &s) {
  const porous::PorePressure *pore = s.model->pore;
  if (!pore) return {};
  std::vector<Vec> x{pore->p, pore->Qu, pore->Hp, pore->Hbar_previous, pore->cavity};
  if (pore->drm_source) x.insert(x.end(), {pore->drm_volume, pore->drm_flow, pore->drm_source_previous});
  return x;
}

// A Vec holding `values` on this rank (its layout defines what a restart must reproduce).
PetscErrorCode viewLocalArray(MPI_Comm comm, const std::vector<double> &values, PetscViewer viewer) {
  Vec          x;
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(VecCreateMPI(comm, (PetscInt)values.size(), PETSC_DETERMINE, &x));
  PetscCall(VecGetArray(x, &a));
  for (size_t i = 0; i < values.size(); ++i) a[i] = values[i];
  PetscCall(VecRestoreArray(x, &a));
  PetscCall(VecView(x, viewer));
  PetscCall(VecDestroy(&x));
  PetscFunctionReturn(0);
}

PetscErrorCode loadLocalArray(MPI_Comm comm, PetscInt local_size, PetscViewer viewer, std::vector<double> *values) {
  Vec                x;
  const PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(VecCreateMPI(comm, local_size, PETSC_DETERMINE, &x));
  PetscCall(VecLoad(x, viewer));
  PetscCall(VecGetArrayRead(x, &a));
  values->assign(a, a + local_size);
  PetscCall(VecRestoreArrayRead(x, &a));
  PetscCall(VecDestroy(&x));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode CheckpointWrite(const std::string &path, const CheckpointState &s) {
  MPI_Comm    comm = s.model->comm;
  PetscMPIInt size, rank;
  PetscViewer viewer;
  PetscInt    step;
  PetscReal   time, dt;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(TSGetStepNumber(s.ts, &step));
  PetscCall(TSGetTime(s.ts, &time));
  PetscCall(TSGetTimeStep(s.ts, &dt));
  const std::string tmp = path + ".tmp";
  PetscCall(PetscViewerBinaryOpen(comm, tmp.c_str(), FILE_MODE_WRITE, &viewer));
  PetscCall(PetscViewerBinarySetSkipInfo(viewer, PETSC_TRUE));
  std::vector<double> samples;
  s.stations->saveRecords(&samples);
  const PetscInt header[kHeader] = {kMagic, kVersion, size, s.model->dim, step, (PetscInt)s.model->interfaces.size(), (PetscInt)s.frame_times->size(),
                                    (PetscInt)!s.model->initial_stress.empty(), s.model->free_field ? (PetscInt)s.model->free_field->sides.size() : 0,
                                    (PetscInt)(s.model->pore != nullptr)};
  PetscCall(PetscViewerBinaryWrite(viewer, header, kHeader, PETSC_INT));
  std::string scene;
  PetscCall(SceneOptionsText(&scene));
  const PetscInt scene_length = (PetscInt)scene.size();
  PetscCall(PetscViewerBinaryWrite(viewer, &scene_length, 1, PETSC_INT));
  PetscCall(PetscViewerBinaryWrite(viewer, scene.data(), scene_length, PETSC_CHAR));
  std::vector<double> scalars = {time, dt, *s.next_output};
  for (double x : ledgerArray(*s.ledger)) scalars.push_back(x);
  for (PetscReal t : *s.frame_times) scalars.push_back(t);
  for (const auto &iface : s.model->interfaces) {
    interface::InterfaceTotals totals;
    PetscCall(iface.Totals(&totals));
    scalars.push_back(iface.maxDrift());
    scalars.push_back((double)totals.switches);
  }
  if (s.model->pore) scalars.push_back(s.model->pore->t);
  PetscCall(PetscViewerBinaryWrite(viewer, scalars.data(), (PetscInt)scalars.size(), PETSC_DOUBLE));
  for (Vec x : stateVectors(s)) PetscCall(VecView(x, viewer));
  if (!s.model->initial_stress.empty()) PetscCall(viewLocalArray(comm, s.model->initial_stress, viewer));
  for (const auto &iface : s.model->interfaces) {
    std::vector<double> state;
    iface.saveState(&state);
    PetscCall(viewLocalArray(comm, state, viewer));
  }
  PetscCall(viewLocalArray(comm, samples, viewer));
  if (s.model->attenuation) PetscCall(viewLocalArray(comm, medium::AttenuationState(s.model->attenuation), viewer));
  if (s.model->hysteresis) PetscCall(viewLocalArray(comm, medium::HysteresisState(s.model->hysteresis), viewer));
  if (s.model->drm) PetscCall(viewLocalArray(comm, input::DrmState(s.model->drm), viewer));
  // The free-field columns are replicated on every rank: rank 0's copy is the state.
  for (PetscInt k = 0; k < header[8]; ++k) {
    const std::vector<double> column = s.model->free_field->sides[k].column.state();
    const PetscInt            n      = (PetscInt)column.size();
    PetscCall(PetscViewerBinaryWrite(viewer, &n, 1, PETSC_INT));
    PetscCall(PetscViewerBinaryWrite(viewer, column.data(), n, PETSC_DOUBLE));
  }
  for (Vec x : poreStateVectors(s)) PetscCall(VecView(x, viewer));
  PetscCall(PetscViewerDestroy(&viewer));
  if (rank == 0) PetscCheck(CheckpointSeal(tmp), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "cannot seal %s: %s", tmp.c_str(), std::strerror(errno));
  if (rank == 0) PetscCheck(std::rename(tmp.c_str(), path.c_str()) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "cannot rename %s to %s", tmp.c_str(), path.c_str());
  PetscCallMPI(MPI_Barrier(comm));
  PetscFunctionReturn(0);
}

namespace {

// The header and the scene text at the start of a checkpoint: a checkpoint of another scene
// is refused, naming the options that differ.
PetscErrorCode readSceneHeader(MPI_Comm comm, const std::string &path, PetscViewer viewer, PetscInt header[kHeader]) {
  PetscFunctionBeginUser;
  PetscCall(PetscViewerBinaryRead(viewer, header, kHeader, nullptr, PETSC_INT));
  PetscCheck(header[0] == kMagic && header[1] == kVersion, comm, PETSC_ERR_USER_INPUT, "-restart = %s is not a slipwave checkpoint (version %" PetscInt_FMT ")",
             path.c_str(), kVersion);
  PetscInt scene_length;
  PetscCall(PetscViewerBinaryRead(viewer, &scene_length, 1, nullptr, PETSC_INT));
  std::string there(scene_length, '\0'), here;
  PetscCall(PetscViewerBinaryRead(viewer, there.data(), scene_length, nullptr, PETSC_CHAR));
  PetscCall(SceneOptionsText(&here));
  const std::string differ = SceneOptionsDifference(there, here);
  PetscCheck(differ.empty(), comm, PETSC_ERR_USER_INPUT, "-restart = %s was written with another scene: %s; allowed: the scene options of the run that wrote it (output, duration and progress options may change)",
             path.c_str(), differ.c_str());
  PetscFunctionReturn(0);
}

} // namespace

std::string CheckpointFolder(const std::string &path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

PetscErrorCode CheckpointVerify(MPI_Comm comm, const std::string &path) {
  PetscMPIInt rank;
  char        problem[256] = "";
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) std::snprintf(problem, sizeof problem, "%s", CheckpointSealProblem(path).c_str());
  PetscCallMPI(MPI_Bcast(problem, sizeof problem, MPI_CHAR, 0, comm));
  PetscCheck(!problem[0], comm, PETSC_ERR_FILE_OPEN, "-restart = %s: %s; allowed: a complete checkpoint written by -checkpoint_interval", path.c_str(), problem);
  // The scene before the mesh and the stations are built: another mesh would otherwise stop
  // on whatever differs first (a station outside it), not on the checkpoint.
  PetscViewer viewer;
  PetscInt    header[kHeader];
  PetscCall(PetscViewerBinaryOpen(comm, path.c_str(), FILE_MODE_READ, &viewer));
  PetscCall(PetscViewerBinarySetSkipInfo(viewer, PETSC_TRUE));
  PetscCall(readSceneHeader(comm, path, viewer, header));
  PetscCall(PetscViewerDestroy(&viewer));
  PetscFunctionReturn(0);
}

PetscErrorCode CheckpointRead(const std::string &path, const CheckpointState &s) {
  MPI_Comm    comm = s.model->comm;
  PetscMPIInt size, rank;
  PetscViewer viewer;
  PetscInt    header[kHeader];
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscViewerBinaryOpen(comm, path.c_str(), FILE_MODE_READ, &viewer));
  PetscCall(PetscViewerBinarySetSkipInfo(viewer, PETSC_TRUE));
  PetscCall(readSceneHeader(comm, path, viewer, header));
  PetscCheck(header[2] == size, comm, PETSC_ERR_USER_INPUT, "-restart = %s was written on %" PetscInt_FMT " ranks; allowed: restart on the same number of ranks (this run: %d)",
             path.c_str(), header[2], size);
  PetscCheck(header[3] == s.model->dim && header[5] == (PetscInt)s.model->interfaces.size(), comm, PETSC_ERR_USER_INPUT,
             "-restart = %s belongs to another scene (%" PetscInt_FMT "D, %" PetscInt_FMT " interfaces); allowed: the scene options of the run that wrote it",
             path.c_str(), header[3], header[5]);
  PetscCheck(header[9] == (PetscInt)(s.model->pore != nullptr), comm, PETSC_ERR_USER_INPUT,
             "-restart = %s belongs to another scene (saturated regions: %s); allowed: the scene options of the run that wrote it", path.c_str(), header[9] ? "yes" : "no");
  const PetscInt      nframes = header[6], ninterfaces = header[5];
  std::vector<double> scalars(3 + kLedgerSize + nframes + 2 * ninterfaces + header[9]);
  PetscCall(PetscViewerBinaryRead(viewer, scalars.data(), (PetscInt)scalars.size(), nullptr, PETSC_DOUBLE));
  PetscCall(TSSetTime(s.ts, scalars[0]));
  PetscCall(TSSetTimeStep(s.ts, scalars[1]));
  PetscCall(TSSetStepNumber(s.ts, header[4]));
  *s.next_output = scalars[2];
  ledgerFromArray(&scalars[3], s.ledger);
  s.frame_times->assign(scalars.begin() + 3 + kLedgerSize, scalars.begin() + 3 + kLedgerSize + nframes);
  PetscCall(TSSetUp(s.ts)); // creates the TS's acceleration vector that the file fills
  std::vector<Vec> vecs = stateVectors(s);
  for (Vec x : vecs) {
    PetscInt n_expected, n_file;
    PetscCall(VecGetSize(x, &n_expected));
    PetscCall(VecLoad(x, viewer));
    PetscCall(VecGetSize(x, &n_file));
    PetscCheck(n_file == n_expected, comm, PETSC_ERR_USER_INPUT, "-restart = %s belongs to another mesh; allowed: the scene options of the run that wrote it", path.c_str());
  }
  PetscCall(time::CentralDifferenceSetAcceleration(s.ts, vecs[2]));
  if (vecs.size() > 4) PetscCall(time::CentralDifferenceSetHistory(s.ts, vecs[4], vecs[5], header[4]));
  if (header[7]) PetscCall(loadLocalArray(comm, 6 * s.model->bulk.cellCount(), viewer, &s.model->initial_stress));
  for (size_t k = 0; k < s.model->interfaces.size(); ++k) {
    auto               &iface = s.model->interfaces[k];
    std::vector<double> state;
    PetscCall(loadLocalArray(comm, (PetscInt)iface.pairs().id.size() * iface.stateWidth(), viewer, &state));
    iface.loadState(state.data());
    iface.setCommittedTime(scalars[0]);
    iface.setMaxDrift(scalars[3 + kLedgerSize + nframes + 2 * k]);
    // The run's total so far, held by one rank (Totals sums the ranks).
    iface.setSwitches(rank == 0 ? (PetscInt)scalars[3 + kLedgerSize + nframes + 2 * k + 1] : 0);
  }
  PetscCall(problem::ElastodynamicsDrainOpenGaps(s.model));
  // Every station has one row per step taken so far (steps 0 .. step).
  if (s.model->pore) s.stations->expectPressure();
  const PetscInt      samples = s.stations->samplesUpTo(header[4]) * s.stations->rowWidth() * (PetscInt)s.stations->localStations();
  std::vector<double> records;
  PetscCall(loadLocalArray(comm, samples, viewer, &records));
  s.stations->loadRecords(records.data(), records.size());
  if (s.model->attenuation) {
    std::vector<double> memory;
    PetscCall(loadLocalArray(comm, medium::AttenuationStateSize(s.model->attenuation), viewer, &memory));
    PetscCheck(medium::AttenuationSetState(s.model->attenuation, memory), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
               "-restart = %s: the attenuation memory does not fit this mesh; allowed: the scene options of the run that wrote it", path.c_str());
  }
  if (s.model->hysteresis) {
    std::vector<double> state;
    PetscCall(loadLocalArray(comm, medium::HysteresisStateSize(s.model->hysteresis), viewer, &state));
    medium::HysteresisSetState(s.model->hysteresis, state);
  }
  if (s.model->drm) {
    std::vector<double> drm;
    PetscCall(loadLocalArray(comm, input::DrmStateSize(s.model->drm), viewer, &drm));
    PetscCheck(input::DrmSetState(s.model->drm, drm), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
               "-restart = %s: the DRM state does not fit this mesh; allowed: the scene options of the run that wrote it", path.c_str());
  }
  const PetscInt sides = s.model->free_field ? (PetscInt)s.model->free_field->sides.size() : 0;
  PetscCheck(header[8] == sides, comm, PETSC_ERR_USER_INPUT, "-restart = %s has %" PetscInt_FMT " free-field sides, this scene %" PetscInt_FMT "; allowed: the scene options of the run that wrote it",
             path.c_str(), header[8], sides);
  for (PetscInt k = 0; k < sides; ++k) {
    PetscInt n;
    PetscCall(PetscViewerBinaryRead(viewer, &n, 1, nullptr, PETSC_INT));
    std::vector<double> column(n);
    PetscCall(PetscViewerBinaryRead(viewer, column.data(), n, nullptr, PETSC_DOUBLE));
    PetscCheck(s.model->free_field->sides[k].column.setState(column), comm, PETSC_ERR_USER_INPUT,
               "-restart = %s: free-field column %" PetscInt_FMT " does not fit this mesh; allowed: the scene options of the run that wrote it", path.c_str(), k);
  }
  for (Vec x : poreStateVectors(s)) PetscCall(VecLoad(x, viewer));
  if (s.model->pore) {
    // The pore pressure update's reference state is the restored one, not the first RHS's.
    s.model->pore->t       = scalars[3 + kLedgerSize + nframes + 2 * ninterfaces];
    s.model->pore->started = true;
    PetscCall(porous::PorePressureDiffuseStep(s.model->pore, scalars[1]));
    // The interfaces' law starts the next step from the restored pressure.
    PetscCall(porous::PorePressureTotal(s.model->pore));
    for (auto &iface : s.model->interfaces) PetscCall(iface.ReadCommittedPorePressure(s.model->pore->p_total));
  }
  PetscCall(PetscViewerDestroy(&viewer));
  PetscFunctionReturn(0);
}

} // namespace slipwave::app
