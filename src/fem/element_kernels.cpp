#include "slipwave/fem/element_kernels.hpp"

#include <cmath>

#include "slipwave/numerics/reference_cell.hpp"

namespace slipwave::fem {
namespace {

using numerics::invertJacobian;
using numerics::jacobian;
using numerics::kMaxCellDim;
using numerics::ReferenceRule;
using numerics::referenceRule;

// Physical gradients dNdx[a][i] = dN_a/dx_i; returns |det J|.
double physicalGradients(const ReferenceRule &r, const double *coords, const double (*dN)[kMaxCellDim],
                         double (*dNdx)[kMaxCellDim]) {
  double J[kMaxCellDim][kMaxCellDim], Jinv[kMaxCellDim][kMaxCellDim];
  jacobian(r.nodes, r.dim, coords, dN, J);
  const double det = invertJacobian(r.dim, J, Jinv);
  for (int a = 0; a < r.nodes; ++a)
    for (int i = 0; i < r.dim; ++i) {
      double v = 0;
      for (int j = 0; j < r.dim; ++j) v += dN[a][j] * Jinv[j][i];
      dNdx[a][i] = v;
    }
  return std::fabs(det);
}

// The element's mean divergence weights: div_mean[a*dim + i] = (1/V) int dN_a/dx_i, so that
// (1/V) int div u = div_mean . u_e; returns V.
double meanDivergence(const ReferenceRule &r, const double *coords, double *div_mean) {
  double dNdx[kMaxCellNodes][kMaxCellDim], volume = 0;
  for (int k = 0; k < r.nodes * r.dim; ++k) div_mean[k] = 0;
  for (int q = 0; q < r.points; ++q) {
    const double dv = r.weight[q] * physicalGradients(r, coords, r.dN[q], dNdx);
    volume += dv;
    for (int a = 0; a < r.nodes; ++a)
      for (int i = 0; i < r.dim; ++i) div_mean[a * r.dim + i] += dv * dNdx[a][i];
  }
  for (int k = 0; k < r.nodes * r.dim; ++k) div_mean[k] /= volume;
  return volume;
}

// kappa = lambda + 2 mu / 3, the bulk modulus: the energy density is kappa tr(eps)^2 / 2 +
// mu dev(eps):dev(eps), in plane strain too (the 3D tensor with eps_zz = 0).
double bulkModulus(const LameParameters &m) { return m.lambda + 2.0 / 3.0 * m.mu; }

} // namespace

void elementStiffness(CellShape s, const double *coords, const LameParameters &m, double *K, Dilatation dilatation) {
  const ReferenceRule &r = referenceRule(s);
  const int n = r.nodes, dim = r.dim, nd = n * dim;
  const bool mean = dilatation == Dilatation::Mean;
  // With the mean dilatation the Gauss points carry lambda - kappa = -2 mu / 3 on div u div u
  // (the deviatoric part) and kappa V div_mean div_mean is added once.
  const double lambda = mean ? m.lambda - bulkModulus(m) : m.lambda;
  for (int k = 0; k < nd * nd; ++k) K[k] = 0;
  double dNdx[kMaxCellNodes][kMaxCellDim];
  for (int q = 0; q < r.points; ++q) {
    const double dv = r.weight[q] * physicalGradients(r, coords, r.dN[q], dNdx);
    // K[ai][bj] = int lambda dNa_i dNb_j + mu (dNa_j dNb_i + delta_ij grad Na . grad Nb),
    // the isotropic form of B^T D B without forming B.
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        double dot = 0;
        for (int k = 0; k < dim; ++k) dot += dNdx[a][k] * dNdx[b][k];
        for (int i = 0; i < dim; ++i)
          for (int j = 0; j < dim; ++j) {
            double v = lambda * dNdx[a][i] * dNdx[b][j] + m.mu * dNdx[a][j] * dNdx[b][i];
            if (i == j) v += m.mu * dot;
            K[(a * dim + i) * nd + b * dim + j] += dv * v;
          }
      }
  }
  if (!mean) return;
  double       div_mean[kMaxCellDofs];
  const double kv = bulkModulus(m) * meanDivergence(r, coords, div_mean);
  for (int a = 0; a < nd; ++a)
    for (int b = 0; b < nd; ++b) K[a * nd + b] += kv * div_mean[a] * div_mean[b];
}

void elementLumpedMass(CellShape s, const double *coords, double rho, double *mass) {
  // N_a |det J| is at most cubic per reference direction, so the Gauss rules are exact.
  const ReferenceRule &r = referenceRule(s);
  double dNdx[kMaxCellNodes][kMaxCellDim];
  for (int a = 0; a < r.nodes; ++a) mass[a] = 0;
  for (int q = 0; q < r.points; ++q) {
    const double dv = r.weight[q] * physicalGradients(r, coords, r.dN[q], dNdx);
    for (int a = 0; a < r.nodes; ++a) mass[a] += rho * r.N[q][a] * dv;
  }
}

void elementCoupling(CellShape s, const double *coords, double *Q) {
  const ReferenceRule &r = referenceRule(s);
  const int n = r.nodes, dim = r.dim, nd = n * dim;
  for (int k = 0; k < n * nd; ++k) Q[k] = 0;
  double dNdx[kMaxCellNodes][kMaxCellDim];
  for (int q = 0; q < r.points; ++q) {
    const double dv = r.weight[q] * physicalGradients(r, coords, r.dN[q], dNdx);
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        for (int j = 0; j < dim; ++j) Q[a * nd + b * dim + j] += dv * r.N[q][a] * dNdx[b][j];
  }
}

void elementDiffusion(CellShape s, const double *coords, double *H) {
  const ReferenceRule &r = referenceRule(s);
  const int n = r.nodes, dim = r.dim;
  for (int k = 0; k < n * n; ++k) H[k] = 0;
  double dNdx[kMaxCellNodes][kMaxCellDim];
  for (int q = 0; q < r.points; ++q) {
    const double dv = r.weight[q] * physicalGradients(r, coords, r.dN[q], dNdx);
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        double dot = 0;
        for (int k = 0; k < dim; ++k) dot += dNdx[a][k] * dNdx[b][k];
        H[a * n + b] += dv * dot;
      }
  }
}

void elementStressOperator(CellShape s, const double *coords, const LameParameters &m, double *S, Dilatation dilatation) {
  const ReferenceRule &r = referenceRule(s);
  const int n = r.nodes, dim = r.dim, nd = n * dim;
  double dNdx[kMaxCellNodes][kMaxCellDim] = {};
  physicalGradients(r, coords, r.centroid_dN, dNdx);
  constexpr int kRowI[kStressComponents] = {0, 1, 2, 0, 1, 0};
  constexpr int kRowJ[kStressComponents] = {0, 1, 2, 1, 2, 2};
  // sigma_ij = lambda delta_ij div u + mu (du_i/dx_j + du_j/dx_i); in 2D the z gradients
  // are zero, which gives the plane-strain zz = lambda (exx + eyy) and yz = xz = 0.
  for (int row = 0; row < kStressComponents; ++row) {
    const int i = kRowI[row], j = kRowJ[row];
    for (int b = 0; b < n; ++b)
      for (int k = 0; k < dim; ++k) {
        double v = i == j ? m.lambda * dNdx[b][k] : 0.0;
        if (k == j) v += m.mu * dNdx[b][i];
        if (k == i) v += m.mu * dNdx[b][j];
        S[row * nd + b * dim + k] = v;
      }
  }
  if (dilatation == Dilatation::Gauss) return;
  // sigma_ii = kappa div u + 2 mu dev(eps)_ii: the centroid's div u replaced by the mean.
  double div_mean[kMaxCellDofs];
  meanDivergence(r, coords, div_mean);
  const double kappa = bulkModulus(m);
  for (int row = 0; row < 3; ++row)
    for (int b = 0; b < n; ++b)
      for (int k = 0; k < dim; ++k) S[row * nd + b * dim + k] += kappa * (div_mean[b * dim + k] - dNdx[b][k]);
}

void elementStiffnessRowAbsSum(CellShape s, const double *coords, const LameParameters &m, double *rowabs) {
  double K[kMaxCellDofs * kMaxCellDofs];
  elementStiffness(s, coords, m, K);
  const int nd = cellNodeCount(s) * cellDimension(s);
  for (int row = 0; row < nd; ++row) {
    double v = 0;
    for (int c = 0; c < nd; ++c) v += std::fabs(K[row * nd + c]);
    rowabs[row] = v;
  }
}

} // namespace slipwave::fem
