#include "slipwave/mesh/box_refinement.hpp"

#include <petscsf.h>

#include "slipwave/fem/gll_basis.hpp"
#include "slipwave/mesh/labels.hpp"
#include "slipwave/mesh/point_centroid.hpp"
#include "slipwave/mesh/spectral_layout.hpp"
#include "slipwave/mesh/vertex_coordinates.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace slipwave::mesh {

const char *const kMeshBuildNames[3] = {"auto", "serial", "distributed"};

namespace {

// A bound inside the box must fall on a coarse grid line; bounds on or beyond the box sides
// cut no cell.
bool boundOnGrid(PetscReal bound, PetscReal lower, PetscReal upper, PetscReal coarse_h) {
  const PetscReal tol = 1e-9 * coarse_h;
  if (bound <= lower + tol || bound >= upper - tol) return true;
  const PetscReal lines = (bound - lower) / coarse_h;
  return std::fabs(lines - std::round(lines)) * coarse_h < tol;
}

bool levelFits(PetscInt dim, const BoxSpec &box, const std::vector<std::vector<PetscReal>> &region_boxes, PetscInt k, double *coarse_cells) {
  const PetscInt factor = (PetscInt)1 << k;
  *coarse_cells         = 1;
  for (PetscInt d = 0; d < dim; ++d) {
    if (box.faces[d] % factor) return false;
    *coarse_cells *= (double)(box.faces[d] / factor);
    const PetscReal coarse_h = (box.upper[d] - box.lower[d]) * factor / box.faces[d];
    for (const auto &b : region_boxes)
      if (!b.empty() && !(boundOnGrid(b[2 * d], box.lower[d], box.upper[d], coarse_h) && boundOnGrid(b[2 * d + 1], box.lower[d], box.upper[d], coarse_h))) return false;
  }
  return true;
}

// Position of a point on the fine lattice along each axis (vertices at integers, cell centroids
// at half-integers, so `shift` 0.5 turns a centroid into its cell's index); `split` lattice
// cells per box cell along each axis (p: the GLL sub-cells of an element).
struct Lattice {
  PetscInt  dim;
  PetscInt  n[3];
  PetscReal lower[3], h[3];
  explicit Lattice(PetscInt d, const BoxSpec &box, PetscInt split = 1) : dim(d) {
    for (PetscInt i = 0; i < 3; ++i) {
      n[i]     = i < d ? box.faces[i] * split : 1;
      lower[i] = box.lower[i];
      h[i]     = i < d ? (box.upper[i] - box.lower[i]) / n[i] : 1;
    }
  }
  // Integer position along axis d (vertices: shift 0; cell centroids: shift 0.5).
  int64_t coordinate(const PetscReal *x, PetscInt d, PetscReal shift) const { return (int64_t)std::llround((x[d] - lower[d]) / h[d] - shift); }
  // Lexicographic, x fastest: DMPlexCreateBoxMesh's order of vertices (extra = 1) and cells (0).
  int64_t index(const PetscReal *x, PetscReal shift, PetscInt extra) const {
    int64_t key = 0, stride = 1;
    for (PetscInt d = 0; d < dim; ++d) {
      key += stride * coordinate(x, d, shift);
      stride *= n[d] + extra;
    }
    return key;
  }
};

// Spectral elements of degree p = 2, 4, 8 are made by log2(p) more refinements: the fine
// lattice holds p sub-cells per element and axis. The serial build (spectral_subdivision.hpp)
// numbers the sub-cells and the GLL nodes of an element lexicographically in its element frame
// (spectral_layout.hpp), read from its parent box cell; DMPlexCreateBoxMesh lays out every cell
// alike, so the frame is one signed permutation of the lattice axes for the whole box.
struct ElementFrame {
  PetscInt dim     = 0;
  PetscInt axis[3] = {0, 1, 2}; // frame axis a runs along lattice axis axis[a],
  PetscInt sign[3] = {1, 1, 1}; // upwards (+1) or downwards (-1)
  PetscInt code() const {
    PetscInt c = 0;
    for (PetscInt a = 0; a < dim; ++a) c |= (2 * axis[a] + (sign[a] < 0)) << (3 * a);
    return c;
  }
  void decode(PetscInt c) {
    for (PetscInt a = 0; a < dim; ++a) axis[a] = ((c >> (3 * a)) & 7) / 2, sign[a] = ((c >> (3 * a)) & 1) ? -1 : 1;
  }
};

struct SpectralLattice {
  Lattice      fine;       // p cells per element and axis (p = 1: the box itself)
  PetscInt     degree = 1; // p
  ElementFrame frame;      // p > 1

  // Index of the sub-cell with centroid xc along lattice axis d in its element (0..p-1), and of
  // its element.
  PetscInt sub(const PetscReal *xc, PetscInt d) const { return (PetscInt)(fine.coordinate(xc, d, 0.5) % degree); }
  int64_t  element(const PetscReal *xc, PetscInt d) const { return fine.coordinate(xc, d, 0.5) / degree; }
  // The element (lattice order over elements, x fastest) and spectral_position of a sub-cell.
  int64_t elementSlot(const PetscReal *xc) const {
    int64_t key = 0, stride = 1;
    for (PetscInt d = 0; d < fine.dim; stride *= fine.n[d] / degree, ++d) key += stride * element(xc, d);
    return key;
  }
  PetscInt position(const PetscReal *xc) const {
    PetscInt pos = 0, stride = 1;
    for (PetscInt a = 0; a < fine.dim; stride *= degree, ++a) {
      const PetscInt j = sub(xc, frame.axis[a]);
      pos += stride * (frame.sign[a] > 0 ? j : degree - 1 - j);
    }
    return pos;
  }
  // Where the serial build numbers the vertex at x, seen from its cell with centroid xc: p = 1,
  // the box's vertex order (lattice order); p > 1, the subdivision's order of first appearance
  // (element by element, in each the GLL nodes lexicographic in the element frame), so the least
  // key over the cells that hold the vertex is its place.
  int64_t vertexKey(const PetscReal *x, const PetscReal *xc) const {
    if (degree == 1) return fine.index(x, 0, 1);
    const PetscInt np1  = degree + 1;
    int64_t        node = 0, stride = 1;
    for (PetscInt a = 0; a < fine.dim; stride *= np1, ++a) {
      const PetscInt d = frame.axis[a];
      const int64_t  j = fine.coordinate(x, d, 0) - element(xc, d) * degree;
      node += stride * (frame.sign[a] > 0 ? j : degree - j);
    }
    return elementSlot(xc) * stride + node;
  }
};

// Refinement gives a point's label value to all its children (a face's to the edges and
// vertices inside it): keep the value on the points of one height only.
PetscErrorCode keepHeight(DM dm, const char *name, PetscInt height) {
  DMLabel         label;
  IS              values;
  const PetscInt *vals;
  PetscInt        nvalues, p_start, p_end;
  PetscFunctionBeginUser;
  PetscCall(DMGetLabel(dm, name, &label));
  if (!label) PetscFunctionReturn(0);
  PetscCall(DMPlexGetHeightStratum(dm, height, &p_start, &p_end));
  PetscCall(DMLabelGetValueIS(label, &values));
  PetscCall(ISGetLocalSize(values, &nvalues));
  PetscCall(ISGetIndices(values, &vals));
  for (PetscInt i = 0; i < nvalues; ++i) {
    IS              stratum;
    const PetscInt *points;
    PetscInt        npoints;
    std::vector<PetscInt> drop;
    PetscCall(DMLabelGetStratumIS(label, vals[i], &stratum));
    if (!stratum) continue;
    PetscCall(ISGetLocalSize(stratum, &npoints));
    PetscCall(ISGetIndices(stratum, &points));
    for (PetscInt k = 0; k < npoints; ++k)
      if (points[k] < p_start || points[k] >= p_end) drop.push_back(points[k]);
    PetscCall(ISRestoreIndices(stratum, &points));
    PetscCall(ISDestroy(&stratum));
    for (PetscInt p : drop) PetscCall(DMLabelClearValue(label, p, vals[i]));
  }
  PetscCall(ISRestoreIndices(values, &vals));
  PetscCall(ISDestroy(&values));
  PetscFunctionReturn(0);
}

// interface_<name>_pair/_side on the fine mesh. The split vertices are the closure vertices of
// the soil-side faces (interface_<name>) and their structure copies, which sit on the same
// lattice point; the pair ids number these points in the serial build's vertex order (the
// serial split numbers pairs by original vertex), SpectralLattice::vertexKey.
PetscErrorCode labelPairs(DM dm, const SpectralLattice &s, const InterfaceSpec &spec, PetscInt structure_region) {
  MPI_Comm              comm = PetscObjectComm((PetscObject)dm);
  const std::string     base = "interface_" + spec.name;
  const Lattice        &lattice = s.fine;
  DMLabel               faces, region, pair, side;
  PetscInt              f_start, f_end, v_start, v_end, c_start, c_end;
  std::vector<int64_t>  mine;
  VertexCoordinates     coords;
  PetscFunctionBeginUser;
  PetscCall(DMRemoveLabel(dm, (base + "_pair").c_str(), nullptr));
  PetscCall(DMRemoveLabel(dm, (base + "_side").c_str(), nullptr));
  PetscCall(DMCreateLabel(dm, (base + "_pair").c_str()));
  PetscCall(DMCreateLabel(dm, (base + "_side").c_str()));
  PetscCall(DMGetLabel(dm, (base + "_pair").c_str(), &pair));
  PetscCall(DMGetLabel(dm, (base + "_side").c_str(), &side));
  PetscCall(DMGetLabel(dm, base.c_str(), &faces));
  PetscCall(DMGetLabel(dm, kRegionLabel, &region));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, &c_end));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &f_start, &f_end));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v_start, &v_end));
  PetscCall(coords.Open(dm));
  for (PetscInt f = f_start; f < f_end; ++f) {
    PetscInt value, nclosure, *closure = nullptr;
    PetscCall(DMLabelGetValue(faces, f, &value));
    if (value < 0) continue;
    PetscCall(DMPlexGetTransitiveClosure(dm, f, PETSC_TRUE, &nclosure, &closure));
    for (PetscInt i = 0; i < nclosure; ++i) {
      const PetscInt v = closure[2 * i];
      if (v < v_start || v >= v_end) continue;
      PetscReal x[3];
      PetscCall(coords.Get(v, x));
      mine.push_back(lattice.index(x, 0, 1));
    }
    PetscCall(DMPlexRestoreTransitiveClosure(dm, f, PETSC_TRUE, &nclosure, &closure));
  }
  std::sort(mine.begin(), mine.end());
  mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
  // The interface is a surface: every rank holding all of its points is cheap.
  PetscMPIInt size, nmine = (PetscMPIInt)mine.size();
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<PetscMPIInt> counts(size), offsets(size + 1, 0);
  PetscCallMPI(MPI_Allgather(&nmine, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
  for (PetscMPIInt r = 0; r < size; ++r) offsets[r + 1] = offsets[r] + counts[r];
  std::vector<int64_t> all(offsets[size]);
  PetscCallMPI(MPI_Allgatherv(mine.data(), nmine, MPI_INT64_T, all.data(), counts.data(), offsets.data(), MPI_INT64_T, comm));
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  // Vertices another rank owns (leaves of the point SF) are counted there.
  PetscSF         point_sf;
  PetscInt        nleaves;
  const PetscInt *leaves;
  std::vector<char> ghost(v_end - v_start, 0);
  PetscCall(DMGetPointSF(dm, &point_sf));
  PetscCall(PetscSFGetGraph(point_sf, nullptr, &nleaves, &leaves, nullptr));
  for (PetscInt i = 0; i < nleaves && nleaves > 0; ++i) {
    const PetscInt p = leaves ? leaves[i] : i;
    if (p >= v_start && p < v_end) ghost[p - v_start] = 1;
  }
  // Each point's place in the serial vertex order: the least key its cells on any rank give.
  struct Split {
    PetscInt v, point, on_structure;
  };
  std::vector<Split>   found;
  std::vector<int64_t> order(all.size(), INT64_MAX);
  // Only structure cells hold a structure copy; the soil copy is shared with no structure cell.
  for (PetscInt v = v_start; v < v_end; ++v) {
    PetscReal x[3];
    PetscCall(coords.Get(v, x));
    auto it = std::lower_bound(all.begin(), all.end(), lattice.index(x, 0, 1));
    if (it == all.end() || *it != lattice.index(x, 0, 1)) continue;
    const PetscInt point = (PetscInt)(it - all.begin());
    PetscInt       nstar, *star = nullptr, on_structure = 0;
    PetscCall(DMPlexGetTransitiveClosure(dm, v, PETSC_FALSE, &nstar, &star));
    for (PetscInt i = 0; i < nstar; ++i) {
      const PetscInt q = star[2 * i];
      PetscInt       r;
      PetscCall(DMLabelGetValue(region, q, &r));
      on_structure = on_structure || r == structure_region;
      if (q < c_start || q >= c_end) continue;
      PetscReal xc[3];
      PetscCall(MeshPointCentroid(dm, q, xc));
      order[point] = std::min(order[point], s.vertexKey(x, xc));
    }
    PetscCall(DMPlexRestoreTransitiveClosure(dm, v, PETSC_FALSE, &nstar, &star));
    found.push_back({v, point, on_structure});
  }
  PetscCall(coords.Close());
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, order.data(), (PetscMPIInt)order.size(), MPI_INT64_T, MPI_MIN, comm));
  std::vector<PetscInt> by_order(all.size()), id(all.size());
  for (size_t i = 0; i < all.size(); ++i) by_order[i] = (PetscInt)i;
  std::sort(by_order.begin(), by_order.end(), [&](PetscInt a, PetscInt b) { return order[a] < order[b]; });
  for (size_t k = 0; k < by_order.size(); ++k) id[by_order[k]] = (PetscInt)k;
  PetscInt owned[2] = {0, 0};
  for (const Split &f : found) {
    PetscCall(DMLabelSetValue(pair, f.v, id[f.point]));
    PetscCall(DMLabelSetValue(side, f.v, f.on_structure));
    if (!ghost[f.v - v_start]) ++owned[f.on_structure];
  }
  // Each lattice point of the interface must hold exactly one soil and one structure vertex; a
  // guard on the interface itself (vertices doubled away from it, which BoxInterfacesRefinable
  // rules out, would not show here).
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, owned, 2, MPIU_INT, MPI_SUM, comm));
  PetscCheck(owned[0] == (PetscInt)all.size() && owned[1] == (PetscInt)all.size(), comm, PETSC_ERR_PLIB,
             "interface '%s' refined: %" PetscInt_FMT " soil and %" PetscInt_FMT " structure vertices for %zu pairs; build with -mesh_build serial", spec.name.c_str(),
             owned[0], owned[1], all.size());
  PetscFunctionReturn(0);
}

// The serial box numbers its cells (p > 1: its elements, sub-cells e p^dim + position) in
// lattice order, less the void ones: an element's number is how many present elements come
// before it on the lattice. The element lattice is laid out over the ranks, each cell marks its
// element's slot, a prefix sum counts the marked slots. At p > 1 spectral_position goes on the
// cells too.
PetscErrorCode numberCells(DM dm, const SpectralLattice &s, std::vector<PetscInt> *serial_cell) {
  MPI_Comm              comm = PetscObjectComm((PetscObject)dm);
  PetscInt              c_start, c_end, total = 1, nroots, before = 0;
  PetscLayout           layout;
  PetscSF               sf;
  DMLabel               position = nullptr;
  std::vector<PetscInt> slots, marks, ones, element;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, &c_end));
  for (PetscInt d = 0; d < s.fine.dim; ++d) total *= s.fine.n[d] / s.degree;
  if (s.degree > 1) {
    PetscCall(DMCreateLabel(dm, kSpectralPositionLabel));
    PetscCall(DMGetLabel(dm, kSpectralPositionLabel, &position));
  }
  serial_cell->assign(c_end - c_start, 0);
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscReal x[3];
    PetscCall(MeshPointCentroid(dm, c, x));
    slots.push_back((PetscInt)s.elementSlot(x));
    (*serial_cell)[c - c_start] = s.position(x);
    if (position) PetscCall(DMLabelSetValue(position, c, (*serial_cell)[c - c_start]));
  }
  PetscCall(PetscLayoutCreate(comm, &layout));
  PetscCall(PetscLayoutSetSize(layout, total));
  PetscCall(PetscLayoutSetUp(layout));
  PetscCall(PetscLayoutGetLocalSize(layout, &nroots));
  PetscCall(PetscSFCreate(comm, &sf));
  PetscCall(PetscSFSetGraphLayout(sf, layout, c_end - c_start, nullptr, PETSC_COPY_VALUES, slots.data()));
  marks.assign(nroots, 0);
  ones.assign(c_end - c_start, 1);
  PetscCall(PetscSFReduceBegin(sf, MPIU_INT, ones.data(), marks.data(), MPI_SUM));
  PetscCall(PetscSFReduceEnd(sf, MPIU_INT, ones.data(), marks.data(), MPI_SUM));
  PetscInt local = 0;
  for (PetscInt &m : marks) {
    const PetscInt present = m > 0;
    m = local;
    local += present;
  }
  PetscCallMPI(MPI_Exscan(&local, &before, 1, MPIU_INT, MPI_SUM, comm));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) before = 0; // MPI_Exscan leaves rank 0's result undefined
  for (PetscInt &m : marks) m += before;
  element.assign(c_end - c_start, 0);
  PetscCall(PetscSFBcastBegin(sf, MPIU_INT, marks.data(), element.data(), MPI_REPLACE));
  PetscCall(PetscSFBcastEnd(sf, MPIU_INT, marks.data(), element.data(), MPI_REPLACE));
  PetscCall(PetscSFDestroy(&sf));
  PetscCall(PetscLayoutDestroy(&layout));
  const PetscInt nsub = SpectralCount(s.degree, s.fine.dim);
  for (PetscInt c = 0; c < c_end - c_start; ++c) (*serial_cell)[c] += element[c] * nsub;
  PetscFunctionReturn(0);
}

// The element frame of cell c (spectral_layout.hpp) as lattice directions: frame axis a runs
// from the frame's corner 0 to its corner 2^a.
PetscErrorCode cellFrame(DM dm, const VertexCoordinates &coords, PetscInt c, ElementFrame *f) {
  PetscInt  lex[8];
  PetscReal x0[3], x1[3];
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &f->dim));
  PetscCall(SpectralCellFrame(dm, coords, c, lex));
  PetscCall(coords.Get(lex[0], x0));
  for (PetscInt a = 0; a < f->dim; ++a) {
    PetscCall(coords.Get(lex[1 << a], x1));
    PetscInt along = 0;
    for (PetscInt d = 1; d < f->dim; ++d)
      if (std::fabs(x1[d] - x0[d]) > std::fabs(x1[along] - x0[along])) along = d;
    f->axis[a] = along;
    f->sign[a] = x1[along] > x0[along] ? 1 : -1;
  }
  PetscFunctionReturn(0);
}

// The element frame, read on the (distributed, coarse) box before it is refined: every cell's,
// which must be one for the whole box.
PetscErrorCode boxElementFrame(DM coarse, ElementFrame *frame) {
  MPI_Comm          comm = PetscObjectComm((PetscObject)coarse);
  PetscInt          c_start, c_end, range[2] = {PETSC_MIN_INT, PETSC_MIN_INT}; // -least, greatest code
  VertexCoordinates coords;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(coarse, 0, &c_start, &c_end));
  PetscCall(coords.Open(coarse));
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscCall(cellFrame(coarse, coords, c, frame));
    range[0] = std::max(range[0], -frame->code());
    range[1] = std::max(range[1], frame->code());
  }
  PetscCall(coords.Close());
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, range, 2, MPIU_INT, MPI_MAX, comm));
  PetscCheck(-range[0] == range[1], comm, PETSC_ERR_PLIB, "box cells with different element frames (codes %" PetscInt_FMT " and %" PetscInt_FMT "); build with -mesh_build serial",
             -range[0], range[1]);
  PetscCall(DMGetDimension(coarse, &frame->dim));
  frame->decode(range[1]);
  PetscFunctionReturn(0);
}

// Every vertex from its lattice point to its GLL node: along each axis, lattice index i lies in
// element e = min(i / p, n - 1) at node j = i - e p, at lower + h (e + (1 + xi_j) / 2), h the
// element size (the serial subdivision's Q1 map of a box element). The position is a function
// of the lattice point, so every rank moves its copy of a shared vertex alike, and the global
// coordinates, made again from the local ones, agree with them.
PetscErrorCode moveToGll(DM dm, const SpectralLattice &s, const BoxSpec &box) {
  Vec          local, moved;
  DM           cdm;
  PetscSection section;
  PetscScalar *x;
  PetscInt     v_start, v_end;
  double       gll[fem::kMaxSpectralDegree + 1], w[fem::kMaxSpectralDegree + 1];
  PetscFunctionBeginUser;
  fem::gllPointsWeights((int)s.degree, gll, w);
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v_start, &v_end));
  PetscCall(DMGetCoordinateDM(dm, &cdm));
  PetscCall(DMGetLocalSection(cdm, &section));
  PetscCall(DMGetCoordinatesLocal(dm, &local));
  PetscCall(VecDuplicate(local, &moved));
  PetscCall(VecCopy(local, moved));
  PetscCall(VecGetArray(moved, &x));
  for (PetscInt v = v_start; v < v_end; ++v) {
    PetscInt  off;
    PetscReal lattice_point[3];
    PetscCall(PetscSectionGetOffset(section, v, &off));
    for (PetscInt d = 0; d < s.fine.dim; ++d) lattice_point[d] = PetscRealPart(x[off + d]);
    for (PetscInt d = 0; d < s.fine.dim; ++d) {
      const int64_t   i = s.fine.coordinate(lattice_point, d, 0), e = std::min<int64_t>(i / s.degree, box.faces[d] - 1);
      const PetscReal h = (box.upper[d] - box.lower[d]) / box.faces[d];
      x[off + d]        = box.lower[d] + h * ((PetscReal)e + 0.5 * (1 + gll[i - e * s.degree]));
    }
  }
  PetscCall(VecRestoreArray(moved, &x));
  PetscCall(DMSetCoordinatesLocal(dm, moved));
  PetscCall(VecDestroy(&moved));
  PetscFunctionReturn(0);
}

} // namespace

PetscInt BoxRefinementLevels(PetscInt dim, const BoxSpec &box, const std::vector<std::vector<PetscReal>> &region_boxes, PetscMPIInt nranks, PetscInt build) {
  if (build == kMeshBuildSerial) return 0;
  const double min_cells = build == kMeshBuildAuto ? kCoarseCellsPerRank * nranks : (double)nranks;
  PetscInt     levels    = 0;
  double       coarse_cells;
  for (PetscInt k = 1; k < 31 && levelFits(dim, box, region_boxes, k, &coarse_cells) && coarse_cells >= min_cells; ++k) levels = k;
  return levels;
}

PetscInt BoxSpectralRefinements(PetscInt degree) {
  PetscInt k = 0;
  while (((PetscInt)1 << k) < degree) ++k;
  return ((PetscInt)1 << k) == degree && degree <= fem::kMaxSpectralDegree ? k : -1;
}

PetscErrorCode BoxInterfacesRefinable(DM coarse, const std::vector<std::string> &regions, const std::vector<InterfaceSpec> &specs, PetscBool *refinable) {
  MPI_Comm comm = PetscObjectComm((PetscObject)coarse);
  PetscInt dim, e_start, e_end, ok = 1;
  DMLabel  region;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(coarse, &dim));
  PetscCall(DMGetLabel(coarse, kRegionLabel, &region));
  PetscCall(DMPlexGetDepthStratum(coarse, 1, &e_start, &e_end));
  auto index = [&](const std::string &name) { return (PetscInt)(std::find(regions.begin(), regions.end(), name) - regions.begin()); };
  for (const InterfaceSpec &spec : specs) {
    ok = ok && spec.face_label.empty();
    const PetscInt soil = index(spec.soil_region), structure = index(spec.structure_region);
    // In 2D the edges are the faces: only 3D has edges that can join the regions alone.
    for (PetscInt e = e_start; e < e_end && ok && dim == 3; ++e) {
      PetscInt nstar, *star = nullptr;
      bool     on_soil = false, on_structure = false, on_interface = false;
      PetscCall(DMPlexGetTransitiveClosure(coarse, e, PETSC_FALSE, &nstar, &star));
      for (PetscInt i = 0; i < nstar; ++i) {
        const PetscInt p = star[2 * i];
        PetscInt       r, nsupp;
        PetscCall(DMLabelGetValue(region, p, &r));
        on_soil      = on_soil || r == soil;
        on_structure = on_structure || r == structure;
        PetscCall(DMPlexGetSupportSize(coarse, p, &nsupp));
        if (p == e || nsupp != 2) continue;
        const PetscInt *supp;
        PetscInt        r0, r1;
        PetscCall(DMPlexGetSupport(coarse, p, &supp));
        PetscCall(DMLabelGetValue(region, supp[0], &r0));
        PetscCall(DMLabelGetValue(region, supp[1], &r1));
        on_interface = on_interface || (r0 == soil && r1 == structure) || (r0 == structure && r1 == soil);
      }
      PetscCall(DMPlexRestoreTransitiveClosure(coarse, e, PETSC_FALSE, &nstar, &star));
      ok = !(on_soil && on_structure) || on_interface;
    }
  }
  PetscCallMPI(MPI_Bcast(&ok, 1, MPIU_INT, 0, comm));
  *refinable = ok ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(0);
}

PetscErrorCode BoxRefineDistributed(DM *dm, PetscInt levels, PetscInt degree, const BoxSpec &box, const std::vector<std::string> &regions,
                                    const std::vector<std::string> &boundaries, const std::vector<InterfaceSpec> &specs, std::vector<PetscInt> *serial_cell) {
  PetscInt dim;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(*dm, &dim));
  SpectralLattice s{Lattice(dim, box, degree), degree, ElementFrame()};
  if (degree > 1) PetscCall(boxElementFrame(*dm, &s.frame));
  for (PetscInt k = 0; k < levels; ++k) {
    DM fine;
    PetscCall(DMRefine(*dm, PetscObjectComm((PetscObject)*dm), &fine));
    PetscCall(DMDestroy(dm));
    *dm = fine;
  }
  PetscCall(keepHeight(*dm, kRegionLabel, 0));
  for (const std::string &b : boundaries) PetscCall(keepHeight(*dm, b.c_str(), 1));
  for (const InterfaceSpec &spec : specs) {
    PetscCall(keepHeight(*dm, ("interface_" + spec.name).c_str(), 1));
    const PetscInt structure = (PetscInt)(std::find(regions.begin(), regions.end(), spec.structure_region) - regions.begin());
    PetscCall(labelPairs(*dm, s, spec, structure));
  }
  PetscCall(numberCells(*dm, s, serial_cell));
  // SpectralLayoutOf reads each sub-cell's frame from its own cone, and positions are read in
  // the element's frame: DMPlex's regular refinement gives every child its parent's frame (its
  // vertices listed from the corner and in the direction of its parent's; no cell differed in
  // the tests), and SpectralLayoutBuild stops on a sub-cell whose frame or position disagrees
  // with its neighbours'. The lattice positions are read on the uniform grid: GLL nodes last.
  if (degree > 1) PetscCall(moveToGll(*dm, s, box));
  PetscFunctionReturn(0);
}

} // namespace slipwave::mesh
