// The Mohr-Coulomb interface law in effective stress (physics::interfaceLawWithPorePressure):
// a pair pressed to a total normal traction sigma_N and sheared slips at
// |sigma_T| = c - (sigma_N + p) tan(phi) (Terzaghi's effective stress in Coulomb friction),
// its tension cut-off holds the effective traction sigma_N + p at sigma_t, p = 0 leaves
// the law as it was, and a pore pressure that rises under a pair on the yield surface makes
// it slip by the consistency condition, with no drift left to return.
#include "slipwave/physics/mohr_coulomb_interface.hpp"

#include "unit_check.hpp"

#include <cmath>
#include <string>

using namespace slipwave::physics;

namespace {

// Presses a 2D pair to sigma_N (penalty E) then shears it in small steps; returns the
// largest |sigma_T| reached.
double shearCapacity(const InterfaceLaw &law, double sigma_N) {
  InterfaceState<2> s = interfaceInitialState<2>(law, 0.0);
  const double      dw_T0[1] = {0.0};
  interfaceUpdate<2>(law, s, dw_T0, sigma_N / law.E);
  double peak = 0;
  for (int k = 0; k < 4000; ++k) {
    const double dw_T[1] = {1e-7};
    interfaceUpdate<2>(law, s, dw_T, 0.0);
    peak = std::fmax(peak, std::fabs(s.sigma_T[0]));
  }
  return peak;
}

} // namespace

int main() {
  InterfaceParams params;
  params.E = 1e10, params.G = 1e10, params.phi = M_PI / 6, params.psi = 0, params.c = 5e3, params.e_ini = 0, params.tensile_strength = 2e3;
  const InterfaceLaw law(params);
  const InterfaceLaw same = interfaceLawWithPorePressure(law, 0.0);
  unit::check(same.c == law.c && same.sigma_t == law.sigma_t && same.tan_phi == law.tan_phi && same.E == law.E, "p = 0 leaves the law unchanged");
  const double sigma_N = -1e5, p = 4e4;
  const double dry     = shearCapacity(law, sigma_N);
  const double wet     = shearCapacity(interfaceLawWithPorePressure(law, p), sigma_N);
  unit::near(dry, params.c - sigma_N * std::tan(params.phi), 1e-12, 0, "dry: slips at c - sigma_N tan(phi)");
  unit::near(wet, params.c - (sigma_N + p) * std::tan(params.phi), 1e-12, 0, "p = 4e4 Pa: slips at c - (sigma_N + p) tan(phi)");
  // Tension cut-off: pulled apart (below e_ini = 0 it stays in contact on the plateau), the
  // total traction stops where the effective one reaches sigma_t.
  {
    params.e_ini = 1e-3;
    const InterfaceLaw   thick(params), thick_wet = interfaceLawWithPorePressure(thick, p);
    InterfaceState<2>    s = interfaceInitialState<2>(thick_wet, sigma_N);
    const double         dw_T[1] = {0.0};
    interfaceUpdate<2>(thick_wet, s, dw_T, 2e-5);
    unit::near(s.sigma_N + p, params.tensile_strength, 1e-12, 0, "tension cut-off on the effective traction: sigma_N + p = sigma_t");
  }
  // A pair sheared onto the surface at p, then p rises by dp with no jump increment: the
  // surface shrinks by dp tan(phi), the pair slips lambda = dp tan(phi) / G (psi = 0: H = G)
  // and ends on the new surface with nothing left for the drift return, dissipating
  // lambda times the mean strength over the step, (R_start + R_end) / 2.
  {
    const InterfaceLaw at_p = interfaceLawWithPorePressure(law, p);
    InterfaceState<2>  s    = interfaceInitialState<2>(at_p, sigma_N);
    const double       onto[1] = {(params.c - (sigma_N + p) * std::tan(params.phi)) / law.G * 1.5}, none[1] = {0.0};
    interfaceUpdate<2>(at_p, s, onto, 0.0);
    const double dp = 2e3, R_start = s.sigma_T[0], slip0 = s.slip, dissipated0 = s.dissipation;
    const double drift = interfaceUpdate<2>(interfaceLawWithPorePressure(law, p + dp), s, none, 0.0, dp);
    const double R_end = params.c - (sigma_N + p + dp) * std::tan(params.phi), lambda = dp * std::tan(params.phi) / law.G;
    unit::check(drift == 0.0, "rising p: no drift returned (" + std::to_string(drift) + " Pa)");
    unit::near(s.sigma_T[0], R_end, 1e-12, 0, "rising p: on the surface of the step's end pressure");
    unit::near(s.slip - slip0, lambda, 1e-12, 0, "rising p: slip dp tan(phi) / G");
    unit::near(s.dissipation - dissipated0, lambda * 0.5 * (R_start + R_end), 1e-12, 0, "rising p: dissipation lambda (R_start + R_end) / 2");
    // Falling back by dp grows the surface: elastic, the traction stays.
    interfaceUpdate<2>(interfaceLawWithPorePressure(law, p), s, none, 0.0, -dp);
    unit::near(s.sigma_T[0], R_end, 1e-12, 0, "falling p: elastic, the traction stays");
  }
  return unit::failures();
}
