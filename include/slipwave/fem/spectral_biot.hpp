// Biot u-p element operators of a spectral element of degree p (docs/saturated-soil.md, "At
// element degree p > 1"): the coupling Q, the Darcy matrix H and the storage, with the
// pressure at the element's GLL nodes (equal order, as Q1/Q1 at p = 1) and GLL quadrature at
// those nodes. Plain doubles, no PETSc.
//
// Collocation makes the coupling a nodal divergence,
//   (Q u)_a = integral of N_a div u = w_a |J_a| div u(x_a),
// and its transpose the nodal force of a pressure, (Q^T p)_(b,j) = sum_a w_a |J_a| p_a
// dN_b/dx_j(x_a); the storage integral of N_a / M is w_a |J_a| / M exactly (diagonal without
// lumping); H_ab = sum_q w_q |J_q| grad N_a(x_q) . grad N_b(x_q). All three are applied by
// sum factorisation (the 1D derivative matrix along each direction, O(p^(dim+1)) per element,
// as the elastic force of fem/spectral_force_kernel.hpp), from the geometric factors of
// spectralGeometry; no element matrix is stored.
//
// Because Q_e^T diag(w |J| / M)^{-1} Q_e = M sum_q w_q |J_q| div N div N^T, the undrained
// stiffening of one element is exactly the spectral elastic element with lambda = alpha^2 M
// and mu = 0 (so its eigenvalue bound is spectralElementEigenBound's).
//
// Layout as fem/spectral_kernels.hpp: nodes lexicographic (x fastest), element vectors of
// displacement node-major (dof (a, j) = a * dim + j). w: per node the quadrature weight times
// |det J| times the caller's coefficient (alpha for Q, the mobility kappa for H); jinv:
// jinv[q * dim * dim + k * dim + i] = d xi_k / d x_i; D: the 1D derivative matrix on the GLL
// points (numerics::lagrangeDerivativeMatrix), kept by callers that apply it every step.
#pragma once

namespace slipwave::fem {

// out[a] = w[a] div u(x_a): Q u for one element (out overwritten, (p+1)^dim values).
void spectralDivergence(int dim, int p, const double *D, const double *w, const double *jinv, const double *ue, double *out);
// fe = Q^T pe: fe[b * dim + j] = sum_a w[a] pe[a] dN_b/dx_j(x_a) (overwritten).
void spectralDivergenceTranspose(int dim, int p, const double *D, const double *w, const double *jinv, const double *pe, double *fe);
// he = H pe: he[b] = sum_q w[q] grad N_b(x_q) . grad p(x_q) (overwritten).
void spectralDiffusion(int dim, int p, const double *D, const double *w, const double *jinv, const double *pe, double *he);

// The dense matrices the three products apply, column by column through the same kernels:
// Q: (p+1)^dim rows of dim (p+1)^dim, row-major (Q[a][b * dim + j]); H: (p+1)^dim squared.
void spectralCouplingMatrix(int dim, int p, const double *w, const double *jinv, double *Q);
void spectralDiffusionMatrix(int dim, int p, const double *w, const double *jinv, double *H);

} // namespace slipwave::fem
