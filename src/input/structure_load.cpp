#include "slipwave/input/structure_load.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "slipwave/physics/rigid_body.hpp"

namespace slipwave::input {
namespace {

struct StructureLoadOptions {
  std::string  region;
  PetscReal    force[3]  = {0, 0, 0};
  PetscReal    moment[3] = {0, 0, 0}; // 2D: moment[0] about z
  TimeFunction history;
};

PetscErrorCode readStructureLoad(MPI_Comm comm, PetscInt dim, const std::vector<std::string> &regions, StructureLoadOptions *o, PetscBool *given) {
  char      region[256] = "";
  PetscInt  nf = 4, nm = 4; // room for one value too many, to report it
  PetscReal force[4] = {0, 0, 0, 0}, moment[4] = {0, 0, 0, 0};
  PetscBool force_set, moment_set;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "structure_load_", "Structure load (forced vibration)", "slipwave");
  PetscCall(PetscOptionsString("-region", "region carrying the resultant force and moment (a structure or foundation)", "StructureLoadCreate", region, region, sizeof region,
                               given));
  PetscCall(PetscOptionsRealArray("-force", "resultant force fx,fy[,fz] [N; N/m in 2D]", "StructureLoadCreate", force, &nf, &force_set));
  PetscCall(PetscOptionsRealArray("-moment", "resultant moment about the region's node centroid: M [N m/m] about z in 2D, mx,my,mz [N m] in 3D", "StructureLoadCreate",
                                  moment, &nm, &moment_set));
  if (*given) PetscCall(o->history.Read(comm, "structure_load_", HistoryRole::Load, PetscOptionsObject));
  PetscOptionsEnd();
  PetscCheck(*given || (!force_set && !moment_set), comm, PETSC_ERR_USER_INPUT,
             "-structure_load_force or -structure_load_moment is given without its region; allowed: -structure_load_region <one of -regions>");
  if (!*given) PetscFunctionReturn(0);
  o->region = region;
  PetscCheck(std::find(regions.begin(), regions.end(), o->region) != regions.end(), comm, PETSC_ERR_USER_INPUT,
             "-structure_load_region = %s is not a region; allowed: one of -regions", region);
  PetscCheck(force_set || moment_set, comm, PETSC_ERR_USER_INPUT, "-structure_load_region = %s has no load; allowed: -structure_load_force and/or -structure_load_moment",
             region);
  PetscCheck(!force_set || nf == dim, comm, PETSC_ERR_USER_INPUT, "-structure_load_force has %" PetscInt_FMT " values; allowed: %" PetscInt_FMT, nf, dim);
  PetscCheck(!moment_set || nm == (dim == 2 ? 1 : 3), comm, PETSC_ERR_USER_INPUT, "-structure_load_moment has %" PetscInt_FMT " values; allowed: %d", nm, dim == 2 ? 1 : 3);
  std::copy(force, force + 3, o->force);
  std::copy(moment, moment + 3, o->moment);
  PetscFunctionReturn(0);
}

// pattern_i = F/N + theta x r_i on the marked nodes (see the header).
PetscErrorCode rigidBodyForces(MPI_Comm comm, PetscInt dim, const StructureLoadOptions &o, Vec marks, Vec coords, Vec pattern, double centroid[3], double *count) {
  PetscInt           n;
  const PetscScalar *m, *x;
  PetscScalar       *f;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(marks, &n));
  PetscCall(VecGetArrayRead(marks, &m));
  PetscCall(VecGetArrayRead(coords, &x));
  double s[4] = {0, 0, 0, 0}; // node count, sum of coordinates
  for (PetscInt i = 0; i < n; i += dim)
    if (PetscRealPart(m[i]) > 0) {
      s[0] += 1;
      for (PetscInt d = 0; d < dim; ++d) s[1 + d] += x[i + d];
    }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, s, 4, MPI_DOUBLE, MPI_SUM, comm));
  *count = s[0];
  for (int d = 0; d < 3; ++d) centroid[d] = s[0] > 0 ? s[1 + d] / s[0] : 0;
  double I[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0}; // sum of |r|^2 1 - r r^T (r padded to 3D)
  for (PetscInt i = 0; i < n; i += dim)
    if (PetscRealPart(m[i]) > 0) {
      double r[3] = {0, 0, 0};
      for (PetscInt d = 0; d < dim; ++d) r[d] = x[i + d] - centroid[d];
      physics::rigidInertiaAdd(1.0, r, I);
    }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, I, 9, MPI_DOUBLE, MPI_SUM, comm));
  // The nodal forces are the "accelerations" of unit masses under (F, M): F/N + theta x r.
  double Iinv[9];
  const bool every_rotation[3] = {true, true, true};
  physics::rigidInertiaInverse((int)dim, I, every_rotation, Iinv);
  const double moment[3] = {dim == 2 ? 0.0 : o.moment[0], dim == 2 ? 0.0 : o.moment[1], dim == 2 ? o.moment[0] : o.moment[2]};
  PetscCall(VecGetArray(pattern, &f));
  for (PetscInt i = 0; i < n; i += dim) {
    if (!(PetscRealPart(m[i]) > 0)) continue;
    double r[3] = {0, 0, 0}, fi[3];
    for (PetscInt d = 0; d < dim; ++d) r[d] = x[i + d] - centroid[d];
    physics::rigidPointAcceleration(s[0], Iinv, o.force, moment, r, fi);
    for (PetscInt d = 0; d < dim; ++d) f[i + d] = fi[d];
  }
  PetscCall(VecRestoreArray(pattern, &f));
  PetscCall(VecRestoreArrayRead(coords, &x));
  PetscCall(VecRestoreArrayRead(marks, &m));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode StructureLoadCreate(DM dm, const fem::BulkOperator &bulk, const std::vector<std::string> &regions, BoundaryConditions *bc) {
  MPI_Comm             comm = PetscObjectComm((PetscObject)dm);
  const PetscInt       dim  = bulk.dimension();
  StructureLoadOptions o;
  PetscBool            given;
  PetscFunctionBeginUser;
  PetscCall(readStructureLoad(comm, dim, regions, &o, &given));
  if (!given) PetscFunctionReturn(0);
  const PetscInt region = (PetscInt)(std::find(regions.begin(), regions.end(), o.region) - regions.begin());
  Vec            marks, coords, pattern;
  double         centroid[3] = {0, 0, 0}, count = 0;
  PetscCall(VecDuplicate(bc->constant_force, &marks));
  PetscCall(VecDuplicate(marks, &coords));
  PetscCall(VecDuplicate(marks, &pattern));
  PetscCall(VecZeroEntries(pattern));
  PetscCall(fem::BulkRegionNodes(dm, bulk, region, marks, coords));
  PetscCall(rigidBodyForces(comm, dim, o, marks, coords, pattern, centroid, &count));
  PetscCall(VecDestroy(&coords));
  PetscCall(VecDestroy(&marks));
  const std::string note = "structure load on '" + o.region + "' (" + std::to_string((long)count) + " nodes, centroid " + LoadVectorText(centroid, dim) +
                           "): force " + LoadVectorText(o.force, dim) + ", moment " + LoadVectorText(o.moment, dim == 2 ? 1 : 3) + ", " +
                           (o.history.active() ? o.history.describe() : "constant");
  bc->load_notes.push_back(note);
  PetscCall(TimedLoadAdopt("structure load " + o.region, pattern, std::move(o.history), bc->constant_force, &bc->timed_loads));
  PetscFunctionReturn(0);
}

} // namespace slipwave::input
