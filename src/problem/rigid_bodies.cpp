#include "slipwave/problem/rigid_bodies.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "slipwave/physics/rigid_body.hpp"

namespace slipwave::problem {
namespace {

// A component held at every node of the body (-constrain_components) fixes the body's
// translation along it and the rotations that would move it; held at some nodes only, or a
// boundary dashpot on the body, stops the run: its supports are its interfaces and welded
// regions.
PetscErrorCode readHeldComponents(MPI_Comm comm, PetscInt dim, const input::BoundaryConditions &bc, RigidBody *body) {
  const PetscScalar *mask, *C;
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(bc.free_mask, &mask));
  PetscCall(VecGetArrayRead(bc.absorbing_blocks, &C));
  long counts[4] = {0, 0, 0, 0}; // held nodes per component, damped nodes
  for (PetscInt off : body->dofs) {
    bool damped = false;
    for (PetscInt d = 0; d < dim; ++d) {
      counts[d] += PetscRealPart(mask[off + d]) == 0.0;
      for (PetscInt k = 0; k < dim; ++k) damped = damped || PetscRealPart(C[(off / dim) * dim * dim + d * dim + k]) != 0.0;
    }
    counts[3] += damped;
  }
  PetscCall(VecRestoreArrayRead(bc.absorbing_blocks, &C));
  PetscCall(VecRestoreArrayRead(bc.free_mask, &mask));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, counts, 4, MPI_LONG, MPI_SUM, comm));
  const char *r = body->region.c_str();
  for (PetscInt d = 0; d < dim; ++d) {
    PetscCheck(counts[d] == 0 || counts[d] == body->nodes, comm, PETSC_ERR_USER_INPUT,
               "-material_%s_model rigid: region '%s' touches a boundary that holds %ld of its %ld nodes along %c; allowed: a rigid region supported by interfaces "
               "or other regions, a component held everywhere (-constrain_components), or -material_%s_model elastic",
               r, r, counts[d], (long)body->nodes, "xyz"[d], r);
    body->fixed[d] = counts[d] > 0;
  }
  PetscCheck(counts[3] == 0, comm, PETSC_ERR_USER_INPUT,
             "-material_%s_model rigid: region '%s' touches an absorbing or free-field boundary; allowed: a rigid region inside the model, or -material_%s_model elastic", r, r,
             r);
  PetscFunctionReturn(0);
}

// The body's owned nodes, mass, centroid and inertia (two passes: the centroid first, so the
// inertia is summed about it and not recovered by a cancelling difference).
PetscErrorCode setUpBody(MPI_Comm comm, PetscInt dim, Vec marks, Vec coords, Vec mass, RigidBody *body) {
  PetscInt           n;
  const PetscScalar *mk, *x, *m;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(marks, &n));
  PetscCall(VecGetArrayRead(marks, &mk));
  PetscCall(VecGetArrayRead(coords, &x));
  PetscCall(VecGetArrayRead(mass, &m));
  double sums[5] = {0, 0, 0, 0, 0}; // nodes, mass, mass-weighted coordinates
  for (PetscInt i = 0; i < n; i += dim)
    if (PetscRealPart(mk[i]) > 0) {
      body->dofs.push_back(i);
      sums[0] += 1;
      sums[1] += PetscRealPart(m[i]);
      for (PetscInt d = 0; d < dim; ++d) sums[2 + d] += PetscRealPart(m[i]) * PetscRealPart(x[i + d]);
    }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums, 5, MPI_DOUBLE, MPI_SUM, comm));
  body->nodes = (PetscInt)sums[0];
  body->mass  = sums[1];
  for (PetscInt d = 0; d < dim; ++d) body->centroid[d] = sums[2 + d] / sums[1];
  for (PetscInt i : body->dofs) {
    double r[3] = {0, 0, 0};
    for (PetscInt d = 0; d < dim; ++d) r[d] = PetscRealPart(x[i + d]) - body->centroid[d];
    body->arm.insert(body->arm.end(), r, r + 3);
    physics::rigidInertiaAdd(PetscRealPart(m[i]), r, body->inertia);
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, body->inertia, 9, MPI_DOUBLE, MPI_SUM, comm));
  PetscCall(VecRestoreArrayRead(mass, &m));
  PetscCall(VecRestoreArrayRead(coords, &x));
  PetscCall(VecRestoreArrayRead(marks, &mk));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode RigidBodiesCreate(DM dm, const fem::BulkOperator &bulk, const std::vector<medium::RegionMaterialInfo> &materials, const input::BoundaryConditions &bc,
                                 Vec mass, RigidBodies **rigid) {
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscFunctionBeginUser;
  *rigid = nullptr;
  if (std::none_of(materials.begin(), materials.end(), [](const medium::RegionMaterialInfo &m) { return m.model == medium::MaterialModel::Rigid; }))
    PetscFunctionReturn(0);
  auto *rb = new RigidBodies;
  rb->comm = comm;
  rb->dim  = bulk.dimension();
  Vec marks, coords, taken;
  PetscCall(VecDuplicate(mass, &marks));
  PetscCall(VecDuplicate(mass, &coords));
  PetscCall(VecDuplicate(mass, &taken));
  PetscCall(VecZeroEntries(taken));
  std::string first_rigid;
  for (size_t r = 0; r < materials.size(); ++r) {
    if (materials[r].model != medium::MaterialModel::Rigid) continue;
    PetscCall(fem::BulkRegionNodes(dm, bulk, (PetscInt)r, marks, coords));
    // A node in two rigid regions would belong to two bodies.
    PetscScalar shared;
    PetscCall(VecDot(taken, marks, &shared)); // both >= 0: nonzero where a node is in both
    PetscCheck(PetscRealPart(shared) == 0, comm, PETSC_ERR_USER_INPUT,
               "-material_%s_model rigid: regions '%s' and '%s' are both rigid and share nodes; allowed: one rigid region for them, or an interface between them",
               materials[r].region.c_str(), first_rigid.c_str(), materials[r].region.c_str());
    if (first_rigid.empty()) first_rigid = materials[r].region;
    PetscCall(VecAXPY(taken, 1.0, marks));
    rb->bodies.emplace_back();
    RigidBody &body = rb->bodies.back();
    body.region     = materials[r].region;
    PetscCall(setUpBody(comm, rb->dim, marks, coords, mass, &body));
    PetscCall(readHeldComponents(comm, rb->dim, bc, &body));
    physics::rigidFreedoms((int)rb->dim, body.fixed, body.translates, body.rotates);
    physics::rigidInertiaInverse((int)rb->dim, body.inertia, body.rotates, body.inverse_inertia);
  }
  rb->resultants.assign(6 * rb->bodies.size(), 0.0);
  PetscCall(VecDestroy(&taken));
  PetscCall(VecDestroy(&coords));
  PetscCall(VecDestroy(&marks));
  *rigid = rb;
  PetscFunctionReturn(0);
}

PetscErrorCode RigidBodiesDestroy(RigidBodies **rigid) {
  PetscFunctionBeginUser;
  delete *rigid;
  *rigid = nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode RigidBodiesMotion(const RigidBodies *rb, Vec mass, Vec u, std::vector<double> *motion) {
  const PetscScalar *x, *m;
  const PetscInt     dim = rb->dim;
  std::vector<double> sums(6 * rb->bodies.size(), 0.0); // per body P = sum m u and L = sum r x m u
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(u, &x));
  PetscCall(VecGetArrayRead(mass, &m));
  for (size_t b = 0; b < rb->bodies.size(); ++b) {
    const RigidBody &body = rb->bodies[b];
    double          *P = &sums[6 * b], *L = P + 3;
    for (size_t k = 0; k < body.dofs.size(); ++k) {
      const PetscInt i     = body.dofs[k];
      double         mu[3] = {0, 0, 0}, l[3];
      for (PetscInt d = 0; d < dim; ++d) mu[d] = PetscRealPart(m[i + d]) * PetscRealPart(x[i + d]);
      physics::cross(&body.arm[3 * k], mu, l);
      for (int d = 0; d < 3; ++d) {
        P[d] += mu[d];
        L[d] += l[d];
      }
    }
  }
  PetscCall(VecRestoreArrayRead(mass, &m));
  PetscCall(VecRestoreArrayRead(u, &x));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums.data(), (int)sums.size(), MPI_DOUBLE, MPI_SUM, rb->comm));
  motion->assign(sums.size(), 0.0);
  for (size_t b = 0; b < rb->bodies.size(); ++b)
    physics::rigidMotionOf(rb->bodies[b].mass, rb->bodies[b].inverse_inertia, &sums[6 * b], &sums[6 * b + 3], &(*motion)[6 * b], &(*motion)[6 * b + 3]);
  PetscFunctionReturn(0);
}

PetscErrorCode RigidBodiesProject(RigidBodies *rb, Vec mass, Vec a) {
  PetscScalar       *acc;
  const PetscScalar *m;
  const PetscInt     dim = rb->dim;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(a, &acc));
  PetscCall(VecGetArrayRead(mass, &m));
  std::fill(rb->resultants.begin(), rb->resultants.end(), 0.0);
  for (size_t b = 0; b < rb->bodies.size(); ++b) {
    const RigidBody &body = rb->bodies[b];
    double          *F = &rb->resultants[6 * b], *M = F + 3;
    for (size_t k = 0; k < body.dofs.size(); ++k) {
      const PetscInt i    = body.dofs[k];
      double         f[3] = {0, 0, 0}, moment[3];
      for (PetscInt d = 0; d < dim; ++d) f[d] = PetscRealPart(m[i + d]) * PetscRealPart(acc[i + d]);
      physics::cross(&body.arm[3 * k], f, moment);
      for (int d = 0; d < 3; ++d) {
        F[d] += f[d];
        M[d] += moment[d];
      }
    }
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, rb->resultants.data(), (int)rb->resultants.size(), MPI_DOUBLE, MPI_SUM, rb->comm));
  for (size_t b = 0; b < rb->bodies.size(); ++b) {
    const RigidBody &body = rb->bodies[b];
    double          *F = &rb->resultants[6 * b];
    for (int d = 0; d < 3; ++d) F[d] = body.translates[d] ? F[d] : 0.0; // held: the supports take it
    for (size_t k = 0; k < body.dofs.size(); ++k) {
      double ai[3];
      physics::rigidPointAcceleration(body.mass, body.inverse_inertia, F, F + 3, &body.arm[3 * k], ai);
      for (PetscInt d = 0; d < dim; ++d) acc[body.dofs[k] + d] = ai[d];
    }
  }
  PetscCall(VecRestoreArrayRead(mass, &m));
  PetscCall(VecRestoreArray(a, &acc));
  PetscFunctionReturn(0);
}

PetscErrorCode RigidBodiesRowBound(const RigidBodies *rb, Vec rows, double *omega2) {
  PetscScalar   *k;
  const PetscInt dim = rb->dim;
  PetscFunctionBeginUser;
  std::vector<double> sums(rb->bodies.size(), 0.0);
  PetscCall(VecGetArray(rows, &k));
  for (size_t b = 0; b < rb->bodies.size(); ++b) {
    const RigidBody &body = rb->bodies[b];
    for (size_t n = 0; n < body.dofs.size(); ++n)
      for (PetscInt d = 0; d < dim; ++d) {
        sums[b] += PetscRealPart(k[body.dofs[n] + d]) * physics::rigidDofCompliance(body.translates[d] ? body.mass : HUGE_VAL, body.inverse_inertia, &body.arm[3 * n], (int)d);
        k[body.dofs[n] + d] = 0;
      }
  }
  PetscCall(VecRestoreArray(rows, &k));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums.data(), (int)sums.size(), MPI_DOUBLE, MPI_SUM, rb->comm));
  *omega2 = sums.empty() ? 0.0 : *std::max_element(sums.begin(), sums.end());
  PetscFunctionReturn(0);
}

std::string RigidBodiesDescribe(const RigidBodies *rb) {
  std::string out;
  if (!rb) return out;
  for (const RigidBody &body : rb->bodies) {
    char       line[320], centroid[96];
    const bool two_d = rb->dim == 2;
    if (two_d) std::snprintf(centroid, sizeof centroid, "(%.4g, %.4g) m", body.centroid[0], body.centroid[1]);
    else std::snprintf(centroid, sizeof centroid, "(%.4g, %.4g, %.4g) m", body.centroid[0], body.centroid[1], body.centroid[2]);
    std::snprintf(line, sizeof line, "  rigid body %s: %ld nodes, mass %.4g %s, centroid %s, inertia %.4g %s; no stiffness or step limit of its own\n", body.region.c_str(),
                  (long)body.nodes, body.mass, two_d ? "kg/m" : "kg", centroid, two_d ? body.inertia[8] : body.inertia[0] + body.inertia[4] + body.inertia[8],
                  two_d ? "kg m2/m about z" : "kg m2 (trace)");
    out += line;
  }
  return out;
}

} // namespace slipwave::problem
