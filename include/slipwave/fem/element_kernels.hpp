// Isoparametric linear elements for small-strain isotropic elasticity: the per-cell
// numbers the assembly needs (stiffness, lumped mass, centroid stress operator, stable-step
// bound, Biot coupling and diffusion). The reference cells, shape functions and face
// weights are numerics/reference_cell.hpp. Plain doubles only, no PETSc and no allocation:
// these run in setup loops over millions of cells.
//
// Arrays:
//   coords  nodes x dim, row-major: x of node a is coords[a*dim + 0].
//   dof     index of node a, component i is a*dim + i.
//   2D is plane strain.
//
// Node order and reference cells: numerics/reference_cell.hpp.
#pragma once
#include "slipwave/numerics/reference_cell.hpp"
#include "slipwave/physics/elastic_material.hpp"

namespace slipwave::fem {

// The material enters the kernels as its Lame pair, which the physics layer owns.
using physics::LameParameters;
// The kernels integrate over the reference cells of numerics/reference_cell.hpp.
using numerics::CellShape;
using numerics::cellDimension;
using numerics::cellNodeCount;
using numerics::FaceShape;
using numerics::kMaxCellNodes;

constexpr int kMaxCellDofs = 24;
constexpr int kStressComponents = 6;  // xx, yy, zz, xy, yz, xz

// K: (n*dim)^2 row-major. Full Gauss quadrature (2x2, 2x2x2; one point for simplices,
// which is exact for their constant strains).
void elementStiffness(CellShape s, const double *coords, const LameParameters &m, double *K);

// mass[a] = rho * integral of N_a over the cell (row-sum lumping; exact quadrature).
void elementLumpedMass(CellShape s, const double *coords, double rho, double *mass);

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

} // namespace slipwave::fem
