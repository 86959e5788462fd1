// Nodal face weights of spectral elements (degree p > 1), for the boundary terms and the
// interface pairs' areas: a node of a parent face (an element side) gets the GLL quadrature
// weight of that face, w_I w_J |surface Jacobian at the node| (2D: w_I |dx/dxi|), split equally
// among the GLL sub-faces of the parent face that touch it ((I in {0,p} ? 1 : 2) per face
// direction), so that summing the sub-faces' weights per node gives exact GLL quadrature on
// the parent face. At p = 1 callers keep numerics::faceLumpedWeights (exact ∫ N_a dA).
#pragma once
#include <petscdmplex.h>

#include "slipwave/mesh/spectral_layout.hpp"
#include "slipwave/mesh/vertex_coordinates.hpp"

namespace slipwave::mesh {

// Pure. corners: the parent face's corners (2 in 2D; 4 in 3D, lexicographic: (0,0) (1,0)
// (0,1) (1,1)), dim coordinates each; (I, J) the node's GLL indices on the face (J = 0 in 2D).
// Returns the node's share of one sub-face.
double gllFaceNodeWeight(int dim, int p, const double *corners, int I, int J);

// The weights of the vertices fverts[0..nfv) of a boundary or interface sub-face of `cell`
// (a sub-cell of an element of `layout`, degree > 1).
PetscErrorCode SpectralFaceWeights(const SpectralLayout &layout, const VertexCoordinates &coords, PetscInt cell_local, PetscInt nfv, const PetscInt *fverts, double *w);

} // namespace slipwave::mesh
