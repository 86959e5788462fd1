// The friction lag (physics/friction_lag.hpp) alone and inside the Mohr-Coulomb law
// (physics/mohr_coulomb_interface.hpp, FrictionLagStep). Expected values from the lag's ODE,
// d sigma*/dt = -(|V| + V*) / L (sigma* - sigma'), solved in closed form:
//  - at rest (V = 0) with sigma' held: sigma* - sigma' = (sigma*_0 - sigma') exp(-V* t / L);
//  - sliding with V* = 0: sigma* - sigma' = (sigma*_0 - sigma') exp(-s / L), s the slip;
// the law's strength is c - sigma* tan(phi), so a pair sliding at its strength carries
// |sigma_T| = c - sigma* tan(phi) after each fully plastic step. The lag's slip is the
// tangential jump (its elastic part included: that is what the law has before the update),
// and the discrete lag is exact for a jump and a target held over each step, so the
// expected values hold to round-off.
#include "slipwave/physics/friction_lag.hpp"
#include "slipwave/physics/mohr_coulomb_interface.hpp"

#include "unit_check.hpp"

#include <cmath>

using namespace slipwave::physics;

namespace {

InterfaceParams sandConcrete() {
  InterfaceParams p;
  p.E = 1e9, p.G = 5e8, p.phi = M_PI / 6, p.psi = 0, p.c = 1e3, p.e_ini = 0, p.tensile_strength = 0;
  return p;
}

} // namespace

int main() {
  // The kernel alone.
  {
    const FrictionLag off{0.0, 1.0};
    unit::check(laggedNormalTraction(off, -5e4, -1e5, 1e-3, 1e-3) == -1e5, "L = 0: sigma* is sigma' at once");
    const FrictionLag lag{0.005, 1.0};
    double s = -5e4;
    for (int k = 0; k < 100; ++k) s = laggedNormalTraction(lag, s, -1e5, 0.0, 1e-4);
    unit::near(s, -1e5 + 5e4 * std::exp(-1.0 * 100 * 1e-4 / 0.005), 1e-13, 0, "at rest: sigma* - sigma' decays as exp(-V* t / L) (t = 2 L / V*)");
    const FrictionLag slip_only{0.005, 0.0};
    s = -5e4;
    for (int k = 0; k < 50; ++k) s = laggedNormalTraction(slip_only, s, -1e5, 2e-4, 1e-4);
    unit::near(s, -1e5 + 5e4 * std::exp(-50 * 2e-4 / 0.005), 1e-13, 0, "V* = 0: decays as exp(-slip / L) over 10 mm of slip");
    unit::check(laggedNormalTraction(slip_only, -5e4, -1e5, 0.0, 1.0) == -5e4, "V* = 0 and no slip: sigma* stays");
  }

  const InterfaceParams params = sandConcrete();
  const InterfaceLaw    law(params);
  const double          tan_phi = std::tan(params.phi), L = 0.004;

  // A pair pressed to sigma_1 = -1e5 Pa and sliding (V* = 0), then pressed to sigma_2 = -2e5
  // Pa: its strength rises from c - sigma_1 tan(phi) to c - sigma_2 tan(phi) over the slip,
  // c - (sigma_2 + (sigma_1 - sigma_2) exp(-s / L)) tan(phi), and the work put into the pair
  // is its stored energy plus its dissipation.
  {
    FrictionLagStep step{FrictionLag{L, 0.0}, 0.0, 1e-4};
    const double    sigma_1 = -1e5, sigma_2 = -2e5;
    InterfaceState<2> s = interfaceInitialState<2>(law, sigma_1);
    const double       ds = 1e-5; // jump per step [m]
    // Shear onto the surface at sigma_1 in one elastic step (sigma* starts at sigma_1, the
    // initial state's), then slide: every step after it is wholly plastic, so the traction
    // is linear over each and the trapezoid gives the work exactly.
    const double R1 = params.c - sigma_1 * tan_phi, onto[1] = {R1 / law.G};
    interfaceUpdate<2>(law, s, onto, 0.0, 0.0, &step);
    double work = 0.5 * s.sigma_T[0] * onto[0];
    for (int k = 0; k < 200; ++k) {
      const double dw[1] = {ds}, tau0 = s.sigma_T[0];
      interfaceUpdate<2>(law, s, dw, 0.0, 0.0, &step);
      work += 0.5 * (tau0 + s.sigma_T[0]) * ds;
    }
    unit::near(s.sigma_T[0], params.c - sigma_1 * tan_phi, 1e-12, 0, "sliding at sigma_1: |sigma_T| = c - sigma_1 tan(phi)");
    // Press to sigma_2 with no slip and no time: the strength has not moved.
    const double dw0[1] = {0.0};
    FrictionLagStep no_time = step;
    no_time.dt            = 0.0;
    const double sN0 = s.sigma_N;
    interfaceUpdate<2>(law, s, dw0, (sigma_2 - sigma_1) / law.E, 0.0, &no_time);
    work += 0.5 * (sN0 + s.sigma_N) * (sigma_2 - sigma_1) / law.E;
    unit::near(s.sigma_N, sigma_2, 1e-12, 0, "pressed to sigma_2");
    unit::near(s.sigma_friction, sigma_1, 1e-12, 0, "no slip, no time: sigma* still sigma_1");
    // Slide 3 L: the strength follows the closed form after every step.
    double worst = 0;
    for (int k = 1; k <= 1200; ++k) {
      const double dw[1] = {ds}, tau0 = s.sigma_T[0];
      interfaceUpdate<2>(law, s, dw, 0.0, 0.0, &step);
      work += 0.5 * (tau0 + s.sigma_T[0]) * ds;
      const double sigma = sigma_2 + (sigma_1 - sigma_2) * std::exp(-k * ds / L);
      worst              = std::fmax(worst, std::fabs(s.sigma_T[0] - (params.c - sigma * tan_phi)) / (params.c - sigma_2 * tan_phi));
    }
    unit::check(s.status == InterfaceStatus::Slip, "still sliding after 3 L");
    unit::near(worst, 0.0, 0, 1e-12, "strength follows c - (sigma_2 + (sigma_1 - sigma_2) exp(-s/L)) tan(phi) after every step (relative)");
    unit::near(s.sigma_friction, sigma_2 + (sigma_1 - sigma_2) * std::exp(-1200 * ds / L), 1e-12, 0, "sigma* after 3 L");
    const double stored = detail::storedEnergy<2>(law, s) - detail::storedEnergy<2>(law, interfaceInitialState<2>(law, sigma_1));
    unit::near(stored + s.dissipation, work, 1e-9, 0, "work in = stored energy + dissipation (the trapezoid is exact per step)");
  }

  // The pore pressure enters sigma' = sigma_N + p: a pair at rest whose p rises by 4e4 Pa
  // (V* = 1 m/s) loses strength over L / V*, not at once, and ends on the new surface
  // without drift.
  {
    const double      p0 = 0.0, p1 = 4e4, sigma_N = -1e5;
    FrictionLagStep   step{FrictionLag{L, 1.0}, p0, 1e-4};
    InterfaceState<2> s = interfaceInitialState<2>(law, sigma_N);
    // Shear to 90 % of the strength at p0.
    const double R0 = params.c - sigma_N * tan_phi, onto[1] = {0.9 * R0 / law.G};
    interfaceUpdate<2>(law, s, onto, 0.0, 0.0, &step);
    step.p = p1;
    const InterfaceLaw wet = interfaceLawWithPorePressure(law, p1);
    const double       none[1] = {0.0};
    double             max_drift = 0;
    int                first_slip = -1;
    for (int k = 1; k <= 400; ++k) {
      max_drift = std::fmax(max_drift, interfaceUpdate<2>(wet, s, none, 0.0, k == 1 ? p1 - p0 : 0.0, &step));
      if (first_slip < 0 && s.status == InterfaceStatus::Slip) first_slip = k;
    }
    // Stick until c - sigma* tan(phi) falls to 0.9 R0: sigma* = sigma_N + p1 (1 - exp(-t/T)),
    // T = L/V* = 4 ms, so t = -T ln(1 - 0.1 R0 / (p1 tan(phi))).
    const double t_slip = -(L / 1.0) * std::log(1 - 0.1 * R0 / (p1 * tan_phi));
    unit::near(first_slip * 1e-4, t_slip, 0, 1.01e-4, "a rise of p makes the pair slip after the lag's time, not at once");
    const double sigma_end = sigma_N + p1 - p1 * std::exp(-400 * 1e-4 * 1.0 / L);
    unit::near(std::fabs(s.sigma_T[0]), params.c - sigma_end * tan_phi, 1e-12, 0, "ends on the lagged surface, c - sigma* tan(phi), sigma* within 5e-5 of sigma_N + p1");
    unit::near(max_drift, 0.0, 0, 1e-9 * R0, "no drift");
  }

  // A static solve (dt NaN): sigma* = sigma' at once.
  {
    FrictionLagStep   step{FrictionLag{L, 1.0}, 2e4, NAN};
    InterfaceState<2> s = interfaceInitialState<2>(law, -1e5);
    const double      none[1] = {0.0};
    interfaceUpdate<2>(interfaceLawWithPorePressure(law, 2e4), s, none, -1e5 / law.E, 0.0, &step);
    unit::near(s.sigma_friction, -2e5 + 2e4, 1e-12, 0, "no time (static): sigma* = sigma_N + p");
  }

  // An opening: sigma* follows the open pair's effective traction (0 + p, held at the
  // tension cut-off: sigma_t = 0, so 0 whatever p) while it is open, and on re-contact the
  // contact's, each over its part of the step: a brief opening changes sigma* little.
  {
    InterfaceParams thick = params;
    thick.e_ini           = 1e-4;
    const InterfaceLaw law_thick(thick);
    const double       p = 3e3, dt = 1e-4, V = 1.0;
    FrictionLagStep    step{FrictionLag{L, V}, p, dt};
    const InterfaceLaw wet = interfaceLawWithPorePressure(law_thick, p);
    InterfaceState<2>  s   = interfaceInitialState<2>(wet, -1e5);
    const double       none[1] = {0.0};
    interfaceUpdate<2>(wet, s, none, 3e-4, 0.0, &step); // opens (u = -1e-4 + 3e-4 > e_ini)
    unit::check(s.status == InterfaceStatus::Open, "opened");
    const double open_1 = 0.0 + (-1e5 - 0.0) * std::exp(-V * dt / L);
    unit::near(s.sigma_friction, open_1, 1e-12, 0, "open: sigma* relaxes toward 0 over the step");
    const double opening = s.opening, dw_N = -opening - 1e-5; // closes, 1e-5 m into contact
    interfaceUpdate<2>(wet, s, none, dw_N, 0.0, &step);
    unit::check(s.status != InterfaceStatus::Open, "closed again");
    const double beta = opening / (opening + 1e-5);
    const double at_touch = open_1 * std::exp(-V * beta * dt / L);
    const double target = s.sigma_N + p;
    unit::near(s.sigma_friction, target + (at_touch - target) * std::exp(-V * (1 - beta) * dt / L), 1e-12, 1e-9,
               "re-contact: sigma* toward 0 before the touch, toward sigma_N + p after it");
  }

  // 3D: sliding along a diagonal with V* = 0 follows the same closed form in the slip's norm.
  {
    FrictionLagStep   step{FrictionLag{L, 0.0}, 0.0, 1e-4};
    const double      sigma_1 = -1e5, sigma_2 = -2e5;
    InterfaceState<3> s = interfaceInitialState<3>(law, sigma_1);
    const double      d = 1e-5 / std::sqrt(2.0), dw[2] = {d, d};
    const double      R1 = params.c - sigma_1 * tan_phi, onto[2] = {R1 / law.G / std::sqrt(2.0), R1 / law.G / std::sqrt(2.0)};
    interfaceUpdate<3>(law, s, onto, 0.0, 0.0, &step);
    for (int k = 0; k < 200; ++k) interfaceUpdate<3>(law, s, dw, 0.0, 0.0, &step);
    const double none[2] = {0, 0};
    FrictionLagStep no_time = step;
    no_time.dt            = 0.0;
    interfaceUpdate<3>(law, s, none, (sigma_2 - sigma_1) / law.E, 0.0, &no_time);
    for (int k = 0; k < 800; ++k) interfaceUpdate<3>(law, s, dw, 0.0, 0.0, &step);
    const double sigma = sigma_2 + (sigma_1 - sigma_2) * std::exp(-800 * 1e-5 / L);
    unit::near(std::hypot(s.sigma_T[0], s.sigma_T[1]), params.c - sigma * tan_phi, 1e-12, 0, "3D: strength after 2 L of diagonal slip");
  }
  return unit::failures();
}
