// Isoparametric linear elements for small-strain isotropic elasticity: the per-cell
// numbers the assembly needs (stiffness, lumped mass, centroid stress operator, stable-step
// bound) and the per-face numbers of the absorbing boundary. Plain doubles only, no PETSc
// and no allocation: these run in setup loops over millions of cells.
//
// Arrays:
//   coords  nodes x dim, row-major: x of node a is coords[a*dim + 0].
//   dof     index of node a, component i is a*dim + i.
//   2D is plane strain.
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
#include "slipwave/physics/elastic_material.hpp"

namespace slipwave::fem {

// The material enters the kernels as its Lame pair, which the physics layer owns.
using physics::LameParameters;

enum class CellShape { Tri3, Quad4, Tet4, Hex8 };
enum class FaceShape { Seg2, Tri3, Quad4 };  // 2D boundary faces: Seg2; 3D: Tri3 / Quad4

constexpr int kMaxCellNodes = 8;
constexpr int kMaxFaceNodes = 4;
constexpr int kMaxCellDofs = 24;
constexpr int kStressComponents = 6;  // xx, yy, zz, xy, yz, xz

int cellNodeCount(CellShape s);
int cellDimension(CellShape s);
int faceNodeCount(FaceShape f);

// K: (n*dim)^2 row-major. Full Gauss quadrature (2x2, 2x2x2; one point for simplices,
// which is exact for their constant strains).
void elementStiffness(CellShape s, const double *coords, const LameParameters &m, double *K);

// mass[a] = rho * integral of N_a over the cell (row-sum lumping; exact quadrature).
void elementLumpedMass(CellShape s, const double *coords, double rho, double *mass);

double elementVolume(CellShape s, const double *coords);

// sigma = S u_e at the cell centroid. S: 6 x (n*dim) row-major, rows xx, yy, zz, xy, yz, xz.
// Plane strain: zz = lambda*(exx + eyy), yz = xz = 0.
void elementStressOperator(CellShape s, const double *coords, const LameParameters &m, double *S);

// Biot u-p coupling (docs/saturated-soil.md): Q[a][b*dim+j] = integral of N_a dN_b/dx_j, so
// (Q u_e)_a is the nodal weight of div u and Q^T p_e the nodal force of a pore pressure p
// (the force on the skeleton is +alpha Q^T p). Q: n x (n*dim) row-major. Same Gauss rules as
// the stiffness (exact on parallelogram cells and simplices).
void elementCoupling(CellShape s, const double *coords, double *Q);
// Darcy diffusion H[a][b] = integral of grad N_a . grad N_b (times the mobility kappa of the
// region where the caller applies it). H: n x n row-major.
void elementDiffusion(CellShape s, const double *coords, double *H);

// rowabs[r] = sum_c |K[r][c]|: Gershgorin bound on the element's largest eigenvalue.
void elementStiffnessRowAbsSum(CellShape s, const double *coords, const LameParameters &m, double *rowabs);

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

// Unit normal. Seg2 from p0 to p1: (dy, -dx)/L, the right-hand side of the direction of
// travel. Tri3 / Quad4: right-hand rule of the node order (Quad4: the normal of the area
// vector, exact for non-planar faces too). The caller flips it to point outward.
void faceNormal(FaceShape f, int dim, const double *coords, double *n);

} // namespace slipwave::fem
