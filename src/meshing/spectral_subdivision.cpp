#include "slipwave/meshing/spectral_subdivision.hpp"

#include "slipwave/mesh/labels.hpp"
#include "slipwave/mesh/spectral_layout.hpp"
#include "slipwave/mesh/vertex_coordinates.hpp"
#include "slipwave/numerics/gll_basis.hpp"

#include <array>
#include <map>

namespace slipwave::meshing {
namespace {

// A node by the parent point it lies in: {kind, ids..., indices...}. kind 0: a vertex {0, v};
// 1: an edge {1, v_low, v_high, t} with t counted from v_low; 2: a face of a hexahedron
// {2, origin, v_axis1, v_axis2, s, t}, the origin its lowest vertex and axis 1 towards the
// lower of its two neighbours; 3: inside cell c {3, c, i, j, k}.
using NodeKey = std::array<PetscInt, 6>;

NodeKey nodeKey(PetscInt dim, PetscInt p, PetscInt cell, const PetscInt *lex, const PetscInt *idx) {
  PetscInt free_dims[3], nfree = 0, fixed_bits = 0;
  for (PetscInt d = 0; d < dim; ++d) {
    if (idx[d] > 0 && idx[d] < p) free_dims[nfree++] = d;
    else if (idx[d] == p) fixed_bits |= 1 << d;
  }
  if (nfree == 0) return {0, lex[fixed_bits], 0, 0, 0, 0};
  if (nfree == dim) return {3, cell, idx[0], idx[1], dim == 3 ? idx[2] : 0, 0};
  if (nfree == 1) {
    const PetscInt f = free_dims[0];
    PetscInt       a = lex[fixed_bits], b = lex[fixed_bits | 1 << f], t = idx[f];
    if (a > b) std::swap(a, b), t = p - t;
    return {1, a, b, t, 0, 0};
  }
  const PetscInt f1 = free_dims[0], f2 = free_dims[1];
  auto corner = [&](PetscInt b1, PetscInt b2) { return lex[fixed_bits | b1 << f1 | b2 << f2]; };
  PetscInt o1 = 0, o2 = 0;
  for (PetscInt b1 = 0; b1 < 2; ++b1)
    for (PetscInt b2 = 0; b2 < 2; ++b2)
      if (corner(b1, b2) < corner(o1, o2)) o1 = b1, o2 = b2;
  PetscInt s = o1 ? p - idx[f1] : idx[f1], t = o2 ? p - idx[f2] : idx[f2];
  PetscInt n1 = corner(1 - o1, o2), n2 = corner(o1, 1 - o2);
  if (n1 > n2) std::swap(n1, n2), std::swap(s, t);
  return {2, corner(o1, o2), n1, n2, s, t};
}

struct Subdivision {
  PetscInt               dim = 0, cdim = 0, p = 1, ncorners = 0, ncell = 0, nnode = 0, nsub = 0;
  std::vector<PetscInt>  frame;          // per parent cell: its corners, lexicographic
  std::vector<PetscInt>  slot_corner;    // per parent cell and closure slot: the lexicographic corner
  std::vector<PetscInt>  cell_nodes;     // per parent cell: (p+1)^dim node numbers, lexicographic
  std::vector<PetscReal> xyz;            // per node: coordinates
  std::vector<PetscInt>  cell_region;    // per parent cell
  PetscInt               nnodes = 0;
};

PetscErrorCode makeNodes(DM serial, Subdivision *s) {
  PetscInt c_start, c_end, v_start, v_end;
  DMLabel  region;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(serial, 0, &c_start, &c_end));
  PetscCall(DMPlexGetDepthStratum(serial, 0, &v_start, &v_end));
  PetscCall(DMGetLabel(serial, mesh::kRegionLabel, &region));
  const PetscInt p = s->p, dim = s->dim, np1 = p + 1;
  double         gll[numerics::kMaxSpectralDegree + 1], w[numerics::kMaxSpectralDegree + 1];
  numerics::gllPointsWeights((int)p, gll, w);
  s->ncell = c_end - c_start;
  s->frame.resize((size_t)s->ncell * s->ncorners);
  s->slot_corner.resize((size_t)s->ncell * s->ncorners);
  s->cell_nodes.resize((size_t)s->ncell * s->nnode);
  s->cell_region.resize(s->ncell);
  std::map<NodeKey, PetscInt> node_of;
  mesh::VertexCoordinates           coords;
  PetscCall(coords.Open(serial));
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscInt *lex = &s->frame[(size_t)(c - c_start) * s->ncorners];
    PetscCall(mesh::SpectralCellFrame(serial, coords, c, lex));
    PetscCall(DMLabelGetValue(region, c, &s->cell_region[c - c_start]));
    // Closure slot -> lexicographic corner: the sub-cells list their vertices in the parent's
    // closure order, so they have its orientation and its frame.
    PetscInt *closure = nullptr, nclosure, nslot = 0;
    PetscCall(DMPlexGetTransitiveClosure(serial, c, PETSC_TRUE, &nclosure, &closure));
    for (PetscInt i = 0; i < nclosure; ++i) {
      const PetscInt v = closure[2 * i];
      if (v < v_start || v >= v_end) continue;
      for (PetscInt k = 0; k < s->ncorners; ++k)
        if (lex[k] == v) s->slot_corner[(size_t)(c - c_start) * s->ncorners + nslot] = k;
      ++nslot;
    }
    PetscCall(DMPlexRestoreTransitiveClosure(serial, c, PETSC_TRUE, &nclosure, &closure));
    double X[8 * 3];
    for (PetscInt k = 0; k < s->ncorners; ++k) PetscCall(coords.Get(lex[k], &X[k * s->cdim]));
    for (PetscInt n = 0; n < s->nnode; ++n) {
      const PetscInt idx[3] = {n % np1, (n / np1) % np1, dim == 3 ? n / (np1 * np1) : 0};
      const NodeKey  key    = nodeKey(dim, p, c, lex, idx);
      auto           it     = node_of.find(key);
      if (it == node_of.end()) {
        it = node_of.emplace(key, s->nnodes++).first;
        // The Q1 map at the GLL point: the product of 1D linear weights per corner.
        for (PetscInt d = 0; d < s->cdim; ++d) s->xyz.push_back(0);
        PetscReal *x = &s->xyz[s->xyz.size() - s->cdim];
        for (PetscInt k = 0; k < s->ncorners; ++k) {
          double N = 1;
          for (PetscInt d = 0; d < dim; ++d) {
            const double xi = 0.5 * (gll[idx[d]] + 1);
            N *= ((k >> d) & 1) ? xi : 1 - xi;
          }
          for (PetscInt d = 0; d < s->cdim; ++d) x[d] += N * X[k * s->cdim + d];
        }
      }
      s->cell_nodes[(size_t)(c - c_start) * s->nnode + n] = it->second;
    }
  }
  PetscCall(coords.Close());
  PetscFunctionReturn(0);
}

// The sub-cell list: sub-cell s of parent c is cell c p^dim + s; its vertices in the parent's
// closure order, shifted to the sub-cell's lexicographic corner.
std::vector<PetscInt> subCellList(const Subdivision &s) {
  const PetscInt        p = s.p, np1 = p + 1;
  std::vector<PetscInt> cells((size_t)s.ncell * s.nsub * s.ncorners);
  for (PetscInt c = 0; c < s.ncell; ++c)
    for (PetscInt q = 0; q < s.nsub; ++q) {
      const PetscInt i = q % p, j = (q / p) % p, k = s.dim == 3 ? q / (p * p) : 0;
      for (PetscInt slot = 0; slot < s.ncorners; ++slot) {
        const PetscInt corner = s.slot_corner[(size_t)c * s.ncorners + slot];
        const PetscInt a = i + (corner & 1), b = j + ((corner >> 1) & 1), z = k + ((corner >> 2) & 1);
        cells[((size_t)c * s.nsub + q) * s.ncorners + slot] = s.cell_nodes[(size_t)c * s.nnode + a + np1 * (b + np1 * z)];
      }
    }
  return cells;
}

// Which side of its cell's frame face f is: dimension *fixed at *bit (0 or 1).
PetscErrorCode faceSide(DM serial, const Subdivision &s, PetscInt cell, PetscInt f, PetscInt *fixed, PetscInt *bit) {
  PetscInt              v_start, v_end, *closure = nullptr, nclosure;
  std::vector<PetscInt> fverts;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(serial, 0, &v_start, &v_end));
  PetscCall(DMPlexGetTransitiveClosure(serial, f, PETSC_TRUE, &nclosure, &closure));
  for (PetscInt i = 0; i < nclosure; ++i)
    if (closure[2 * i] >= v_start && closure[2 * i] < v_end) fverts.push_back(closure[2 * i]);
  PetscCall(DMPlexRestoreTransitiveClosure(serial, f, PETSC_TRUE, &nclosure, &closure));
  const PetscInt *lex = &s.frame[(size_t)cell * s.ncorners];
  *fixed = -1;
  for (PetscInt d = 0; d < s.dim && *fixed < 0; ++d)
    for (PetscInt b = 0; b < 2 && *fixed < 0; ++b) {
      bool all = true;
      for (PetscInt v : fverts) {
        bool found = false;
        for (PetscInt k = 0; k < s.ncorners; ++k) found = found || (lex[k] == v && ((k >> d) & 1) == b);
        all = all && found;
      }
      if (all) *fixed = d, *bit = b;
    }
  PetscCheck(*fixed >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "SpectralSubdivideSerialMesh: face %" PetscInt_FMT " is not a side of cell %" PetscInt_FMT, f, cell);
  PetscFunctionReturn(0);
}

// Each labelled face of the parent gives its value to its p^(dim-1) sub-faces.
PetscErrorCode carryBoundaryLabels(DM serial, const Subdivision &s, const std::vector<std::string> &boundaries, DM fine) {
  PetscInt f_start, f_end, c_start, nv_start, nv_end;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(serial, 1, &f_start, &f_end));
  PetscCall(DMPlexGetHeightStratum(serial, 0, &c_start, nullptr));
  PetscCall(DMPlexGetDepthStratum(fine, 0, &nv_start, &nv_end));
  const PetscInt p = s.p, np1 = p + 1, nfv = s.dim == 2 ? 2 : 4;
  for (const std::string &name : boundaries) {
    DMLabel old_label, new_label;
    PetscCall(DMCreateLabel(fine, name.c_str()));
    PetscCall(DMGetLabel(fine, name.c_str(), &new_label));
    PetscCall(DMGetLabel(serial, name.c_str(), &old_label));
    if (!old_label) continue;
    for (PetscInt f = f_start; f < f_end; ++f) {
      PetscInt value;
      PetscCall(DMLabelGetValue(old_label, f, &value));
      if (value < 0) continue;
      const PetscInt *supp;
      PetscInt        fixed = -1, bit = 0;
      PetscCall(DMPlexGetSupport(serial, f, &supp));
      const PetscInt cell = supp[0] - c_start;
      PetscCall(faceSide(serial, s, cell, f, &fixed, &bit));
      PetscInt t1 = -1, t2 = -1; // the tangential dimensions
      for (PetscInt d = 0; d < s.dim; ++d)
        if (d != fixed) (t1 < 0 ? t1 : t2) = d;
      for (PetscInt u = 0; u < p; ++u)
        for (PetscInt v = 0; v < (s.dim == 3 ? p : 1); ++v) {
          PetscInt verts[4];
          for (PetscInt a = 0; a < nfv; ++a) {
            PetscInt idx[3] = {0, 0, 0};
            idx[fixed]      = bit * p;
            idx[t1]         = u + (a & 1);
            if (t2 >= 0) idx[t2] = v + ((a >> 1) & 1);
            verts[a] = nv_start + s.cell_nodes[(size_t)cell * s.nnode + idx[0] + np1 * (idx[1] + np1 * idx[2])];
          }
          PetscInt        njoin;
          const PetscInt *join;
          PetscCall(DMPlexGetFullJoin(fine, nfv, verts, &njoin, &join));
          PetscCheck(njoin == 1, PETSC_COMM_SELF, PETSC_ERR_PLIB, "SpectralSubdivideSerialMesh: a sub-face of face %" PetscInt_FMT " has %" PetscInt_FMT " matches", f, njoin);
          PetscCall(DMLabelSetValue(new_label, join[0], value));
          PetscCall(DMPlexRestoreJoin(fine, nfv, verts, &njoin, &join));
        }
    }
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode SpectralSubdivideSerialMesh(DM serial, PetscInt degree, const std::vector<std::string> &boundaries, DM *fine) {
  MPI_Comm    comm = PetscObjectComm((PetscObject)serial);
  PetscMPIInt rank;
  Subdivision s;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(DMGetDimension(serial, &s.dim));
  PetscCall(DMGetCoordinateDim(serial, &s.cdim));
  s.p        = degree;
  s.ncorners = s.dim == 2 ? 4 : 8;
  s.nnode    = mesh::SpectralCount(degree + 1, s.dim);
  s.nsub     = mesh::SpectralCount(degree, s.dim);
  PetscCall(makeNodes(serial, &s));
  const bool            root  = rank == 0;
  std::vector<PetscInt> cells = subCellList(s);
  PetscCall(DMPlexCreateFromCellListPetsc(comm, s.dim, root ? s.ncell * s.nsub : 0, root ? s.nnodes : 0, s.ncorners, PETSC_TRUE, root ? cells.data() : nullptr, s.cdim,
                                          root ? s.xyz.data() : nullptr, fine));
  const char *name;
  PetscCall(PetscObjectGetName((PetscObject)serial, &name));
  PetscCall(PetscObjectSetName((PetscObject)*fine, name));
  DMLabel region, position;
  PetscCall(DMCreateLabel(*fine, mesh::kRegionLabel));
  PetscCall(DMCreateLabel(*fine, mesh::kSpectralPositionLabel));
  PetscCall(DMGetLabel(*fine, mesh::kRegionLabel, &region));
  PetscCall(DMGetLabel(*fine, mesh::kSpectralPositionLabel, &position));
  PetscInt fc_start;
  PetscCall(DMPlexGetHeightStratum(*fine, 0, &fc_start, nullptr));
  for (PetscInt c = 0; c < s.ncell; ++c)
    for (PetscInt q = 0; q < s.nsub; ++q) {
      const PetscInt sub = fc_start + c * s.nsub + q;
      PetscCall(DMLabelSetValue(region, sub, s.cell_region[c]));
      PetscCall(DMLabelSetValue(position, sub, q));
    }
  PetscCall(carryBoundaryLabels(serial, s, boundaries, *fine));
  PetscFunctionReturn(0);
}

PetscErrorCode SpectralPartitionWholeElements(DM parent, PetscPartitioner part, PetscInt degree, DM fine) {
  MPI_Comm     comm = PetscObjectComm((PetscObject)parent);
  PetscMPIInt  size;
  PetscInt     dim, c_start;
  PetscSection parts;
  IS           assignment;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(DMGetDimension(parent, &dim));
  PetscCall(DMPlexGetHeightStratum(parent, 0, &c_start, nullptr));
  const PetscInt nsub = mesh::SpectralCount(degree, dim);
  PetscCall(PetscSectionCreate(comm, &parts));
  PetscCall(PetscPartitionerDMPlexPartition(part, parent, nullptr, parts, &assignment));
  std::vector<PetscInt> sizes(size, 0), points;
  const PetscInt       *cells;
  PetscCall(ISGetIndices(assignment, &cells));
  for (PetscMPIInt r = 0; r < size; ++r) {
    PetscInt n, off;
    PetscCall(PetscSectionGetDof(parts, r, &n));
    PetscCall(PetscSectionGetOffset(parts, r, &off));
    sizes[r] = n * nsub;
    for (PetscInt i = off; i < off + n; ++i)
      for (PetscInt q = 0; q < nsub; ++q) points.push_back((cells[i] - c_start) * nsub + q);
  }
  PetscCall(ISRestoreIndices(assignment, &cells));
  PetscCall(ISDestroy(&assignment));
  PetscCall(PetscSectionDestroy(&parts));
  PetscPartitioner fine_part;
  PetscCall(DMPlexGetPartitioner(fine, &fine_part));
  PetscCall(PetscPartitionerSetType(fine_part, PETSCPARTITIONERSHELL));
  PetscCall(PetscPartitionerShellSetPartition(fine_part, size, sizes.data(), points.empty() ? nullptr : points.data()));
  PetscFunctionReturn(0);
}

} // namespace slipwave::meshing
