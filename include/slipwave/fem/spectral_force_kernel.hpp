// The sum-factorised internal force of one spectral element (or of a batch of elements that
// share their geometric factors), f = K u, for small-strain isotropic elasticity. Header-only
// template so that the degree P and the dimension DIM are compile-time constants (the 1D
// contractions unroll) and so that the same code runs on scalars (one element) and on GCC
// vector types (one lane per element of a batch: the factors are then broadcast scalars).
//
// Work per element: reference gradients of u at every GLL node with the 1D derivative matrix
// along each direction (DIM^2 (P+1) multiply-adds per node), the physical gradient through
// J^{-1}, the stress (scaled by the node's quadrature weight w_q |det J_q|), back through
// J^{-T}, and the transposed 1D contractions. K is never formed: O(P^{DIM+1}) instead of
// O(P^{2 DIM}).
//
// Layout: u and f component-major, u[c * NQ + q] (q the lexicographic node, x fastest), so a
// 1D line of one component is strided by 1, N1 or N1^2. Factors per node q: wdet[q] =
// w_q |det J_q|, jinv[q * DIM * DIM + k * DIM + i] = d xi_k / d x_i.
#pragma once

namespace slipwave::fem {

template <int P, int DIM>
struct SpectralShape {
  static constexpr int N1 = P + 1;
  static constexpr int NQ = DIM == 2 ? N1 * N1 : N1 * N1 * N1;
};

// D: (P+1)^2 row-major, D[i * (P+1) + j] = l_j'(x_i). f is overwritten. F, the type of the
// factors, is double (one element, or a batch sharing its factors) or V (a batch of
// elements of one material, each lane with its own factors).
template <int P, int DIM, class V, class F = double>
inline void spectralForce(const double *__restrict D, const F *__restrict wdet, const F *__restrict jinv, double lambda, double mu,
                          const V *__restrict u, V *__restrict f) {
  constexpr int N1 = P + 1, NQ = SpectralShape<P, DIM>::NQ, NZ = DIM == 3 ? N1 : 1;
  constexpr int stride[3] = {1, N1, N1 * N1};
  // t[(c * DIM + k) * NQ + q]: w_q |det J_q| (sigma J^{-T})_{ck} at node q.
  V t[DIM * DIM * NQ];
  for (int i2 = 0; i2 < NZ; ++i2)
    for (int i1 = 0; i1 < N1; ++i1)
#pragma GCC unroll 9
      for (int i0 = 0; i0 < N1; ++i0) {
        const int q      = i0 + N1 * (i1 + N1 * i2);
        const int idx[3] = {i0, i1, i2};
        V         g[DIM][DIM]; // g[c][k] = d u_c / d xi_k
#pragma GCC unroll 3
        for (int c = 0; c < DIM; ++c)
#pragma GCC unroll 3
          for (int k = 0; k < DIM; ++k) {
            const V *__restrict line = u + c * NQ + q - idx[k] * stride[k];
            const double *__restrict Dr = D + idx[k] * N1;
            V s = Dr[0] * line[0];
#pragma GCC unroll 9
            for (int m = 1; m < N1; ++m) s += Dr[m] * line[m * stride[k]];
            g[c][k] = s;
          }
        const F *__restrict J = jinv + q * DIM * DIM;
        V H[DIM][DIM]; // H[c][i] = d u_c / d x_i
#pragma GCC unroll 3
        for (int c = 0; c < DIM; ++c)
#pragma GCC unroll 3
          for (int i = 0; i < DIM; ++i) {
            V s = g[c][0] * J[i];
#pragma GCC unroll 3
            for (int k = 1; k < DIM; ++k) s += g[c][k] * J[k * DIM + i];
            H[c][i] = s;
          }
        const F lw = lambda * wdet[q], mw = mu * wdet[q];
        V            div = H[0][0];
#pragma GCC unroll 3
        for (int i = 1; i < DIM; ++i) div += H[i][i];
        const V tr = lw * div;
        V       S[DIM][DIM];
#pragma GCC unroll 3
        for (int c = 0; c < DIM; ++c)
#pragma GCC unroll 3
          for (int i = c; i < DIM; ++i) {
            S[c][i] = mw * (H[c][i] + H[i][c]);
            if (i == c) S[c][i] += tr;
            else S[i][c] = S[c][i];
          }
#pragma GCC unroll 3
        for (int c = 0; c < DIM; ++c)
#pragma GCC unroll 3
          for (int k = 0; k < DIM; ++k) {
            V s = S[c][0] * J[k * DIM];
#pragma GCC unroll 3
            for (int i = 1; i < DIM; ++i) s += S[c][i] * J[k * DIM + i];
            t[(c * DIM + k) * NQ + q] = s;
          }
      }
  // f_c(n) = sum_k sum_a D[a][n_k] t_ck(node n with its k-th index replaced by a).
  for (int i2 = 0; i2 < NZ; ++i2)
    for (int i1 = 0; i1 < N1; ++i1)
#pragma GCC unroll 9
      for (int i0 = 0; i0 < N1; ++i0) {
        const int n      = i0 + N1 * (i1 + N1 * i2);
        const int idx[3] = {i0, i1, i2};
#pragma GCC unroll 3
        for (int c = 0; c < DIM; ++c) {
          V s = D[idx[0]] * t[(c * DIM) * NQ + n - idx[0]];
#pragma GCC unroll 9
          for (int a = 1; a < N1; ++a) s += D[a * N1 + idx[0]] * t[(c * DIM) * NQ + n - idx[0] + a];
#pragma GCC unroll 3
          for (int k = 1; k < DIM; ++k) {
            const V *__restrict line = t + (c * DIM + k) * NQ + n - idx[k] * stride[k];
#pragma GCC unroll 9
            for (int a = 0; a < N1; ++a) s += D[a * N1 + idx[k]] * line[a * stride[k]];
          }
          f[c * NQ + n] = s;
        }
      }
}

} // namespace slipwave::fem
