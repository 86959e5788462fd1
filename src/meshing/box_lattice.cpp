#include "slipwave/meshing/box_lattice.hpp"

#include <petscsf.h>

#include "slipwave/mesh/cell_vertices.hpp"
#include "slipwave/mesh/labels.hpp"
#include "slipwave/mesh/point_centroid.hpp"
#include "slipwave/mesh/spectral_layout.hpp"
#include "slipwave/meshing/box_element_frame.hpp"
#include "slipwave/numerics/gll_basis.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

namespace slipwave::meshing {
namespace {

// The doubled lattice: a lattice entity (vertex, edge, face, cell) at its centre, in half
// sub-cells: odd coordinates along the axes it extends over, even ones along the others. Its
// type is the mask of its odd axes, its depth their number.
PetscInt typeDepth(PetscInt type) { return (type & 1) + ((type >> 1) & 1) + ((type >> 2) & 1); }

// The cone of every entity of one type, relative to the entity: offsets (doubled) and
// orientations, as DMPlexCreateBoxMesh builds them.
struct Cone {
  PetscInt                            size = 0;
  std::array<std::array<PetscInt, 3>, 6> offset{};
  std::array<PetscInt, 6>             orientation{};
};

// Reads the cones of every type off a one-cell box [0, 2]^dim (doubled coordinates are its
// own), checking that the entities of one type agree, the element frame of its cell and its
// vertices in closure order (as offsets from its centre).
PetscErrorCode readOneCellBox(PetscInt dim, std::array<Cone, 8> *cones, ElementFrame *frame, std::vector<std::array<PetscInt, 3>> *closure_vertices) {
  DM                      ref;
  PetscInt                faces[3] = {1, 1, 1}, p_start, p_end, v_start, v_end;
  PetscReal               lower[3] = {0, 0, 0}, upper[3] = {2, 2, 2};
  mesh::VertexCoordinates coords;
  PetscFunctionBeginUser;
  PetscCall(DMPlexCreateBoxMesh(PETSC_COMM_SELF, dim, PETSC_FALSE, faces, lower, upper, nullptr, PETSC_TRUE, &ref));
  PetscCall(DMPlexGetChart(ref, &p_start, &p_end));
  PetscCall(DMPlexGetDepthStratum(ref, 0, &v_start, &v_end));
  std::vector<std::array<PetscInt, 3>> at(p_end - p_start);
  for (PetscInt q = p_start; q < p_end; ++q) {
    PetscReal x[3] = {0, 0, 0};
    PetscCall(mesh::MeshPointCentroid(ref, q, x));
    for (PetscInt d = 0; d < 3; ++d) at[q - p_start][d] = d < dim ? (PetscInt)std::lround(x[d]) : 0;
  }
  std::array<bool, 8> seen{};
  for (PetscInt q = p_start; q < p_end; ++q) {
    const PetscInt *cone, *orientation;
    PetscInt        size, type = 0;
    for (PetscInt d = 0; d < dim; ++d) type |= (at[q - p_start][d] & 1) << d;
    PetscCall(DMPlexGetConeSize(ref, q, &size));
    PetscCall(DMPlexGetCone(ref, q, &cone));
    PetscCall(DMPlexGetConeOrientation(ref, q, &orientation));
    Cone c;
    c.size = size;
    for (PetscInt k = 0; k < size; ++k) {
      for (PetscInt d = 0; d < 3; ++d) c.offset[k][d] = at[cone[k] - p_start][d] - at[q - p_start][d];
      c.orientation[k] = orientation[k];
    }
    Cone &known = (*cones)[type];
    if (!seen[type]) known = c, seen[type] = true;
    bool same = known.size == c.size;
    for (PetscInt k = 0; k < c.size && same; ++k) same = known.offset[k] == c.offset[k] && known.orientation[k] == c.orientation[k];
    PetscCheck(same, PETSC_COMM_SELF, PETSC_ERR_PLIB, "BoxLatticeBuild: the box's entities of one kind (type %" PetscInt_FMT ") have different cones", type);
  }
  PetscCall(coords.Open(ref));
  PetscCall(BoxCellFrame(ref, coords, 0, frame));
  PetscCall(coords.Close());
  PetscInt *closure = nullptr, nclosure;
  PetscCall(DMPlexGetTransitiveClosure(ref, 0, PETSC_TRUE, &nclosure, &closure));
  for (PetscInt i = 0; i < nclosure; ++i)
    if (closure[2 * i] >= v_start && closure[2 * i] < v_end) {
      std::array<PetscInt, 3> offset{};
      for (PetscInt d = 0; d < dim; ++d) offset[d] = at[closure[2 * i] - p_start][d] - 1;
      closure_vertices->push_back(offset);
    }
  PetscCall(DMPlexRestoreTransitiveClosure(ref, 0, PETSC_TRUE, &nclosure, &closure));
  PetscCall(DMDestroy(&ref));
  PetscFunctionReturn(0);
}

// This rank's coarse cells (lattice index, x fastest, and region) in lattice order, and the
// map of the present (not void) coarse cells, from rank 0's coarse box and its partition.
struct CoarseCells {
  std::vector<int64_t>  index;
  std::vector<PetscInt> region;
  std::vector<char>     present; // per coarse cell of the box
};

PetscErrorCode receiveCoarseCells(DM coarse, PetscPartitioner part, const PetscInt *ncoarse, PetscInt dim, const BoxSpec &box, CoarseCells *mine) {
  MPI_Comm    comm = PetscObjectComm((PetscObject)coarse);
  PetscMPIInt size, rank;
  PetscInt    c_start, c_end;
  DMLabel     region;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(DMPlexGetHeightStratum(coarse, 0, &c_start, &c_end));
  PetscCall(DMGetLabel(coarse, mesh::kRegionLabel, &region));
  int64_t total = 1;
  for (PetscInt d = 0; d < dim; ++d) total *= ncoarse[d];
  // Per coarse cell of rank 0's box: lattice index and region, two int64 each.
  std::vector<int64_t> cells(2 * (size_t)(c_end - c_start));
  mine->present.assign(total, 0);
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscReal x[3];
    int64_t   key = 0, stride = 1;
    PetscInt  r;
    PetscCall(mesh::MeshPointCentroid(coarse, c, x));
    for (PetscInt d = 0; d < dim; stride *= ncoarse[d], ++d) key += stride * (int64_t)std::floor((x[d] - box.lower[d]) / (box.upper[d] - box.lower[d]) * ncoarse[d]);
    PetscCall(DMLabelGetValue(region, c, &r));
    cells[2 * (c - c_start)]     = key;
    cells[2 * (c - c_start) + 1] = r;
    mine->present[key]           = 1;
  }
  PetscCallMPI(MPI_Bcast(mine->present.data(), (PetscMPIInt)total, MPI_CHAR, 0, comm));
  std::vector<int64_t>     received;
  std::vector<PetscMPIInt> counts(size, 0), offsets(size, 0);
  if (size == 1) {
    received.swap(cells);
  } else {
    PetscSection parts;
    IS           assignment;
    PetscCall(PetscSectionCreate(comm, &parts));
    PetscCall(PetscPartitionerDMPlexPartition(part, coarse, nullptr, parts, &assignment));
    std::vector<int64_t> sorted;
    const PetscInt      *order;
    PetscCall(ISGetIndices(assignment, &order));
    for (PetscMPIInt r = 0; r < size && rank == 0; ++r) {
      PetscInt n, off;
      PetscCall(PetscSectionGetDof(parts, r, &n));
      PetscCall(PetscSectionGetOffset(parts, r, &off));
      counts[r]  = (PetscMPIInt)(2 * n);
      offsets[r] = (PetscMPIInt)(2 * off);
      for (PetscInt i = off; i < off + n; ++i) sorted.insert(sorted.end(), {cells[2 * (order[i] - c_start)], cells[2 * (order[i] - c_start) + 1]});
    }
    PetscCall(ISRestoreIndices(assignment, &order));
    PetscCall(ISDestroy(&assignment));
    PetscCall(PetscSectionDestroy(&parts));
    PetscMPIInt n = 0;
    PetscCallMPI(MPI_Scatter(counts.data(), 1, MPI_INT, &n, 1, MPI_INT, 0, comm));
    received.resize(n);
    PetscCallMPI(MPI_Scatterv(sorted.data(), counts.data(), offsets.data(), MPI_INT64_T, received.data(), n, MPI_INT64_T, 0, comm));
  }
  std::vector<std::pair<int64_t, int64_t>> pairs;
  for (size_t i = 0; i < received.size(); i += 2) pairs.emplace_back(received[i], received[i + 1]);
  std::sort(pairs.begin(), pairs.end());
  for (const auto &[key, r] : pairs) mine->index.push_back(key), mine->region.push_back((PetscInt)r);
  PetscFunctionReturn(0);
}

// The box of doubled positions that holds this rank's cells and their closure, and in it the
// local point at each position (kNone: none; kMarked: a closure point not yet numbered).
constexpr PetscInt kNone = -1, kMarked = -2;
struct Window {
  PetscInt             dim = 0;
  int64_t              lo[3] = {0, 0, 0}, n[3] = {1, 1, 1};
  std::vector<PetscInt> point;
  int64_t index(const int64_t *X) const { return (X[0] - lo[0]) + n[0] * ((X[1] - lo[1]) + n[1] * (X[2] - lo[2])); }
  void    position(int64_t i, int64_t *X) const {
    X[0] = lo[0] + i % n[0], X[1] = lo[1] + (i / n[0]) % n[1], X[2] = lo[2] + i / (n[0] * n[1]);
  }
  bool inside(const int64_t *X) const {
    for (PetscInt d = 0; d < 3; ++d)
      if (X[d] < lo[d] || X[d] >= lo[d] + n[d]) return false;
    return true;
  }
};

// The points another rank may hold too (a cell of their star is not local: at the part's
// surface) matched across the ranks by their position on the doubled lattice of the box. A part
// is a union of coarse cells (s sub-cells per axis), so only a point on a coarse cell's side (an
// even coordinate that is a multiple of 2 s) can be on its surface.
PetscErrorCode setPointSF(DM dm, const Window &w, const int64_t *nbox, PetscInt s, PetscInt ncell, PetscInt npoints) {
  MPI_Comm              comm = PetscObjectComm((PetscObject)dm);
  std::vector<PetscInt> keys, points;
  double                total = 1;
  PetscFunctionBeginUser;
  for (PetscInt d = 0; d < w.dim; ++d) total *= (double)nbox[d];
  PetscCheck(total < (double)PETSC_MAX_INT, comm, PETSC_ERR_SUP, "the box's lattice has %g points, more than this PETSc's integers count; build with -mesh_build serial", total);
  int64_t i = 0;
  for (int64_t z = 0; z < w.n[2]; ++z)
    for (int64_t y = 0; y < w.n[1]; ++y)
      for (int64_t x = 0; x < w.n[0]; ++x, ++i) {
        const PetscInt q = w.point[i];
        const int64_t  X[3] = {w.lo[0] + x, w.lo[1] + y, w.lo[2] + z};
        bool           side = false;
        for (PetscInt d = 0; d < w.dim; ++d) side = side || X[d] % (2 * s) == 0;
        if (q < ncell || !side) continue;
        bool surface = false;
        // The star's cells: along an odd axis the entity's own position, along an even one both
        // neighbours inside the box.
        for (PetscInt corner = 0; corner < (1 << w.dim) && !surface; ++corner) {
          int64_t Y[3] = {X[0], X[1], X[2]};
          bool    in_box = true, repeat = false;
          for (PetscInt d = 0; d < w.dim; ++d) {
            const bool high = (corner >> d) & 1;
            if (X[d] & 1) repeat = repeat || high, Y[d] = X[d];
            else Y[d] = X[d] + (high ? 1 : -1);
            in_box = in_box && Y[d] >= 0 && Y[d] < nbox[d];
          }
          if (repeat || !in_box) continue;
          surface = !w.inside(Y) || w.point[w.index(Y)] < 0 || w.point[w.index(Y)] >= ncell;
        }
        if (!surface) continue;
        keys.push_back((PetscInt)(X[0] + nbox[0] * (X[1] + nbox[1] * X[2])));
        points.push_back(q);
      }
  PetscLayout layout;
  PetscSF     matched, sf;
  PetscCall(PetscLayoutCreate(comm, &layout));
  PetscCall(PetscLayoutSetSize(layout, (PetscInt)total));
  PetscCall(PetscLayoutSetUp(layout));
  // Roots are named by their point, leaves by their place in `keys`: every surface point comes
  // back with its owner (rank, point there).
  PetscCall(PetscSFCreateByMatchingIndices(layout, (PetscInt)keys.size(), keys.data(), points.data(), 0, (PetscInt)keys.size(), keys.data(), nullptr, 0, nullptr, &matched));
  PetscCall(PetscLayoutDestroy(&layout));
  // The point SF: the surface points another rank owns, over every point of the mesh.
  PetscMPIInt        rank;
  PetscInt           nmatched, nleaves = 0;
  const PetscInt    *ilocal;
  const PetscSFNode *iremote;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscSFGetGraph(matched, nullptr, &nmatched, &ilocal, &iremote));
  PetscInt    *leaves;
  PetscSFNode *remotes;
  PetscCall(PetscMalloc1(nmatched, &leaves));
  PetscCall(PetscMalloc1(nmatched, &remotes));
  for (PetscInt i = 0; i < nmatched; ++i) {
    if (iremote[i].rank == rank) continue;
    leaves[nleaves]    = points[ilocal ? ilocal[i] : i];
    remotes[nleaves++] = iremote[i];
  }
  PetscCall(PetscSFDestroy(&matched));
  PetscCall(PetscSFCreate(comm, &sf));
  PetscCall(PetscSFSetGraph(sf, npoints, nleaves, leaves, PETSC_OWN_POINTER, remotes, PETSC_OWN_POINTER));
  PetscCall(PetscObjectSetName((PetscObject)sf, "point SF"));
  PetscCall(DMSetPointSF(dm, sf));
  PetscCall(PetscSFDestroy(&sf));
  PetscFunctionReturn(0);
}

// A label with one stratum per value; points[v]: the (increasing) points of value v. A stratum
// of evenly spaced points (a region's cells, one position in every element) is a stride: a
// label lookup (DMLabelGetValue, for every cell in the set-up) is then a division, not a search.
PetscErrorCode setLabel(DM dm, const char *name, const std::vector<std::vector<PetscInt>> &points) {
  DMLabel label;
  PetscFunctionBeginUser;
  PetscCall(DMCreateLabel(dm, name));
  PetscCall(DMGetLabel(dm, name, &label));
  for (size_t v = 0; v < points.size(); ++v) {
    const std::vector<PetscInt> &at = points[v];
    if (at.empty()) continue;
    const PetscInt step = at.size() > 1 ? at[1] - at[0] : 1;
    bool           even = true;
    for (size_t i = 1; i < at.size() && even; ++i) even = at[i] - at[i - 1] == step;
    IS is;
    if (even) PetscCall(ISCreateStride(PETSC_COMM_SELF, (PetscInt)at.size(), at[0], step, &is));
    else PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)at.size(), at.data(), PETSC_COPY_VALUES, &is));
    PetscCall(ISSetInfo(is, IS_SORTED, IS_LOCAL, PETSC_TRUE, PETSC_TRUE));
    PetscCall(DMLabelSetStratumIS(label, (PetscInt)v, is));
    PetscCall(ISDestroy(&is));
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode BoxLatticeBuild(DM coarse, PetscPartitioner part, PetscInt levels, PetscInt degree, const BoxSpec &box, const std::vector<std::string> &sides, DM *dm,
                               std::vector<PetscInt> *serial_cell) {
  MPI_Comm            comm = PetscObjectComm((PetscObject)coarse);
  PetscInt            dim;
  std::array<Cone, 8> cones;
  ElementFrame        frame;
  CoarseCells         mine;
  std::vector<std::array<PetscInt, 3>> corners; // a cell's vertices in closure order, from its centre
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(coarse, &dim));
  const PetscInt p = degree, per = (PetscInt)1 << levels, s = per * p; // elements, sub-cells per coarse cell and axis
  const PetscInt nsub = mesh::SpectralCount(p, dim), nblock = mesh::SpectralCount(per, dim);
  PetscInt       ncoarse[3] = {1, 1, 1};
  int64_t        nbox[3]    = {1, 1, 1}; // doubled positions per axis
  for (PetscInt d = 0; d < dim; ++d) ncoarse[d] = box.faces[d] >> levels, nbox[d] = 2 * (int64_t)box.faces[d] * p + 1;
  PetscCall(readOneCellBox(dim, &cones, &frame, &corners));
  PetscCall(receiveCoarseCells(coarse, part, ncoarse, dim, box, &mine));

  // The window over the local coarse cells' doubled positions.
  Window w;
  w.dim = dim;
  const size_t ncoarse_local = mine.index.size();
  if (ncoarse_local) {
    int64_t lo[3] = {INT64_MAX, INT64_MAX, INT64_MAX}, hi[3] = {0, 0, 0};
    for (int64_t key : mine.index)
      for (PetscInt d = 0; d < dim; key /= ncoarse[d], ++d) lo[d] = std::min(lo[d], key % ncoarse[d]), hi[d] = std::max(hi[d], key % ncoarse[d]);
    for (PetscInt d = 0; d < dim; ++d) w.lo[d] = 2 * lo[d] * s, w.n[d] = 2 * (hi[d] + 1) * s - w.lo[d] + 1;
  }
  w.point.assign((size_t)(w.n[0] * w.n[1] * w.n[2]), kNone);

  // Cells: coarse cell by coarse cell, element by element, sub-cell by sub-cell (lattice order
  // in each); each with its element's lattice position, its position in the element, region.
  const PetscInt        ncell = (PetscInt)(ncoarse_local * nblock * nsub);
  std::vector<int64_t>  where(ncell);         // per point: its window index
  std::vector<int64_t>  element(ncell);       // per cell: its element's lattice position (x fastest), over the box's elements
  std::vector<PetscInt> position(ncell, 0);   // per cell: its place in its element (spectral_position)
  std::vector<PetscInt> region_of(ncell, 0);  // per cell: its region
  std::vector<std::vector<PetscInt>> region_cells, position_cells(p > 1 ? nsub : 0);
  PetscInt              cell = 0;
  for (size_t k = 0; k < ncoarse_local; ++k) {
    PetscInt c[3] = {0, 0, 0};
    int64_t  key  = mine.index[k];
    for (PetscInt d = 0; d < dim; key /= ncoarse[d], ++d) c[d] = (PetscInt)(key % ncoarse[d]);
    if ((size_t)mine.region[k] >= region_cells.size()) region_cells.resize(mine.region[k] + 1);
    for (PetscInt b = 0; b < nblock; ++b)
      for (PetscInt q = 0; q < nsub; ++q, ++cell) {
        PetscInt e[3] = {0, 0, 0}, sub[3] = {0, 0, 0};
        int64_t  X[3] = {0, 0, 0}, slot = 0, stride = 1;
        for (PetscInt d = 0, bb = b, qq = q; d < dim; bb /= per, qq /= p, ++d) {
          e[d]   = c[d] * per + bb % per;
          sub[d] = qq % p;
          X[d]   = 2 * ((int64_t)e[d] * p + sub[d]) + 1;
          slot += stride * e[d];
          stride *= box.faces[d];
        }
        const int64_t i = w.index(X);
        w.point[i]      = cell;
        where[cell]     = i;
        element[cell]   = slot;
        position[cell]  = p > 1 ? frame.position(p, sub) : 0;
        region_of[cell] = mine.region[k];
        region_cells[mine.region[k]].push_back(cell);
        if (p > 1) position_cells[position[cell]].push_back(cell);
        // Its closure: the doubled positions around it.
        for (PetscInt around = 0; around < (dim == 2 ? 9 : 27); ++around) {
          int64_t Y[3] = {X[0] + around % 3 - 1, X[1] + (around / 3) % 3 - 1, dim == 3 ? X[2] + around / 9 - 1 : 0};
          PetscInt &at = w.point[w.index(Y)];
          if (at == kNone) at = kMarked;
        }
      }
  }

  // The other points by depth stratum (vertices, then faces, then edges), in window order; a
  // position's type is the mask of its odd coordinates.
  PetscInt count[4] = {0, 0, 0, 0}, start[4] = {0, 0, 0, 0};
  auto     forEachPosition = [&](auto &&visit) {
    int64_t i = 0;
    for (int64_t z = 0; z < w.n[2]; ++z)
      for (int64_t y = 0; y < w.n[1]; ++y)
        for (int64_t x = 0; x < w.n[0]; ++x, ++i) {
          const int64_t X[3] = {w.lo[0] + x, w.lo[1] + y, w.lo[2] + z};
          visit(i, X, (PetscInt)((X[0] & 1) | (X[1] & 1) << 1 | (dim == 3 ? (X[2] & 1) << 2 : 0)));
        }
  };
  forEachPosition([&](int64_t i, const int64_t *, PetscInt type) {
    if (w.point[i] == kMarked) ++count[typeDepth(type)];
  });
  start[dim] = 0;
  start[0]   = ncell;
  for (PetscInt depth = dim - 1, next = ncell + count[0]; depth >= 1; next += count[depth], --depth) start[depth] = next;
  PetscInt npoints = ncell;
  for (PetscInt depth = 0; depth < dim; ++depth) npoints += count[depth];
  where.resize(npoints);
  std::vector<unsigned char>         type_of(npoints, (unsigned char)((1 << dim) - 1)); // cells: every axis odd
  std::vector<std::vector<PetscInt>> side_faces(2 * dim);
  PetscInt                           next[4] = {start[0], start[1], start[2], start[3]};
  forEachPosition([&](int64_t i, const int64_t *X, PetscInt type) {
    if (w.point[i] != kMarked) return;
    const PetscInt depth = typeDepth(type), q = next[depth]++;
    w.point[i] = q;
    where[q]   = i;
    type_of[q] = (unsigned char)type;
    // A face on a side of the box: its one even axis at 0 or at the far end.
    if (depth == dim - 1)
      for (PetscInt d = 0; d < dim; ++d)
        if (!(type >> d & 1) && (X[d] == 0 || X[d] == nbox[d] - 1)) side_faces[2 * d + (X[d] != 0)].push_back(q);
  });

  // Cones and orientations (a cone point's window index is the point's plus a shift of its
  // type), then the rest of the topology.
  std::array<std::array<int64_t, 6>, 8> shift{};
  for (PetscInt type = 0; type < 8; ++type)
    for (PetscInt k = 0; k < cones[type].size; ++k) shift[type][k] = cones[type].offset[k][0] + w.n[0] * (cones[type].offset[k][1] + w.n[1] * cones[type].offset[k][2]);
  PetscCall(DMCreate(comm, dm));
  PetscCall(DMSetType(*dm, DMPLEX));
  PetscCall(DMSetDimension(*dm, dim));
  PetscCall(DMPlexSetChart(*dm, 0, npoints));
  for (PetscInt q = 0; q < npoints; ++q) PetscCall(DMPlexSetConeSize(*dm, q, cones[type_of[q]].size));
  PetscCall(DMSetUp(*dm));
  PetscSection cone_section;
  PetscInt    *cone_points, *cone_orientations;
  PetscCall(DMPlexGetConeSection(*dm, &cone_section));
  PetscCall(DMPlexGetCones(*dm, &cone_points));
  PetscCall(DMPlexGetConeOrientations(*dm, &cone_orientations));
  for (PetscInt q = 0; q < npoints; ++q) {
    const Cone &c = cones[type_of[q]];
    PetscInt    off;
    PetscCall(PetscSectionGetOffset(cone_section, q, &off));
    for (PetscInt k = 0; k < c.size; ++k) {
      cone_points[off + k]       = w.point[where[q] + shift[type_of[q]][k]];
      cone_orientations[off + k] = c.orientation[k];
    }
  }
  PetscCall(DMPlexSymmetrize(*dm));
  PetscCall(DMPlexStratify(*dm));
  // Cell types by stratum (one per depth), as stride strata: DMPlexComputeCellTypes would set
  // them point by point.
  {
    const DMPolytopeType types[4] = {DM_POLYTOPE_POINT, DM_POLYTOPE_SEGMENT, DM_POLYTOPE_QUADRILATERAL, DM_POLYTOPE_HEXAHEDRON};
    DMLabel              celltype;
    PetscCall(DMCreateLabel(*dm, "celltype"));
    PetscCall(DMPlexGetCellTypeLabel(*dm, &celltype));
    for (PetscInt depth = 0; depth <= dim; ++depth) {
      const PetscInt n = depth == dim ? ncell : count[depth];
      if (!n) continue;
      IS is;
      PetscCall(ISCreateStride(PETSC_COMM_SELF, n, start[depth], 1, &is));
      PetscCall(DMLabelSetStratumIS(celltype, types[depth], is));
      PetscCall(ISDestroy(&is));
    }
  }
  PetscMPIInt size;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  if (size > 1) PetscCall(setPointSF(*dm, w, nbox, s, ncell, npoints));

  // Coordinates (before the labels: the coordinate DM is a clone that copies them).
  {
    double       gll[numerics::kMaxSpectralDegree + 1], weights[numerics::kMaxSpectralDegree + 1];
    PetscSection section;
    Vec          coordinates;
    PetscScalar *x;
    numerics::gllPointsWeights((int)p, gll, weights);
    PetscCall(DMSetCoordinateDim(*dm, dim));
    PetscCall(DMGetCoordinateSection(*dm, &section));
    PetscCall(PetscSectionSetNumFields(section, 1));
    PetscCall(PetscSectionSetFieldComponents(section, 0, dim));
    PetscCall(PetscSectionSetChart(section, start[0], start[0] + count[0]));
    for (PetscInt v = start[0]; v < start[0] + count[0]; ++v) {
      PetscCall(PetscSectionSetDof(section, v, dim));
      PetscCall(PetscSectionSetFieldDof(section, v, 0, dim));
    }
    PetscCall(PetscSectionSetUp(section));
    PetscCall(VecCreate(PETSC_COMM_SELF, &coordinates));
    PetscCall(PetscObjectSetName((PetscObject)coordinates, "coordinates"));
    PetscCall(VecSetSizes(coordinates, dim * count[0], PETSC_DETERMINE));
    PetscCall(VecSetBlockSize(coordinates, dim));
    PetscCall(VecSetType(coordinates, VECSTANDARD));
    PetscCall(VecGetArray(coordinates, &x));
    for (PetscInt v = 0; v < count[0]; ++v) {
      int64_t X[3];
      w.position(where[start[0] + v], X);
      for (PetscInt d = 0; d < dim; ++d) x[dim * v + d] = BoxGllCoordinate(box, d, p, gll, (PetscInt)(X[d] / 2));
    }
    PetscCall(VecRestoreArray(coordinates, &x));
    PetscCall(DMSetCoordinatesLocal(*dm, coordinates));
    PetscCall(VecDestroy(&coordinates));
  }

  // Every cell's vertices in closure order (cell_vertices.hpp): those of the one-cell box's cell.
  {
    mesh::CellVertices table;
    table.per_cell = (PetscInt)corners.size();
    table.vertex.resize((size_t)ncell * table.per_cell);
    for (PetscInt c = 0; c < ncell; ++c) {
      int64_t X[3];
      w.position(where[c], X);
      for (PetscInt k = 0; k < table.per_cell; ++k) {
        const int64_t Y[3] = {X[0] + corners[k][0], X[1] + corners[k][1], X[2] + corners[k][2]};
        table.vertex[(size_t)c * table.per_cell + k] = w.point[w.index(Y)];
      }
    }
    PetscCall(mesh::CellVerticesAttach(*dm, std::move(table)));
  }
  PetscCall(setLabel(*dm, mesh::kRegionLabel, region_cells));
  if (p > 1) {
    PetscCall(setLabel(*dm, mesh::kSpectralPositionLabel, position_cells));
    // The elements as SpectralLayoutBuild would find them from the topology: element k is cells
    // k p^dim .. (k + 1) p^dim - 1, its GLL nodes lexicographic in the element frame.
    mesh::SpectralLayout layout;
    const PetscInt       nelem = ncell / nsub, n1 = p + 1, nnode = mesh::SpectralCount(n1, dim);
    layout.degree = p;
    layout.dim    = dim;
    layout.nelem  = nelem;
    layout.element_cells.resize((size_t)ncell);
    layout.element_nodes.resize((size_t)nelem * nnode);
    layout.element_region.resize(nelem);
    layout.element_id.resize(nelem);
    layout.cell_element.resize(ncell);
    layout.cell_position = position;
    for (PetscInt e = 0; e < nelem; ++e) {
      const PetscInt first = e * nsub;
      for (PetscInt q = 0; q < nsub; ++q) {
        layout.element_cells[(size_t)first + position[first + q]] = first + q;
        layout.cell_element[first + q]                             = e;
        if (position[first + q] == 0) layout.element_id[e] = first + q;
      }
      // The element's lowest lattice vertex: the lower corner of its sub-cell at q = 0.
      int64_t X0[3];
      w.position(where[first], X0);
      for (PetscInt n = 0; n < nnode; ++n) {
        const PetscInt j[3] = {n % n1, (n / n1) % n1, dim == 3 ? n / (n1 * n1) : 0}; // lattice offsets
        int64_t        X[3] = {X0[0] - 1 + 2 * j[0], X0[1] - 1 + 2 * j[1], dim == 3 ? X0[2] - 1 + 2 * j[2] : 0};
        PetscInt       node = 0;
        for (PetscInt a = 0, stride = 1; a < dim; stride *= n1, ++a) node += stride * (frame.sign[a] > 0 ? j[frame.axis[a]] : p - j[frame.axis[a]]);
        layout.element_nodes[(size_t)e * nnode + node] = w.point[w.index(X)];
      }
      layout.element_region[e] = region_of[first];
    }
    PetscCall(mesh::SpectralLayoutAttach(*dm, std::move(layout)));
  }
  for (PetscInt k = 0; k < 2 * dim; ++k) PetscCall(setLabel(*dm, sides[k].c_str(), {{}, side_faces[k]}));

  // serial_cell: the elements in lattice order less the void ones. Element (x, y, z) is
  // preceded by the present elements of the rows (y, z) before its own (row_start) and, in its
  // row, by those of the present coarse cells before its own and those before it in its coarse
  // cell.
  {
    const int64_t        rows = dim == 2 ? box.faces[1] : (int64_t)box.faces[1] * box.faces[2];
    std::vector<int64_t> row_start(rows + 1, 0), before_in_row(mine.present.size(), 0);
    for (int64_t r = 0; r < rows; ++r) {
      const int64_t crow = (r % box.faces[1]) / per + (dim == 3 ? ncoarse[1] * ((r / box.faces[1]) / per) : 0);
      int64_t       n    = 0;
      for (PetscInt cx = 0; cx < ncoarse[0]; ++cx) n += mine.present[crow * ncoarse[0] + cx];
      row_start[r + 1] = row_start[r] + n * per;
    }
    for (size_t crow = 0; crow * ncoarse[0] < mine.present.size(); ++crow)
      for (PetscInt cx = 1; cx < ncoarse[0]; ++cx) before_in_row[crow * ncoarse[0] + cx] = before_in_row[crow * ncoarse[0] + cx - 1] + mine.present[crow * ncoarse[0] + cx - 1];
    serial_cell->resize(ncell);
    for (PetscInt c = 0; c < ncell; ++c) {
      const int64_t ex = element[c] % box.faces[0], row = element[c] / box.faces[0];
      const int64_t crow = (row % box.faces[1]) / per + (dim == 3 ? ncoarse[1] * ((row / box.faces[1]) / per) : 0);
      const int64_t serial = row_start[row] + per * before_in_row[crow * ncoarse[0] + ex / per] + ex % per;
      (*serial_cell)[c] = (PetscInt)(serial * nsub) + position[c];
    }
  }
  PetscFunctionReturn(0);
}

} // namespace slipwave::meshing
