#include "slipwave/problem/nodal_acceleration.hpp"

#include <petsc/private/petscimpl.h>

#include <algorithm>

namespace slipwave::problem {
namespace {

// Appends the local indices where x is nonzero.
PetscErrorCode addSupport(Vec x, std::vector<PetscInt> *dofs) {
  PetscInt           n;
  const PetscScalar *xa;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArrayRead(x, &xa));
  for (PetscInt i = 0; i < n; ++i)
    if (xa[i] != 0.0) dofs->push_back(i);
  PetscCall(VecRestoreArrayRead(x, &xa));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode NodalAccelerationUpdate(const NodalSources &src, Vec f_input, Vec f_external, NodalAcceleration *na) {
  // PETSc 3.18 has no public getter for the state; every write access increases it.
  const PetscObjectState mask_state = ((PetscObject)src.free_mask)->state, constant_state = ((PetscObject)src.constant_force)->state;
  PetscFunctionBeginUser;
  if (na->free_inv_mass && src.free_mask == na->seen_mask && mask_state == na->mask_state && src.constant_force == na->seen_constant &&
      constant_state == na->constant_state)
    PetscFunctionReturn(0);
  if (!na->free_inv_mass) PetscCall(VecDuplicate(src.inv_mass, &na->free_inv_mass));
  PetscCall(VecPointwiseMult(na->free_inv_mass, src.free_mask, src.inv_mass));
  PetscCall(VecZeroEntries(f_input));
  PetscCall(VecZeroEntries(f_external));
  na->external_dofs.clear();
  na->held_dofs.clear();
  {
    PetscInt           n;
    const PetscScalar *mask;
    PetscCall(VecGetLocalSize(src.free_mask, &n));
    PetscCall(VecGetArrayRead(src.free_mask, &mask));
    for (PetscInt i = 0; i < n; ++i)
      if (mask[i] == 0.0) na->held_dofs.push_back(i);
    PetscCall(VecRestoreArrayRead(src.free_mask, &mask));
  }
  na->listed = !src.others_add_external;
  if (na->listed) {
    PetscCall(addSupport(src.input_force, &na->external_dofs));
    PetscCall(addSupport(src.constant_force, &na->external_dofs));
    for (const input::TimedLoad &load : *src.timed_loads) PetscCall(addSupport(load.pattern, &na->external_dofs));
    std::sort(na->external_dofs.begin(), na->external_dofs.end());
    na->external_dofs.erase(std::unique(na->external_dofs.begin(), na->external_dofs.end()), na->external_dofs.end());
    // A list of most dofs (gravity loads every node) is slower than the plain sweep.
    PetscInt n;
    PetscCall(VecGetLocalSize(f_input, &n));
    if (4 * (PetscInt)na->external_dofs.size() > n) {
      na->listed = false;
      na->external_dofs.clear();
    }
  }
  na->seen_mask      = src.free_mask;
  na->seen_constant  = src.constant_force;
  na->mask_state     = mask_state;
  na->constant_state = constant_state;
  PetscFunctionReturn(0);
}

PetscErrorCode NodalAccelerationDestroy(NodalAcceleration *na) {
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&na->free_inv_mass));
  na->external_dofs.clear();
  na->held_dofs.clear();
  PetscFunctionReturn(0);
}

PetscErrorCode NodalAccelerationInput(const NodalAcceleration &na, double v_in, Vec input_force, Vec f_input) {
  PetscFunctionBeginUser;
  if (!na.listed) {
    PetscCall(VecAXPBY(f_input, v_in, 0.0, input_force));
    PetscFunctionReturn(0);
  }
  PetscScalar       *fin;
  const PetscScalar *F;
  PetscCall(VecGetArray(f_input, &fin));
  PetscCall(VecGetArrayRead(input_force, &F));
  for (PetscInt i : na.external_dofs) fin[i] = v_in * F[i];
  PetscCall(VecRestoreArrayRead(input_force, &F));
  PetscCall(VecRestoreArray(f_input, &fin));
  PetscFunctionReturn(0);
}

PetscErrorCode NodalAccelerationExternal(const NodalAcceleration &na, Vec constant_force, Vec f_input, Vec f_external) {
  PetscFunctionBeginUser;
  if (!na.listed) {
    PetscCall(VecWAXPY(f_external, 1.0, constant_force, f_input));
    PetscFunctionReturn(0);
  }
  PetscScalar       *fx;
  const PetscScalar *fc, *fin;
  PetscCall(VecGetArray(f_external, &fx));
  PetscCall(VecGetArrayRead(constant_force, &fc));
  PetscCall(VecGetArrayRead(f_input, &fin));
  for (PetscInt i : na.external_dofs) fx[i] = fc[i] + fin[i];
  PetscCall(VecRestoreArrayRead(f_input, &fin));
  PetscCall(VecRestoreArrayRead(constant_force, &fc));
  PetscCall(VecRestoreArray(f_external, &fx));
  PetscFunctionReturn(0);
}

PetscErrorCode NodalAccelerationAssemble(const NodalAcceleration &na, const NodalForces &f, Vec a) {
  PetscInt           n;
  PetscScalar       *acc;
  const PetscScalar *mim, *fe = nullptr, *fi = nullptr, *fd = nullptr, *fif = nullptr, *fan = nullptr, *fcd = nullptr, *fhy = nullptr;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(a, &n));
  PetscCall(VecGetArrayWrite(a, &acc));
  PetscCall(VecGetArrayRead(na.free_inv_mass, &mim));
  PetscCall(VecGetArrayRead(f.external, &fe));
  PetscCall(VecGetArrayRead(f.internal, &fi));
  if (f.stiffness_damping) PetscCall(VecGetArrayRead(f.stiffness_damping, &fd));
  if (f.interface) PetscCall(VecGetArrayRead(f.interface, &fif));
  if (f.anelastic) PetscCall(VecGetArrayRead(f.anelastic, &fan));
  if (f.contact_damping) PetscCall(VecGetArrayRead(f.contact_damping, &fcd));
  if (f.hysteretic) PetscCall(VecGetArrayRead(f.hysteretic, &fhy));
  // The terms after f_ext - f_int, in the order the sum has always had.
  auto accelerate = [&](PetscInt i, double sum) {
    if (fd) sum -= fd[i];
    if (fif) sum += fif[i];
    if (fan) sum += fan[i];
    if (fcd) sum += fcd[i];
    if (fhy) sum += fhy[i];
    return mim[i] * sum;
  };
  // Off the listed dofs f_ext is zero, and 0 - f_int needs no read of it.
  if (na.listed) {
    for (PetscInt i = 0; i < n; ++i) acc[i] = accelerate(i, 0.0 - fi[i]);
    for (PetscInt i : na.external_dofs) acc[i] = accelerate(i, fe[i] - fi[i]);
  } else {
    for (PetscInt i = 0; i < n; ++i) acc[i] = accelerate(i, fe[i] - fi[i]);
  }
  if (f.hysteretic) PetscCall(VecRestoreArrayRead(f.hysteretic, &fhy));
  if (f.contact_damping) PetscCall(VecRestoreArrayRead(f.contact_damping, &fcd));
  if (f.anelastic) PetscCall(VecRestoreArrayRead(f.anelastic, &fan));
  if (f.interface) PetscCall(VecRestoreArrayRead(f.interface, &fif));
  if (f.stiffness_damping) PetscCall(VecRestoreArrayRead(f.stiffness_damping, &fd));
  PetscCall(VecRestoreArrayRead(f.internal, &fi));
  PetscCall(VecRestoreArrayRead(f.external, &fe));
  PetscCall(VecRestoreArrayRead(na.free_inv_mass, &mim));
  PetscCall(VecRestoreArrayWrite(a, &acc));
  PetscFunctionReturn(0);
}

} // namespace slipwave::problem
