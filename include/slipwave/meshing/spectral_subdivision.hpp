// Spectral elements of degree p > 1 as GLL sub-cells (see spectral_layout.hpp): on the
// serial, interpolated, labelled mesh (before the interface split, so the split duplicates
// every GLL node of an interface face, and before the distribution), each quadrilateral or
// hexahedron is replaced by p^dim linear sub-cells whose vertices are the GLL nodes mapped by
// the cell's Q1 map. Cells that share an edge or a face share its nodes: a node is known by
// the parent point it lies in (vertex, edge, face, cell) and its GLL indices in a frame of
// that point that does not depend on the cell (from its vertex numbers).
//
// Numbering: the sub-cells of parent cell c are cells c p^dim .. c p^dim + p^dim - 1, in
// lexicographic order of the parent's element frame (spectral_layout.hpp); vertices are
// numbered in order of first appearance, cell by cell.
// Labels on the result: "region" (the parent's), every boundary label in `boundaries` on the
// sub-faces of the labelled faces (same values), and spectral_position (the lexicographic
// index in the element, labels.hpp) on every sub-cell.
#pragma once
#include <petscdmplex.h>

#include <string>
#include <vector>

namespace slipwave::meshing {

// Collective; all cells on rank 0 (the serial mesh); quadrilaterals or hexahedra only.
PetscErrorCode SpectralSubdivideSerialMesh(DM serial, PetscInt degree, const std::vector<std::string> &boundaries, DM *fine);

// Partitions whole elements: `parent` (the serial mesh before subdivision) is partitioned by
// the configured PetscPartitioner `part`, and `fine` (the subdivided, possibly split, serial
// mesh, whose cell c p^dim + s belongs to parent cell c) gets a shell partitioner that sends
// every sub-cell to its parent's rank. Collective.
PetscErrorCode SpectralPartitionWholeElements(DM parent, PetscPartitioner part, PetscInt degree, DM fine);

} // namespace slipwave::meshing
