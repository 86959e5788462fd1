// Rigid-body kernels (physics/rigid_body.hpp): inertia of point sets with closed forms, the
// inverse on the free rotations, and the defining property of the projection: the rigid
// accelerations of a set of point forces carry the same resultant force and moment.
#include "slipwave/physics/rigid_body.hpp"

#include "unit_check.hpp"

#include <cmath>
#include <string>

using namespace slipwave::physics;

int main() {
  // Four masses m at (+-a, +-b, 0): J_zz = 4 m (a^2 + b^2), J_xx = 4 m b^2, J_yy = 4 m a^2.
  const double m = 2.5, a = 1.5, b = 0.5;
  double       J[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  for (int i = 0; i < 4; ++i) {
    const double r[3] = {(i & 1) ? a : -a, (i & 2) ? b : -b, 0};
    rigidInertiaAdd(m, r, J);
  }
  unit::near(J[8], 4 * m * (a * a + b * b), 1e-15, 0, "rectangle of four masses: J_zz = 4 m (a^2 + b^2)");
  unit::near(J[0], 4 * m * b * b, 1e-15, 0, "J_xx = 4 m b^2");
  unit::near(J[4], 4 * m * a * a, 1e-15, 0, "J_yy = 4 m a^2");
  unit::near(J[1], 0, 0, 1e-15, "J_xy = 0 by symmetry");

  // Free rotations: 2D only about z; a held in-plane component removes it; 3D with z held
  // (plane motion) keeps the rotation about z alone; 3D with x held keeps the one about x.
  bool t[3], rot[3];
  const bool none[3] = {false, false, false}, y_held[3] = {false, true, false}, z_held[3] = {false, false, true}, x_held[3] = {true, false, false};
  rigidFreedoms(2, none, t, rot);
  unit::check(t[0] && t[1] && !t[2] && !rot[0] && !rot[1] && rot[2], "2D: x, y translations and the rotation about z");
  rigidFreedoms(2, y_held, t, rot);
  unit::check(t[0] && !t[1] && !rot[2], "2D, y held everywhere: x translation only");
  rigidFreedoms(3, z_held, t, rot);
  unit::check(t[0] && t[1] && !t[2] && !rot[0] && !rot[1] && rot[2], "3D, z held: plane motion (rotation about z)");
  rigidFreedoms(3, x_held, t, rot);
  unit::check(!t[0] && t[1] && t[2] && rot[0] && !rot[1] && !rot[2], "3D, x held: rotation about x only");

  // 3D: a general point set; J Jinv = 1 with every rotation free.
  double       J3[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0}, Jinv[9];
  const double pts[5][3] = {{1, 0.2, -0.3}, {-0.4, 1.1, 0.5}, {0.3, -0.7, 0.9}, {-0.9, -0.6, -1.2}, {0.0, 0.0, 0.1}};
  const double ms[5]     = {1.0, 2.0, 0.5, 1.5, 3.0};
  for (int i = 0; i < 5; ++i) rigidInertiaAdd(ms[i], pts[i], J3);
  const bool all[3] = {true, true, true};
  rigidInertiaInverse(3, J3, all, Jinv);
  double worst = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += J3[i * 3 + k] * Jinv[k * 3 + j];
      worst = std::fmax(worst, std::fabs(s - (i == j ? 1.0 : 0.0)));
    }
  unit::near(worst, 0, 0, 1e-13, "3D: J Jinv = 1");
  rigidInertiaInverse(3, J3, rot, Jinv); // rot: x held, rotation about x only
  unit::near(Jinv[0], 1 / J3[0], 1e-14, 0, "3D, rotation about x only: Jinv_xx = 1 / J_xx");
  unit::near(std::fabs(Jinv[1]) + std::fabs(Jinv[4]) + std::fabs(Jinv[8]), 0, 0, 0, "and zero for the fixed rotations");

  // Projection: point forces f_i at r_i (about the mass centroid) on masses m_i; the rigid
  // accelerations a_i = F/M + (Jinv Mo) x r_i give back sum m_i a_i = F and
  // sum r_i x m_i a_i = Mo (the lumped-mass projection onto rigid motions).
  double M = 0, c[3] = {0, 0, 0};
  for (int i = 0; i < 5; ++i) {
    M += ms[i];
    for (int d = 0; d < 3; ++d) c[d] += ms[i] * pts[i][d];
  }
  for (double &x : c) x /= M;
  double r[5][3], Jc[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0}, F[3] = {0, 0, 0}, Mo[3] = {0, 0, 0};
  const double f[5][3] = {{1, -2, 0.5}, {0.3, 0.1, -1}, {-2, 0.7, 0.2}, {0.9, 0.9, 0.9}, {-0.1, 3, -0.4}};
  for (int i = 0; i < 5; ++i) {
    double mo[3];
    for (int d = 0; d < 3; ++d) r[i][d] = pts[i][d] - c[d];
    rigidInertiaAdd(ms[i], r[i], Jc);
    cross(r[i], f[i], mo);
    for (int d = 0; d < 3; ++d) {
      F[d] += f[i][d];
      Mo[d] += mo[d];
    }
  }
  rigidInertiaInverse(3, Jc, all, Jinv);
  double F2[3] = {0, 0, 0}, Mo2[3] = {0, 0, 0};
  for (int i = 0; i < 5; ++i) {
    double acc[3], p[3], mo[3];
    rigidPointAcceleration(M, Jinv, F, Mo, r[i], acc);
    for (int d = 0; d < 3; ++d) p[d] = ms[i] * acc[d];
    cross(r[i], p, mo);
    for (int d = 0; d < 3; ++d) {
      F2[d] += p[d];
      Mo2[d] += mo[d];
    }
  }
  for (int d = 0; d < 3; ++d) {
    unit::near(F2[d], F[d], 1e-13, 1e-13, "projected accelerations keep the resultant force, component " + std::to_string(d));
    unit::near(Mo2[d], Mo[d], 1e-13, 1e-13, "and the moment about the centroid, component " + std::to_string(d));
  }

  // Motion of the body: a rigid displacement u_i = U + theta x r_i of the five points gives
  // back U and theta (sum m_i r_i x (theta x r_i) = J theta exactly).
  const double U0[3] = {0.01, -0.03, 0.002}, th0[3] = {1e-3, -4e-4, 2.5e-3};
  double       P[3] = {0, 0, 0}, L[3] = {0, 0, 0}, U1[3], th1[3];
  for (int i = 0; i < 5; ++i) {
    double spin[3], mu[3], l[3];
    cross(th0, r[i], spin);
    for (int d = 0; d < 3; ++d) mu[d] = ms[i] * (U0[d] + spin[d]);
    cross(r[i], mu, l);
    for (int d = 0; d < 3; ++d) {
      P[d] += mu[d];
      L[d] += l[d];
    }
  }
  rigidMotionOf(M, Jinv, P, L, U1, th1);
  for (int d = 0; d < 3; ++d) {
    unit::near(U1[d], U0[d], 1e-13, 1e-16, "rigid displacement field: the mass centre's displacement, component " + std::to_string(d));
    unit::near(th1[d], th0[d], 1e-12, 1e-16, "and its rotation, component " + std::to_string(d));
  }

  // Compliance: 2D, a unit x force at r = (0, b) from the centroid of the rectangle above
  // (mass 4 m) accelerates that point by 1/(4 m) + b^2 / J_zz.
  double J2inv[9];
  rigidFreedoms(2, none, t, rot);
  rigidInertiaInverse(2, J, rot, J2inv);
  const double rb[3] = {0, b, 0};
  unit::near(rigidDofCompliance(4 * m, J2inv, rb, 0), 1 / (4 * m) + b * b / J[8], 1e-15, 0, "2D compliance along x at (0, b): 1/M + b^2/J");
  unit::near(rigidDofCompliance(4 * m, J2inv, rb, 1), 1 / (4 * m), 1e-15, 0, "along y at (0, b): 1/M (the rotation moves it along x only)");
  return unit::failures();
}
