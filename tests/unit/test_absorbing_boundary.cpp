// Lysmer-Kuhlemeyer dashpots and the incident-wave traction.
#include "slipwave/physics/absorbing_boundary.hpp"

#include "unit_check.hpp"

#include <cmath>

using namespace slipwave::physics;

int main() {
  const ElasticMaterial m{1900, 600, 300};
  const double zp = m.rho * m.vp, zs = m.rho * m.vs;

  // Base with n = (0, -1) in 2D, face weight 2: C = 2 diag(rho vs, rho vp).
  const double n2[2] = {0, -1};
  double C2[4];
  lysmerDashpot(2, n2, 2.0, m, C2);
  unit::near(C2[0], 2 * zs, 1e-15, 0, "2D base: tangential dashpot = A rho vs");
  unit::near(C2[3], 2 * zp, 1e-15, 0, "2D base: normal dashpot = A rho vp");
  unit::near(C2[1], 0, 0, 1e-9, "2D base: no coupling");

  // Oblique normal in 3D: n is an eigenvector with rho vp, any t with t.n = 0 gets rho vs.
  const double n3[3] = {2.0 / 3, -1.0 / 3, 2.0 / 3}, t3[3] = {1.0 / std::sqrt(2.0), 0, -1.0 / std::sqrt(2.0)};
  double C3[9];
  lysmerDashpot(3, n3, 1.0, m, C3);
  for (int i = 0; i < 3; ++i) {
    double cn = 0, ct = 0;
    for (int j = 0; j < 3; ++j) cn += C3[i * 3 + j] * n3[j], ct += C3[i * 3 + j] * t3[j];
    unit::near(cn, zp * n3[i], 1e-14, 1e-9, "3D: C n = rho vp n, component " + std::to_string(i));
    unit::near(ct, zs * t3[i], 1e-14, 1e-9, "3D: C t = rho vs t, component " + std::to_string(i));
  }
  unit::near(C3[1], C3[3], 1e-15, 0, "3D: C symmetric");

  // 1D bar of impedance Z = rho c ending in a dashpot of constant Cd: an incident wave is
  // reflected with R = (Z - Cd)/(Z + Cd) (stress continuity and the dashpot law). With the
  // Lysmer coefficient per unit area Cd = Z exactly, for P along n and S across it.
  auto reflection = [](double Z, double Cd) { return (Z - Cd) / (Z + Cd); };
  unit::near(reflection(zp, C2[3] / 2), 0, 0, 1e-15, "P wave: zero reflection at the dashpot");
  unit::near(reflection(zs, C2[0] / 2), 0, 0, 1e-15, "S wave: zero reflection at the dashpot");

  // Incident SV wave of velocity 0.1 m/s in x: t = 2 rho vs v_in e_x = 2*1900*300*0.1 = 114000 Pa.
  const double ex[2] = {1, 0};
  double t[2];
  incidentWaveTraction(2, ex, m.rho, m.vs, 0.1, t);
  unit::near(t[0], 114000, 1e-15, 0, "SV incident traction 2 rho vs v_in");
  unit::near(t[1], 0, 0, 0, "SV incident traction has no normal part");
  // With the boundary moving at the incident velocity only (no wave coming down), the net
  // force t - C v must be the stress of the up-going plane wave, rho c v_in (sigma = Z v).
  unit::near(t[0] - (C2[0] / 2) * 0.1, zs * 0.1, 1e-15, 0, "net traction = plane-wave stress rho vs v_in");
  // A P wave: 2 rho vp v_in along the normal.
  const double ey[2] = {0, 1};
  incidentWaveTraction(2, ey, m.rho, m.vp, -0.02, t);
  unit::near(t[1], 2 * zp * -0.02, 1e-15, 0, "P incident traction 2 rho vp v_in");
  return unit::failures();
}
