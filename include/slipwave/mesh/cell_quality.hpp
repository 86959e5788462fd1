// Shape of one linear cell, from its node coordinates (element_kernels.hpp's node order),
// to refuse meshes the kernels would integrate wrongly: an inverted (bow-tie) or degenerate
// cell gives a wrong or infinite stiffness, and a badly distorted one a poor answer and a
// tiny stable step. Plain doubles, no PETSc.
//
// Corner Jacobians: the Jacobian determinant of the isoparametric map at each vertex (the
// bilinear / trilinear map takes its extreme values there), divided by the reference
// corner's own scale, so a square, a cube or a right simplex gives the cell's volume (up to a
// constant). Simplices have one constant Jacobian.
#pragma once
#include "slipwave/numerics/reference_cell.hpp"

namespace slipwave::mesh {

struct CellShapeQuality {
  // min over corners of J_corner / max |J_corner|, with the sign of the largest corner taken
  // as positive (either node order is allowed): 1 for parallelograms, parallelepipeds and
  // simplices; <= 0 when the map folds (an inverted, bow-tie cell) or is singular at a corner.
  double jacobian_ratio;
  // (h_max^d / (c V))^(1/(d-1)), h_max the longest edge, V the volume, c the value for the
  // regular cell (equilateral triangle, square, regular tetrahedron, cube): 1 for those cells,
  // r for an r:1 rectangle or an r:1:1 box.
  double aspect;
  // max |J_corner| / h_max^d: ~0 (below 1e-12) for a cell of zero area or volume.
  double relative_size;
};

CellShapeQuality cellShapeQuality(numerics::CellShape s, const double *coords);

enum class CellDefect { None, Degenerate, Inverted, Distorted };

// Degenerate and inverted cells are defects whatever the thresholds; distorted means
// aspect > max_aspect or jacobian_ratio < min_jacobian_ratio.
CellDefect cellDefect(const CellShapeQuality &q, double max_aspect, double min_jacobian_ratio);

} // namespace slipwave::mesh
