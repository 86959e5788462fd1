#include "slipwave/input/point_force.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "slipwave/mesh/vertex_coordinates.hpp"

namespace slipwave::input {
namespace {

constexpr PetscInt kMaxPointForces = 64;

struct PointForceOptions {
  std::string  name;
  PetscReal    location[3] = {0, 0, 0};
  PetscReal    force[3]    = {0, 0, 0};
  TimeFunction history;
};

PetscErrorCode readPointForce(MPI_Comm comm, PetscInt dim, const std::string &name, PointForceOptions *o) {
  const std::string prefix = "point_force_" + name + "_", title = "Point force " + name;
  PetscInt          nloc = 4, nforce = 4; // room for one value too many, to report it
  PetscReal         location[4] = {0, 0, 0, 0}, force[4] = {0, 0, 0, 0};
  PetscBool         loc_set, force_set;
  PetscFunctionBeginUser;
  o->name = name;
  PetscOptionsBegin(comm, prefix.c_str(), title.c_str(), "slipwave");
  PetscCall(PetscOptionsRealArray("-location", "point of application x,y[,z] [m] (the nearest mesh node takes the force)", "PointForcesCreate", location, &nloc, &loc_set));
  PetscCall(PetscOptionsRealArray("-force", "force fx,fy[,fz] [N in 3D; N/m (line load per unit thickness) in 2D]", "PointForcesCreate", force, &nforce, &force_set));
  PetscCall(o->history.Read(comm, prefix, HistoryRole::Load, PetscOptionsObject));
  PetscOptionsEnd();
  PetscCheck(loc_set && nloc == dim, comm, PETSC_ERR_USER_INPUT, "-%slocation has %" PetscInt_FMT " values; allowed: %" PetscInt_FMT " coordinates [m]", prefix.c_str(),
             loc_set ? nloc : 0, dim);
  PetscCheck(force_set && nforce == dim, comm, PETSC_ERR_USER_INPUT, "-%sforce has %" PetscInt_FMT " values; allowed: %" PetscInt_FMT " components [N, or N/m in 2D]",
             prefix.c_str(), force_set ? nforce : 0, dim);
  std::copy(location, location + dim, o->location);
  std::copy(force, force + dim, o->force);
  PetscFunctionReturn(0);
}

// Candidate (distance, x, y, z): smaller distance first, then smaller coordinates.
using Candidate = std::array<double, 4>;

// The owned vertex nearest to p on this rank (distance +inf when the rank owns none).
PetscErrorCode nearestOwnedVertex(DM dm, PetscInt dim, const double *p, Candidate *best, PetscInt *vertex) {
  PetscSection gs;
  PetscInt     vs, ve;
  mesh::VertexCoordinates xyz;
  PetscFunctionBeginUser;
  *best   = {INFINITY, 0, 0, 0};
  *vertex = -1;
  PetscCall(DMGetGlobalSection(dm, &gs));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vs, &ve));
  PetscCall(xyz.Open(dm));
  for (PetscInt v = vs; v < ve; ++v) {
    PetscInt goff;
    PetscCall(PetscSectionGetOffset(gs, v, &goff));
    if (goff < 0) continue; // a ghost: its owner proposes it
    double x[3] = {0, 0, 0}, d2 = 0;
    PetscCall(xyz.Get(v, x));
    for (PetscInt k = 0; k < dim; ++k) d2 += (x[k] - p[k]) * (x[k] - p[k]);
    const Candidate c = {std::sqrt(d2), x[0], x[1], x[2]};
    if (c < *best) *best = c, *vertex = v;
  }
  PetscCall(xyz.Close());
  PetscFunctionReturn(0);
}

// The force pattern of one point force: the force on the nearest node over all ranks (a global
// vector of like's layout).
PetscErrorCode pointForcePattern(DM dm, PetscInt dim, const PointForceOptions &o, Vec like, Vec *pattern, Candidate *chosen) {
  MPI_Comm    comm = PetscObjectComm((PetscObject)dm);
  PetscMPIInt size;
  Candidate   mine;
  PetscInt    vertex;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(nearestOwnedVertex(dm, dim, o.location, &mine, &vertex));
  std::vector<Candidate> all(size);
  PetscCallMPI(MPI_Allgather(mine.data(), 4, MPI_DOUBLE, all.data(), 4, MPI_DOUBLE, comm));
  *chosen = all[0];
  for (const Candidate &c : all)
    if (c < *chosen) *chosen = c;
  Vec local;
  PetscCall(VecDuplicate(like, pattern));
  PetscCall(VecZeroEntries(*pattern));
  PetscCall(DMGetLocalVector(dm, &local));
  PetscCall(VecZeroEntries(local));
  if (vertex >= 0 && mine == *chosen) { // only the owner of the chosen vertex holds it
    PetscSection s;
    PetscInt     off;
    PetscScalar *a;
    PetscCall(DMGetLocalSection(dm, &s));
    PetscCall(PetscSectionGetOffset(s, vertex, &off));
    PetscCall(VecGetArray(local, &a));
    for (PetscInt d = 0; d < dim; ++d) a[off + d] = o.force[d];
    PetscCall(VecRestoreArray(local, &a));
  }
  PetscCall(DMLocalToGlobal(dm, local, ADD_VALUES, *pattern));
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode PointForcesCreate(DM dm, BoundaryConditions *bc) {
  MPI_Comm            comm = PetscObjectComm((PetscObject)dm);
  PetscInt            dim, n = kMaxPointForces + 1;
  PetscBool           given = PETSC_FALSE;
  std::vector<char *> names(kMaxPointForces + 1, nullptr);
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscOptionsBegin(comm, "", "Point forces", "slipwave");
  PetscCall(PetscOptionsStringArray("-point_forces", "names of point forces (2D: line loads per unit thickness), each set by -point_force_<name>_*", "PointForcesCreate",
                                    names.data(), &n, &given));
  PetscOptionsEnd();
  if (!given) PetscFunctionReturn(0);
  PetscCheck(n <= kMaxPointForces, comm, PETSC_ERR_USER_INPUT, "-point_forces lists more than %d names; allowed: at most %d", (int)kMaxPointForces, (int)kMaxPointForces);
  PetscReal lo[3], hi[3];
  PetscCall(DMGetBoundingBox(dm, lo, hi));
  for (PetscInt i = 0; i < n; ++i) {
    PointForceOptions o;
    PetscCall(readPointForce(comm, dim, names[i], &o));
    PetscCall(PetscFree(names[i]));
    bool inside = true;
    for (PetscInt d = 0; d < dim; ++d) inside = inside && o.location[d] >= lo[d] && o.location[d] <= hi[d];
    char box[256]; // formatted here: PETSc's own %g would print 0 as "0."
    std::snprintf(box, sizeof box, "[%g, %g] x [%g, %g]%s", (double)lo[0], (double)hi[0], (double)lo[1], (double)hi[1], dim == 3 ? " x [the mesh's z range]" : "");
    PetscCheck(inside, comm, PETSC_ERR_USER_INPUT, "-point_force_%s_location is outside the mesh; allowed: a point in %s", o.name.c_str(), box);
    Vec       pattern;
    Candidate node;
    PetscCall(pointForcePattern(dm, dim, o, bc->constant_force, &pattern, &node));
    const double at[3] = {node[1], node[2], node[3]};
    const std::string note = "point force " + o.name + ": " + LoadVectorText(o.force, dim) + (dim == 2 ? " N/m" : " N") + " on the node at " + LoadVectorText(at, dim) +
                             ", " + (o.history.active() ? o.history.describe() : "constant");
    bc->load_notes.push_back(note);
    PetscCall(TimedLoadAdopt("point force " + o.name, pattern, std::move(o.history), bc->constant_force, &bc->timed_loads));
  }
  PetscFunctionReturn(0);
}

} // namespace slipwave::input
