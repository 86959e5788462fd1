#include "slipwave/mesh/box_refinement.hpp"

#include <petscsf.h>

#include "slipwave/mesh/labels.hpp"
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
// lattice point; the pair id is the rank of that point among all of the interface's points in
// lattice order, which is the serial split's order (it numbers pairs by original vertex).
PetscErrorCode labelPairs(DM dm, const Lattice &lattice, const InterfaceSpec &spec, PetscInt structure_region) {
  MPI_Comm              comm = PetscObjectComm((PetscObject)dm);
  const std::string     base = "interface_" + spec.name;
  DMLabel               faces, region, pair, side;
  PetscInt              f_start, f_end, v_start, v_end;
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
  PetscInt owned[2] = {0, 0};
  // Only structure cells hold a structure copy; the soil copy is shared with no structure cell.
  for (PetscInt v = v_start; v < v_end; ++v) {
    PetscReal x[3];
    PetscCall(coords.Get(v, x));
    const int64_t key = lattice.index(x, 0, 1);
    auto          it  = std::lower_bound(all.begin(), all.end(), key);
    if (it == all.end() || *it != key) continue;
    PetscInt nstar, *star = nullptr, on_structure = 0;
    PetscCall(DMPlexGetTransitiveClosure(dm, v, PETSC_FALSE, &nstar, &star));
    for (PetscInt i = 0; i < nstar; ++i) {
      PetscInt r;
      PetscCall(DMLabelGetValue(region, star[2 * i], &r));
      on_structure = on_structure || r == structure_region;
    }
    PetscCall(DMPlexRestoreTransitiveClosure(dm, v, PETSC_FALSE, &nstar, &star));
    PetscCall(DMLabelSetValue(pair, v, (PetscInt)(it - all.begin())));
    PetscCall(DMLabelSetValue(side, v, on_structure));
    if (!ghost[v - v_start]) ++owned[on_structure];
  }
  PetscCall(coords.Close());
  // Each lattice point of the interface must hold exactly one soil and one structure vertex; a
  // guard on the interface itself (vertices doubled away from it, which BoxInterfacesRefinable
  // rules out, would not show here).
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, owned, 2, MPIU_INT, MPI_SUM, comm));
  PetscCheck(owned[0] == (PetscInt)all.size() && owned[1] == (PetscInt)all.size(), comm, PETSC_ERR_PLIB,
             "interface '%s' refined: %" PetscInt_FMT " soil and %" PetscInt_FMT " structure vertices for %zu pairs; build with -mesh_build serial", spec.name.c_str(),
             owned[0], owned[1], all.size());
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

PetscErrorCode BoxRefineDistributed(DM *dm, PetscInt levels, const BoxSpec &box, const std::vector<std::string> &regions, const std::vector<std::string> &boundaries,
                                    const std::vector<InterfaceSpec> &specs, std::vector<PetscInt> *serial_cell) {
  PetscInt dim;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(*dm, &dim));
  for (PetscInt k = 0; k < levels; ++k) {
    DM fine;
    PetscCall(DMRefine(*dm, PetscObjectComm((PetscObject)*dm), &fine));
    PetscCall(DMDestroy(dm));
    *dm = fine;
  }
  PetscCall(keepHeight(*dm, kRegionLabel, 0));
  for (const std::string &b : boundaries) PetscCall(keepHeight(*dm, b.c_str(), 1));
  const Lattice lattice(dim, box);
  for (const InterfaceSpec &spec : specs) {
    PetscCall(keepHeight(*dm, ("interface_" + spec.name).c_str(), 1));
    const PetscInt structure = (PetscInt)(std::find(regions.begin(), regions.end(), spec.structure_region) - regions.begin());
    PetscCall(labelPairs(*dm, lattice, spec, structure));
  }
  PetscCall(serialCellNumbers(*dm, lattice, serial_cell));
  PetscFunctionReturn(0);
}

} // namespace slipwave::mesh
