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

// Where the volumetric strain tr(eps) is taken. Gauss: at each Gauss point, as the rest of the
// strain (full integration). Mean: the element's mean, (1/V) int div u (the mean-dilatation or
// B-bar element of Nagtegaal, Parks & Rice 1974 and Hughes 1980), the deviatoric strain still
// at the Gauss points: a quadrilateral or hexahedron does not lock when the deformation is
// nearly isochoric (the plastic flow of a yielding soil, a nearly incompressible solid), and
// it is the same element under a uniform strain. Simplices have one point: the two agree.
enum class Dilatation { Gauss, Mean };

// K: (n*dim)^2 row-major. Gauss quadrature (2x2, 2x2x2; one point for simplices, which is
// exact for their constant strains), the volumetric part as `dilatation` says. With Mean,
// K_mean <= K_gauss as quadratic forms (Jensen: (mean div)^2 <= mean of div^2), so a bound on
// K_gauss bounds it too.
void elementStiffness(CellShape s, const double *coords, const LameParameters &m, double *K, Dilatation dilatation = Dilatation::Gauss);

// mass[a] = rho * integral of N_a over the cell (row-sum lumping; exact quadrature).
void elementLumpedMass(CellShape s, const double *coords, double rho, double *mass);

// sigma = S u_e at the cell centroid. S: 6 x (n*dim) row-major, rows xx, yy, zz, xy, yz, xz.
// Plane strain: zz = lambda*(exx + eyy), yz = xz = 0. With Dilatation::Mean the volumetric
// part is the element's mean: kappa (mean div u) on the three normal stresses.
void elementStressOperator(CellShape s, const double *coords, const LameParameters &m, double *S, Dilatation dilatation = Dilatation::Gauss);

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
