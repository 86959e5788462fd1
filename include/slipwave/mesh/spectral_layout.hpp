// Spectral elements of degree p live in the mesh as p^dim linear sub-cells per element whose
// vertices are the element's GLL nodes (meshing/spectral_subdivision builds them before the
// interface split and the distribution, and partitions whole elements). Every node is then a
// DMPlex vertex: boundaries, interface pairs, output and every vertex loop work unchanged,
// and the output is the "linear sub-cells on the GLL nodes" a viewer opens. This table groups
// the sub-cells of this rank back into elements for the operators that need the element
// (stiffness, mass, stress, interpolation). At p = 1 each cell is its own element.
//
// The element frame: lexicographic corners (x fastest) of a quadrilateral (0,0) (1,0) (0,1)
// (1,1), of a hexahedron the same at z = 0 then at z = 1 (this is NOT the element kernels'
// cyclic order). The frame is right-handed (positive Jacobian at the centre), chosen from the
// cell's closure order: a sub-cell has the frame of its element, so the frame of every cell is
// recomputed from the cell alone on any rank.
#pragma once
#include <petscdmplex.h>

#include <vector>

#include "slipwave/mesh/vertex_coordinates.hpp"

namespace slipwave::mesh {

struct SpectralLayout {
  PetscInt              degree = 1, dim = 0;
  PetscInt              nelem  = 0;    // elements of this rank
  std::vector<PetscInt> element_nodes; // nelem * (p+1)^dim DM vertices, lexicographic (x fastest)
  std::vector<PetscInt> element_cells; // nelem * p^dim DM cells (the sub-cells), lexicographic
  std::vector<PetscInt> element_region; // per element: its "region" label value
  std::vector<PetscInt> element_id;    // per element: its first sub-cell (position 0), a local cell number
  std::vector<PetscInt> cell_element;  // per local DM cell (c - c_start): its element
  std::vector<PetscInt> cell_position; // per local DM cell: its lexicographic index in the element
};

// n^dim: sub-cells (n = p) or nodes (n = p + 1) of an element.
inline PetscInt SpectralCount(PetscInt n, PetscInt dim) { return dim == 2 ? n * n : n * n * n; }

// The 4 (quadrilateral) or 8 (hexahedron) vertices of a cell in the element frame above.
// Errors for other cell types (PETSC_ERR_SUP).
PetscErrorCode SpectralCellFrame(DM dm, const VertexCoordinates &coords, PetscInt cell, PetscInt *lex_vertices);

// Builds this rank's table (degree 1: from the cells). Degree > 1: from the label
// spectral_position (mesh/labels.hpp) and the topology: sub-cells (i,j,k) and (i+1,j,k) of an
// element share the face of the first one's frame at x = 1 (likewise y, z), so the sub-cells
// joined that way from position 0 are its element. Elements are listed in the order of their
// position-0 sub-cells. Quadrilaterals and hexahedra only (any degree). Not collective. Checks that every element is whole on this rank and
// that neighbouring sub-cells agree on their shared nodes.
PetscErrorCode SpectralLayoutBuild(DM dm, PetscInt degree, SpectralLayout *layout);

// The layout of the mesh's elements, built once per DM and kept on it (a composed object):
// nullptr for a mesh without the spectral labels (degree 1). The degree is read from the
// sub-cells' positions (p^dim of them per element, all on this rank).
PetscErrorCode SpectralLayoutOf(DM dm, const SpectralLayout **layout);

// Keeps `layout` on dm for SpectralLayoutOf: a mesh builder that made the elements knows them
// (meshing/box_lattice.hpp), and gives the table SpectralLayoutBuild would find.
PetscErrorCode SpectralLayoutAttach(DM dm, SpectralLayout &&layout);

} // namespace slipwave::mesh
