// Constant-Q (frequency-independent) viscoelastic damping per region: -material_<r>_damping_ratio
// xi > 0 gives the region a generalized Maxwell body (physics/constant_q.hpp) fitted to
// Q = 1/(2 xi) over -attenuation_band with -attenuation_mechanisms mechanisms; the same Q for P
// and S waves (Qp = Qs). The given vp, vs hold at a reference frequency f_r
// (-attenuation_reference_frequency, or chosen by AttenuationChooseReferences); the element
// matrices use the unrelaxed moduli
// M_U = factor * rho c^2.
// Memory variables: with one set of Y_l for P and S, the body acts on the element force
// vector, a damped cell's internal force being K_U u_e - sum_l zeta_l with
//   d zeta_l/dt = w_l (Y_l K_U u_e - zeta_l).
// This ODE is linear with the same coefficients in every cell of a region, so its assembled
// form is the same ODE for the assembled zeta_l driven by the region's assembled K_U u: the
// memory lives on the nodes of each damped region (dim values per mechanism per node, on the
// owned dofs), which is exact (not a lumping) and needs no element loop of its own when one
// damped region covers the whole mesh (its drive is K_U u itself); otherwise the region's
// K_U u is one more pass of the element loop over its cells.
// The update is the exact one for a drive linear in time between the committed state
// (committed_time) and the trial time (memoryUpdate): the trial is computed from the committed
// state, so asking again at the same time gives the same force; AttenuationCommit, once the
// step is accepted, makes the trial the committed state. Off during the geostatic stage: the
// memory starts from zero with the dynamic stage, as the displacements do.
#pragma once
#include <petscdm.h>

#include <string>
#include <vector>

#include "slipwave/fem/bulk_operator.hpp"
#include "slipwave/medium/materials.hpp"
#include "slipwave/physics/constant_q.hpp"

namespace slipwave::medium {

struct DampedRegion {
  PetscInt                       region = -1;
  std::vector<double>            weight;     // Y_l
  bool                           whole_mesh = false; // every cell on every rank: drive = K_U u
  fem::BulkOperator::CellSubset  cells;      // otherwise: this rank's cells of the region
  std::vector<PetscInt>          dofs;       // owned dofs (global-array index) the region touches
  // Per dof k: zeta_l at [k * L + l]; the drive (assembled K_U u of the region) at the state's time.
  std::vector<double>            zeta_committed, zeta_trial, drive_committed, drive_trial;
};

struct Attenuation {
  double                               f_min = 0, f_max = 0; // fitted band [Hz]
  PetscInt                             mechanisms = 0;
  std::vector<double>                  omega;            // w_l shared by the damped regions [rad/s]
  std::vector<physics::ConstantQModel> region_models;    // per region; no mechanisms if elastic
  std::vector<double>                  region_reference; // f_r per region [Hz] (0 if elastic)
  std::vector<double>                  region_factor;    // M_U / (rho c(f_r)^2) per region (1 if elastic)
  bool                                 reference_auto = true;
  std::vector<DampedRegion>            damped;
  Vec                                  drive = nullptr, drive_local = nullptr; // work: a region's K_U u
  bool   started   = false; // a trial has been committed
  bool   has_trial = false; // AttenuationForce computed a trial not yet committed
  double committed_time = 0, trial_time = 0;
};

// Reads the band options, fits every damped region and scales its element moduli (fe.lame)
// to the unrelaxed ones. *att is null when no region is damped.
PetscErrorCode AttenuationCreate(MPI_Comm comm, std::vector<RegionMaterialInfo> *materials, Attenuation **att);
// The automatic reference frequency (no -attenuation_reference_frequency): per damped region
// the lowest frequency from the band's geometric centre up that keeps the whole mesh's
// Gershgorin stable step within 1.9 % of the elastic one, from the elastic bulk (its element
// moduli are then scaled to the unrelaxed ones: set the bulk up again).
PetscErrorCode AttenuationChooseReferences(Attenuation *att, DM dm, const fem::BulkOperator &bulk, Vec mass, Vec free_mask, std::vector<RegionMaterialInfo> *materials);
PetscErrorCode AttenuationSetupCells(Attenuation *att, DM dm, const fem::BulkOperator &bulk);
PetscErrorCode AttenuationDestroy(Attenuation **att);
// f = sum_l zeta_l at time t (global) from the ghosted displacement u_local and the global
// K_U u of the whole mesh (f_internal, just computed from it). With hysteretic regions
// (hysteresis not null; medium/hysteresis.hpp) the drive is the force the soil's stress
// gives, K_U u - f_hysteretic (the global relaxation force of the same u): the mechanisms
// act on the stress the soil carries.
PetscErrorCode AttenuationForce(Attenuation *att, DM dm, const fem::BulkOperator &bulk, Vec u_local, Vec f_internal, struct Hysteresis *hysteresis, Vec f_hysteretic,
                                PetscReal t, Vec f);
// Lines for the run report: per damped region the fitted Q over the band, the reference
// frequency, the speeds at the band ends and the stable-step cost.
std::vector<std::string> AttenuationReport(const Attenuation *att, const std::vector<RegionMaterialInfo> &materials);
// The trial of the last AttenuationForce becomes the committed state (no-op without one).
void AttenuationCommit(Attenuation *att);
// Committed state for checkpoints: [started, committed_time, memory and drive of this rank].
std::vector<double> AttenuationState(const Attenuation *att);
bool                AttenuationSetState(Attenuation *att, const std::vector<double> &state);
PetscInt            AttenuationStateSize(const Attenuation *att);

} // namespace slipwave::medium
