#include "slipwave/input/lateral_tie.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "slipwave/input/boundary_faces.hpp"
#include "slipwave/mesh/vertex_coordinates.hpp"

namespace slipwave::input {
namespace {

struct SideNode {
  std::vector<long long> key; // coordinates along the side, quantised
  PetscInt               dof; // global index of the x component
};

// The owned vertices of a side on all ranks (gathered, so every rank can match them), with
// their coordinates along it (all but `axis`) and global dof; and the sum of the side's outward
// face normals. axis < 0: the normals only.
PetscErrorCode sideNodes(DM dm, const std::string &side, PetscInt axis, double quantum, std::vector<SideNode> *nodes, double normal_sum[3]) {
  MPI_Comm     comm = PetscObjectComm((PetscObject)dm);
  PetscInt     dim;
  PetscSection gs;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMGetGlobalSection(dm, &gs));
  std::vector<BoundaryFace> faces;
  PetscCall(BoundaryFacesGet(dm, side, &faces));
  mesh::VertexCoordinates vc;
  PetscCall(vc.Open(dm));
  std::vector<double> local; // per owned vertex: dof, then dim-1 coordinates
  std::map<PetscInt, bool> done;
  for (const BoundaryFace &f : faces) {
    for (PetscInt d = 0; d < dim; ++d) normal_sum[d] += f.normal[d];
    for (PetscInt k = 0; k < f.nvert; ++k) {
      const PetscInt v = f.vertices[k];
      PetscInt       goff;
      PetscCall(PetscSectionGetOffset(gs, v, &goff));
      if (goff < 0 || done[v]) continue; // a ghost: its owner lists it
      done[v] = true;
      double x[3];
      PetscCall(vc.Get(v, x));
      local.push_back((double)goff);
      for (PetscInt d = 0; d < dim; ++d)
        if (d != axis) local.push_back(x[d]);
    }
  }
  PetscCall(vc.Close());
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, normal_sum, 3, MPI_DOUBLE, MPI_SUM, comm));
  if (axis < 0) PetscFunctionReturn(0); // only the direction was asked for
  PetscMPIInt size, n = (PetscMPIInt)local.size();
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<PetscMPIInt> counts(size), displs(size, 0);
  PetscCallMPI(MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
  for (PetscMPIInt r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<double> all(displs[size - 1] + counts[size - 1]);
  PetscCallMPI(MPI_Allgatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, comm));
  for (size_t i = 0; i < all.size(); i += dim) {
    SideNode node;
    node.dof = (PetscInt)all[i];
    for (PetscInt d = 1; d < dim; ++d) node.key.push_back(std::llround(all[i + d] / quantum));
    nodes->push_back(node);
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode LateralTieCreate(DM dm, const BoundaryConditions &bc, Vec mass, LateralTie **out) {
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscInt dim, lo, hi;
  PetscFunctionBeginUser;
  *out = nullptr;
  if (bc.tied_pairs.empty()) PetscFunctionReturn(0);
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(VecGetOwnershipRange(mass, &lo, &hi));
  PetscReal bounds[6];
  PetscCall(DMGetBoundingBox(dm, bounds, bounds + 3));
  double extent = 0;
  for (PetscInt d = 0; d < dim; ++d) extent = std::max(extent, (double)(bounds[3 + d] - bounds[d]));
  const double quantum = 1e-9 * extent;

  // Every tie pair on every rank (the side nodes are gathered), joined into groups: a node on
  // two tied directions (3D, the vertical edges of a box tied left-right and front-back) ties
  // all four corner nodes at its height, which pairwise means would not (each node's
  // acceleration would be the last pair's mean). Groups are keyed by their nodes' x-dofs.
  std::map<PetscInt, PetscInt> parent;
  auto find = [&](PetscInt x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto &[a, b] : bc.tied_pairs) {
    // The tie direction is the axis of side a's mean outward normal.
    double n_a[3] = {0, 0, 0}, n_b[3] = {0, 0, 0};
    std::vector<SideNode> none;
    PetscCall(sideNodes(dm, a, -1, quantum, &none, n_a));
    PetscInt axis = 0;
    for (PetscInt d = 1; d < dim; ++d)
      if (std::fabs(n_a[d]) > std::fabs(n_a[axis])) axis = d;
    std::vector<SideNode> nodes_a, nodes_b;
    double                unused[3] = {0, 0, 0};
    PetscCall(sideNodes(dm, a, axis, quantum, &nodes_a, unused));
    PetscCall(sideNodes(dm, b, axis, quantum, &nodes_b, n_b));
    PetscCheck(n_a[axis] * n_b[axis] < 0, comm, PETSC_ERR_USER_INPUT, "tied sides '%s' and '%s' do not face each other; allowed: opposite sides (e.g. left and right)",
               a.c_str(), b.c_str());
    std::map<std::vector<long long>, PetscInt> by_key;
    for (const SideNode &node : nodes_b) by_key[node.key] = node.dof;
    PetscCheck(nodes_a.size() == nodes_b.size(), comm, PETSC_ERR_USER_INPUT,
               "tied sides '%s' (%zu nodes) and '%s' (%zu nodes) do not have the same nodes; allowed: sides meshed alike (node for node at the same positions along them)",
               a.c_str(), nodes_a.size(), b.c_str(), nodes_b.size());
    for (const SideNode &node : nodes_a) {
      auto hit = by_key.find(node.key);
      PetscCheck(hit != by_key.end(), comm, PETSC_ERR_USER_INPUT,
                 "a node of tied side '%s' has no node facing it on '%s'; allowed: sides meshed alike (node for node at the same positions along them)", a.c_str(),
                 b.c_str());
      for (PetscInt x : {node.dof, hit->second})
        if (!parent.count(x)) parent[x] = x;
      parent[find(node.dof)] = find(hit->second);
    }
  }
  std::map<PetscInt, std::vector<PetscInt>> groups; // root -> members (ascending: the map's order)
  for (const auto &entry : parent) groups[find(entry.first)].push_back(entry.first);
  auto *tie = new LateralTie();
  tie->dim  = dim;
  std::vector<PetscInt> from; // global dofs, node after node, group after group
  tie->group_start.push_back(0);
  for (const auto &entry : groups) {
    const std::vector<PetscInt> &members = entry.second;
    if (members[0] < lo || members[0] >= hi) continue; // the owner of the group's first node takes it
    for (PetscInt x : members)
      for (PetscInt d = 0; d < dim; ++d) from.push_back(x + d);
    tie->group_start.push_back((PetscInt)from.size() / dim);
  }
  IS is_from, is_to;
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)from.size(), from.data(), PETSC_COPY_VALUES, &is_from));
  PetscCall(ISCreateStride(PETSC_COMM_SELF, (PetscInt)from.size(), 0, 1, &is_to));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, (PetscInt)from.size(), &tie->node_values));
  PetscCall(VecScatterCreate(mass, is_from, tie->node_values, is_to, &tie->scatter));
  PetscCall(ISDestroy(&is_from));
  PetscCall(ISDestroy(&is_to));
  PetscCall(VecScatterBegin(tie->scatter, mass, tie->node_values, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(tie->scatter, mass, tie->node_values, INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar *m;
  PetscCall(VecGetArrayRead(tie->node_values, &m));
  for (size_t k = 0; k < from.size(); k += dim) tie->mass.push_back(PetscRealPart(m[k]));
  PetscCall(VecRestoreArrayRead(tie->node_values, &m));
  *out = tie;
  PetscFunctionReturn(0);
}

PetscErrorCode LateralTieApply(LateralTie *tie, Vec accel) {
  PetscFunctionBeginUser;
  if (!tie) PetscFunctionReturn(0);
  const PetscInt dim = tie->dim;
  PetscCall(VecScatterBegin(tie->scatter, accel, tie->node_values, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(tie->scatter, accel, tie->node_values, INSERT_VALUES, SCATTER_FORWARD));
  PetscScalar *a;
  PetscCall(VecGetArray(tie->node_values, &a));
  for (size_t g = 0; g + 1 < tie->group_start.size(); ++g) {
    const PetscInt first = tie->group_start[g], end = tie->group_start[g + 1];
    double         total = 0;
    for (PetscInt k = first; k < end; ++k) total += tie->mass[k];
    for (PetscInt d = 0; d < dim; ++d) {
      double momentum = 0;
      for (PetscInt k = first; k < end; ++k) momentum += tie->mass[k] * PetscRealPart(a[k * dim + d]);
      for (PetscInt k = first; k < end; ++k) a[k * dim + d] = momentum / total;
    }
  }
  PetscCall(VecRestoreArray(tie->node_values, &a));
  PetscCall(VecScatterBegin(tie->scatter, tie->node_values, accel, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterEnd(tie->scatter, tie->node_values, accel, INSERT_VALUES, SCATTER_REVERSE));
  PetscFunctionReturn(0);
}

PetscErrorCode LateralTieDestroy(LateralTie **tie) {
  PetscFunctionBeginUser;
  if (!*tie) PetscFunctionReturn(0);
  PetscCall(VecScatterDestroy(&(*tie)->scatter));
  PetscCall(VecDestroy(&(*tie)->node_values));
  delete *tie;
  *tie = nullptr;
  PetscFunctionReturn(0);
}

} // namespace slipwave::input
