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

namespace slipwave::fem {

constexpr int kMaxSpectralDegree = 8;

// x, w: p+1 values each. 1 <= p <= kMaxSpectralDegree (p = 1: the trapezoid rule on +-1).
void gllPointsWeights(int p, double *x, double *w);

// l[j] = l_j(xi), the Lagrange basis on the p+1 nodes x (any distinct nodes).
void lagrangeValues(int p, const double *x, double xi, double *l);

// D[i*(p+1) + j] = l_j'(x_i): the derivative at node i of the basis function of node j.
// Rows sum to zero (the derivative of a constant).
void lagrangeDerivativeMatrix(int p, const double *x, double *D);

} // namespace slipwave::fem
