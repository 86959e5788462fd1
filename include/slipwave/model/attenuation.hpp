// Constant-Q (frequency-independent) viscoelastic damping per region: -material_<r>_damping_ratio
// xi > 0 gives the region a generalized Maxwell body (physics/constant_q.hpp) fitted to
// Q = 1/(2 xi) over -attenuation_band with -attenuation_mechanisms mechanisms; the same Q for P
// and S waves (Qp = Qs). The given vp, vs hold at a reference frequency f_r
// (-attenuation_reference_frequency); the element matrices use the unrelaxed moduli
// M_U = factor * rho c^2, and the memory variables add an element force
// (fem/anelastic_operator.hpp). Off during the geostatic stage: the memory starts from zero
// with the dynamic stage, as the displacements do.
#pragma once
#include <petscdm.h>

#include <string>
#include <vector>

#include "slipwave/fem/anelastic_operator.hpp"
#include "slipwave/model/materials.hpp"

namespace slipwave::model {

struct Attenuation {
  double                               f_min = 0, f_max = 0; // fitted band [Hz]
  PetscInt                             mechanisms = 0;
  std::vector<physics::ConstantQModel> region_models;    // per region; no mechanisms if elastic
  std::vector<double>                  region_reference; // f_r per region [Hz] (0 if elastic)
  std::vector<double>                  region_factor;    // M_U / (rho c(f_r)^2) per region (1 if elastic)
  bool                                 reference_auto = true;
  fem::AnelasticOperator               op;
  Vec                                  f_local = nullptr;
  // The committed memory state is at committed_time, the trial one at trial_time.
  bool   started = false;
  double committed_time = 0, trial_time = 0;
};

// Reads the band options, fits every damped region and scales its element moduli (fe.lame)
// to the unrelaxed ones. *att is null when no region is damped.
PetscErrorCode AttenuationCreate(MPI_Comm comm, std::vector<RegionMaterialInfo> *materials, Attenuation **att);
PetscErrorCode AttenuationSetupCells(Attenuation *att, DM dm, const fem::BulkOperator &bulk);
PetscErrorCode AttenuationDestroy(Attenuation **att);
// f = sum_l zeta_l at time t (global, assembled) from the ghosted displacement u_local. A time
// later than the last one commits the last trial state first; the same time again recomputes it.
PetscErrorCode AttenuationForce(Attenuation *att, DM dm, const fem::BulkOperator &bulk, Vec u_local, PetscReal t, Vec f);
// Lines for the run report: per damped region the fitted Q over the band, the reference
// frequency, the speeds at the band ends and the stable-step cost.
std::vector<std::string> AttenuationReport(const Attenuation *att, const std::vector<RegionMaterialInfo> &materials);
// Full state for checkpoints: [started, committed_time, trial_time, memory of this rank].
std::vector<double> AttenuationState(const Attenuation *att);
bool                AttenuationSetState(Attenuation *att, const std::vector<double> &state);
PetscInt            AttenuationStateSize(const Attenuation *att);

} // namespace slipwave::model
