#include "slipwave/numerics/reference_cell.hpp"

#include <cmath>

namespace slipwave::numerics {
namespace {

constexpr double kQuadCorner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

double cross3Norm(const double *u, const double *v, double *c) {
  c[0] = u[1] * v[2] - u[2] * v[1];
  c[1] = u[2] * v[0] - u[0] * v[2];
  c[2] = u[0] * v[1] - u[1] * v[0];
  return std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
}

} // namespace

int cellNodeCount(CellShape s) {
  switch (s) {
  case CellShape::Tri3: return 3;
  case CellShape::Quad4: return 4;
  case CellShape::Tet4: return 4;
  case CellShape::Hex8: return 8;
  }
  return 0;
}

int cellDimension(CellShape s) { return s == CellShape::Tri3 || s == CellShape::Quad4 ? 2 : 3; }

int faceNodeCount(FaceShape f) {
  switch (f) {
  case FaceShape::Seg2: return 2;
  case FaceShape::Tri3: return 3;
  case FaceShape::Quad4: return 4;
  }
  return 0;
}

void shapeFunctions(CellShape s, const double *xi, double *N) {
  switch (s) {
  case CellShape::Tri3:
    N[0] = 1 - xi[0] - xi[1], N[1] = xi[0], N[2] = xi[1];
    return;
  case CellShape::Tet4:
    N[0] = 1 - xi[0] - xi[1] - xi[2], N[1] = xi[0], N[2] = xi[1], N[3] = xi[2];
    return;
  case CellShape::Quad4:
    for (int a = 0; a < 4; ++a) N[a] = 0.25 * (1 + kQuadCorner[a][0] * xi[0]) * (1 + kQuadCorner[a][1] * xi[1]);
    return;
  case CellShape::Hex8:
    for (int a = 0; a < 8; ++a)
      N[a] = 0.125 * (1 + kQuadCorner[a % 4][0] * xi[0]) * (1 + kQuadCorner[a % 4][1] * xi[1]) *
             (1 + (a < 4 ? -1.0 : 1.0) * xi[2]);
    return;
  }
}

void referenceGradients(CellShape s, const double *xi, double (*dN)[kMaxCellDim]) {
  switch (s) {
  case CellShape::Tri3:
    dN[0][0] = -1, dN[0][1] = -1;
    dN[1][0] = 1, dN[1][1] = 0;
    dN[2][0] = 0, dN[2][1] = 1;
    return;
  case CellShape::Tet4:
    for (int a = 0; a < 4; ++a)
      for (int j = 0; j < 3; ++j) dN[a][j] = a == 0 ? -1.0 : (a - 1 == j ? 1.0 : 0.0);
    return;
  case CellShape::Quad4:
    for (int a = 0; a < 4; ++a) {
      const double xa = kQuadCorner[a][0], ya = kQuadCorner[a][1];
      dN[a][0] = 0.25 * xa * (1 + ya * xi[1]);
      dN[a][1] = 0.25 * ya * (1 + xa * xi[0]);
    }
    return;
  case CellShape::Hex8:
    for (int a = 0; a < 8; ++a) {
      const double xa = kQuadCorner[a % 4][0], ya = kQuadCorner[a % 4][1], za = a < 4 ? -1.0 : 1.0;
      const double fx = 1 + xa * xi[0], fy = 1 + ya * xi[1], fz = 1 + za * xi[2];
      dN[a][0] = 0.125 * xa * fy * fz;
      dN[a][1] = 0.125 * ya * fx * fz;
      dN[a][2] = 0.125 * za * fx * fy;
    }
    return;
  }
}

// J[i][j] = d x_i / d xi_j.
void jacobian(int n, int dim, const double *coords, const double (*dN)[kMaxCellDim], double J[kMaxCellDim][kMaxCellDim]) {
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) {
      double v = 0;
      for (int a = 0; a < n; ++a) v += coords[a * dim + i] * dN[a][j];
      J[i][j] = v;
    }
}

double invertJacobian(int dim, const double J[kMaxCellDim][kMaxCellDim], double Jinv[kMaxCellDim][kMaxCellDim]) {
  if (dim == 2) {
    const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    if (det == 0) return 0;
    Jinv[0][0] = J[1][1] / det, Jinv[0][1] = -J[0][1] / det;
    Jinv[1][0] = -J[1][0] / det, Jinv[1][1] = J[0][0] / det;
    return det;
  }
  const double c00 = J[1][1] * J[2][2] - J[1][2] * J[2][1];
  const double c01 = J[1][2] * J[2][0] - J[1][0] * J[2][2];
  const double c02 = J[1][0] * J[2][1] - J[1][1] * J[2][0];
  const double det = J[0][0] * c00 + J[0][1] * c01 + J[0][2] * c02;
  if (det == 0) return 0;
  Jinv[0][0] = c00 / det;
  Jinv[1][0] = c01 / det;
  Jinv[2][0] = c02 / det;
  Jinv[0][1] = (J[0][2] * J[2][1] - J[0][1] * J[2][2]) / det;
  Jinv[1][1] = (J[0][0] * J[2][2] - J[0][2] * J[2][0]) / det;
  Jinv[2][1] = (J[0][1] * J[2][0] - J[0][0] * J[2][1]) / det;
  Jinv[0][2] = (J[0][1] * J[1][2] - J[0][2] * J[1][1]) / det;
  Jinv[1][2] = (J[0][2] * J[1][0] - J[0][0] * J[1][2]) / det;
  Jinv[2][2] = (J[0][0] * J[1][1] - J[0][1] * J[1][0]) / det;
  return det;
}

bool referenceCoordinates(CellShape s, const double *coords, const double *x, double *xi, double tol) {
  const int n = cellNodeCount(s), dim = cellDimension(s);
  const bool simplex = s == CellShape::Tri3 || s == CellShape::Tet4;
  for (int i = 0; i < dim; ++i) xi[i] = simplex ? 1.0 / (dim + 1) : 0.0;
  constexpr int kMaxNewton = 50;
  bool converged = false;
  for (int it = 0; it < kMaxNewton && !converged; ++it) {
    double N[kMaxCellNodes], dN[kMaxCellNodes][kMaxCellDim], J[kMaxCellDim][kMaxCellDim], Jinv[kMaxCellDim][kMaxCellDim];
    shapeFunctions(s, xi, N);
    referenceGradients(s, xi, dN);
    jacobian(n, dim, coords, dN, J);
    if (invertJacobian(dim, J, Jinv) == 0) return false;
    double res[kMaxCellDim];
    for (int i = 0; i < dim; ++i) {
      res[i] = -x[i];
      for (int a = 0; a < n; ++a) res[i] += N[a] * coords[a * dim + i];
    }
    double step = 0;
    for (int i = 0; i < dim; ++i) {
      double d = 0;
      for (int j = 0; j < dim; ++j) d += Jinv[i][j] * res[j];
      xi[i] -= d;
      step = std::fmax(step, std::fabs(d));
    }
    // Far outside a distorted cell the Newton iterates may run away; that point is not in
    // this cell either way.
    if (!std::isfinite(step) || step > 1e6) return false;
    converged = step <= 1e-12;
  }
  if (!converged) return false;
  if (simplex) {
    double sum = 0;
    for (int i = 0; i < dim; ++i) {
      if (xi[i] < -tol) return false;
      sum += xi[i];
    }
    return sum <= 1 + tol;
  }
  for (int i = 0; i < dim; ++i)
    if (std::fabs(xi[i]) > 1 + tol) return false;
  return true;
}

void faceLumpedWeights(FaceShape f, int dim, const double *coords, double *w) {
  switch (f) {
  case FaceShape::Seg2: {
    const double L = std::hypot(coords[dim] - coords[0], coords[dim + 1] - coords[1]);
    w[0] = w[1] = 0.5 * L;
    return;
  }
  case FaceShape::Tri3: {
    double u[3], v[3], c[3];
    for (int i = 0; i < 3; ++i) u[i] = coords[3 + i] - coords[i], v[i] = coords[6 + i] - coords[i];
    w[0] = w[1] = w[2] = cross3Norm(u, v, c) / 6.0;
    return;
  }
  case FaceShape::Quad4: {
    // Bilinear face, possibly warped: w_a = sum_q N_a |x_xi x x_eta| over the 2x2 Gauss points.
    const double g = 1.0 / std::sqrt(3.0);
    for (int a = 0; a < 4; ++a) w[a] = 0;
    for (int q = 0; q < 4; ++q) {
      const double s = g * kQuadCorner[q][0], t = g * kQuadCorner[q][1];
      double ts[3] = {0, 0, 0}, tt[3] = {0, 0, 0}, c[3];
      for (int a = 0; a < 4; ++a) {
        const double xa = kQuadCorner[a][0], ya = kQuadCorner[a][1];
        for (int i = 0; i < 3; ++i) {
          ts[i] += 0.25 * xa * (1 + ya * t) * coords[a * 3 + i];
          tt[i] += 0.25 * ya * (1 + xa * s) * coords[a * 3 + i];
        }
      }
      const double da = cross3Norm(ts, tt, c);
      for (int a = 0; a < 4; ++a) w[a] += 0.25 * (1 + kQuadCorner[a][0] * s) * (1 + kQuadCorner[a][1] * t) * da;
    }
    return;
  }
  }
}

void faceConsistentMass(FaceShape f, int dim, const double *coords, double *M) {
  const int n = faceNodeCount(f);
  if (f != FaceShape::Quad4) {
    // Linear simplices: integral of N_a N_b = measure (1 + delta_ab) / ((n + 1) n).
    double w[kMaxFaceNodes];
    faceLumpedWeights(f, dim, coords, w);
    const double measure = n * w[0];
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) M[a * n + b] = measure * (a == b ? 2.0 : 1.0) / ((n + 1) * n);
    return;
  }
  // N_a N_b |x_xi x x_eta| is at most cubic per direction on a bilinear face: 2 x 2 Gauss is exact.
  const double g = 1.0 / std::sqrt(3.0);
  for (int k = 0; k < 16; ++k) M[k] = 0;
  for (int q = 0; q < 4; ++q) {
    const double s = g * kQuadCorner[q][0], t = g * kQuadCorner[q][1];
    double       ts[3] = {0, 0, 0}, tt[3] = {0, 0, 0}, c[3], N[4];
    for (int a = 0; a < 4; ++a) {
      const double xa = kQuadCorner[a][0], ya = kQuadCorner[a][1];
      N[a]            = 0.25 * (1 + xa * s) * (1 + ya * t);
      for (int i = 0; i < 3; ++i) {
        ts[i] += 0.25 * xa * (1 + ya * t) * coords[a * 3 + i];
        tt[i] += 0.25 * ya * (1 + xa * s) * coords[a * 3 + i];
      }
    }
    const double da = cross3Norm(ts, tt, c);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) M[a * 4 + b] += N[a] * N[b] * da;
  }
}

void faceNormal(FaceShape f, int dim, const double *coords, double *n) {
  double c[3] = {0, 0, 0};
  double len = 0;
  switch (f) {
  case FaceShape::Seg2: {
    const double dx = coords[dim] - coords[0], dy = coords[dim + 1] - coords[1];
    len = std::hypot(dx, dy);
    n[0] = dy / len, n[1] = -dx / len;
    return;
  }
  case FaceShape::Tri3: {
    double u[3], v[3];
    for (int i = 0; i < 3; ++i) u[i] = coords[3 + i] - coords[i], v[i] = coords[6 + i] - coords[i];
    len = cross3Norm(u, v, c);
    break;
  }
  case FaceShape::Quad4: {
    // The cross product of the diagonals is twice the area vector of any quadrilateral.
    double u[3], v[3];
    for (int i = 0; i < 3; ++i) u[i] = coords[6 + i] - coords[i], v[i] = coords[9 + i] - coords[3 + i];
    len = cross3Norm(u, v, c);
    break;
  }
  }
  for (int i = 0; i < 3; ++i) n[i] = c[i] / len;
}

namespace {

ReferenceRule buildRule(CellShape s) {
  ReferenceRule r;
  r.nodes = cellNodeCount(s);
  r.dim = cellDimension(s);
  double pts[kMaxRulePoints][kMaxCellDim] = {};
  double centroid[kMaxCellDim] = {};
  const double g = 1.0 / std::sqrt(3.0);
  switch (s) {
  case CellShape::Tri3:
    r.points = 1, r.weight[0] = 0.5, pts[0][0] = pts[0][1] = 1.0 / 3.0;
    centroid[0] = centroid[1] = 1.0 / 3.0;
    break;
  case CellShape::Tet4:
    r.points = 1, r.weight[0] = 1.0 / 6.0, pts[0][0] = pts[0][1] = pts[0][2] = 0.25;
    centroid[0] = centroid[1] = centroid[2] = 0.25;
    break;
  case CellShape::Quad4:
    r.points = 4;
    for (int q = 0; q < 4; ++q) r.weight[q] = 1, pts[q][0] = g * kQuadCorner[q][0], pts[q][1] = g * kQuadCorner[q][1];
    break;
  case CellShape::Hex8:
    r.points = 8;
    for (int q = 0; q < 8; ++q) {
      r.weight[q] = 1;
      pts[q][0] = g * kQuadCorner[q % 4][0], pts[q][1] = g * kQuadCorner[q % 4][1], pts[q][2] = q < 4 ? -g : g;
    }
    break;
  }
  for (int q = 0; q < r.points; ++q) {
    shapeFunctions(s, pts[q], r.N[q]);
    referenceGradients(s, pts[q], r.dN[q]);
  }
  referenceGradients(s, centroid, r.centroid_dN);
  return r;
}

} // namespace

const ReferenceRule &referenceRule(CellShape s) {
  static const ReferenceRule rules[4] = {buildRule(CellShape::Tri3), buildRule(CellShape::Quad4),
                                         buildRule(CellShape::Tet4), buildRule(CellShape::Hex8)};
  return rules[static_cast<int>(s)];
}

double cellVolume(CellShape s, const double *coords) {
  const ReferenceRule &r = referenceRule(s);
  double J[kMaxCellDim][kMaxCellDim], Jinv[kMaxCellDim][kMaxCellDim];
  double v = 0;
  for (int q = 0; q < r.points; ++q) {
    jacobian(r.nodes, r.dim, coords, r.dN[q], J);
    v += r.weight[q] * std::fabs(invertJacobian(r.dim, J, Jinv));
  }
  return v;
}

} // namespace slipwave::numerics
