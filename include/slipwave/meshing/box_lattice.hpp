// Box meshes without interfaces built distributed at any element degree (issue 25 parts 5 and
// 7): every rank builds its own cells, directly, as a part of the box's lattice of GLL
// sub-cells (box_element_frame.hpp; at degree 1 the sub-cells are the cells), with nothing
// refined, subdivided or sent but the coarse cells it gets and its shared points' owners.
//
// Rank 0 holds the coarse box (2^levels elements per axis in a coarse cell, levels from
// BoxRefinementLevels: the box of elements itself at levels 0), labelled and with its void
// cells removed, and partitions it with the mesh's partitioner (METIS by default); each rank
// receives its coarse cells (lattice index and region) and the map of the present ones. Its
// cells are the sub-cells of its coarse cells: coarse cell by coarse cell (lattice order),
// element by element in each, sub-cell by sub-cell in each element. Its points are the lattice
// entities in their closure, numbered by depth stratum (cells, vertices, faces, edges: DMPlex's
// order) and along each stratum in lattice order; cones and orientations repeat those of the
// one cell of a one-cell DMPlexCreateBoxMesh (read off it, not written down here), which every
// box cell shares. Points on a part's surface are matched by their lattice position across
// the ranks (PetscSFCreateByMatchingIndices: the highest rank owns a shared point).
//
// The result has what a serially built and distributed box has (mesh_builder.hpp): region on
// every cell, the box sides on their faces, spectral_position on every sub-cell (p > 1), the
// vertices at the GLL nodes, and serial_cell, the number each cell has in the serial build (the
// box's elements in lattice order less the void ones, e p^dim + position). A sub-cell has the
// corner order, so the element frame, of every box cell. Results therefore agree with the
// serial build's to the order of floating-point sums, on any number of ranks.
#pragma once
#include <petscdmplex.h>

#include <string>
#include <vector>

#include "slipwave/meshing/mesh_options.hpp"

namespace slipwave::meshing {

// Collective. coarse: rank 0 holds the labelled coarse box (other ranks: no cells); part: the
// partitioner of the coarse cells (unused on one rank); sides: the names of the box sides'
// labels, left, right(, front, back), bottom, top. *dm: the new mesh; serial_cell per local cell.
PetscErrorCode BoxLatticeBuild(DM coarse, PetscPartitioner part, PetscInt levels, PetscInt degree, const BoxSpec &box, const std::vector<std::string> &sides, DM *dm,
                               std::vector<PetscInt> *serial_cell);

} // namespace slipwave::meshing
