#include "slipwave/interface/interface_assembler.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "slipwave/physics/contact_damping.hpp"
#include "slipwave/physics/friction_lag.hpp"

namespace slipwave::interface {
namespace {

// A right-handed tangent basis of the plane normal to n: in 2D t = (-n_y, n_x) (spec §2);
// in 3D t1 along the axis least aligned with n, projected, and t2 = n x t1.
void tangentBasis(PetscInt dim, const double *n, double *t) {
  if (dim == 2) {
    t[0] = -n[1];
    t[1] = n[0];
    return;
  }
  double e[3] = {0, 0, 0};
  int    k    = 0;
  for (int i = 1; i < 3; ++i)
    if (std::fabs(n[i]) < std::fabs(n[k])) k = i;
  e[k]         = 1;
  const double d = e[0] * n[0] + e[1] * n[1] + e[2] * n[2];
  double       len = 0;
  for (int i = 0; i < 3; ++i) {
    t[i] = e[i] - d * n[i];
    len += t[i] * t[i];
  }
  len = std::sqrt(len);
  for (int i = 0; i < 3; ++i) t[i] /= len;
  t[3] = n[1] * t[2] - n[2] * t[1];
  t[4] = n[2] * t[0] - n[0] * t[2];
  t[5] = n[0] * t[1] - n[1] * t[0];
}

// pore: the trial pore pressure at each pair's soil node (saturated soil side), or null;
// pore_committed: that of the committed state. lag: the friction's lag, and dt the step
// since the committed state (NaN: none, friction_lag.hpp).
template <int Dim>
double updatePairs(const physics::InterfaceLaw &law, const meshing::InterfacePairs &pairs, const double *tangent, std::vector<physics::InterfaceState<Dim>> &states,
                   std::vector<double> &jump_prev, const PetscScalar *pu, const PetscScalar *pore, const double *pore_committed, const physics::FrictionLag &lag,
                   double dt, PetscScalar *pf) {
  const bool lagged = physics::frictionLagged(lag);
  constexpr int NT = Dim - 1;
  double        max_drift = 0;
  for (size_t p = 0; p < states.size(); ++p) {
    const double *n = &pairs.normal[p * Dim];
    const double *t = &tangent[p * NT * Dim];
    double        dj[Dim];
    for (int i = 0; i < Dim; ++i) {
      const double jump = PetscRealPart(pu[p * 2 * Dim + Dim + i]) - PetscRealPart(pu[p * 2 * Dim + i]);
      dj[i]             = jump - jump_prev[p * Dim + i];
      jump_prev[p * Dim + i] = jump;
    }
    double dw_N = 0, dw_T[NT];
    for (int i = 0; i < Dim; ++i) dw_N += dj[i] * n[i];
    for (int k = 0; k < NT; ++k) {
      dw_T[k] = 0;
      for (int i = 0; i < Dim; ++i) dw_T[k] += dj[i] * t[k * Dim + i];
    }
    physics::InterfaceState<Dim> &s = states[p];
    const physics::FrictionLagStep step{lag, pore ? PetscRealPart(pore[p]) : 0.0, dt};
    const physics::FrictionLagStep *lag_step = lagged ? &step : nullptr;
    const double drift = pore ? physics::interfaceUpdate<Dim>(physics::interfaceLawWithPorePressure(law, PetscRealPart(pore[p])), s, dw_T, dw_N,
                                                              PetscRealPart(pore[p]) - pore_committed[p], lag_step)
                              : physics::interfaceUpdate<Dim>(law, s, dw_T, dw_N, 0.0, lag_step);
    max_drift = std::max(max_drift, drift);
    // tau: force per unit area of the structure on the soil (spec §2).
    const double A = pairs.area[p];
    for (int i = 0; i < Dim; ++i) {
      double tau = s.sigma_N * n[i];
      for (int k = 0; k < NT; ++k) tau += s.sigma_T[k] * t[k * Dim + i];
      pf[p * 2 * Dim + i]       = A * tau;
      pf[p * 2 * Dim + Dim + i] = -A * tau;
    }
  }
  return max_drift;
}

template <int Dim>
void totalsOf(const physics::InterfaceLaw &law, const meshing::InterfacePairs &pairs, const std::vector<physics::InterfaceState<Dim>> &states, InterfaceTotals *t) {
  for (size_t p = 0; p < states.size(); ++p) {
    const auto &s = states[p];
    t->stored += pairs.area[p] * physics::detail::storedEnergy<Dim>(law, s);
    t->dissipated += pairs.area[p] * s.dissipation;
    t->n_stick += s.status == physics::InterfaceStatus::Stick;
    t->n_slip += s.status == physics::InterfaceStatus::Slip;
    t->n_open += s.status == physics::InterfaceStatus::Open;
  }
}

// opening w_N, slip vector (tangential jump in x,y,z), sigma_N, sigma_T vector (x,y,z),
// plastic opening, accumulated slip, status (0 stick, 1 slip, 2 open), dissipation [J/m^2];
// a lagged friction's sigma*; on a saturated soil side the pore pressure and sigma_N + p.
template <int Dim>
void fieldsOf(const meshing::InterfacePairs &pairs, const double *tangent, const std::vector<physics::InterfaceState<Dim>> &states, const std::vector<double> &jump,
              bool lagged, const std::vector<double> &pore, std::vector<double> *out) {
  constexpr int NT = Dim - 1;
  for (size_t p = 0; p < states.size(); ++p) {
    const auto   &s = states[p];
    const double *n = &pairs.normal[p * Dim];
    const double *t = &tangent[p * NT * Dim];
    double        wn = 0, slip[3] = {0, 0, 0}, st[3] = {0, 0, 0};
    for (int i = 0; i < Dim; ++i) wn += jump[p * Dim + i] * n[i];
    for (int i = 0; i < Dim; ++i) {
      slip[i] = jump[p * Dim + i] - wn * n[i];
      for (int k = 0; k < NT; ++k) st[i] += s.sigma_T[k] * t[k * Dim + i];
    }
    out->push_back(wn);
    out->insert(out->end(), slip, slip + 3);
    out->push_back(s.sigma_N);
    out->insert(out->end(), st, st + 3);
    out->push_back(s.wp_N);
    out->push_back(s.slip);
    out->push_back((double)s.status);
    out->push_back(s.dissipation);
    if (lagged) out->push_back(s.sigma_friction);
    if (!pore.empty()) {
      // Saturated soil side: the law acts on sigma_N + p (physics/mohr_coulomb_interface.hpp).
      out->push_back(pore[p]);
      out->push_back(s.sigma_N + pore[p]);
    }
  }
}

} // namespace

std::vector<std::string> InterfaceAssembler::pairFieldNames() const {
  std::vector<std::string> names = {"opening", "slip", "sigma_N", "sigma_T", "plastic_opening", "accumulated_slip", "status", "dissipation"};
  if (physics::frictionLagged(lag_)) names.push_back("sigma_N_friction");
  if (pore_scatter_) names.insert(names.end(), {"pore_pressure", "sigma_N_effective"});
  return names;
}

PetscErrorCode InterfaceAssembler::Setup(MPI_Comm comm, PetscInt dim, const meshing::InterfaceSpec &spec, const meshing::InterfacePairs &pairs,
                                         const physics::InterfaceParams &params, double sigma_N0, double contact_damping, const physics::FrictionLag &lag, Vec mass) {
  PetscFunctionBeginUser;
  lag_    = lag;
  comm_   = comm;
  dim_    = dim;
  spec_   = spec;
  pairs_  = pairs;
  params_ = params;
  const PetscInt np = (PetscInt)pairs_.id.size();
  tangent_.resize(np * (dim - 1) * dim);
  for (PetscInt p = 0; p < np; ++p) tangentBasis(dim, &pairs_.normal[p * dim], &tangent_[p * (dim - 1) * dim]);
  jump_prev_.assign(np * dim, 0.0);
  const physics::InterfaceLaw law(params_);
  if (dim == 2) states2_.assign(np, physics::interfaceInitialState<2>(law, sigma_N0));
  else states3_.assign(np, physics::interfaceInitialState<3>(law, sigma_N0));

  std::vector<PetscInt> from(np * 2 * dim);
  for (PetscInt p = 0; p < np; ++p)
    for (PetscInt i = 0; i < dim; ++i) {
      from[p * 2 * dim + i]       = pairs_.soil_dof[p] + i;
      from[p * 2 * dim + dim + i] = pairs_.structure_dof[p] + i;
    }
  IS is_from, is_to;
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, np * 2 * dim, from.data(), PETSC_COPY_VALUES, &is_from));
  PetscCall(ISCreateStride(PETSC_COMM_SELF, np * 2 * dim, 0, 1, &is_to));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, np * 2 * dim, &pair_u_));
  PetscCall(VecDuplicate(pair_u_, &pair_f_));
  PetscCall(VecScatterCreate(mass, is_from, pair_u_, is_to, &scatter_));
  PetscCall(ISDestroy(&is_from));
  PetscCall(ISDestroy(&is_to));

  // Each pair's normal spring E A between its two lumped masses.
  contact_damping_ = contact_damping;
  dashpot_.assign(np, 0.0);
  PetscCall(VecScatterBegin(scatter_, mass, pair_u_, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(scatter_, mass, pair_u_, INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar *pm;
  PetscCall(VecGetArrayRead(pair_u_, &pm));
  for (PetscInt p = 0; p < np; ++p)
    dashpot_[p] = physics::contactDashpotCoefficient(contact_damping, params_.E * pairs_.area[p], PetscRealPart(pm[p * 2 * dim]), PetscRealPart(pm[p * 2 * dim + dim]));
  PetscCall(VecRestoreArrayRead(pair_u_, &pm));
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAssembler::AddForces(Vec u, Vec f, PetscReal t) {
  PetscFunctionBeginUser;
  const physics::InterfaceLaw law(params_);
  trial_states2_ = states2_;
  trial_states3_ = states3_;
  trial_jump_    = jump_prev_;
  trial_time_    = t;
  // No time (a static solve) or no committed time yet (the first step): the lag starts at
  // rest, sigma* = sigma_N + p.
  const double dt = std::isfinite(t) && std::isfinite(committed_time_) ? t - committed_time_ : NAN;
  const PetscScalar *pore = nullptr;
  if (pore_scatter_) {
    PetscCall(VecScatterBegin(pore_scatter_, pore_source_, pair_p_, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(pore_scatter_, pore_source_, pair_p_, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecGetArrayRead(pair_p_, &pore));
    trial_pair_pore_.assign(pore, pore + pairs_.id.size());
  }
  PetscCall(applyToPairs(u, f, [&](const PetscScalar *pu, PetscScalar *pf) {
    const double drift = dim_ == 2 ? updatePairs<2>(law, pairs_, tangent_.data(), trial_states2_, trial_jump_, pu, pore, pair_pore_.data(), lag_, dt, pf)
                                   : updatePairs<3>(law, pairs_, tangent_.data(), trial_states3_, trial_jump_, pu, pore, pair_pore_.data(), lag_, dt, pf);
    trial_max_drift_   = std::max(max_drift_, drift);
  }));
  if (pore) PetscCall(VecRestoreArrayRead(pair_p_, &pore));
  has_trial_ = true;
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAssembler::applyToPairs(Vec x, Vec f, const std::function<void(const PetscScalar *, PetscScalar *)> &kernel) {
  const PetscScalar *px;
  PetscScalar       *pf;
  PetscFunctionBeginUser;
  PetscCall(VecScatterBegin(scatter_, x, pair_u_, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(scatter_, x, pair_u_, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetArrayRead(pair_u_, &px));
  PetscCall(VecGetArray(pair_f_, &pf));
  kernel(px, pf);
  PetscCall(VecRestoreArray(pair_f_, &pf));
  PetscCall(VecRestoreArrayRead(pair_u_, &px));
  PetscCall(VecScatterBegin(scatter_, pair_f_, f, ADD_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterEnd(scatter_, pair_f_, f, ADD_VALUES, SCATTER_REVERSE));
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAssembler::SoilSideDisplacement(Vec u, std::vector<double> *values) const {
  const PetscInt     np = (PetscInt)pairs_.id.size();
  const PetscScalar *pu;
  PetscFunctionBeginUser;
  PetscCall(VecScatterBegin(scatter_, u, pair_u_, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(scatter_, u, pair_u_, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetArrayRead(pair_u_, &pu));
  values->resize(np * dim_);
  for (PetscInt p = 0; p < np; ++p)
    for (PetscInt i = 0; i < dim_; ++i) (*values)[p * dim_ + i] = PetscRealPart(pu[p * 2 * dim_ + i]); // soil node first, then structure
  PetscCall(VecRestoreArrayRead(pair_u_, &pu));
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAssembler::SetPorePressure(Vec p) {
  const PetscInt np = (PetscInt)pairs_.id.size();
  PetscFunctionBeginUser;
  // The pressure layout numbers node i where the displacement has dofs i*dim .. i*dim+dim-1.
  std::vector<PetscInt> from(np);
  for (PetscInt k = 0; k < np; ++k) from[k] = pairs_.soil_dof[k] / dim_;
  IS is_from, is_to;
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, np, from.data(), PETSC_COPY_VALUES, &is_from));
  PetscCall(ISCreateStride(PETSC_COMM_SELF, np, 0, 1, &is_to));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, np, &pair_p_));
  PetscCall(VecScatterCreate(p, is_from, pair_p_, is_to, &pore_scatter_));
  PetscCall(ISDestroy(&is_from));
  PetscCall(ISDestroy(&is_to));
  // The initial state's pore pressure (the output's until the first committed step).
  PetscCall(ReadCommittedPorePressure(p));
  pore_source_ = p;
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAssembler::ReadCommittedPorePressure(Vec p_committed) {
  const PetscScalar *pp;
  PetscFunctionBeginUser;
  if (!pore_scatter_) PetscFunctionReturn(0);
  PetscCall(VecScatterBegin(pore_scatter_, p_committed, pair_p_, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(pore_scatter_, p_committed, pair_p_, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetArrayRead(pair_p_, &pp));
  pair_pore_.assign(pp, pp + pairs_.id.size());
  PetscCall(VecRestoreArrayRead(pair_p_, &pp));
  PetscFunctionReturn(0);
}

void InterfaceAssembler::openSoilDofs(std::vector<PetscInt> *dofs) const {
  dofs->clear();
  const size_t n = dim_ == 2 ? states2_.size() : states3_.size();
  for (size_t i = 0; i < n; ++i) {
    const physics::InterfaceStatus status = dim_ == 2 ? states2_[i].status : states3_[i].status;
    if (status == physics::InterfaceStatus::Open) dofs->push_back(pairs_.soil_dof[i]);
  }
}

namespace {

template <int Dim>
PetscInt switchedPairs(const std::vector<physics::InterfaceState<Dim>> &before, const std::vector<physics::InterfaceState<Dim>> &after) {
  PetscInt n = 0;
  for (size_t p = 0; p < after.size(); ++p) n += (before[p].status == physics::InterfaceStatus::Open) != (after[p].status == physics::InterfaceStatus::Open);
  return n;
}

} // namespace

void InterfaceAssembler::Commit() {
  if (!has_trial_) return;
  switches_ += dim_ == 2 ? switchedPairs<2>(states2_, trial_states2_) : switchedPairs<3>(states3_, trial_states3_);
  states2_.swap(trial_states2_);
  states3_.swap(trial_states3_);
  jump_prev_.swap(trial_jump_);
  if (pore_scatter_) pair_pore_.swap(trial_pair_pore_);
  committed_time_ = trial_time_;
  max_drift_ = trial_max_drift_;
  has_trial_ = false;
}

namespace {

// Normal dashpot of each closed pair on the jump rate (structure minus soil) along n:
// +A sigma_d n on the soil node, -A sigma_d n on the structure node, like the spring.
template <int Dim>
void dampPairs(const meshing::InterfacePairs &pairs, const std::vector<double> &dashpot, const std::vector<physics::InterfaceState<Dim>> &states, const PetscScalar *pv,
               PetscScalar *pf) {
  for (size_t p = 0; p < states.size(); ++p) {
    const double *n      = &pairs.normal[p * Dim];
    double        w_dot  = 0;
    for (int i = 0; i < Dim; ++i) w_dot += (PetscRealPart(pv[p * 2 * Dim + Dim + i]) - PetscRealPart(pv[p * 2 * Dim + i])) * n[i];
    const bool   closed  = states[p].status != physics::InterfaceStatus::Open;
    const double A       = pairs.area[p];
    const double sigma_d = closed ? physics::contactDampingTraction(dashpot[p] / A, w_dot, states[p].sigma_N) : 0.0;
    for (int i = 0; i < Dim; ++i) {
      pf[p * 2 * Dim + i]       = A * sigma_d * n[i];
      pf[p * 2 * Dim + Dim + i] = -A * sigma_d * n[i];
    }
  }
}

} // namespace

PetscErrorCode InterfaceAssembler::AddDampingForces(Vec v, Vec f) {
  PetscFunctionBeginUser;
  if (contact_damping_ == 0) PetscFunctionReturn(0);
  PetscCall(applyToPairs(v, f, [&](const PetscScalar *pv, PetscScalar *pf) {
    if (dim_ == 2) dampPairs<2>(pairs_, dashpot_, trial_states2_, pv, pf);
    else dampPairs<3>(pairs_, dashpot_, trial_states3_, pv, pf);
  }));
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAssembler::AddDampingRowAbsSums(Vec rowabs) {
  PetscFunctionBeginUser;
  PetscCall(addPairRowAbsSums(rowabs, [this](size_t p, const double *n, PetscInt i, PetscInt j) { return dashpot_[p] * n[i] * n[j]; }));
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAssembler::DashpotRange(double *c_min, double *c_max) const {
  PetscFunctionBeginUser;
  double lo = 1e300, hi = 0;
  for (double c : dashpot_) lo = std::min(lo, c), hi = std::max(hi, c);
  PetscCallMPI(MPI_Allreduce(&lo, c_min, 1, MPI_DOUBLE, MPI_MIN, comm_));
  PetscCallMPI(MPI_Allreduce(&hi, c_max, 1, MPI_DOUBLE, MPI_MAX, comm_));
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAssembler::AddStiffnessRowAbsSums(Vec rowabs) {
  PetscFunctionBeginUser;
  PetscCall(addPairRowAbsSums(rowabs, [this](size_t p, const double *n, PetscInt i, PetscInt j) {
    return pairs_.area[p] * (params_.E * n[i] * n[j] + params_.G * ((i == j ? 1.0 : 0.0) - n[i] * n[j]));
  }));
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAssembler::addPairRowAbsSums(Vec rowabs, const std::function<double(size_t, const double *, PetscInt, PetscInt)> &k) {
  PetscScalar *pf;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(pair_f_, &pf));
  for (size_t p = 0; p < pairs_.id.size(); ++p) {
    const double *n = &pairs_.normal[p * dim_];
    for (PetscInt i = 0; i < dim_; ++i) {
      double row = 0;
      for (PetscInt j = 0; j < dim_; ++j) row += std::fabs(k(p, n, i, j));
      // The pair couples the two nodes with +k and -k: each row sees |k| twice.
      pf[p * 2 * dim_ + i] = pf[p * 2 * dim_ + dim_ + i] = 2 * row;
    }
  }
  PetscCall(VecRestoreArray(pair_f_, &pf));
  PetscCall(VecScatterBegin(scatter_, pair_f_, rowabs, ADD_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterEnd(scatter_, pair_f_, rowabs, ADD_VALUES, SCATTER_REVERSE));
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAssembler::AddStickStiffness(Mat K) const {
  PetscFunctionBeginUser;
  std::vector<PetscInt> rows(2 * dim_);
  std::vector<double>   block(4 * dim_ * dim_);
  const PetscInt        n = 2 * dim_;
  for (size_t p = 0; p < pairs_.id.size(); ++p) {
    const double *nrm = &pairs_.normal[p * dim_];
    for (PetscInt i = 0; i < dim_; ++i) {
      rows[i]        = pairs_.soil_dof[p] + i;
      rows[dim_ + i] = pairs_.structure_dof[p] + i;
      for (PetscInt j = 0; j < dim_; ++j) {
        const double k = pairs_.area[p] * (params_.E * nrm[i] * nrm[j] + params_.G * ((i == j ? 1.0 : 0.0) - nrm[i] * nrm[j]));
        block[i * n + j]                     = k;
        block[(dim_ + i) * n + dim_ + j]     = k;
        block[i * n + dim_ + j]              = -k;
        block[(dim_ + i) * n + j]            = -k;
      }
    }
    PetscCall(MatSetValues(K, n, rows.data(), n, rows.data(), block.data(), ADD_VALUES));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAssembler::CountOffLinearStick(PetscInt *count) const {
  PetscFunctionBeginUser;
  const physics::InterfaceLaw law(params_);
  PetscInt                    local = 0;
  for (const auto &s : states2_) local += !physics::interfaceOnLinearStickBranch<2>(law, s);
  for (const auto &s : states3_) local += !physics::interfaceOnLinearStickBranch<3>(law, s);
  PetscCallMPI(MPI_Allreduce(&local, count, 1, MPIU_INT, MPI_SUM, comm_));
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAssembler::Totals(InterfaceTotals *t) const {
  PetscFunctionBeginUser;
  const physics::InterfaceLaw law(params_);
  InterfaceTotals             local;
  if (dim_ == 2) totalsOf<2>(law, pairs_, states2_, &local);
  else totalsOf<3>(law, pairs_, states3_, &local);
  double   sums[2] = {local.stored, local.dissipated};
  PetscInt counts[4] = {local.n_stick, local.n_slip, local.n_open, switches_};
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, comm_));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, counts, 4, MPIU_INT, MPI_SUM, comm_));
  double drift = max_drift_;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &drift, 1, MPI_DOUBLE, MPI_MAX, comm_));
  *t = InterfaceTotals{sums[0], sums[1], drift, counts[0], counts[1], counts[2], counts[3]};
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAssembler::CountCutPairs(Vec u_template, PetscInt *cut) const {
  PetscInt lo, hi, local = 0;
  PetscFunctionBeginUser;
  PetscCall(VecGetOwnershipRange(u_template, &lo, &hi));
  for (size_t p = 0; p < pairs_.id.size(); ++p) local += pairs_.structure_dof[p] < lo || pairs_.structure_dof[p] >= hi;
  PetscCallMPI(MPI_Allreduce(&local, cut, 1, MPIU_INT, MPI_SUM, comm_));
  PetscFunctionReturn(0);
}

void InterfaceAssembler::pairFields(std::vector<double> *values, int *per_pair) const {
  values->clear();
  const bool lagged = physics::frictionLagged(lag_);
  if (dim_ == 2) fieldsOf<2>(pairs_, tangent_.data(), states2_, jump_prev_, lagged, pair_pore_, values);
  else fieldsOf<3>(pairs_, tangent_.data(), states3_, jump_prev_, lagged, pair_pore_, values);
  *per_pair = (pore_scatter_ ? 14 : 12) + (lagged ? 1 : 0);
}

namespace {

template <int Dim>
void packStates(const std::vector<physics::InterfaceState<Dim>> &states, const std::vector<double> &jump, std::vector<double> *out) {
  for (size_t p = 0; p < states.size(); ++p) {
    const auto &s = states[p];
    out->insert(out->end(), s.sigma_T, s.sigma_T + Dim - 1);
    out->push_back(s.sigma_N);
    out->insert(out->end(), s.wp_T, s.wp_T + Dim - 1);
    out->insert(out->end(), {s.wp_N, s.opening, s.slip, s.dissipation, s.sigma_friction, (double)s.status});
    out->insert(out->end(), &jump[p * Dim], &jump[p * Dim] + Dim);
  }
}

template <int Dim>
void unpackStates(const double *in, std::vector<physics::InterfaceState<Dim>> &states, std::vector<double> &jump) {
  for (size_t p = 0; p < states.size(); ++p) {
    auto &s = states[p];
    for (int k = 0; k < Dim - 1; ++k) s.sigma_T[k] = *in++;
    s.sigma_N = *in++;
    for (int k = 0; k < Dim - 1; ++k) s.wp_T[k] = *in++;
    s.wp_N        = *in++;
    s.opening     = *in++;
    s.slip        = *in++;
    s.dissipation = *in++;
    s.sigma_friction = *in++;
    s.status      = (physics::InterfaceStatus)(int)*in++;
    for (int k = 0; k < Dim; ++k) jump[p * Dim + k] = *in++;
  }
}

} // namespace

void InterfaceAssembler::saveState(std::vector<double> *out) const {
  out->clear();
  if (dim_ == 2) packStates<2>(states2_, jump_prev_, out);
  else packStates<3>(states3_, jump_prev_, out);
}

void InterfaceAssembler::loadState(const double *in) {
  if (dim_ == 2) unpackStates<2>(in, states2_, jump_prev_);
  else unpackStates<3>(in, states3_, jump_prev_);
}

PetscErrorCode InterfaceAssembler::Destroy() {
  PetscFunctionBeginUser;
  PetscCall(VecScatterDestroy(&pore_scatter_));
  PetscCall(VecDestroy(&pair_p_));
  PetscCall(VecScatterDestroy(&scatter_));
  PetscCall(VecDestroy(&pair_u_));
  PetscCall(VecDestroy(&pair_f_));
  PetscFunctionReturn(0);
}

} // namespace slipwave::interface
