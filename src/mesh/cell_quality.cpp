#include "slipwave/mesh/cell_quality.hpp"

#include <algorithm>
#include <cmath>

namespace slipwave::mesh {
namespace {

// Relative size below which a cell counts as having no area or volume (round-off of
// coordinates of order 1e-16 relative).
constexpr double kDegenerate = 1e-12;

void sub(const double *a, const double *b, int dim, double *out) {
  for (int i = 0; i < dim; ++i) out[i] = a[i] - b[i];
}
double cross2(const double *u, const double *v) { return u[0] * v[1] - u[1] * v[0]; }
double triple(const double *u, const double *v, const double *w) {
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

// Corner Jacobians (edge vectors along the reference axes at each vertex); returns the count.
int cornerJacobians(numerics::CellShape s, const double *x, double *J) {
  double e1[3], e2[3], e3[3];
  switch (s) {
  case numerics::CellShape::Tri3:
    sub(x + 2, x, 2, e1), sub(x + 4, x, 2, e2);
    J[0] = cross2(e1, e2);
    return 1;
  case numerics::CellShape::Tet4:
    sub(x + 3, x, 3, e1), sub(x + 6, x, 3, e2), sub(x + 9, x, 3, e3);
    J[0] = triple(e1, e2, e3);
    return 1;
  case numerics::CellShape::Quad4:
    for (int a = 0; a < 4; ++a) {
      sub(x + 2 * ((a + 1) % 4), x + 2 * a, 2, e1), sub(x + 2 * ((a + 3) % 4), x + 2 * a, 2, e2);
      J[a] = cross2(e1, e2);
    }
    return 4;
  case numerics::CellShape::Hex8:
    for (int a = 0; a < 8; ++a) {
      const int ring = a < 4 ? 0 : 4, k = a % 4, across = a < 4 ? a + 4 : a - 4;
      sub(x + 3 * (ring + (k + 1) % 4), x + 3 * a, 3, e1), sub(x + 3 * (ring + (k + 3) % 4), x + 3 * a, 3, e2), sub(x + 3 * across, x + 3 * a, 3, e3);
      // The edge to the opposite face points the other way on the top face.
      J[a] = (a < 4 ? 1 : -1) * triple(e1, e2, e3);
    }
    return 8;
  }
  return 0;
}

bool isEdge(numerics::CellShape s, int a, int b) {
  switch (s) {
  case numerics::CellShape::Tri3:
  case numerics::CellShape::Tet4: return true;
  case numerics::CellShape::Quad4: return (b - a) % 2 == 1; // neighbours in the cycle, not the diagonals
  case numerics::CellShape::Hex8: return (a / 4 == b / 4 && (b - a) % 2 == 1) || b == a + 4;
  }
  return false;
}

double longestEdge(numerics::CellShape s, const double *x) {
  const int n = numerics::cellNodeCount(s), dim = numerics::cellDimension(s);
  double    h = 0;
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      if (!isEdge(s, a, b)) continue;
      double d2 = 0;
      for (int i = 0; i < dim; ++i) d2 += (x[a * dim + i] - x[b * dim + i]) * (x[a * dim + i] - x[b * dim + i]);
      h = std::max(h, std::sqrt(d2));
    }
  return h;
}

// Volume of the regular cell of unit edge.
double regularVolume(numerics::CellShape s) {
  switch (s) {
  case numerics::CellShape::Tri3: return std::sqrt(3.0) / 4.0;
  case numerics::CellShape::Tet4: return 1.0 / (6.0 * std::sqrt(2.0));
  case numerics::CellShape::Quad4:
  case numerics::CellShape::Hex8: return 1.0;
  }
  return 1;
}

} // namespace

CellShapeQuality cellShapeQuality(numerics::CellShape s, const double *coords) {
  double    J[8];
  const int n   = cornerJacobians(s, coords, J);
  const int dim = numerics::cellDimension(s);
  double    largest = 0;
  int       sign    = 1;
  for (int a = 0; a < n; ++a)
    if (std::fabs(J[a]) > largest) largest = std::fabs(J[a]), sign = J[a] < 0 ? -1 : 1;
  CellShapeQuality q{};
  const double     h = longestEdge(s, coords);
  q.relative_size    = h > 0 ? largest / std::pow(h, dim) : 0;
  q.jacobian_ratio   = 1;
  for (int a = 0; a < n; ++a) q.jacobian_ratio = std::min(q.jacobian_ratio, largest > 0 ? sign * J[a] / largest : 0.0);
  const double volume = numerics::cellVolume(s, coords);
  q.aspect            = volume > 0 ? std::pow(std::pow(h, dim) * regularVolume(s) / volume, 1.0 / (dim - 1)) : HUGE_VAL;
  return q;
}

CellDefect cellDefect(const CellShapeQuality &q, double max_aspect, double min_jacobian_ratio) {
  if (q.relative_size < kDegenerate) return CellDefect::Degenerate;
  if (q.jacobian_ratio <= kDegenerate) return CellDefect::Inverted;
  if (q.aspect > max_aspect || q.jacobian_ratio < min_jacobian_ratio) return CellDefect::Distorted;
  return CellDefect::None;
}

} // namespace slipwave::mesh
