// Box meshes built distributed (box_refinement.hpp).
//  1. BoxRefinementLevels: how many times a box is refined. Expected levels follow from the
//     rule in box_refinement.hpp by hand: the largest k with 2^k dividing every face count,
//     every region bound inside the box on a coarse grid line, and enough coarse cells (1000
//     per rank for auto, 1 per rank for distributed).
//  2. MeshCreate with -mesh_build serial and distributed on the same box, on any number of
//     ranks (tests/cases/mesh_build_distributed.sh runs it on 2): the meshes must be the same,
//     label by label. Per cell: its serial number, region and centroid; per split vertex: pair
//     id, side and position; per boundary label and interface: the centroids of its faces.
//     Gathered on rank 0 and sorted (cells by serial number, vertices by pair id and side,
//     faces by position), positions equal to 1e-12 of the box (refinement averages corners,
//     the box scales a lattice: round-off apart). Scenes: a 2D block embedded in the soil
//     beside a void (the interface bends at the block's corners and ends at the surface) and
//     a 3D block on the surface of a soil with a void above; the same at -element_degree 4 (2D)
//     and 2 (3D), where the sub-cells also carry spectral_position (the serial subdivision's)
//     and the distributed build's vertices sit at the GLL nodes (its global coordinates made
//     from the local ones: equal), and SpectralLayoutOf groups the sub-cells back on every rank.
//     Without interfaces (box_lattice.hpp: every rank builds its part): 2D and 3D boxes of two
//     regions beside a void at degree 1, and at p = 3, 5, 6, 7 (2D) and 3 (3D). The element
//     table (SpectralLayoutOf) and the cells' vertices (CellVerticesOf) a builder hands to the
//     mesh must be those its topology gives.
#include "slipwave/mesh/cell_vertices.hpp"
#include "slipwave/mesh/point_centroid.hpp"
#include "slipwave/mesh/spectral_layout.hpp"
#include "slipwave/meshing/box_refinement.hpp"
#include "slipwave/meshing/mesh_builder.hpp"

#include "petsc_test_main.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace slipwave::mesh;
using namespace slipwave::meshing;

namespace {

BoxSpec box3(PetscInt n, PetscReal length) {
  BoxSpec b;
  for (int d = 0; d < 3; ++d) b.faces[d] = n, b.lower[d] = 0, b.upper[d] = length;
  return b;
}

void expect(PetscInt got, PetscInt want, const std::string &what) { unit::check(got == want, what + ": " + std::to_string(got) + " levels, want " + std::to_string(want)); }

// Rows of numbers (a key, then a position), gathered on rank 0 and sorted.
using Rows = std::vector<std::vector<double>>;

PetscErrorCode gatherRows(MPI_Comm comm, size_t width, const Rows &mine, Rows *all) {
  std::vector<double> flat;
  PetscMPIInt         size, n;
  PetscFunctionBeginUser;
  for (const auto &r : mine) flat.insert(flat.end(), r.begin(), r.end());
  n = (PetscMPIInt)flat.size();
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<PetscMPIInt> counts(size), offsets(size + 1, 0);
  PetscCallMPI(MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm));
  for (PetscMPIInt r = 0; r < size; ++r) offsets[r + 1] = offsets[r] + counts[r];
  std::vector<double> every(offsets[size]);
  PetscCallMPI(MPI_Gatherv(flat.data(), n, MPI_DOUBLE, every.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0, comm));
  all->clear();
  for (size_t i = 0; i + width <= every.size(); i += width) all->emplace_back(every.begin() + i, every.begin() + i + width);
  // Rounded so that copies of one point on several ranks (and the two builds' round-off) sort
  // alike; duplicates (a face or vertex on two ranks) dropped.
  for (auto &r : *all)
    for (double &x : r) x = std::round(x * 1e6) / 1e6;
  std::sort(all->begin(), all->end());
  all->erase(std::unique(all->begin(), all->end()), all->end());
  PetscFunctionReturn(0);
}

struct Signature {
  Rows cells, pairs;
  std::vector<Rows> faces; // per label of `face_labels`
  double            coordinates_gap = 0; // |global coordinates scattered to local - local coordinates|
  PetscInt          elements = 0;        // SpectralLayoutOf's elements over all ranks (p > 1)
  PetscInt          layout_found = 1;    // SpectralLayoutOf's table is SpectralLayoutBuild's, on every rank
  PetscInt          vertices_found = 1;  // CellVerticesOf's table is the closures', on every rank
};

PetscErrorCode signatureOf(DM dm, const slipwave::meshing::MeshDescription &desc, const std::vector<std::string> &face_labels, Signature *sig) {
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscInt c_start, c_end, v_start, v_end, f_start, f_end;
  DMLabel  region, position;
  Rows     mine;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &c_start, &c_end));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &v_start, &v_end));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &f_start, &f_end));
  PetscCall(DMGetLabel(dm, slipwave::mesh::kRegionLabel, &region));
  PetscCall(DMGetLabel(dm, slipwave::mesh::kSpectralPositionLabel, &position));
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscReal x[3] = {0, 0, 0};
    PetscInt  r, pos = -1;
    PetscCall(slipwave::mesh::MeshPointCentroid(dm, c, x));
    PetscCall(DMLabelGetValue(region, c, &r));
    if (position) PetscCall(DMLabelGetValue(position, c, &pos));
    mine.push_back({(double)desc.serial_cell[c - c_start], (double)r, (double)pos, x[0], x[1], x[2]});
  }
  PetscCall(gatherRows(comm, 6, mine, &sig->cells));
  const slipwave::mesh::SpectralLayout *layout;
  PetscCall(slipwave::mesh::SpectralLayoutOf(dm, &layout));
  sig->elements = layout ? layout->nelem : 0;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &sig->elements, 1, MPIU_INT, MPI_SUM, comm));
  // A builder may hand its own table to the mesh (box_lattice.hpp): it must be the one the
  // topology gives.
  if (layout) {
    slipwave::mesh::SpectralLayout found;
    PetscCall(slipwave::mesh::SpectralLayoutBuild(dm, layout->degree, &found));
    sig->layout_found = found.nelem == layout->nelem && found.element_nodes == layout->element_nodes && found.element_cells == layout->element_cells &&
                        found.element_region == layout->element_region && found.element_id == layout->element_id && found.cell_element == layout->cell_element &&
                        found.cell_position == layout->cell_position;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &sig->layout_found, 1, MPIU_INT, MPI_MIN, comm));
  const slipwave::mesh::CellVertices *table;
  PetscCall(slipwave::mesh::CellVerticesOf(dm, &table));
  for (PetscInt c = c_start; c < c_end; ++c) {
    PetscInt *closure = nullptr, nclosure, n = 0;
    PetscCall(DMPlexGetTransitiveClosure(dm, c, PETSC_TRUE, &nclosure, &closure));
    for (PetscInt i = 0; i < nclosure; ++i)
      if (closure[2 * i] >= v_start && closure[2 * i] < v_end) sig->vertices_found = sig->vertices_found && n < table->per_cell && table->of(c - c_start)[n++] == closure[2 * i];
    PetscCall(DMPlexRestoreTransitiveClosure(dm, c, PETSC_TRUE, &nclosure, &closure));
    sig->vertices_found = sig->vertices_found && n == table->per_cell;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &sig->vertices_found, 1, MPIU_INT, MPI_MIN, comm));
  Vec global, local, scattered;
  DM  cdm;
  PetscCall(DMGetCoordinateDM(dm, &cdm));
  PetscCall(DMGetCoordinates(dm, &global));
  PetscCall(DMGetCoordinatesLocal(dm, &local));
  PetscCall(VecDuplicate(local, &scattered));
  PetscCall(DMGlobalToLocal(cdm, global, INSERT_VALUES, scattered));
  PetscCall(VecAXPY(scattered, -1, local));
  PetscCall(VecNorm(scattered, NORM_INFINITY, &sig->coordinates_gap));
  PetscCall(VecDestroy(&scattered));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &sig->coordinates_gap, 1, MPI_DOUBLE, MPI_MAX, comm));
  mine.clear();
  for (const auto &spec : desc.interfaces) {
    DMLabel pair, side;
    PetscCall(DMGetLabel(dm, ("interface_" + spec.name + "_pair").c_str(), &pair));
    PetscCall(DMGetLabel(dm, ("interface_" + spec.name + "_side").c_str(), &side));
    for (PetscInt v = v_start; v < v_end; ++v) {
      PetscInt  id, s;
      PetscReal x[3] = {0, 0, 0};
      PetscCall(DMLabelGetValue(pair, v, &id));
      PetscCall(DMLabelGetValue(side, v, &s));
      if (id < 0 && s < 0) continue;
      PetscCall(slipwave::mesh::MeshPointCentroid(dm, v, x));
      mine.push_back({(double)id, (double)s, x[0], x[1], x[2]});
    }
  }
  PetscCall(gatherRows(comm, 5, mine, &sig->pairs));
  sig->faces.clear();
  for (const std::string &name : face_labels) {
    DMLabel label;
    mine.clear();
    PetscCall(DMGetLabel(dm, name.c_str(), &label));
    for (PetscInt f = f_start; f < f_end && label; ++f) {
      PetscInt  value;
      PetscReal x[3] = {0, 0, 0};
      PetscCall(DMLabelGetValue(label, f, &value));
      if (value < 0) continue;
      PetscCall(slipwave::mesh::MeshPointCentroid(dm, f, x));
      mine.push_back({(double)value, x[0], x[1], x[2]});
    }
    // Points of other heights under the label would be a difference too: count them.
    PetscInt on_faces = 0;
    if (label) {
      IS              values;
      PetscInt        nvalues;
      const PetscInt *vals;
      PetscCall(DMLabelGetValueIS(label, &values));
      PetscCall(ISGetLocalSize(values, &nvalues));
      PetscCall(ISGetIndices(values, &vals));
      for (PetscInt i = 0; i < nvalues; ++i) {
        PetscInt n;
        PetscCall(DMLabelGetStratumSize(label, vals[i], &n));
        on_faces += n;
      }
      PetscCall(ISRestoreIndices(values, &vals));
      PetscCall(ISDestroy(&values));
    }
    mine.push_back({-1.0, (double)(on_faces - (PetscInt)mine.size()), 0, 0}); // this rank's points off the faces
    PetscCall(gatherRows(comm, 4, mine, &sig->faces.emplace_back()));
  }
  PetscFunctionReturn(0);
}

bool sameRows(const Rows &a, const Rows &b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t k = 0; k < a[i].size(); ++k)
      if (std::fabs(a[i][k] - b[i][k]) > 1e-12 * 64) return false;
  return true;
}

PetscErrorCode compareBuilds(const std::string &tag, const char *options) {
  PetscOptions opts;
  Signature    sig[2];
  PetscMPIInt  rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  for (int b = 0; b < 2; ++b) {
    PetscCall(PetscOptionsCreate(&opts));
    PetscCall(PetscOptionsInsertString(opts, options));
    PetscCall(PetscOptionsSetValue(opts, "-mesh_build", b == 0 ? "serial" : "distributed"));
    PetscCall(PetscOptionsPush(opts));
    DM                              dm;
    slipwave::meshing::MeshDescription desc;
    PetscCall(slipwave::meshing::MeshCreate(PETSC_COMM_WORLD, &dm, &desc));
    const bool refined = desc.source.find("built distributed") != std::string::npos;
    unit::check(refined == (b == 1), tag + ": " + (b ? "distributed" : "serial") + " build reported as such (" + desc.source + ")");
    std::vector<std::string> faces = desc.boundaries;
    for (const auto &spec : desc.interfaces) faces.push_back("interface_" + spec.name);
    PetscCall(signatureOf(dm, desc, faces, &sig[b]));
    PetscCall(DMDestroy(&dm));
    PetscCall(PetscOptionsPop());
    PetscCall(PetscOptionsDestroy(&opts));
  }
  if (rank == 0) {
    unit::check(!sig[0].cells.empty() && sameRows(sig[0].cells, sig[1].cells),
                tag + ": same cells (" + std::to_string(sig[0].cells.size()) + "): serial number, region, centroid");
    if (std::string(options).find("-interfaces") != std::string::npos)
      unit::check(!sig[0].pairs.empty() && sameRows(sig[0].pairs, sig[1].pairs),
                  tag + ": same split vertices (" + std::to_string(sig[0].pairs.size()) + "): pair id, side, position");
    bool faces_same = sig[0].faces.size() == sig[1].faces.size();
    for (size_t l = 0; l < sig[0].faces.size() && faces_same; ++l) faces_same = sameRows(sig[0].faces[l], sig[1].faces[l]);
    unit::check(faces_same, tag + ": same boundary and interface faces (" + std::to_string(sig[0].faces.size()) + " labels), and no other points under them");
    unit::check(sig[1].coordinates_gap == 0, tag + ": global and local coordinates agree (gap " + std::to_string(sig[1].coordinates_gap) + ")");
    unit::check(sig[0].elements == sig[1].elements, tag + ": the layout groups " + std::to_string(sig[1].elements) + " elements, as serially (" + std::to_string(sig[0].elements) + ")");
    unit::check(sig[0].layout_found && sig[1].layout_found, tag + ": the layout on the mesh is the one its topology gives (SpectralLayoutBuild)");
    unit::check(sig[0].vertices_found && sig[1].vertices_found, tag + ": the cells' vertices on the mesh are those of their closures (CellVerticesOf)");
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Run(bool) {
  PetscFunctionBeginUser;
  PetscCall(compareBuilds("2D embedded block", "-mesh_dim 2 -mesh_box_faces 32,16 -mesh_box_upper 32,16 -regions soil,air,block -region_air_box 0,32,12,16 "
                                               "-region_block_box 12,20,8,16 -void_regions air -interfaces base -interface_base_regions soil,block"));
  PetscCall(compareBuilds("3D block on the surface", "-mesh_dim 3 -mesh_box_faces 16,16,8 -mesh_box_upper 16,16,8 -regions soil,air,block "
                                                     "-region_air_box 0,16,0,16,4,8 -region_block_box 4,12,4,12,4,8 -void_regions air -interfaces base "
                                                     "-interface_base_regions soil,block"));
  PetscCall(compareBuilds("2D embedded block, p = 4", "-element_degree 4 -mesh_dim 2 -mesh_box_faces 16,8 -mesh_box_upper 32,16 -regions soil,air,block "
                                                      "-region_air_box 0,32,12,16 -region_block_box 12,20,8,16 -void_regions air -interfaces base "
                                                      "-interface_base_regions soil,block"));
  PetscCall(compareBuilds("3D block on the surface, p = 2", "-element_degree 2 -mesh_dim 3 -mesh_box_faces 8,8,4 -mesh_box_upper 16,16,8 -regions soil,air,block "
                                                            "-region_air_box 0,16,0,16,4,8 -region_block_box 4,12,4,12,4,8 -void_regions air -interfaces base "
                                                            "-interface_base_regions soil,block"));
  // Without interfaces every rank builds its part (box_lattice.hpp), at every degree: two
  // regions and a void, the void's and the rock's bounds on the coarse grid (2D: 4 m, 3D: 2 m).
  const std::string plain2d = "-mesh_dim 2 -mesh_box_upper 32,16 -regions soil,air,rock -region_air_box 0,8,12,16 -region_rock_box 0,32,0,4 -void_regions air";
  const std::string plain3d = "-mesh_dim 3 -mesh_box_upper 8,8,8 -regions soil,air,rock -region_air_box 0,4,0,4,4,8 -region_rock_box 0,8,0,8,0,2 -void_regions air";
  PetscCall(compareBuilds("2D layers beside a void, built by parts", (plain2d + " -mesh_box_faces 32,16").c_str()));
  PetscCall(compareBuilds("3D layers beside a void, built by parts", (plain3d + " -mesh_box_faces 8,8,8").c_str()));
  for (int p : {3, 5, 6, 7})
    PetscCall(compareBuilds("2D layers beside a void, built by parts, p = " + std::to_string(p), (plain2d + " -mesh_box_faces 8,4 -element_degree " + std::to_string(p)).c_str()));
  PetscCall(compareBuilds("3D layers beside a void, built by parts, p = 3", (plain3d + " -mesh_box_faces 4,4,4 -element_degree 3").c_str()));
  PetscFunctionReturn(0);
}

void checkLevels() {
  const std::vector<std::vector<PetscReal>> none;
  // 128^3 on 16 ranks: 32^3 = 32768 >= 16000 coarse cells, 16^3 = 4096 < 16000: 2 levels.
  expect(BoxRefinementLevels(3, box3(128, 128), none, 16, kMeshBuildAuto), 2, "128^3, 16 ranks, auto");
  // 64^3 on 2 ranks: 16^3 = 4096 >= 2000, 8^3 = 512 < 2000: 2 levels.
  expect(BoxRefinementLevels(3, box3(64, 64), none, 2, kMeshBuildAuto), 2, "64^3, 2 ranks, auto");
  // distributed asks only one coarse cell per rank: 64 = 2^6, 1 cell at k = 6 < 2 ranks: 5.
  expect(BoxRefinementLevels(3, box3(64, 64), none, 2, kMeshBuildDistributed), 5, "64^3, 2 ranks, distributed");
  expect(BoxRefinementLevels(3, box3(64, 64), none, 2, kMeshBuildSerial), 0, "serial never refines");
  // A small box stays serial under auto: 40 x 20 has 800 cells < 1000.
  BoxSpec small;
  small.faces[0] = 40, small.faces[1] = 20, small.upper[0] = 100, small.upper[1] = 50;
  expect(BoxRefinementLevels(2, small, none, 1, kMeshBuildAuto), 0, "40 x 20, auto");
  // An odd face count allows no refinement.
  BoxSpec odd   = box3(64, 64);
  odd.faces[2] = 63;
  expect(BoxRefinementLevels(3, odd, none, 1, kMeshBuildDistributed), 0, "63 cells on z");
  // Region bounds: on the 1 m grid of 64^3 over 64 m, a bound at 24 m lies on the grid of
  // 8 m (k = 3) but not of 16 m (k = 4); bounds at 0 and 64 m (the sides) and beyond cut no cell.
  const std::vector<std::vector<PetscReal>> at24 = {{0, 64, -5, 70, 24, 64}};
  expect(BoxRefinementLevels(3, box3(64, 64), at24, 1, kMeshBuildDistributed), 3, "bound at 24 m");
  // A bound at 24.5 m lies between fine grid lines: no coarse grid holds it.
  const std::vector<std::vector<PetscReal>> at245 = {{0, 64, 0, 64, 24.5, 64}};
  expect(BoxRefinementLevels(3, box3(64, 64), at245, 1, kMeshBuildDistributed), 0, "bound at 24.5 m");
  // A region without a box (the fill region) bounds nothing.
  const std::vector<std::vector<PetscReal>> fill = {{}, {0, 64, 0, 64, 32, 64}};
  expect(BoxRefinementLevels(3, box3(64, 64), fill, 1, kMeshBuildDistributed), 5, "fill region and a bound at 32 m");
}

} // namespace

int main(int argc, char **argv) {
  checkLevels();
  return unit::runPetscTest(argc, argv, Run);
}
