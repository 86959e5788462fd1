#include "slipwave/mesh/spectral_layout.hpp"

#include "slipwave/mesh/dm_table.hpp"
#include "slipwave/mesh/labels.hpp"

#include <cmath>
#include <utility>

namespace slipwave::mesh {
namespace {

constexpr char kLayoutKey[] = "slipwave_spectral_layout";

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

// The cell across the face of c's frame at axis d = 1 (-1 if none: a boundary): the cone face
// whose vertices (read through the cones: a face's closure would also order them) are all
// corners of c with bit d set.
static PetscErrorCode frameNeighbour(DM dm, PetscInt dim, PetscInt c, const PetscInt *lex, PetscInt ncorner, PetscInt d, PetscInt *neighbour) {
  const PetscInt *cone;
  PetscInt        ncone;
  PetscFunctionBeginUser;
  *neighbour = -1;
  PetscCall(DMPlexGetConeSize(dm, c, &ncone));
  PetscCall(DMPlexGetCone(dm, c, &cone));
  auto onSide = [&](PetscInt v) {
    for (PetscInt k = 0; k < ncorner; ++k)
      if (lex[k] == v) return ((k >> d) & 1) == 1;
    return false;
  };
  for (PetscInt q = 0; q < ncone && *neighbour < 0; ++q) {
    const PetscInt *edges;
    PetscInt        nedges;
    bool            on_side = true;
    // 2D: the face is an edge (its cone: two vertices); 3D: a face of edges.
    if (dim == 2) nedges = 1, edges = &cone[q];
    else {
      PetscCall(DMPlexGetConeSize(dm, cone[q], &nedges));
      PetscCall(DMPlexGetCone(dm, cone[q], &edges));
    }
    for (PetscInt k = 0; k < nedges && on_side; ++k) {
      const PetscInt *ends;
      PetscCall(DMPlexGetCone(dm, edges[k], &ends));
      on_side = onSide(ends[0]) && onSide(ends[1]);
    }
    if (!on_side) continue;
    const PetscInt *supp;
    PetscInt        nsupp;
    PetscCall(DMPlexGetSupportSize(dm, cone[q], &nsupp));
    PetscCall(DMPlexGetSupport(dm, cone[q], &supp));
    for (PetscInt k = 0; k < nsupp; ++k)
      if (supp[k] != c) *neighbour = supp[k];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode SpectralLayoutBuild(DM dm, PetscInt degree, SpectralLayout *L) {
  PetscInt dim, c_start, c_end;
  DMLabel  region, position = nullptr;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, &c_end));
  PetscCall(DMGetLabel(dm, kRegionLabel, &region));
  if (degree > 1) {
    PetscCall(DMGetLabel(dm, kSpectralPositionLabel, &position));
    PetscCheck(position, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "SpectralLayoutBuild: degree %" PetscInt_FMT " but the mesh has no %s label (not subdivided)", degree,
               kSpectralPositionLabel);
  }
  const PetscInt ncell = c_end - c_start, p = degree, nsub = SpectralCount(p, dim), nnode = SpectralCount(p + 1, dim), ncorner = dim == 2 ? 4 : 8;
  *L        = SpectralLayout();
  L->degree = degree;
  L->dim    = dim;
  L->cell_element.assign(ncell, -1);
  L->cell_position.assign(ncell, degree > 1 ? -1 : 0);
  // Positions stratum by stratum (a label lookup per cell would search every value).
  for (PetscInt q = 0; position && q < nsub; ++q) {
    IS              is;
    PetscInt        n;
    const PetscInt *points;
    PetscCall(DMLabelGetStratumIS(position, q, &is));
    if (!is) continue;
    PetscCall(ISGetLocalSize(is, &n));
    PetscCall(ISGetIndices(is, &points));
    for (PetscInt i = 0; i < n; ++i)
      if (points[i] >= c_start && points[i] < c_end) L->cell_position[points[i] - c_start] = q;
    PetscCall(ISRestoreIndices(is, &points));
    PetscCall(ISDestroy(&is));
  }
  std::vector<PetscInt> frames((size_t)ncell * 8, -1);
  VertexCoordinates     coords;
  PetscCall(coords.Open(dm));
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscCheck(L->cell_position[c - c_start] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "SpectralLayoutBuild: cell %" PetscInt_FMT " has no %s", c, kSpectralPositionLabel);
    PetscCall(SpectralCellFrame(dm, coords, c, &frames[(size_t)(c - c_start) * 8]));
  }
  PetscCall(coords.Close());
  // Each element from its position-0 sub-cell, through the faces at x, y, z = 1 of the frames.
  std::vector<PetscInt> stack;
  for (PetscInt c0 = c_start; c0 < c_end; ++c0) {
    if (L->cell_position[c0 - c_start] != 0) continue;
    const PetscInt e = L->nelem++;
    L->element_id.push_back(c0);
    L->element_cells.resize((size_t)L->nelem * nsub, -1);
    L->element_nodes.resize((size_t)L->nelem * nnode, -1);
    PetscInt r = -1;
    if (region) PetscCall(DMLabelGetValue(region, c0, &r));
    L->element_region.push_back(r);
    L->cell_element[c0 - c_start] = e;
    stack.assign(1, c0);
    while (!stack.empty()) {
      const PetscInt c = stack.back(), pos = L->cell_position[c - c_start];
      stack.pop_back();
      PetscCheck(L->element_cells[(size_t)e * nsub + pos] < 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "SpectralLayoutBuild: two cells at position %" PetscInt_FMT " of the element of cell %" PetscInt_FMT,
                 pos, c0);
      L->element_cells[(size_t)e * nsub + pos] = c;
      const PetscInt *lex = &frames[(size_t)(c - c_start) * 8];
      const PetscInt  idx[3] = {pos % p, (pos / p) % p, dim == 3 ? pos / (p * p) : 0};
      for (PetscInt corner = 0; corner < ncorner; ++corner) {
        const PetscInt a = idx[0] + (corner & 1), b = idx[1] + ((corner >> 1) & 1), z = idx[2] + ((corner >> 2) & 1);
        PetscInt      &node = L->element_nodes[(size_t)e * nnode + a + (p + 1) * (b + (p + 1) * z)];
        PetscCheck(node < 0 || node == lex[corner], PETSC_COMM_SELF, PETSC_ERR_PLIB, "SpectralLayoutBuild: the sub-cells of the element of cell %" PetscInt_FMT " disagree on a shared node", c0);
        node = lex[corner];
      }
      for (PetscInt d = 0, stride = 1; d < dim; stride *= p, ++d) {
        if (idx[d] == p - 1) continue;
        PetscInt n;
        PetscCall(frameNeighbour(dm, dim, c, lex, ncorner, d, &n));
        PetscCheck(n >= 0 && L->cell_position[n - c_start] == pos + stride, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                   "SpectralLayoutBuild: cell %" PetscInt_FMT " (position %" PetscInt_FMT ") has no sub-cell of its element beyond its side %" PetscInt_FMT " on this rank", c, pos, d);
        if (L->cell_element[n - c_start] < 0) {
          L->cell_element[n - c_start] = e;
          stack.push_back(n);
        }
      }
    }
  }
  for (PetscInt c = c_start; c < c_end; ++c)
    PetscCheck(L->cell_element[c - c_start] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "SpectralLayoutBuild: cell %" PetscInt_FMT " belongs to no element whole on this rank; partition whole elements", c);
  for (PetscInt e = 0; e < L->nelem; ++e)
    for (PetscInt q = 0; q < nsub; ++q)
      PetscCheck(L->element_cells[(size_t)e * nsub + q] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "SpectralLayoutBuild: the element of cell %" PetscInt_FMT " is not whole on this rank (sub-cell %" PetscInt_FMT " missing); partition whole elements", L->element_id[e], q);
  PetscFunctionReturn(0);
}

PetscErrorCode SpectralLayoutOf(DM dm, const SpectralLayout **layout) {
  PetscFunctionBeginUser;
  PetscCall(DMTableFind(dm, kLayoutKey, layout));
  if (*layout) PetscFunctionReturn(0);
  DMLabel position;
  PetscCall(DMGetLabel(dm, kSpectralPositionLabel, &position));
  if (!position) PetscFunctionReturn(0);
  // The label is on cells only: its largest value here is the last position.
  PetscInt        dim, nvalues, nsub = 0;
  IS              values;
  const PetscInt *vals;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMLabelGetValueIS(position, &values));
  PetscCall(ISGetLocalSize(values, &nvalues));
  PetscCall(ISGetIndices(values, &vals));
  for (PetscInt i = 0; i < nvalues; ++i) nsub = PetscMax(nsub, vals[i] + 1);
  PetscCall(ISRestoreIndices(values, &vals));
  PetscCall(ISDestroy(&values));
  if (nsub == 0) PetscFunctionReturn(0); // no cells here: nothing to group
  const PetscInt degree = (PetscInt)std::lround(std::pow((double)nsub, 1.0 / dim));
  PetscCheck(SpectralCount(degree, dim) == nsub, PETSC_COMM_SELF, PETSC_ERR_PLIB, "SpectralLayoutOf: %" PetscInt_FMT " sub-cells per element is not p^%" PetscInt_FMT, nsub, dim);
  SpectralLayout built;
  PetscCall(SpectralLayoutBuild(dm, degree, &built));
  PetscCall(SpectralLayoutAttach(dm, std::move(built)));
  PetscCall(SpectralLayoutOf(dm, layout));
  PetscFunctionReturn(0);
}

PetscErrorCode SpectralLayoutAttach(DM dm, SpectralLayout &&layout) {
  PetscFunctionBeginUser;
  PetscCall(DMTableAttach(dm, kLayoutKey, std::move(layout)));
  PetscFunctionReturn(0);
}

} // namespace slipwave::mesh
