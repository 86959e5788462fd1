// Spectral elements of degree p live in the mesh as p^dim linear sub-cells per element whose
// vertices are the element's GLL nodes (mesh/spectral_subdivision builds them before the
// interface split and the distribution, and partitions whole elements). Every node is then a
// DMPlex vertex: boundaries, interface pairs, output and every vertex loop work unchanged,
// and the output is the "linear sub-cells on the GLL nodes" a viewer opens. This table groups
// the sub-cells of this rank back into elements for the operators that need the element
// (stiffness, mass, stress, interpolation). At p = 1 each cell is its own element.
#pragma once
#include <petscdmplex.h>

#include <vector>

namespace slipwave::mesh {

struct SpectralLayout {
  PetscInt              degree = 1, dim = 0;
  PetscInt              nelem  = 0;    // elements of this rank
  std::vector<PetscInt> element_nodes; // nelem * (p+1)^dim DM vertices, lexicographic (x fastest)
  std::vector<PetscInt> element_cells; // nelem * p^dim DM cells (the sub-cells), lexicographic
  std::vector<PetscInt> element_region; // per element: its "region" label value
  std::vector<PetscInt> cell_element;  // per local DM cell (c - c_start): its element
  std::vector<PetscInt> cell_position; // per local DM cell: its lexicographic index in the element
};

} // namespace slipwave::mesh
