// The reference cells of the linear elements (Tri3, Quad4, Tet4, Hex8) and their faces: shape
// functions and gradients, the Jacobian of the map, the inverse map of a physical point, and
// the lumped weights and normals of boundary faces. Pure geometry, shared by the mesh (cell
// quality, interface face weights) and the element kernels (fem/element_kernels.hpp). Plain
// doubles only, no PETSc and no allocation.
//
// Arrays: coords  nodes x dim, row-major: x of node a is coords[a*dim + 0]. 2D is plane strain.
//
// Node order the caller guarantees:
//   Tri3, Tet4  the vertices in any order (negative orientation is fine: |det J| is used).
//   Quad4       the 4 vertices cyclically around the cell, counter-clockwise or clockwise.
//   Hex8        nodes 0-3 one face in cyclic order (either sense), nodes 4-7 the opposite
//               face with node 4 joined by an edge to node 0, 5 to 1, 6 to 2, 7 to 3.
//
// Reference cells (what shapeFunctions and referenceCoordinates use):
//   Tri3   (0,0) (1,0) (0,1)                     Tet4  (0,0,0) (1,0,0) (0,1,0) (0,0,1)
//   Quad4  (-1,-1) (1,-1) (1,1) (-1,1)           Hex8  Quad4 nodes at zeta = -1, then at +1
#pragma once

namespace slipwave::numerics {

enum class CellShape { Tri3, Quad4, Tet4, Hex8 };
enum class FaceShape { Seg2, Tri3, Quad4 };  // 2D boundary faces: Seg2; 3D: Tri3 / Quad4

constexpr int kMaxCellNodes = 8;
constexpr int kMaxFaceNodes = 4;
constexpr int kMaxCellDim = 3;
int cellNodeCount(CellShape s);
int cellDimension(CellShape s);
int faceNodeCount(FaceShape f);

// dN[a][j] = dN_a/dxi_j at reference point xi.
void referenceGradients(CellShape s, const double *xi, double (*dN)[kMaxCellDim]);
// J[i][j] = d x_i / d xi_j of the n nodes' map (dN: referenceGradients).
void jacobian(int n, int dim, const double *coords, const double (*dN)[kMaxCellDim], double J[kMaxCellDim][kMaxCellDim]);
// Returns det J and writes its inverse (left untouched when det J == 0).
double invertJacobian(int dim, const double J[kMaxCellDim][kMaxCellDim], double Jinv[kMaxCellDim][kMaxCellDim]);

// N at reference point xi (length cellDimension(s)).
void shapeFunctions(CellShape s, const double *xi, double *N);

// Reference coordinates xi of the physical point x (Newton; one step is exact for
// simplices). Returns false if x lies outside the reference cell by more than tol in
// reference coordinates, or if the map cannot be inverted there (degenerate cell, no
// convergence); xi is then unspecified.
bool referenceCoordinates(CellShape s, const double *coords, const double *x, double *xi, double tol = 1e-8);

// coords: faceNodeCount(f) x dim; dim must be 2 for Seg2 and 3 for Tri3 / Quad4.
// w[a] = integral of N_a over the face (their sum is the face length / area).
void faceLumpedWeights(FaceShape f, int dim, const double *coords, double *w);
// M[a * n + b] = integral of N_a N_b over the face (n = faceNodeCount(f); exact, the Quad4 by
// 2 x 2 Gauss points): the face integral of a nodal field interpolated on the face.
void faceConsistentMass(FaceShape f, int dim, const double *coords, double *M);

// Unit normal. Seg2 from p0 to p1: (dy, -dx)/L, the right-hand side of the direction of
// travel. Tri3 / Quad4: right-hand rule of the node order (Quad4: the normal of the area
// vector, exact for non-planar faces too). The caller flips it to point outward.
void faceNormal(FaceShape f, int dim, const double *coords, double *n);

constexpr int kMaxRulePoints = 8;

// Shape functions and their reference gradients, tabulated once per shape at the Gauss
// points and the centroid so the per-cell loops only do the geometry.
struct ReferenceRule {
  int nodes = 0;
  int dim = 0;
  int points = 0;
  double weight[kMaxRulePoints] = {};
  double N[kMaxRulePoints][kMaxCellNodes] = {};
  double dN[kMaxRulePoints][kMaxCellNodes][kMaxCellDim] = {};
  double centroid_dN[kMaxCellNodes][kMaxCellDim] = {};
};

// The rule of shape s: full Gauss quadrature (2x2, 2x2x2; one point for simplices, which is
// exact for their constant strains), built once.
const ReferenceRule &referenceRule(CellShape s);
// Area (2D) or volume (3D) of the cell: |det J| integrated by its rule (exact for the
// bilinear and trilinear maps).
double cellVolume(CellShape s, const double *coords);

} // namespace slipwave::numerics
