#include "slipwave/model/energy_ledger.hpp"

#include <algorithm>
#include <cmath>

#include "slipwave/core/log_events.hpp"
#include "slipwave/model/pore_pressure.hpp"
#include "slipwave/time/central_difference.hpp"

namespace slipwave::model {

PetscErrorCode EnergyLedgerUpdate(Elastodynamics *m, TS ts, PetscReal h, EnergyLedger *e) {
  Vec u, v, a;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(core::event_energy, 0, 0, 0, 0));
  PetscCall(TS2GetSolution(ts, &u, &v));
  PetscCall(time::CentralDifferenceGetAcceleration(ts, &a));
  PetscInt           n;
  const PetscInt     bs = m->dim;
  const PetscScalar *ua, *va, *aa, *ma, *fi, *fx, *fin, *fsd, *fif, *fan, *fcd, *C, *mask;
  PetscCall(VecGetLocalSize(u, &n));
  PetscCall(VecGetArrayRead(u, &ua));
  PetscCall(VecGetArrayRead(v, &va));
  PetscCall(VecGetArrayRead(a, &aa));
  PetscCall(VecGetArrayRead(m->mass, &ma));
  PetscCall(VecGetArrayRead(m->f_internal, &fi));
  PetscCall(VecGetArrayRead(m->f_external, &fx));
  PetscCall(VecGetArrayRead(m->f_input, &fin));
  PetscCall(VecGetArrayRead(m->f_stiffness_damping, &fsd));
  PetscCall(VecGetArrayRead(m->f_interface, &fif));
  PetscCall(VecGetArrayRead(m->f_anelastic, &fan));
  PetscCall(VecGetArrayRead(m->f_contact_damping, &fcd));
  PetscCall(VecGetArrayRead(m->bc.absorbing_blocks, &C));
  PetscCall(VecGetArrayRead(m->bc.free_mask, &mask));
  // Local sums: 0 kinetic, 1 strain, 2 shadow, 3 input power, 4 external power,
  // 5 reaction power, 6 absorbed power, 7 damping power, 8 interface power, 9 power of the
  // constant-Q memory forces, 10 contact dashpot power. Written without branches (the mask is
  // 0 or 1) because this pass runs every step over every dof.
  double       s[11] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  const double alpha = m->rayleigh.alpha;
  for (PetscInt k = 0; k < n; ++k) {
    const double vk = va[k], mk = ma[k], fik = fi[k], held = 1.0 - mask[k];
    const double vhalf = vk + 0.5 * h * aa[k];
    s[0] += 0.5 * mk * vk * vk;
    s[1] += 0.5 * ua[k] * fik;
    s[2] += 0.5 * mk * vhalf * vhalf + 0.5 * ua[k] * fik + 0.5 * h * vhalf * fik;
    s[3] += vk * fin[k];
    s[4] += vk * (fx[k] - fin[k]);
    // What a support supplies: everything M a + K u asks beyond the applied loads.
    s[5] += held * vk * (mk * aa[k] + fik - fx[k] - fif[k] - fan[k] - fcd[k]);
    s[8] += vk * fif[k];
    s[9] += mask[k] * vk * fan[k];
    s[10] += vk * fcd[k];
    s[7] += mask[k] * vk * (alpha * mk * vk + fsd[k]);
  }
  for (PetscInt node : m->absorbing_nodes)
    for (PetscInt i = 0; i < bs; ++i)
      for (PetscInt j = 0; j < bs; ++j)
        s[6] += mask[node * bs + i] * mask[node * bs + j] * va[node * bs + i] * C[node * bs * bs + i * bs + j] * va[node * bs + j];
  PetscCall(VecRestoreArrayRead(m->bc.free_mask, &mask));
  PetscCall(VecRestoreArrayRead(m->bc.absorbing_blocks, &C));
  PetscCall(VecRestoreArrayRead(m->f_contact_damping, &fcd));
  PetscCall(VecRestoreArrayRead(m->f_anelastic, &fan));
  PetscCall(VecRestoreArrayRead(m->f_interface, &fif));
  PetscCall(VecRestoreArrayRead(m->f_stiffness_damping, &fsd));
  PetscCall(VecRestoreArrayRead(m->f_input, &fin));
  PetscCall(VecRestoreArrayRead(m->f_external, &fx));
  PetscCall(VecRestoreArrayRead(m->f_internal, &fi));
  PetscCall(VecRestoreArrayRead(m->mass, &ma));
  PetscCall(VecRestoreArrayRead(a, &aa));
  PetscCall(VecRestoreArrayRead(v, &va));
  PetscCall(VecRestoreArrayRead(u, &ua));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, s, 11, MPI_DOUBLE, MPI_SUM, m->comm));

  PoreEnergy fluid;
  if (m->pore) {
    PetscCall(PorePressureEnergy(m->pore, h, v, a, m->f_pore, m->bc.free_mask, &fluid));
    s[2] += fluid.storage;
    s[5] -= fluid.held_power;
    e->fluid        = true;
    e->fluid_stored = fluid.storage;
  }
  e->kinetic = s[0];
  e->strain  = s[1];
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
    e->darcy += fluid.darcy;
    e->fluid_inflow += fluid.inflow;
  }
  e->h_prev = h;
  e->shadow        = s[2];
  e->balance_error = (e->shadow - e->shadow_start) - (e->input + e->external + e->reactions + e->interface_work - e->absorbed - e->damped - e->anelastic - e->contact_damped) -
                     (e->fluid_inflow - e->darcy);
  e->scale         = std::max({e->scale, std::fabs(e->shadow), std::fabs(e->input), std::fabs(e->external), std::fabs(e->absorbed), std::fabs(e->damped), std::fabs(e->anelastic),
                               std::fabs(e->reactions), std::fabs(e->interface_work), std::fabs(e->contact_damped), e->kinetic + std::fabs(e->strain), e->darcy, std::fabs(e->fluid_stored)});
  PetscCall(PetscLogEventEnd(core::event_energy, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

} // namespace slipwave::model
