// Box meshes with interfaces built distributed (issue 11, parallel set-up; a box without
// interfaces is built by parts, box_lattice.hpp): the requested box with 2^levels
// fewer cells per axis is built, labelled, split and partitioned serially as before (a small
// mesh), then refined `levels` times by DMPlex's regular refinement on the distributed mesh,
// so no rank ever holds the whole fine mesh and the fine partition follows METIS' coarse one.
// The result has the labels of a serially built box (mesh_builder.hpp, interface_split.hpp):
// the same region of every cell, the same boundary faces, the same node pairs with the same
// pair ids (ids follow the serial box's vertex order, x fastest), so results agree with a
// serially built mesh to round-off. Only the local point numbers differ.
//
// When is this exact? Refinement keeps a coarse cell's region for its children, so every
// region and void box bound inside the mesh must lie on a coarse grid line
// (BoxRefinementLevels), and the coarse split must refine into the fine one
// (InterfacesRefinable, mesh_refinement.hpp, which also holds the refinement and the label
// repair the box shares with refined Gmsh meshes).
//
// Spectral elements of degree p = 2, 4, 8 (-element_degree): log2(p) more refinements make
// each element's p^dim GLL sub-cells (2^levels coarse cells per element and axis before),
// whole on one rank by construction; the vertices are then moved to the GLL nodes. Every
// sub-cell has the spectral_position, serial_cell (e p^dim + position) and element frame (from
// its cone: refinement keeps the parent's, spectral_layout.hpp), and the interface pairs have
// the ids, of the serial build, which subdivides the whole box on rank 0
// (spectral_subdivision.hpp). Other degrees are no powers of 2: with interfaces they are built
// serially.
#pragma once
#include <petscdmplex.h>

#include <string>
#include <vector>

#include "slipwave/meshing/interface_split.hpp"
#include "slipwave/meshing/mesh_options.hpp"

namespace slipwave::meshing {

// -mesh_build: auto (distributed where the box allows it and is big enough to pay), serial
// (the whole mesh built on rank 0, then distributed), distributed (refuse a box that cannot).
enum MeshBuild : PetscInt { kMeshBuildAuto = 0, kMeshBuildSerial = 1, kMeshBuildDistributed = 2 };
extern const char *const kMeshBuildNames[3];

// auto refines only while the coarse box keeps this many cells per rank: METIS then balances
// the coarse cells to within about 1/kCoarseCellsPerRank, and the fine partition inherits it.
inline constexpr double kCoarseCellsPerRank = 1000;

// Number of refinements for a box (0: build it serially). The largest k such that 2^k divides
// every face count and every bound of region_boxes (regions and voids) strictly inside the box
// lies on a line of the coarse grid (to 1e-9 of the cell size), and the coarse box holds at
// least kCoarseCellsPerRank cells per rank (auto) or one cell per rank (distributed). Pure.
PetscInt BoxRefinementLevels(PetscInt dim, const BoxSpec &box, const std::vector<std::vector<PetscReal>> &region_boxes, PetscMPIInt nranks, PetscInt build);

// Degree p of spectral elements built by refinement: log2(p) refinements into the GLL
// sub-cells for p = 2, 4, 8 (0 at p = 1); -1 for a degree that cannot be.
PetscInt BoxSpectralRefinements(PetscInt degree);

// Refines the distributed coarse box `levels` times in place (at degree p > 1 the last
// BoxSpectralRefinements(p) of them make the GLL sub-cells of `box`'s elements) and puts back
// the labels of the serial build: region on cells, boundaries and interface_<name> on faces
// only (refinement spreads a label to every child point), interface_<name>_pair/_side on every
// split vertex, spectral_position at p > 1. serial_cell receives the number each local cell
// has in the serially built box.
PetscErrorCode BoxRefineDistributed(DM *dm, PetscInt levels, PetscInt degree, const BoxSpec &box, const std::vector<std::string> &regions,
                                    const std::vector<std::string> &boundaries, const std::vector<InterfaceSpec> &specs, std::vector<PetscInt> *serial_cell);

} // namespace slipwave::meshing
