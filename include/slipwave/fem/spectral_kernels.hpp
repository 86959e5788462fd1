// Spectral elements of degree p (1..kMaxSpectralDegree) on quadrilaterals and hexahedra for
// small-strain isotropic elasticity (2D: plane strain): the per-element numbers the operator
// and the stable step need. Plain doubles, no PETSc.
//
// Nodes: the (p+1)^dim GLL tensor points, lexicographic with x fastest: node (i, j, k) is
// i + n1 (j + n1 k), n1 = p + 1; reference element [-1, 1]^dim. Element vectors node-major:
// dof (node a, component c) is a * dim + c. Geometry: the isoparametric map of degree p
// through the element's own node coordinates (coords: nodes x dim, row-major); on a mesh's
// Q1 map that map is exact. Quadrature: GLL at the nodes, so the mass is diagonal.
#pragma once
#include "slipwave/physics/elastic_material.hpp"

namespace slipwave::fem {

using physics::LameParameters;

constexpr int kMaxSpectralNodes1D = 9;                       // kMaxSpectralDegree + 1
constexpr int kMaxSpectralNodes   = 9 * 9 * 9;               // hexahedron at degree 8
constexpr int kMaxSpectralDofs    = 3 * kMaxSpectralNodes;

// (p+1)^dim.
int spectralNodeCount(int dim, int p);

// Geometric factors at the nodes: wdet[q] = w_q |det J_q| (w_q the tensor GLL weight) and
// jinv[q * dim * dim + k * dim + i] = d xi_k / d x_i. Returns false when det J vanishes at a
// node or changes sign between nodes (a folded or degenerate element); either orientation
// of the whole element is fine.
bool spectralGeometry(int dim, int p, const double *coords, double *wdet, double *jinv);

// Lumped (diagonal, exact GLL) mass per node: mass[q] = rho * wdet[q]; the same for each
// component of the node.
void spectralLumpedMass(int dim, int p, const double *wdet, double rho, double *mass);

// fe = K ue by sum factorisation (fe overwritten; ue, fe node-major, dim * (p+1)^dim each).
void spectralElementForce(int dim, int p, const double *wdet, const double *jinv, const LameParameters &m, const double *ue, double *fe);
// The same with the 1D derivative matrix D of degree p given (numerics::lagrangeDerivativeMatrix
// on the GLL points), for callers that apply it every step and keep D.
void spectralElementForce(int dim, int p, const double *D, const double *wdet, const double *jinv, const LameParameters &m, const double *ue, double *fe);

// The dense element matrix K (N x N row-major, N = dim (p+1)^dim), column by column with
// the same kernel, so it is exactly the operator the force applies.
void spectralElementStiffness(int dim, int p, const double *wdet, const double *jinv, const LameParameters &m, double *K);

// rowabs[r] = sum_c |K[r][c]|: the element's share of the global Gershgorin row sums.
void spectralElementRowAbsSums(int dim, int p, const double *wdet, const double *jinv, const LameParameters &m, double *rowabs);

// Rigorous upper bounds on lambda_max(M_e^{-1} K_e), M_e = the element's lumped mass. By the
// Rayleigh quotient, u^T K u = sum_e u_e^T K_e u_e <= max_e lambda_e u^T M u, so the largest
// of these over the elements bounds lambda_max(M^{-1} K) (omega_max^2) of the assembled
// system. Kinds, from cheapest and loosest:
//   Gershgorin       max_r sum_c |K_rc| / m_r.
//   CollatzWielandt  max_r (A d)_r / d_r >= rho(A) >= lambda_max for A = M_e^{-1} |K_e| and
//                    any d > 0; d from 30 power steps on A (the smallest value seen).
//   Certified        the smallest sigma = lambda~ (1 + 0.005 3^k), k = 0..4, for which a
//                    Cholesky factorisation proves sigma I - M_e^{-1/2} K_e M_e^{-1/2}
//                    positive definite, with the shift of Rump (BIT 46, 2006) for its
//                    round-off (lambda~: a Rayleigh quotient of power steps); the
//                    Collatz-Wielandt value when none is proven. O(N^3), N = dim (p+1)^dim.
enum class EigenBoundKind { Gershgorin, CollatzWielandt, Certified };
double spectralElementEigenBound(int dim, int p, const double *wdet, const double *jinv, const LameParameters &m, double rho, EigenBoundKind kind);

// N[a] = the tensor Lagrange basis of node a at the reference point xi (dim values).
void spectralBasisValues(int dim, int p, const double *xi, double *N);

// Stress (xx, yy, zz, xy, yz, xz) at the reference point xi from the element's node
// coordinates and displacements ue (node-major). Plane strain: zz = lambda (exx + eyy),
// yz = xz = 0. Returns false when the map is singular at xi.
bool spectralStress(int dim, int p, const double *coords, const LameParameters &m, const double *ue, const double *xi, double *sigma);

} // namespace slipwave::fem
