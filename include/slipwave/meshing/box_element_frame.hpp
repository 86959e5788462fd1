// The geometry every box mesh of spectral elements shares, whichever way it is built (serially
// subdivided, refined on the distributed mesh, or built by each rank on the lattice): the
// element frame of the box's cells, and where a point of the lattice of GLL sub-cells sits.
//
// Element frame (mesh/spectral_layout.hpp): the lexicographic corner order that numbers an
// element's sub-cells (spectral_position) and GLL nodes. DMPlexCreateBoxMesh lays out every
// cell alike, so for a box it is one signed permutation of the lattice axes: frame axis a runs
// along lattice axis axis[a], upwards (sign +1) or downwards (-1).
//
// The lattice: p sub-cells per element and axis, the vertices at integer positions i = 0 ..
// faces p along each axis; vertex i lies in element e = min(i / p, faces - 1) at GLL node
// j = i - e p, at lower + h (e + (1 + xi_j) / 2) with h the element size (the Q1 map of a box
// element at its GLL points, as the serial subdivision places them). A function of i alone, so
// every rank places its copy of a shared vertex alike.
#pragma once
#include <petscdmplex.h>

#include "slipwave/mesh/vertex_coordinates.hpp"
#include "slipwave/meshing/mesh_options.hpp"

namespace slipwave::meshing {

struct ElementFrame {
  PetscInt dim     = 0;
  PetscInt axis[3] = {0, 1, 2};
  PetscInt sign[3] = {1, 1, 1};
  // One integer for the whole frame (to compare frames across cells and ranks), and back.
  PetscInt code() const;
  void     decode(PetscInt code);
  // The lexicographic index in its element's frame of the sub-cell at lattice position q (0 ..
  // p-1 along each lattice axis, x first): its spectral_position.
  PetscInt position(PetscInt p, const PetscInt *q) const;
};

// The frame of cell c of a box mesh (from its closure order and coordinates, as
// SpectralCellFrame reads it), as lattice directions.
PetscErrorCode BoxCellFrame(DM dm, const mesh::VertexCoordinates &coords, PetscInt c, ElementFrame *frame);

// The coordinate along axis d of lattice vertex i of `box` at degree p; gll: the p + 1 GLL
// points on [-1, 1] (numerics/gll_basis.hpp).
PetscReal BoxGllCoordinate(const BoxSpec &box, PetscInt d, PetscInt p, const double *gll, PetscInt i);

} // namespace slipwave::meshing
