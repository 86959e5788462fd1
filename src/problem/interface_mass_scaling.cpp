#include "slipwave/problem/interface_mass_scaling.hpp"

#include <algorithm>
#include <vector>

#include "slipwave/numerics/reference_cell.hpp"
#include "slipwave/physics/stable_time_step.hpp"
#include "slipwave/problem/rigid_bodies.hpp"

namespace slipwave::problem {

PetscErrorCode InterfaceMassScale(Elastodynamics *m, Vec bulk_rows, double dt_target, PetscInt *nodes) {
  Vec            springs, dashpots, added;
  PetscInt       n;
  const PetscInt bs = m->dim;
  PetscFunctionBeginUser;
  *nodes = 0;
  PetscCall(VecDuplicate(bulk_rows, &springs));
  PetscCall(VecDuplicate(bulk_rows, &dashpots));
  PetscCall(VecDuplicate(bulk_rows, &added));
  PetscCall(VecZeroEntries(springs));
  PetscCall(VecZeroEntries(dashpots));
  PetscCall(VecZeroEntries(added));
  for (auto &iface : m->interfaces) {
    PetscCall(iface.AddStiffnessRowAbsSums(springs));
    PetscCall(iface.AddDampingRowAbsSums(dashpots));
  }
  PetscCall(VecGetLocalSize(bulk_rows, &n));
  std::vector<char> keep(n / bs, 0); // nodes whose mass stays the physical one
  if (m->rigid)
    for (const RigidBody &body : m->rigid->bodies)
      for (PetscInt dof : body.dofs) keep[dof / bs] = 1;
  for (PetscInt node : m->absorbing_nodes) keep[node] = 1;
  {
    const PetscScalar *B, *S, *C, *mass, *mask;
    PetscScalar       *a;
    PetscCall(VecGetArrayRead(bulk_rows, &B));
    PetscCall(VecGetArrayRead(springs, &S));
    PetscCall(VecGetArrayRead(dashpots, &C));
    PetscCall(VecGetArrayRead(m->mass, &mass));
    PetscCall(VecGetArrayRead(m->bc.free_mask, &mask));
    PetscCall(VecGetArray(added, &a));
    for (PetscInt node = 0; node < n / bs; ++node) {
      if (keep[node]) continue;
      // One mass for the node's components (a lumped mass is isotropic): the largest any
      // free component's row needs.
      double need = 0;
      for (PetscInt i = node * bs; i < (node + 1) * bs; ++i) {
        const double k = PetscRealPart(B[i] + S[i]);
        if (PetscRealPart(S[i]) > 0 && PetscRealPart(mask[i]) > 0)
          need = std::max(need, physics::massForStableStep(k, m->rayleigh.beta * k + PetscRealPart(C[i]), dt_target) - PetscRealPart(mass[i]));
      }
      if (need <= 0) continue;
      for (PetscInt i = node * bs; i < (node + 1) * bs; ++i) a[i] = need;
      *nodes += 1;
    }
    PetscCall(VecRestoreArray(added, &a));
    PetscCall(VecRestoreArrayRead(m->bc.free_mask, &mask));
    PetscCall(VecRestoreArrayRead(m->mass, &mass));
    PetscCall(VecRestoreArrayRead(dashpots, &C));
    PetscCall(VecRestoreArrayRead(springs, &S));
    PetscCall(VecRestoreArrayRead(bulk_rows, &B));
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, nodes, 1, MPIU_INT, MPI_SUM, m->comm));
  if (*nodes > 0) PetscCall(ElastodynamicsAddMass(m, added));
  PetscCall(VecDestroy(&added));
  PetscCall(VecDestroy(&dashpots));
  PetscCall(VecDestroy(&springs));
  PetscFunctionReturn(0);
}

PetscErrorCode MassScalingSummarize(const Elastodynamics *m, Vec physical_mass, MassScalingResult *result) {
  PetscInt           n;
  const PetscInt     bs = m->dim;
  const PetscScalar *scaled, *own;
  PetscFunctionBeginUser;
  *result = MassScalingResult();
  PetscCall(VecGetLocalSize(physical_mass, &n));
  PetscCall(VecGetArrayRead(m->mass, &scaled));
  PetscCall(VecGetArrayRead(physical_mass, &own));
  for (PetscInt i = 0; i < n; i += bs) {
    const double mass = PetscRealPart(own[i]), added = PetscRealPart(scaled[i]) - mass;
    result->model_mass += mass;
    if (added <= 0) continue;
    result->added += added;
    result->nodes += 1;
    result->largest_factor = std::max(result->largest_factor, 1 + added / mass);
  }
  PetscCall(VecRestoreArrayRead(physical_mass, &own));
  PetscCall(VecRestoreArrayRead(m->mass, &scaled));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &result->added, 1, MPI_DOUBLE, MPI_SUM, m->comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &result->model_mass, 1, MPI_DOUBLE, MPI_SUM, m->comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &result->largest_factor, 1, MPI_DOUBLE, MPI_MAX, m->comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &result->nodes, 1, MPIU_INT, MPI_SUM, m->comm));
  // Each region's mass, rho times its cells' volume.
  std::vector<double> region_mass(m->materials.size(), 0.0);
  for (PetscInt c = 0; c < m->bulk.cellCount(); ++c) {
    const PetscInt r = m->bulk.cellRegion(c);
    region_mass[r] += m->materials[r].elastic.rho * numerics::cellVolume(m->bulk.shape(), m->bulk.cellCoordinates(c));
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, region_mass.data(), (int)region_mass.size(), MPI_DOUBLE, MPI_SUM, m->comm));
  result->lightest_side = 1e300;
  for (const auto &iface : m->interfaces)
    for (size_t r = 0; r < m->materials.size(); ++r)
      if ((m->materials[r].region == iface.spec().soil_region || m->materials[r].region == iface.spec().structure_region) && region_mass[r] < result->lightest_side) {
        result->lightest_side   = region_mass[r];
        result->lightest_region = m->materials[r].region;
      }
  PetscFunctionReturn(0);
}

} // namespace slipwave::problem
