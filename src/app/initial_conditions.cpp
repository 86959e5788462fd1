#include "slipwave/app/initial_conditions.hpp"

#include <string>

namespace slipwave::app {
namespace {

PetscErrorCode setUniformVelocity(PetscInt dim, Vec free_mask, const PetscReal uniform[], Vec v) {
  PetscInt           n;
  PetscScalar       *va;
  const PetscScalar *mask;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(v, &n));
  PetscCall(VecGetArray(v, &va));
  PetscCall(VecGetArrayRead(free_mask, &mask));
  for (PetscInt i = 0; i < n; ++i) va[i] = mask[i] * uniform[i % dim];
  PetscCall(VecRestoreArrayRead(free_mask, &mask));
  PetscCall(VecRestoreArray(v, &va));
  PetscFunctionReturn(0);
}

PetscErrorCode setRegionVelocities(DM dm, const fem::BulkOperator &bulk, Vec free_mask, const RegionVelocities &regions, Vec v) {
  PetscInt dim;
  Vec      local;
  PetscFunctionBeginUser;
  bool any = false;
  for (const auto &vel : regions) any = any || !vel.empty();
  if (!any) PetscFunctionReturn(0);
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMGetLocalVector(dm, &local));
  PetscCall(DMGlobalToLocal(dm, v, INSERT_VALUES, local));
  PetscScalar *va;
  PetscCall(VecGetArray(local, &va));
  for (PetscInt c = 0; c < bulk.cellCount(); ++c) {
    const auto &vel = regions[bulk.cellRegion(c)];
    if (vel.empty()) continue;
    for (PetscInt a = 0; a < bulk.nodesPerCell(); ++a)
      for (PetscInt d = 0; d < dim; ++d) va[bulk.cellNodeOffset(c, a) + d] = vel[d];
  }
  PetscCall(VecRestoreArray(local, &va));
  PetscCall(DMLocalToGlobal(dm, local, INSERT_VALUES, v));
  PetscCall(VecPointwiseMult(v, v, free_mask));
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode RegionVelocitiesRead(MPI_Comm comm, PetscInt dim, const std::vector<medium::RegionMaterialInfo> &materials, RegionVelocities *velocities) {
  PetscFunctionBeginUser;
  velocities->assign(materials.size(), {});
  PetscOptionsBegin(comm, "", "Initial conditions", "slipwave");
  for (size_t reg = 0; reg < materials.size(); ++reg) {
    const std::string opt = "-initial_velocity_" + materials[reg].region;
    PetscReal         vel[3] = {0, 0, 0};
    PetscInt          n      = 3;
    PetscBool         set;
    PetscCall(PetscOptionsRealArray(opt.c_str(), "initial velocity vx,vy[,vz] of the region's nodes [m/s]", "SimulationRun", vel, &n, &set));
    if (!set) continue;
    PetscCheck(n == dim, comm, PETSC_ERR_USER_INPUT, "%s has %" PetscInt_FMT " values; allowed: %" PetscInt_FMT, opt.c_str(), n, dim);
    (*velocities)[reg].assign(vel, vel + dim);
  }
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

PetscErrorCode InitialVelocitySet(DM dm, const fem::BulkOperator &bulk, Vec free_mask, const PetscReal uniform[], const RegionVelocities &regions, Vec v) {
  PetscInt dim;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(setUniformVelocity(dim, free_mask, uniform, v));
  PetscCall(setRegionVelocities(dm, bulk, free_mask, regions, v));
  PetscFunctionReturn(0);
}

} // namespace slipwave::app
