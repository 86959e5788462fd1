#include "slipwave/mesh/box_refinement.hpp"

#include <petscsf.h>

#include "slipwave/mesh/labels.hpp"
#include "slipwave/mesh/mesh_refinement.hpp"
#include "slipwave/mesh/point_centroid.hpp"
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
// at half-integers, so `shift` 0.5 turns a centroid into its cell's index).
struct Lattice {
  PetscInt  dim;
  PetscInt  n[3];
  PetscReal lower[3], h[3];
  explicit Lattice(PetscInt d, const BoxSpec &box) : dim(d) {
    for (PetscInt i = 0; i < 3; ++i) {
      n[i]     = i < d ? box.faces[i] : 1;
      lower[i] = box.lower[i];
      h[i]     = i < d ? (box.upper[i] - box.lower[i]) / box.faces[i] : 1;
    }
  }
  // Lexicographic, x fastest: DMPlexCreateBoxMesh's order of vertices (extra = 1) and cells (0).
  int64_t index(const PetscReal *x, PetscReal shift, PetscInt extra) const {
    int64_t key = 0, stride = 1;
    for (PetscInt d = 0; d < dim; ++d) {
      key += stride * (int64_t)std::llround((x[d] - lower[d]) / h[d] - shift);
      stride *= n[d] + extra;
    }
    return key;
  }
};

// interface_<name>_pair/_side on the fine mesh, keyed by lattice point: a split vertex and
// its structure copy sit on the same one, and lattice order is the serial split's order (it
// numbers pairs by original vertex).
PetscErrorCode labelPairs(DM dm, const Lattice &lattice, const InterfaceSpec &spec, PetscInt structure_region) {
  VertexCoordinates coords;
  PetscFunctionBeginUser;
  PetscCall(coords.Open(dm));
  PetscCall(LabelRefinedPairs(dm, spec, structure_region, [&](PetscInt v, PairKey *key, bool *known) -> PetscErrorCode {
    PetscReal x[3];
    PetscFunctionBeginUser;
    PetscCall(coords.Get(v, x));
    key->fill(0);
    (*key)[0] = lattice.index(x, 0, 1);
    *known    = true;
    PetscFunctionReturn(0);
  }));
  PetscCall(coords.Close());
  PetscFunctionReturn(0);
}

// The serial box numbers its cells in lattice order, less the void cells: a cell's number is
// how many present cells come before it on the lattice. The lattice is laid out over the
// ranks, each cell marks its lattice slot, a prefix sum counts the marks.
PetscErrorCode serialCellNumbers(DM dm, const Lattice &lattice, std::vector<PetscInt> *serial_cell) {
  MPI_Comm              comm = PetscObjectComm((PetscObject)dm);
  PetscInt              c_start, c_end, total = 1, nroots, before = 0;
  PetscLayout           layout;
  PetscSF               sf;
  std::vector<PetscInt> slots, marks, ones;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, &c_end));
  for (PetscInt d = 0; d < lattice.dim; ++d) total *= lattice.n[d];
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscReal x[3];
    PetscCall(MeshPointCentroid(dm, c, x));
    slots.push_back((PetscInt)lattice.index(x, 0.5, 0));
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
    const PetscInt present = m;
    m = local;
    local += present;
  }
  PetscCallMPI(MPI_Exscan(&local, &before, 1, MPIU_INT, MPI_SUM, comm));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) before = 0; // MPI_Exscan leaves rank 0's result undefined
  for (PetscInt &m : marks) m += before;
  serial_cell->assign(c_end - c_start, 0);
  PetscCall(PetscSFBcastBegin(sf, MPIU_INT, marks.data(), serial_cell->data(), MPI_REPLACE));
  PetscCall(PetscSFBcastEnd(sf, MPIU_INT, marks.data(), serial_cell->data(), MPI_REPLACE));
  PetscCall(PetscSFDestroy(&sf));
  PetscCall(PetscLayoutDestroy(&layout));
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

PetscErrorCode BoxRefineDistributed(DM *dm, PetscInt levels, const BoxSpec &box, const std::vector<std::string> &regions, const std::vector<std::string> &boundaries,
                                    const std::vector<InterfaceSpec> &specs, std::vector<PetscInt> *serial_cell) {
  PetscInt dim;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(*dm, &dim));
  PetscCall(RefineRegularly(dm, levels));
  PetscCall(KeepRefinedLabels(*dm, boundaries, specs));
  const Lattice lattice(dim, box);
  for (const InterfaceSpec &spec : specs) {
    const PetscInt structure = (PetscInt)(std::find(regions.begin(), regions.end(), spec.structure_region) - regions.begin());
    PetscCall(labelPairs(*dm, lattice, spec, structure));
  }
  PetscCall(serialCellNumbers(*dm, lattice, serial_cell));
  PetscFunctionReturn(0);
}

} // namespace slipwave::mesh
