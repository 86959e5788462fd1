// The one-dimensional ingredients of spectral elements of degree p: the p+1 Gauss-Lobatto-
// Legendre (GLL) points on [-1, 1], their quadrature weights, the Lagrange basis on those
// points and its derivative matrix. Tensor products of these give the quadrilateral and
// hexahedral spectral elements; collocating the nodes with the quadrature points makes the
// mass matrix diagonal and positive (the whole point of GLL). Plain doubles, no PETSc.
//
// GLL points: x_0 = -1, x_p = +1 and the p-1 roots of P'_p (P_p the Legendre polynomial);
// weights w_i = 2 / (p (p+1) P_p(x_i)^2). The rule integrates polynomials of degree 2p-1
// exactly. The points are ascending and exactly antisymmetric (x_{p-i} = -x_i), so mapping
// index i to p-i mirrors the element.
#pragma once

namespace slipwave::numerics {

constexpr int kMaxSpectralDegree = 8;

// x, w: p+1 values each. 1 <= p <= kMaxSpectralDegree (p = 1: the trapezoid rule on +-1).
void gllPointsWeights(int p, double *x, double *w);

// l[j] = l_j(xi), the Lagrange basis on the p+1 nodes x (any distinct nodes).
void lagrangeValues(int p, const double *x, double xi, double *l);

// D[i*(p+1) + j] = l_j'(x_i): the derivative at node i of the basis function of node j.
// Rows sum to zero (the derivative of a constant).
void lagrangeDerivativeMatrix(int p, const double *x, double *D);

// The stiffness of an end node of a 1D degree-p GLL element of length h and modulus M is
// K_00 = (M/h) 2 int_{-1}^{1} l_0'(xi)^2 dxi; this returns that factor, (p^2 + p + 1)/3
// (1 at p = 1: M/h). Integrating by parts, int l_0'^2 = -l_0'(-1) - int l_0 l_0'' with
// l_0'(-1) = -p(p+1)/4, and the GLL rule (exact for the degree 2p - 2 integrand) leaves
// only the node -1 in the last integral. What a face node of a spectral element sees in the
// normal direction per unit face area (its tributary area cancels).
double gllEndNodeStiffness(int p);

} // namespace slipwave::numerics
