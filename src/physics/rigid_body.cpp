#include "slipwave/physics/rigid_body.hpp"

namespace slipwave::physics {

void cross(const double a[3], const double b[3], double out[3]) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

void rigidInertiaAdd(double m, const double r[3], double J[9]) {
  const double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) J[a * 3 + b] += m * ((a == b ? r2 : 0.0) - r[a] * r[b]);
}

void rigidFreedoms(int dim, const bool fixed[3], bool translates[3], bool rotates[3]) {
  for (int d = 0; d < 3; ++d) translates[d] = d < dim && !fixed[d];
  for (int e = 0; e < 3; ++e) {
    rotates[e] = dim == 3 || e == 2;
    for (int d = 0; d < dim; ++d) rotates[e] = rotates[e] && (d == e || !fixed[d]);
  }
}

void rigidInertiaInverse(int dim, const double J[9], const bool rotates[3], double Jinv[9]) {
  double A[9];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      // 2D: only the rotation about z exists; its J[8] stands alone.
      const bool kept = rotates[a] && rotates[b] && (dim == 3 || (a == 2 && b == 2));
      A[a * 3 + b]    = kept ? J[a * 3 + b] : (a == b ? 1.0 : 0.0);
    }
  // Cofactors of the symmetric A over its determinant.
  const double c00 = A[4] * A[8] - A[5] * A[7], c01 = A[5] * A[6] - A[3] * A[8], c02 = A[3] * A[7] - A[4] * A[6];
  const double det = A[0] * c00 + A[1] * c01 + A[2] * c02;
  Jinv[0]          = c00 / det;
  Jinv[1]          = (A[2] * A[7] - A[1] * A[8]) / det;
  Jinv[2]          = (A[1] * A[5] - A[2] * A[4]) / det;
  Jinv[3]          = c01 / det;
  Jinv[4]          = (A[0] * A[8] - A[2] * A[6]) / det;
  Jinv[5]          = (A[2] * A[3] - A[0] * A[5]) / det;
  Jinv[6]          = c02 / det;
  Jinv[7]          = (A[1] * A[6] - A[0] * A[7]) / det;
  Jinv[8]          = (A[0] * A[4] - A[1] * A[3]) / det;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      if (!(rotates[a] && rotates[b] && (dim == 3 || (a == 2 && b == 2)))) Jinv[a * 3 + b] = 0;
}

void rigidPointAcceleration(double mass, const double Jinv[9], const double F[3], const double M[3], const double r[3], double out[3]) {
  double alpha[3] = {0, 0, 0}, spin[3];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) alpha[a] += Jinv[a * 3 + b] * M[b];
  cross(alpha, r, spin);
  for (int a = 0; a < 3; ++a) out[a] = F[a] / mass + spin[a];
}

void rigidMotionOf(double mass, const double Jinv[9], const double P[3], const double L[3], double U[3], double theta[3]) {
  for (int a = 0; a < 3; ++a) {
    U[a]     = P[a] / mass;
    theta[a] = 0;
    for (int b = 0; b < 3; ++b) theta[a] += Jinv[a * 3 + b] * L[b];
  }
}

double rigidDofCompliance(double mass, const double Jinv[9], const double r[3], int d) {
  const double e[3] = {d == 0 ? 1.0 : 0.0, d == 1 ? 1.0 : 0.0, d == 2 ? 1.0 : 0.0};
  double       t[3];
  cross(r, e, t);
  double q = 0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) q += t[a] * Jinv[a * 3 + b] * t[b];
  return 1 / mass + q;
}

} // namespace slipwave::physics
