#include "slipwave/problem/energy_ledger.hpp"

#include <algorithm>
#include <cmath>

#include "slipwave/core/log_events.hpp"
#include "slipwave/medium/hysteresis.hpp"
#include "slipwave/porous/pore_pressure.hpp"
#include "slipwave/time/central_difference.hpp"

namespace slipwave::problem {

namespace {

// The nodal arrays the ledger reads (local, global-vector order).
struct LedgerArrays {
  const PetscScalar *u, *v, *a, *mass, *fi, *fx, *fin, *fsd, *fif, *fan, *fcd, *fhy, *mask;
};

PetscErrorCode getArrays(Elastodynamics *m, Vec u, Vec v, Vec a, LedgerArrays *x) {
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(u, &x->u));
  PetscCall(VecGetArrayRead(v, &x->v));
  PetscCall(VecGetArrayRead(a, &x->a));
  PetscCall(VecGetArrayRead(m->mass, &x->mass));
  PetscCall(VecGetArrayRead(m->f_internal, &x->fi));
  PetscCall(VecGetArrayRead(m->f_external, &x->fx));
  PetscCall(VecGetArrayRead(m->f_input, &x->fin));
  PetscCall(VecGetArrayRead(m->f_stiffness_damping, &x->fsd));
  PetscCall(VecGetArrayRead(m->f_interface, &x->fif));
  PetscCall(VecGetArrayRead(m->f_anelastic, &x->fan));
  PetscCall(VecGetArrayRead(m->f_contact_damping, &x->fcd));
  x->fhy = nullptr; // without hysteretic regions: not read
  if (m->f_hysteretic) PetscCall(VecGetArrayRead(m->f_hysteretic, &x->fhy));
  PetscCall(VecGetArrayRead(m->bc.free_mask, &x->mask));
  PetscFunctionReturn(0);
}

PetscErrorCode restoreArrays(Elastodynamics *m, Vec u, Vec v, Vec a, LedgerArrays *x) {
  PetscFunctionBeginUser;
  PetscCall(VecRestoreArrayRead(m->bc.free_mask, &x->mask));
  if (m->f_hysteretic) PetscCall(VecRestoreArrayRead(m->f_hysteretic, &x->fhy));
  PetscCall(VecRestoreArrayRead(m->f_contact_damping, &x->fcd));
  PetscCall(VecRestoreArrayRead(m->f_anelastic, &x->fan));
  PetscCall(VecRestoreArrayRead(m->f_interface, &x->fif));
  PetscCall(VecRestoreArrayRead(m->f_stiffness_damping, &x->fsd));
  PetscCall(VecRestoreArrayRead(m->f_input, &x->fin));
  PetscCall(VecRestoreArrayRead(m->f_external, &x->fx));
  PetscCall(VecRestoreArrayRead(m->f_internal, &x->fi));
  PetscCall(VecRestoreArrayRead(m->mass, &x->mass));
  PetscCall(VecRestoreArrayRead(a, &x->a));
  PetscCall(VecRestoreArrayRead(v, &x->v));
  PetscCall(VecRestoreArrayRead(u, &x->u));
  PetscFunctionReturn(0);
}

// Local sums: 0 kinetic, 1 strain, 2 shadow (the stored energies, only when `stored`),
// 3 input power, 4 external power, 5 reaction power, 6 absorbed power, 7 damping power,
// 8 interface power, 9 power of the constant-Q memory forces, 10 contact dashpot power,
// 11 power of the hysteretic relaxation forces.
// Written without branches (the mask is 0 or 1) because this pass runs over every dof.
template <bool stored, bool hysteretic>
void sumEveryDof(const LedgerArrays &x, PetscInt n, double h, double alpha, double s[12]) {
  for (PetscInt k = 0; k < n; ++k) {
    const double vk = x.v[k], mk = x.mass[k], fik = x.fi[k], held = 1.0 - x.mask[k];
    if (stored) {
      const double vhalf = vk + 0.5 * h * x.a[k];
      s[0] += 0.5 * mk * vk * vk;
      s[1] += 0.5 * x.u[k] * fik;
      s[2] += 0.5 * mk * vhalf * vhalf + 0.5 * x.u[k] * fik + 0.5 * h * vhalf * fik;
    }
    s[3] += vk * x.fin[k];
    s[4] += vk * (x.fx[k] - x.fin[k]);
    // What a support supplies: everything M a + K u asks beyond the applied loads.
    s[5] += held * vk * (mk * x.a[k] + fik - x.fx[k] - x.fif[k] - x.fan[k] - x.fcd[k]);
    if (hysteretic) {
      s[5] -= held * vk * x.fhy[k];
      // On every dof: on a held one the reaction (s[5]) leaves it out, as the support
      // supplies the rest of what the soil's own stress asks.
      s[11] += vk * x.fhy[k];
    }
    s[8] += vk * x.fif[k];
    s[9] += x.mask[k] * vk * x.fan[k];
    s[10] += vk * x.fcd[k];
    s[7] += x.mask[k] * vk * (alpha * x.mass[k] * vk + x.fsd[k]);
  }
}

// The same work sums where a scene has no force spread over the mesh (no Rayleigh damping,
// constant Q or interfaces; loads listed by problem/nodal_acceleration): loads act on their
// listed dofs only and a support's reaction on its held dofs only, so only those are visited.
// A hysteretic soil's relaxation forces are spread over the mesh: their power is summed apart
// (sumHystereticPower), their share of a reaction here.
void sumListedWork(const LedgerArrays &x, const NodalAcceleration &na, double s[12]) {
  for (PetscInt k : na.external_dofs) {
    s[3] += x.v[k] * x.fin[k];
    s[4] += x.v[k] * (x.fx[k] - x.fin[k]);
  }
  for (PetscInt k : na.held_dofs) s[5] += x.v[k] * (x.mass[k] * x.a[k] + x.fi[k] - x.fx[k] - x.fif[k] - x.fan[k] - x.fcd[k] - (x.fhy ? x.fhy[k] : 0.0));
}

// The power of the hysteretic relaxation forces (11), on every dof: two arrays read where
// sumEveryDof reads ten.
void sumHystereticPower(const LedgerArrays &x, PetscInt n, double s[12]) {
  for (PetscInt k = 0; k < n; ++k) s[11] += x.v[k] * x.fhy[k];
}

// The stored energies alone.
void sumStored(const LedgerArrays &x, PetscInt n, double h, double s[12]) {
  for (PetscInt k = 0; k < n; ++k) {
    const double vk = x.v[k], mk = x.mass[k], fik = x.fi[k];
    const double vhalf = vk + 0.5 * h * x.a[k];
    s[0] += 0.5 * mk * vk * vk;
    s[1] += 0.5 * x.u[k] * fik;
    s[2] += 0.5 * mk * vhalf * vhalf + 0.5 * x.u[k] * fik + 0.5 * h * vhalf * fik;
  }
}

// The power v . M c of the fourth-order correction c, added to *power (this rank's dofs).
PetscErrorCode sumCorrectionPower(Elastodynamics *m, Vec v, Vec c, double *power) {
  const PetscScalar *vv, *cc, *mm;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(v, &n));
  PetscCall(VecGetArrayRead(v, &vv));
  PetscCall(VecGetArrayRead(c, &cc));
  PetscCall(VecGetArrayRead(m->mass, &mm));
  for (PetscInt k = 0; k < n; ++k) *power += PetscRealPart(vv[k] * mm[k] * cc[k]);
  PetscCall(VecRestoreArrayRead(m->mass, &mm));
  PetscCall(VecRestoreArrayRead(c, &cc));
  PetscCall(VecRestoreArrayRead(v, &vv));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode EnergyLedgerUpdate(Elastodynamics *m, TS ts, PetscReal h, bool evaluate, EnergyLedger *e) {
  Vec u, v, a;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(core::event_energy, 0, 0, 0, 0));
  // The first call is the reference W_{1/2}: always evaluated.
  evaluate = evaluate || !e->started;
  PetscCall(TS2GetSolution(ts, &u, &v));
  PetscCall(time::CentralDifferenceGetAcceleration(ts, &a));
  PetscInt           n;
  const PetscInt     bs = m->dim;
  const PetscScalar *C;
  LedgerArrays       x;
  PetscCall(VecGetLocalSize(u, &n));
  PetscCall(getArrays(m, u, v, a, &x));
  PetscCall(VecGetArrayRead(m->bc.absorbing_blocks, &C));
  double       s[13] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  const double alpha = m->rayleigh.alpha;
  const bool   listed = m->nodal.listed && alpha == 0 && m->rayleigh.beta == 0 && !m->attenuation && m->interfaces.empty();
  if (listed) {
    sumListedWork(x, m->nodal, s);
    if (m->hysteresis) sumHystereticPower(x, n, s);
    if (evaluate) sumStored(x, n, h, s);
  } else if (m->hysteresis) {
    if (evaluate) sumEveryDof<true, true>(x, n, h, alpha, s);
    else sumEveryDof<false, true>(x, n, h, alpha, s);
  } else if (evaluate) {
    sumEveryDof<true, false>(x, n, h, alpha, s);
  } else {
    sumEveryDof<false, false>(x, n, h, alpha, s);
  }
  // The relaxation energy E_r of the committed soil state at u_n (the state the step's RHS
  // reached at u_n; TS2 keeps u global, the sum needs its ghosts).
  double relaxation = 0;
  if (m->hysteresis && evaluate) {
    const PetscScalar *ul;
    PetscCall(DMGlobalToLocal(m->dm, u, INSERT_VALUES, m->u_local));
    PetscCall(VecGetArrayRead(m->u_local, &ul));
    relaxation = medium::HysteresisRelaxationEnergy(m->hysteresis, ul);
    PetscCall(VecRestoreArrayRead(m->u_local, &ul));
  }
  // Built once per run (a restart's ledger comes without it).
  if (e->absorbing_free_blocks.size() != m->absorbing_nodes.size() * bs * bs) {
    e->absorbing_free_blocks.clear();
    for (PetscInt node : m->absorbing_nodes)
      for (PetscInt i = 0; i < bs; ++i)
        for (PetscInt j = 0; j < bs; ++j)
          e->absorbing_free_blocks.push_back(x.mask[node * bs + i] * x.mask[node * bs + j] > 0 ? C[node * bs * bs + i * bs + j] : 0.0);
  }
  PetscCall(VecRestoreArrayRead(m->bc.absorbing_blocks, &C));
  const double *Cfree = e->absorbing_free_blocks.data();
  for (PetscInt node : m->absorbing_nodes) {
    const double *vn = x.v + node * bs;
    for (PetscInt i = 0; i < bs; ++i)
      for (PetscInt j = 0; j < bs; ++j) s[6] += vn[i] * Cfree[i * bs + j] * vn[j];
    Cfree += bs * bs;
  }
  PetscCall(restoreArrays(m, u, v, a, &x));
  // The fourth-order integrator's correction c (zero at order 2): its force M c is not in
  // f_int or the loads, and its work is booked apart (13th sum).
  Vec correction;
  PetscCall(time::CentralDifferenceGetCorrection(ts, &correction));
  if (correction) PetscCall(sumCorrectionPower(m, v, correction, &s[12]));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, s, 13, MPI_DOUBLE, MPI_SUM, m->comm));
  if (m->hysteresis) {
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &relaxation, 1, MPI_DOUBLE, MPI_SUM, m->comm));
    // The soil's own stored energies: the linear ones less E_r (energy_ledger.hpp).
    s[1] -= relaxation;
    s[2] -= relaxation;
  }

  porous::PoreEnergy fluid;
  if (m->pore) {
    // Its Darcy and inflow work are booked every step like the rest of the work. The storage
    // energy F_{n+1/2} needs the DRM's volume source of the coming step.
    PetscReal t;
    PetscCall(TSGetTime(ts, &t));
    if (m->input_enabled) PetscCall(ElastodynamicsDrmPoreSource(m, ts, t + h));
    PetscCall(porous::PorePressureEnergy(m->pore, m->dm, h, v, a, m->f_pore, m->bc.free_mask, &fluid));
    s[2] += fluid.storage;
    s[5] -= fluid.held_power;
    e->fluid = true;
  }
  if (!e->started) {
    // W_{1/2} is the reference; the work of step 0 is inside it.
    e->shadow_start = s[2];
    e->started      = true;
  } else {
    const double h_mean = 0.5 * (e->h_prev + h);
    e->input += h_mean * s[3];
    e->external += h_mean * s[4];
    e->external_gross += std::fabs(h_mean * s[4]);
    e->reactions += h_mean * s[5];
    e->absorbed += h_mean * s[6];
    e->damped += h_mean * s[7];
    e->interface_work += h_mean * s[8];
    e->anelastic -= h_mean * s[9];
    e->contact_damped -= h_mean * s[10];
    e->hysteretic_work -= h_mean * s[11];
    e->integrator_correction += h_mean * s[12];
    e->darcy += fluid.darcy;
    e->fluid_inflow += fluid.inflow;
    e->input += fluid.drm_input;
    e->cavitation += fluid.cavitation;
  }
  e->h_prev = h;
  e->evaluated = evaluate;
  if (evaluate) {
    e->hysteretic_dissipated = e->hysteretic_work + relaxation;
    e->kinetic = s[0];
    e->strain  = s[1];
    if (m->pore) e->fluid_stored = fluid.storage;
    e->shadow        = s[2];
    e->balance_error = (e->shadow - e->shadow_start) - (e->input + e->external + e->reactions + e->interface_work - e->absorbed - e->damped - e->anelastic - e->contact_damped -
                                         e->hysteretic_dissipated + e->integrator_correction) -
                       (e->fluid_inflow - e->darcy - e->cavitation);
    e->scale         = std::max({e->scale, std::fabs(e->shadow), std::fabs(e->input), std::fabs(e->external), std::fabs(e->absorbed), std::fabs(e->damped), std::fabs(e->anelastic),
                                 std::fabs(e->reactions), std::fabs(e->interface_work), std::fabs(e->contact_damped), std::fabs(e->hysteretic_dissipated), std::fabs(e->integrator_correction), e->kinetic + std::fabs(e->strain), e->darcy, std::fabs(e->fluid_stored), std::fabs(e->cavitation)});
  }
  PetscCall(PetscLogEventEnd(core::event_energy, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

} // namespace slipwave::problem
