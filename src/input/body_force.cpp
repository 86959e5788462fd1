#include "slipwave/input/body_force.hpp"


namespace slipwave::input {

PetscErrorCode BodyForceCreate(DM dm, Vec mass, BoundaryConditions *bc) {
  MPI_Comm     comm = PetscObjectComm((PetscObject)dm);
  PetscInt     dim, nb;
  PetscReal    b[4] = {0, 0, 0, 0}; // room for one value too many, to report it
  PetscBool    set;
  TimeFunction history;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  nb = 4;
  PetscOptionsBegin(comm, "", "Body force", "slipwave");
  PetscCall(PetscOptionsRealArray("-body_force", "body force per unit mass bx,by[,bz] [m/s^2] on every cell (times -body_force_stf)", "BodyForceCreate", b, &nb, &set));
  if (set) PetscCall(history.Read(comm, "body_force_", HistoryRole::Load, PetscOptionsObject));
  PetscOptionsEnd();
  if (!set) PetscFunctionReturn(0);
  PetscCheck(nb == dim, comm, PETSC_ERR_USER_INPUT, "-body_force has %" PetscInt_FMT " values; allowed: %" PetscInt_FMT " components [m/s^2]", nb, dim);
  Vec                pattern;
  PetscInt           n;
  PetscScalar       *f;
  const PetscScalar *m;
  PetscCall(VecDuplicate(mass, &pattern));
  PetscCall(VecGetLocalSize(mass, &n));
  PetscCall(VecGetArray(pattern, &f));
  PetscCall(VecGetArrayRead(mass, &m));
  for (PetscInt i = 0; i < n; ++i) f[i] = b[i % dim] * m[i];
  PetscCall(VecRestoreArrayRead(mass, &m));
  PetscCall(VecRestoreArray(pattern, &f));
  const std::string note = "body force: " + LoadVectorText(b, dim) + " m/s^2 per unit mass, " + (history.active() ? history.describe() : "constant");
  bc->load_notes.push_back(note);
  PetscCall(TimedLoadAdopt("body force", pattern, std::move(history), bc->constant_force, &bc->timed_loads));
  PetscFunctionReturn(0);
}

} // namespace slipwave::input
