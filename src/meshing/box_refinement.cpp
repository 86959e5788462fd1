#include "slipwave/meshing/box_refinement.hpp"

#include <petscsf.h>

#include "slipwave/mesh/labels.hpp"
#include "slipwave/meshing/box_element_frame.hpp"
#include "slipwave/mesh/point_centroid.hpp"
#include "slipwave/mesh/spectral_layout.hpp"
#include "slipwave/mesh/vertex_coordinates.hpp"
#include "slipwave/meshing/mesh_refinement.hpp"
#include "slipwave/numerics/gll_basis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace slipwave::meshing {

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
// (box_element_frame.hpp), read from its parent box cell.
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
    PetscInt q[3] = {0, 0, 0};
    for (PetscInt d = 0; d < fine.dim; ++d) q[d] = sub(xc, d);
    return frame.position(degree, q);
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

// interface_<name>_pair/_side on the fine mesh. The split vertices are the closure vertices of
// the soil-side faces (interface_<name>) and their structure copies, which sit on the same
// lattice point; the pair ids number these points in the serial build's vertex order (the
// serial split numbers pairs by original vertex): the least SpectralLattice::vertexKey over the
// cells of either copy, on any rank, is a point's place in that order and its pair key.
PetscErrorCode labelPairs(DM dm, const SpectralLattice &s, const InterfaceSpec &spec, PetscInt structure_region) {
  MPI_Comm             comm    = PetscObjectComm((PetscObject)dm);
  const Lattice       &lattice = s.fine;
  PetscInt             v_start, v_end, c_start, c_end;
  std::vector<int64_t> mine;
  mesh::VertexCoordinates    coords;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, &c_end));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v_start, &v_end));
  PetscCall(coords.Open(dm));
  PetscCall(ForEachInterfaceFaceVertex(dm, spec, [&](PetscInt v) -> PetscErrorCode {
    PetscReal x[3];
    PetscFunctionBeginUser;
    PetscCall(coords.Get(v, x));
    mine.push_back(lattice.index(x, 0, 1));
    PetscFunctionReturn(0);
  }));
  std::sort(mine.begin(), mine.end());
  mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
  // The interface's lattice points on every rank (a surface: cheap), then each one's least key.
  PetscMPIInt size, nmine = (PetscMPIInt)mine.size();
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<PetscMPIInt> counts(size), offsets(size + 1, 0);
  PetscCallMPI(MPI_Allgather(&nmine, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
  for (PetscMPIInt r = 0; r < size; ++r) offsets[r + 1] = offsets[r] + counts[r];
  std::vector<int64_t> all(offsets[size]);
  PetscCallMPI(MPI_Allgatherv(mine.data(), nmine, MPI_INT64_T, all.data(), counts.data(), offsets.data(), MPI_INT64_T, comm));
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  auto pointOf = [&](const PetscReal *x) -> PetscInt {
    auto it = std::lower_bound(all.begin(), all.end(), lattice.index(x, 0, 1));
    return it == all.end() || *it != lattice.index(x, 0, 1) ? -1 : (PetscInt)(it - all.begin());
  };
  std::vector<int64_t> order(all.size(), INT64_MAX);
  for (PetscInt v = v_start; v < v_end; ++v) {
    PetscReal x[3];
    PetscCall(coords.Get(v, x));
    const PetscInt point = pointOf(x);
    if (point < 0) continue;
    PetscInt nstar, *star = nullptr;
    PetscCall(DMPlexGetTransitiveClosure(dm, v, PETSC_FALSE, &nstar, &star));
    for (PetscInt i = 0; i < nstar; ++i) {
      const PetscInt q = star[2 * i];
      if (q < c_start || q >= c_end) continue;
      PetscReal xc[3];
      PetscCall(mesh::MeshPointCentroid(dm, q, xc));
      order[point] = std::min(order[point], s.vertexKey(x, xc));
    }
    PetscCall(DMPlexRestoreTransitiveClosure(dm, v, PETSC_FALSE, &nstar, &star));
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, order.data(), (PetscMPIInt)order.size(), MPI_INT64_T, MPI_MIN, comm));
  PetscCall(LabelRefinedPairs(dm, spec, structure_region, [&](PetscInt v, PairKey *key, bool *known) -> PetscErrorCode {
    PetscReal x[3];
    PetscFunctionBeginUser;
    PetscCall(coords.Get(v, x));
    const PetscInt point = pointOf(x);
    *known               = point >= 0;
    key->fill(0);
    if (*known) (*key)[0] = order[point];
    PetscFunctionReturn(0);
  }));
  PetscCall(coords.Close());
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
    PetscCall(DMCreateLabel(dm, mesh::kSpectralPositionLabel));
    PetscCall(DMGetLabel(dm, mesh::kSpectralPositionLabel, &position));
  }
  serial_cell->assign(c_end - c_start, 0);
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscReal x[3];
    PetscCall(mesh::MeshPointCentroid(dm, c, x));
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
  const PetscInt nsub = mesh::SpectralCount(s.degree, s.fine.dim);
  for (PetscInt c = 0; c < c_end - c_start; ++c) (*serial_cell)[c] += element[c] * nsub;
  PetscFunctionReturn(0);
}

// The element frame, read on the (distributed, coarse) box before it is refined: every cell's,
// which must be one for the whole box.
PetscErrorCode boxElementFrame(DM coarse, ElementFrame *frame) {
  MPI_Comm          comm = PetscObjectComm((PetscObject)coarse);
  PetscInt          c_start, c_end, range[2] = {PETSC_MIN_INT, PETSC_MIN_INT}; // -least, greatest code
  mesh::VertexCoordinates coords;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(coarse, 0, &c_start, &c_end));
  PetscCall(coords.Open(coarse));
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscCall(BoxCellFrame(coarse, coords, c, frame));
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

// Every vertex from its lattice point to its GLL node (BoxGllCoordinate): a function of the
// lattice point, so every rank moves its copy of a shared vertex alike, and the global
// coordinates, made again from the local ones, agree with them.
PetscErrorCode moveToGll(DM dm, const SpectralLattice &s, const BoxSpec &box) {
  Vec          local, moved;
  DM           cdm;
  PetscSection section;
  PetscScalar *x;
  PetscInt     v_start, v_end;
  double       gll[numerics::kMaxSpectralDegree + 1], w[numerics::kMaxSpectralDegree + 1];
  PetscFunctionBeginUser;
  numerics::gllPointsWeights((int)s.degree, gll, w);
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
    for (PetscInt d = 0; d < s.fine.dim; ++d) x[off + d] = BoxGllCoordinate(box, d, s.degree, gll, (PetscInt)s.fine.coordinate(lattice_point, d, 0));
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
  return ((PetscInt)1 << k) == degree && degree <= numerics::kMaxSpectralDegree ? k : -1;
}

PetscErrorCode BoxRefineDistributed(DM *dm, PetscInt levels, PetscInt degree, const BoxSpec &box, const std::vector<std::string> &regions,
                                    const std::vector<std::string> &boundaries, const std::vector<InterfaceSpec> &specs, std::vector<PetscInt> *serial_cell) {
  PetscInt dim;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(*dm, &dim));
  SpectralLattice s{Lattice(dim, box, degree), degree, ElementFrame()};
  if (degree > 1) PetscCall(boxElementFrame(*dm, &s.frame));
  PetscCall(RefineRegularly(dm, levels));
  PetscCall(KeepRefinedLabels(*dm, boundaries, specs));
  for (const InterfaceSpec &spec : specs) {
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

} // namespace slipwave::meshing
