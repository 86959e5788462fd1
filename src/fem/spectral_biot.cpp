#include "slipwave/fem/spectral_biot.hpp"

#include <vector>

#include "slipwave/fem/spectral_force_kernel.hpp"
#include "slipwave/fem/spectral_kernels.hpp"
#include "slipwave/numerics/gll_basis.hpp"

namespace slipwave::fem {
namespace {

// The 1D lines through node q: along direction k its nodes are q + (m - idx[k]) stride[k].
template <int P, int DIM>
struct Lines {
  static constexpr int N1 = P + 1, NQ = SpectralShape<P, DIM>::NQ, NZ = DIM == 3 ? N1 : 1;
  static constexpr int stride[3] = {1, N1, N1 * N1};
  // d f / d xi_k at node q of a nodal field f with `step` values between nodes.
  static double derivative(const double *D, const double *f, int step, int q, const int *idx, int k) {
    const double *line = f + (q - idx[k] * stride[k]) * step;
    const double *Dr   = D + idx[k] * N1;
    double        s    = 0;
#pragma GCC unroll 9
    for (int m = 0; m < N1; ++m) s += Dr[m] * line[m * stride[k] * step];
    return s;
  }
  // The transpose: adds r times d N_b / d xi_k (x_q) to out at every node b of q's line.
  static void addDerivativeTranspose(const double *D, double r, int q, const int *idx, int k, double *out, int step) {
    double       *line = out + (q - idx[k] * stride[k]) * step;
    const double *Dr   = D + idx[k] * N1;
#pragma GCC unroll 9
    for (int m = 0; m < N1; ++m) line[m * stride[k] * step] += Dr[m] * r;
  }
};

template <int P, int DIM>
void divergence(const double *D, const double *w, const double *jinv, const double *ue, double *out) {
  using L = Lines<P, DIM>;
  for (int i2 = 0; i2 < L::NZ; ++i2)
    for (int i1 = 0; i1 < L::N1; ++i1)
      for (int i0 = 0; i0 < L::N1; ++i0) {
        const int     q = i0 + L::N1 * (i1 + L::N1 * i2), idx[3] = {i0, i1, i2};
        const double *J = jinv + q * DIM * DIM;
        double        div = 0;
        for (int i = 0; i < DIM; ++i)
          for (int k = 0; k < DIM; ++k) div += J[k * DIM + i] * L::derivative(D, ue + i, DIM, q, idx, k);
        out[q] = w[q] * div;
      }
}

template <int P, int DIM>
void divergenceTranspose(const double *D, const double *w, const double *jinv, const double *pe, double *fe) {
  using L = Lines<P, DIM>;
  for (int r = 0; r < DIM * L::NQ; ++r) fe[r] = 0;
  for (int i2 = 0; i2 < L::NZ; ++i2)
    for (int i1 = 0; i1 < L::N1; ++i1)
      for (int i0 = 0; i0 < L::N1; ++i0) {
        const int     q = i0 + L::N1 * (i1 + L::N1 * i2), idx[3] = {i0, i1, i2};
        const double *J = jinv + q * DIM * DIM;
        const double  s = w[q] * pe[q];
        for (int j = 0; j < DIM; ++j)
          for (int k = 0; k < DIM; ++k) L::addDerivativeTranspose(D, J[k * DIM + j] * s, q, idx, k, fe + j, DIM);
      }
}

template <int P, int DIM>
void diffusion(const double *D, const double *w, const double *jinv, const double *pe, double *he) {
  using L = Lines<P, DIM>;
  for (int r = 0; r < L::NQ; ++r) he[r] = 0;
  for (int i2 = 0; i2 < L::NZ; ++i2)
    for (int i1 = 0; i1 < L::N1; ++i1)
      for (int i0 = 0; i0 < L::N1; ++i0) {
        const int     q = i0 + L::N1 * (i1 + L::N1 * i2), idx[3] = {i0, i1, i2};
        const double *J = jinv + q * DIM * DIM;
        double        g[DIM], flux[DIM]; // d p / d xi_k; w grad p
        for (int k = 0; k < DIM; ++k) g[k] = L::derivative(D, pe, 1, q, idx, k);
        for (int i = 0; i < DIM; ++i) {
          double s = 0;
          for (int k = 0; k < DIM; ++k) s += J[k * DIM + i] * g[k];
          flux[i] = w[q] * s;
        }
        for (int k = 0; k < DIM; ++k) {
          double r = 0;
          for (int i = 0; i < DIM; ++i) r += J[k * DIM + i] * flux[i];
          L::addDerivativeTranspose(D, r, q, idx, k, he, 1);
        }
      }
}

struct Kernels {
  void (*divergence)(const double *, const double *, const double *, const double *, double *);
  void (*divergenceTranspose)(const double *, const double *, const double *, const double *, double *);
  void (*diffusion)(const double *, const double *, const double *, const double *, double *);
};

template <int P, int DIM>
constexpr Kernels kernelsOf() {
  return {divergence<P, DIM>, divergenceTranspose<P, DIM>, diffusion<P, DIM>};
}

template <int DIM>
Kernels kernelsOfDegree(int p) {
  switch (p) {
  case 1: return kernelsOf<1, DIM>();
  case 2: return kernelsOf<2, DIM>();
  case 3: return kernelsOf<3, DIM>();
  case 4: return kernelsOf<4, DIM>();
  case 5: return kernelsOf<5, DIM>();
  case 6: return kernelsOf<6, DIM>();
  case 7: return kernelsOf<7, DIM>();
  default: return kernelsOf<8, DIM>();
  }
}

Kernels kernels(int dim, int p) { return dim == 2 ? kernelsOfDegree<2>(p) : kernelsOfDegree<3>(p); }

// The 1D derivative matrix of degree p on its GLL points.
std::vector<double> derivativeMatrix(int p) {
  double              x[kMaxSpectralNodes1D], w[kMaxSpectralNodes1D];
  std::vector<double> D((size_t)(p + 1) * (p + 1));
  numerics::gllPointsWeights(p, x, w);
  numerics::lagrangeDerivativeMatrix(p, x, D.data());
  return D;
}

} // namespace

void spectralDivergence(int dim, int p, const double *D, const double *w, const double *jinv, const double *ue, double *out) {
  kernels(dim, p).divergence(D, w, jinv, ue, out);
}

void spectralDivergenceTranspose(int dim, int p, const double *D, const double *w, const double *jinv, const double *pe, double *fe) {
  kernels(dim, p).divergenceTranspose(D, w, jinv, pe, fe);
}

void spectralDiffusion(int dim, int p, const double *D, const double *w, const double *jinv, const double *pe, double *he) {
  kernels(dim, p).diffusion(D, w, jinv, pe, he);
}

void spectralCouplingMatrix(int dim, int p, const double *w, const double *jinv, double *Q) {
  const std::vector<double> D  = derivativeMatrix(p);
  const int                 nq = spectralNodeCount(dim, p), n = dim * nq;
  std::vector<double>       e(n, 0.0), col(nq);
  for (int c = 0; c < n; ++c) {
    e[c] = 1;
    spectralDivergence(dim, p, D.data(), w, jinv, e.data(), col.data());
    e[c] = 0;
    for (int a = 0; a < nq; ++a) Q[a * n + c] = col[a];
  }
}

void spectralDiffusionMatrix(int dim, int p, const double *w, const double *jinv, double *H) {
  const std::vector<double> D  = derivativeMatrix(p);
  const int                 nq = spectralNodeCount(dim, p);
  std::vector<double>       e(nq, 0.0), col(nq);
  for (int b = 0; b < nq; ++b) {
    e[b] = 1;
    spectralDiffusion(dim, p, D.data(), w, jinv, e.data(), col.data());
    e[b] = 0;
    for (int a = 0; a < nq; ++a) H[a * nq + b] = col[a];
  }
}

} // namespace slipwave::fem
