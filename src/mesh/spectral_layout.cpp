#include "slipwave/mesh/spectral_layout.hpp"

#include "slipwave/mesh/labels.hpp"

#include <cmath>
#include <map>

namespace slipwave::mesh {
namespace {

constexpr char kLayoutKey[] = "slipwave_spectral_layout";

PetscErrorCode destroyLayout(void *ctx) {
  PetscFunctionBeginUser;
  delete static_cast<SpectralLayout *>(ctx);
  PetscFunctionReturn(0);
}

// Signed Jacobian of the Q1 map at the centre of the frame's corners (x: lexicographic).
double centreJacobian(PetscInt dim, const double *x) {
  double a[3][3] = {{0}};
  const PetscInt n = dim == 2 ? 4 : 8;
  for (PetscInt k = 0; k < n; ++k)
    for (PetscInt r = 0; r < dim; ++r) {
      const double sign = ((k >> r) & 1) ? 1.0 : -1.0; // d/dxi_r of the corner's Q1 function at the centre (up to 1/2^(dim-1))
      for (PetscInt d = 0; d < dim; ++d) a[d][r] += sign * x[k * dim + d];
    }
  if (dim == 2) return a[0][0] * a[1][1] - a[0][1] * a[1][0];
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

PetscInt ipow(PetscInt b, PetscInt e) {
  PetscInt r = 1;
  for (PetscInt i = 0; i < e; ++i) r *= b;
  return r;
}

} // namespace

PetscErrorCode SpectralCellFrame(DM dm, const VertexCoordinates &coords, PetscInt cell, PetscInt *lex) {
  DMPolytopeType ct;
  PetscInt       dim, v_start, v_end, e_start, e_end, *closure = nullptr, nclosure;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMPlexGetCellType(dm, cell, &ct));
  PetscCheck(ct == DM_POLYTOPE_QUADRILATERAL || ct == DM_POLYTOPE_HEXAHEDRON, PETSC_COMM_SELF, PETSC_ERR_SUP,
             "SpectralCellFrame: cell %" PetscInt_FMT " is a %s; spectral elements are quadrilaterals or hexahedra", cell, DMPolytopeTypes[ct]);
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v_start, &v_end));
  PetscCall(DMPlexGetDepthStratum(dm, 1, &e_start, &e_end));
  PetscInt slot[8], nv = 0;
  std::vector<PetscInt> edges;
  PetscCall(DMPlexGetTransitiveClosure(dm, cell, PETSC_TRUE, &nclosure, &closure));
  for (PetscInt i = 0; i < nclosure; ++i) {
    const PetscInt p = closure[2 * i];
    if (p >= v_start && p < v_end && nv < 8) slot[nv++] = p;
    else if (dim == 3 && p >= e_start && p < e_end) edges.push_back(p);
  }
  PetscCall(DMPlexRestoreTransitiveClosure(dm, cell, PETSC_TRUE, &nclosure, &closure));
  // Closure order: a quadrilateral's vertices go around it; a hexahedron lists one face
  // around it, then the opposite face in an order of PETSc's own, so the vertex joined by an
  // edge to each of the first four is found from the edges.
  const PetscInt around[4] = {0, 1, 3, 2}; // lexicographic corner of the k-th vertex around a face
  for (PetscInt k = 0; k < 4; ++k) lex[around[k]] = slot[k];
  if (dim == 3) {
    for (PetscInt k = 0; k < 4; ++k) {
      PetscInt above = -1;
      for (PetscInt e : edges) {
        const PetscInt *cone;
        PetscCall(DMPlexGetCone(dm, e, &cone));
        for (PetscInt t = 4; t < 8; ++t)
          if ((cone[0] == slot[k] && cone[1] == slot[t]) || (cone[1] == slot[k] && cone[0] == slot[t])) above = slot[t];
      }
      PetscCheck(above >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "SpectralCellFrame: hexahedron %" PetscInt_FMT ": no edge joins its two faces at vertex %" PetscInt_FMT, cell, k);
      lex[4 + around[k]] = above;
    }
  }
  // Right-handed: swap the first two axes where the closure order goes the other way.
  const PetscInt n = dim == 2 ? 4 : 8;
  double         x[24];
  for (PetscInt k = 0; k < n; ++k) PetscCall(coords.Get(lex[k], &x[k * dim]));
  if (centreJacobian(dim, x) < 0)
    for (PetscInt z = 0; z < n; z += 4) std::swap(lex[z + 1], lex[z + 2]);
  PetscFunctionReturn(0);
}

PetscErrorCode SpectralLayoutBuild(DM dm, PetscInt degree, SpectralLayout *L) {
  PetscInt dim, c_start, c_end;
  DMLabel  region, element = nullptr, position = nullptr;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, &c_end));
  PetscCall(DMGetLabel(dm, kRegionLabel, &region));
  if (degree > 1) {
    PetscCall(DMGetLabel(dm, kSpectralElementLabel, &element));
    PetscCall(DMGetLabel(dm, kSpectralPositionLabel, &position));
    PetscCheck(element && position, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "SpectralLayoutBuild: degree %" PetscInt_FMT " but the mesh has no %s/%s labels (not subdivided)", degree,
               kSpectralElementLabel, kSpectralPositionLabel);
  }
  const PetscInt ncell = c_end - c_start, p = degree, nsub = ipow(p, dim), nnode = ipow(p + 1, dim);
  *L        = SpectralLayout();
  L->degree = degree;
  L->dim    = dim;
  L->cell_element.assign(ncell, -1);
  L->cell_position.assign(ncell, 0);
  // Elements in increasing serial number: the same order on any rank that holds them.
  std::map<PetscInt, PetscInt> local_of;
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscInt id = c, pos = 0;
    if (element) {
      PetscCall(DMLabelGetValue(element, c, &id));
      PetscCall(DMLabelGetValue(position, c, &pos));
      PetscCheck(id >= 0 && pos >= 0 && pos < nsub, PETSC_COMM_SELF, PETSC_ERR_PLIB, "SpectralLayoutBuild: cell %" PetscInt_FMT " has element %" PetscInt_FMT " position %" PetscInt_FMT, c, id, pos);
    }
    local_of.emplace(id, 0);
    L->cell_position[c - c_start] = pos;
    L->cell_element[c - c_start]  = id; // serial number for now
  }
  for (auto &kv : local_of) {
    kv.second = L->nelem++;
    L->element_id.push_back(kv.first);
  }
  L->element_cells.assign((size_t)L->nelem * nsub, -1);
  L->element_nodes.assign((size_t)L->nelem * nnode, -1);
  L->element_region.assign(L->nelem, -1);
  VertexCoordinates coords;
  PetscCall(coords.Open(dm));
  for (PetscInt c = c_start; c < c_end; ++c) {
    const PetscInt e = local_of[L->cell_element[c - c_start]], pos = L->cell_position[c - c_start];
    L->cell_element[c - c_start] = e;
    PetscCheck(L->element_cells[(size_t)e * nsub + pos] < 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "SpectralLayoutBuild: two cells at position %" PetscInt_FMT " of element %" PetscInt_FMT, pos,
               L->element_id[e]);
    L->element_cells[(size_t)e * nsub + pos] = c;
    PetscInt r;
    if (region) PetscCall(DMLabelGetValue(region, c, &r));
    else r = -1;
    L->element_region[e] = r;
    PetscInt lex[8];
    PetscCall(SpectralCellFrame(dm, coords, c, lex));
    const PetscInt i = pos % p, j = (pos / p) % p, k = dim == 3 ? pos / (p * p) : 0;
    for (PetscInt corner = 0; corner < (dim == 2 ? 4 : 8); ++corner) {
      const PetscInt a = i + (corner & 1), b = j + ((corner >> 1) & 1), z = k + ((corner >> 2) & 1);
      PetscInt      &node = L->element_nodes[(size_t)e * nnode + a + (p + 1) * (b + (p + 1) * z)];
      PetscCheck(node < 0 || node == lex[corner], PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "SpectralLayoutBuild: the sub-cells of element %" PetscInt_FMT " disagree on a shared node", L->element_id[e]);
      node = lex[corner];
    }
  }
  PetscCall(coords.Close());
  for (PetscInt e = 0; e < L->nelem; ++e)
    for (PetscInt s = 0; s < nsub; ++s)
      PetscCheck(L->element_cells[(size_t)e * nsub + s] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "SpectralLayoutBuild: element %" PetscInt_FMT " is not whole on this rank (sub-cell %" PetscInt_FMT " missing); partition whole elements", L->element_id[e], s);
  PetscFunctionReturn(0);
}

PetscErrorCode SpectralLayoutOf(DM dm, const SpectralLayout **layout) {
  PetscContainer container = nullptr;
  PetscFunctionBeginUser;
  *layout = nullptr;
  PetscCall(PetscObjectQuery((PetscObject)dm, kLayoutKey, (PetscObject *)&container));
  if (container) {
    void *ctx;
    PetscCall(PetscContainerGetPointer(container, &ctx));
    *layout = static_cast<const SpectralLayout *>(ctx);
    PetscFunctionReturn(0);
  }
  DMLabel position;
  PetscCall(DMGetLabel(dm, kSpectralPositionLabel, &position));
  if (!position) PetscFunctionReturn(0);
  PetscInt dim, c_start, c_end, nsub = 0;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, &c_end));
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscInt pos;
    PetscCall(DMLabelGetValue(position, c, &pos));
    nsub = PetscMax(nsub, pos + 1);
  }
  if (nsub == 0) PetscFunctionReturn(0); // no cells here: nothing to group
  const PetscInt degree = (PetscInt)std::lround(std::pow((double)nsub, 1.0 / dim));
  PetscCheck(ipow(degree, dim) == nsub, PETSC_COMM_SELF, PETSC_ERR_PLIB, "SpectralLayoutOf: %" PetscInt_FMT " sub-cells per element is not p^%" PetscInt_FMT, nsub, dim);
  auto *built = new SpectralLayout;
  PetscCall(SpectralLayoutBuild(dm, degree, built));
  PetscCall(PetscContainerCreate(PETSC_COMM_SELF, &container));
  PetscCall(PetscContainerSetPointer(container, built));
  PetscCall(PetscContainerSetUserDestroy(container, destroyLayout));
  PetscCall(PetscObjectCompose((PetscObject)dm, kLayoutKey, (PetscObject)container));
  PetscCall(PetscContainerDestroy(&container));
  *layout = built;
  PetscFunctionReturn(0);
}

} // namespace slipwave::mesh
