// Rigid-body motion of a set of point masses under small rotations (linearised kinematics:
// the displacement of a point at r from the centroid is U + theta x r, which has no strain).
// 2D points are padded to 3D with z = 0; a 2D rotation is about z (component 2).
// Used by the rigid regions (problem/rigid_bodies.hpp), where the points are the region's
// nodes with their lumped masses, and by the structure load (input/structure_load.hpp),
// which spreads a moment over a region's nodes as unit masses.
#pragma once

namespace slipwave::physics {

// out = a x b.
void cross(const double a[3], const double b[3], double out[3]);

// J += m (|r|^2 1 - r r^T): the point's contribution to the inertia tensor about the point r
// is measured from (row-major 3 x 3).
void rigidInertiaAdd(double m, const double r[3], double J[9]);

// The rigid motions left when the components `fixed` are held at every point: translations
// along the free components, and rotations about axis e only where every component other
// than e is free (a rotation about e moves the other two). 2D: rotation about z only.
void rigidFreedoms(int dim, const bool fixed[3], bool translates[3], bool rotates[3]);

// Jinv = the inverse of J restricted to the free rotations, zero elsewhere (Cramer on the
// symmetric 3 x 3 J with the fixed rows and columns replaced by the identity's). J must be
// positive definite on them (3D: the points not on one line).
void rigidInertiaInverse(int dim, const double J[9], const bool rotates[3], double Jinv[9]);

// The rigid-body acceleration of the point at r from the centroid, a = A + alpha x r, for
// the resultant force F and the moment M about the centroid: A = F / mass, alpha = Jinv M.
void rigidPointAcceleration(double mass, const double Jinv[9], const double F[3], const double M[3], const double r[3], double out[3]);

// The rigid motion U + theta x r that a rigid body's point displacements u_i (masses m_i at
// r_i from the centroid) carry: U = P / mass, the mass centre's displacement, and
// theta = Jinv L, its small rotation [rad], from P = sum m_i u_i and L = sum r_i x m_i u_i.
// Exact for a rigid displacement field (sum m_i r_i x (theta x r_i) = J theta); the same
// projection as rigidPointAcceleration's, applied to displacements.
void rigidMotionOf(double mass, const double Jinv[9], const double P[3], const double L[3], double U[3], double theta[3]);

// 1 / m_eff of a unit force along axis d at r: how much acceleration a force there gives the
// point itself along d, 1/mass + (r x e_d)^T Jinv (r x e_d) (mass HUGE_VAL: d is fixed). A spring k on that dof adds
// k / m_eff to the trace of M_r^-1 K_r of the body's reduced system, an upper bound on its
// largest omega^2 (K_r positive semi-definite).
double rigidDofCompliance(double mass, const double Jinv[9], const double r[3], int d);

} // namespace slipwave::physics
