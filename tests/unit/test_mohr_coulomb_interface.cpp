// Mohr-Coulomb interface law ("spec N": section N of the interface-law specification, not
// part of this repository; the law itself is stated in mohr_coulomb_interface.hpp). Every
// expected value is derived on paper from the rate equations of spec section 4; the
// derivation is stated with it.
#include "slipwave/physics/mohr_coulomb_interface.hpp"

#include "unit_check.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace slipwave::physics;

namespace {

constexpr double kDeg = M_PI / 180.0;

// A sand-concrete interface: stiff penalty, phi = 30, psi = 10 (non-associated), cohesion.
InterfaceParams baseParams() {
  InterfaceParams p;
  p.E = 1e8;
  p.G = 5e7;
  p.phi = 30 * kDeg;
  p.psi = 10 * kDeg;
  p.c = 2e3;
  p.e_ini = 0.0;
  p.tensile_strength = 0.0;
  return p;
}

double step2(const InterfaceLaw &law, InterfaceState<2> &s, double dwT, double dwN) {
  return interfaceUpdate<2>(law, s, &dwT, dwN);
}

double yield2(const InterfaceLaw &law, const InterfaceState<2> &s) {
  return std::fabs(s.sigma_T[0]) + s.sigma_N * law.tan_phi - law.c;
}

double yield3(const InterfaceLaw &law, const InterfaceState<3> &s) {
  return std::hypot(s.sigma_T[0], s.sigma_T[1]) + s.sigma_N * law.tan_phi - law.c;
}

// Direct shear at constant normal LOAD p with dilatancy. sigma_N stays -p only if the
// elastic normal jump stays constant, i.e. dw_N = dw_N^p = lambda tan(psi); sigma_T stays
// at the strength only if dw_T = dw_T^p = lambda. So the normal jump must follow
//   w_N = tan(psi) * max(0, w_T - w_Ty),   w_Ty = (p tan(phi) + c) / G,
// (check with the spec-5 matrix: -E G tan(psi)/H + (E - E^2 tan(phi) tan(psi)/H) tan(psi) = 0).
// The yield point is put on a step boundary so each step is wholly elastic or plastic.
void testDirectShearConstantLoad() {
  const InterfaceParams p = baseParams();
  const InterfaceLaw law(p);
  const double load = 1e5, strength = load * law.tan_phi + p.c, w_y = strength / p.G, h = w_y / 4;
  auto s = interfaceInitialState<2>(law, -load);
  bool ok_T = true, ok_N = true, ok_dil = true, ok_wp = true, ok_D = true;
  double wT = 0.0, wN = 0.0;
  for (int k = 1; k <= 40; ++k) {
    const double wT_new = k * h, wN_new = std::tan(p.psi) * std::max(0.0, wT_new - w_y);
    step2(law, s, wT_new - wT, wN_new - wN);
    wT = wT_new;
    wN = wN_new;
    const double sT = std::min(p.G * wT, strength), wpT = wT - sT / p.G;
    ok_T = ok_T && std::fabs(s.sigma_T[0] - sT) <= 1e-10 * strength;
    ok_N = ok_N && std::fabs(s.sigma_N + load) <= 1e-10 * load;
    ok_wp = ok_wp && std::fabs(s.wp_T[0] - wpT) <= 1e-10 * w_y;
    ok_dil = ok_dil && std::fabs(s.wp_N - std::tan(p.psi) * s.wp_T[0]) <= 1e-10 * w_y;
    // D = lambda (c + |sigma_N| (tan phi - tan psi)) with lambda = w_T^p (spec section 4).
    const double D = wpT * (p.c + load * (law.tan_phi - law.tan_psi));
    ok_D = ok_D && std::fabs(s.dissipation - D) <= 1e-9 * (1.0 + D);
  }
  unit::check(ok_T, "constant load: sigma_T = min(G w_T, p tan(phi) + c) at every step");
  unit::check(ok_N, "constant load: sigma_N stays -p");
  unit::check(ok_wp, "constant load: plastic slip = w_T - sigma_T / G");
  unit::check(ok_dil, "constant load: plastic opening = tan(psi) x plastic slip");
  unit::check(ok_D, "constant load: dissipation = (c + p (tan phi - tan psi)) x plastic slip");
  unit::check(s.status == InterfaceStatus::Slip, "constant load: status slip after yield");
}

// Direct shear at constant normal DISPLACEMENT (dw_N = 0), psi != phi. On the yield surface
// the spec-5 matrix gives d sigma_N / d w_T = -E G tan(psi) / H and d sigma_T / d w_T =
// G - G^2/H; the seed's symmetric matrix would give -E G tan(phi) / H instead.
void testDirectShearConstantDisplacement() {
  const InterfaceParams p = baseParams();
  const InterfaceLaw law(p);
  const double load = 1e5, w_y = (load * law.tan_phi + p.c) / p.G, h = 0.37 * w_y;
  auto s = interfaceInitialState<2>(law, -load);
  double sN_prev = 0, sT_prev = 0;
  for (int k = 0; k < 6; ++k) {
    sN_prev = s.sigma_N;
    sT_prev = s.sigma_T[0];
    step2(law, s, h, 0.0);
  }
  const double rateN = (s.sigma_N - sN_prev) / h, rateT = (s.sigma_T[0] - sT_prev) / h;
  const double expectN = -p.E * p.G * law.tan_psi / law.H, seedN = -p.E * p.G * law.tan_phi / law.H;
  unit::near(rateN, expectN, 1e-9, 0.0, "constant displacement: d sigma_N / d w_T = -E G tan(psi) / H");
  unit::check(std::fabs(rateN - seedN) > 0.5 * std::fabs(seedN - expectN), "constant displacement: not the seed's -E G tan(phi) / H");
  unit::near(rateT, p.G - p.G * p.G / law.H, 1e-9, 0.0, "constant displacement: d sigma_T / d w_T = G - G^2 / H");
  unit::near(yield2(law, s), 0.0, 0.0, 1e-9 * p.c, "constant displacement: stays on f = 0");
}

// One 2D step of any size from (sigma_T0, sigma_N0) with the closed form of spec 5: gamma
// from the linear f on the branch of sign s, then the total-increment matrix.
struct Closed {
  double sT, sN, gamma;
};
Closed closedForm2D(const InterfaceLaw &law, double sT0, double sN0, double dwT, double dwN, double s) {
  // f = s (sT0 + g G dwT) + (sN0 + g E dwN) tan(phi) - c = 0 on the branch of sign s.
  const double gamma = (law.c - s * sT0 - sN0 * law.tan_phi) / (s * law.G * dwT + law.E * dwN * law.tan_phi);
  if (gamma >= 1.0) return {sT0 + law.G * dwT, sN0 + law.E * dwN, gamma}; // elastic step
  const double r = 1.0 - gamma, E = law.E, G = law.G, H = law.H, tf = law.tan_phi, tp = law.tan_psi;
  const double dsT = (G - r * G * G / H) * dwT - s * r * (E * G * tf / H) * dwN;
  const double dsN = -s * r * (E * G * tp / H) * dwT + (E - r * E * E * tf * tp / H) * dwN;
  return {sT0 + dsT, sN0 + dsN, gamma};
}

void testLargeIncrements2D() {
  const InterfaceParams p = baseParams();
  const InterfaceLaw law(p);
  const double load = 1e5, R0 = load * law.tan_phi + p.c, w_y = R0 / p.G;
  double worst = 0.0, worst_f = 0.0;
  // From rest: shear of 1.01 to 1000 yield jumps, with compression, none, or opening
  // (opening limited so that the pair stays compressed: dw_N < p / E). Compression with
  // 1.01 w_y stays elastic (the closed form then is the trial).
  for (double kT : {1.01, 2.0, 10.0, 1000.0, -3.0})
    for (double kN : {0.0, -0.3, 0.2}) {
      auto s = interfaceInitialState<2>(law, -load);
      step2(law, s, kT * w_y, kN * w_y);
      const Closed e = closedForm2D(law, 0.0, -load, kT * w_y, kN * w_y, kT > 0 ? 1.0 : -1.0);
      worst = std::max({worst, std::fabs(s.sigma_T[0] - e.sT) / R0, std::fabs(s.sigma_N - e.sN) / load});
      if (e.gamma < 1.0) worst_f = std::max(worst_f, std::fabs(yield2(law, s)) / R0);
    }
  unit::near(worst, 0.0, 0.0, 1e-10, "2D from rest, increments of 1.01 to 1000 yield jumps: exact closed form");
  unit::near(worst_f, 0.0, 0.0, 1e-12, "2D from rest: ends on f = 0");

  // Reversals that start ON the yield surface and cross to the other side (gamma = 0 is
  // also a root there; the seed's smallest root would be wrong by tens of percent).
  worst = 0.0;
  for (double kT : {-3.0, -4.0, -50.0})
    for (double kN : {0.0, -0.2, 0.1}) {
      auto s = interfaceInitialState<2>(law, -load);
      step2(law, s, 2.0 * w_y, 0.0); // on the surface, sigma_T > 0
      const double sT0 = s.sigma_T[0], sN0 = s.sigma_N;
      step2(law, s, kT * w_y, kN * w_y);
      const Closed e = closedForm2D(law, sT0, sN0, kT * w_y, kN * w_y, -1.0);
      worst = std::max({worst, std::fabs(s.sigma_T[0] - e.sT) / R0, std::fabs(s.sigma_N - e.sN) / load});
      if (!(e.gamma > 0.0 && e.gamma < 1.0)) worst = 1.0; // the case must cross the surface
    }
  unit::near(worst, 0.0, 0.0, 1e-10, "2D reversal from the yield surface to the opposite side: exact closed form");

  // Reversal that stays inside: pure elastic unloading (lambda would be negative).
  auto s = interfaceInitialState<2>(law, -load);
  step2(law, s, 2.0 * w_y, 0.0);
  const double sT0 = s.sigma_T[0], sN0 = s.sigma_N, wpT0 = s.wp_T[0], wpN0 = s.wp_N;
  step2(law, s, -0.5 * w_y, -0.1 * w_y);
  unit::near(s.sigma_T[0], sT0 - 0.5 * p.G * w_y, 1e-13, 0.0, "2D unloading from the surface: sigma_T elastic");
  unit::near(s.sigma_N, sN0 - 0.1 * p.E * w_y, 1e-13, 0.0, "2D unloading from the surface: sigma_N elastic");
  unit::check(s.wp_T[0] == wpT0 && s.wp_N == wpN0 && s.status == InterfaceStatus::Stick,
              "2D unloading from the surface: no plastic jump, status stick");
}

// 3D: the same planar path as 2D gives the same numbers (the 3D root is the quadratic one).
void testPlanar3DMatches2D() {
  const InterfaceLaw law(baseParams());
  auto s2 = interfaceInitialState<2>(law, -1e5);
  auto s3 = interfaceInitialState<3>(law, -1e5);
  const double w_y = (1e5 * law.tan_phi + law.c) / law.G;
  const double path[][2] = {{3, 0}, {-5, -0.1}, {0.5, 0}, {7, 0.05}, {-20, 0}};
  double worst = 0.0;
  for (const auto &inc : path) {
    step2(law, s2, inc[0] * w_y, inc[1] * w_y);
    const double dw[2] = {0.0, inc[0] * w_y}; // along the second tangent, to exercise both
    interfaceUpdate<3>(law, s3, dw, inc[1] * w_y);
    worst = std::max({worst, std::fabs(s3.sigma_T[1] - s2.sigma_T[0]), std::fabs(s3.sigma_N - s2.sigma_N),
                      std::fabs(s3.sigma_T[0])});
  }
  unit::near(worst / 1e5, 0.0, 0.0, 1e-10, "3D kernel on a planar path with reversals equals the 2D one");
}

// 3D path that turns by 90 degrees while slipping: w_T along e1 to 3 w_y, then along e2 for
// 3 w_y, with w_N fixed. No closed form; the reference is the same law on 2^16 sub-steps per
// leg. An explicit update from the yield point is first order: halving the step halves the
// error. Along every run f <= 0 after each update and dissipation never decreases.
struct Run3D {
  double sT[2], sN;
  bool admissible, dissipation_monotone;
};
Run3D turnPath(const InterfaceLaw &law, int n) {
  const double load = 1e5, w_y = (load * law.tan_phi + law.c) / law.G;
  auto s = interfaceInitialState<3>(law, -load);
  Run3D r{{0, 0}, 0, true, true};
  for (int leg = 0; leg < 2; ++leg)
    for (int k = 0; k < n; ++k) {
      const double h = 3.0 * w_y / n;
      const double dw[2] = {leg == 0 ? h : 0.0, leg == 1 ? h : 0.0};
      const double D0 = s.dissipation;
      interfaceUpdate<3>(law, s, dw, 0.0);
      // Roundoff bound relative to the current strength (the return tolerates 1e-13 of it).
      r.admissible = r.admissible && yield3(law, s) <= 1e-12 * (law.c - s.sigma_N * law.tan_phi);
      r.dissipation_monotone = r.dissipation_monotone && s.dissipation >= D0;
    }
  r.sT[0] = s.sigma_T[0];
  r.sT[1] = s.sigma_T[1];
  r.sN = s.sigma_N;
  return r;
}

void testTurning3D() {
  const InterfaceLaw law(baseParams());
  const Run3D ref = turnPath(law, 1 << 16);
  std::vector<double> err;
  bool admissible = ref.admissible, monotone = ref.dissipation_monotone;
  for (int n : {16, 32, 64, 128, 256}) {
    const Run3D r = turnPath(law, n);
    err.push_back(std::hypot(r.sT[0] - ref.sT[0], r.sT[1] - ref.sT[1]) + std::fabs(r.sN - ref.sN));
    admissible = admissible && r.admissible;
    monotone = monotone && r.dissipation_monotone;
  }
  bool first_order = true;
  std::string orders;
  for (std::size_t k = 1; k < err.size(); ++k) {
    const double order = std::log2(err[k - 1] / err[k]);
    orders += " " + std::to_string(order);
    first_order = first_order && order > 0.85 && order < 1.2;
  }
  unit::report(first_order && err.back() < 1e-2 * 1e5, "3D turning path converges at first order to the sub-stepped reference",
               "(observed orders" + orders + ")");
  unit::check(admissible, "3D turning path: f <= 0 after every update");
  unit::check(monotone, "3D turning path: dissipation never decreases");
}

// Drift: on the surface with sigma_T = (R, 0), a shear increment of 10 R / G perpendicular to
// sigma_T has t.dw_T = 0, so lambda = 0 and the forward step is the trial (R, 10 R): |.| =
// sqrt(101) R. The return scales it back to R along (1, 10)/sqrt(101); the drift sqrt(101) R
// - R becomes plastic slip drift / G and the elastic energy removed, (101 - 1) R^2 / 2G, is
// dissipated. phi = psi = 0 (R = c exactly): with phi > 0 the start state sits a roundoff
// delta off the surface and a path tangent to it exits at gamma = sqrt(2 delta R) / |b|
// ~ 1e-9, a true but roundoff-driven sliver of plastic flow that this check is not about.
void testDriftReturn() {
  InterfaceParams p = baseParams();
  p.phi = p.psi = 0.0;
  const InterfaceLaw law(p);
  const double load = 1e5, R = p.c;
  auto s = interfaceInitialState<3>(law, -load);
  s.sigma_T[0] = R;
  const double slip0 = s.slip, D0 = s.dissipation;
  const double turn[2] = {0.0, 10.0 * R / p.G};
  const double drift = interfaceUpdate<3>(law, s, turn, 0.0);
  unit::near(drift, (std::sqrt(101.0) - 1.0) * R, 1e-12, 0.0, "drift: the correction reported is |trial| - R");
  unit::near(s.sigma_T[0], R / std::sqrt(101.0), 1e-12, 0.0, "drift: sigma_T returned along its direction (1)");
  unit::near(s.sigma_T[1], 10.0 * R / std::sqrt(101.0), 1e-12, 0.0, "drift: sigma_T returned along its direction (2)");
  unit::near(s.sigma_N, -load, 1e-14, 0.0, "drift: sigma_N fixed by the return");
  unit::near(s.slip - slip0, drift / p.G, 1e-12, 0.0, "drift: booked as plastic slip");
  unit::near(s.dissipation - D0, 50.0 * R * R / p.G, 1e-12, 0.0, "drift: dissipation = removed elastic energy");
  unit::check(std::hypot(s.sigma_T[0], s.sigma_T[1]) <= R * (1 + 1e-14), "drift: f <= 0 after the return");
  unit::check(s.status == InterfaceStatus::Slip, "drift: status slip");
}

// Opening and re-contact, e_ini = 0.1 mm, no tensile strength, psi = 0 so that shear at
// sigma_N = 0 has strength exactly c.
void testOpeningAndRecontact() {
  InterfaceParams p = baseParams();
  p.psi = 0.0;
  p.e_ini = 1e-4;
  const InterfaceLaw law(p);
  const double load = 1e5;
  auto s = interfaceInitialState<2>(law, -load); // u = -p/E = -1 mm
  // Open to 0.05 mm beyond the zero-stress state: still within e_ini, so in contact with
  // sigma_N = 0 (cut-off) and shear strength c.
  step2(law, s, 0.0, load / p.E + 0.5e-4);
  unit::near(s.sigma_N, 0.0, 0.0, 1e-9, "within e_ini: sigma_N = 0 at the tension cut-off");
  unit::check(s.status != InterfaceStatus::Open, "within e_ini: still in contact");
  step2(law, s, 2.0 * p.c / p.G, 0.0);
  unit::near(s.sigma_T[0], p.c, 1e-12, 0.0, "within e_ini: shear limited by the cohesion c");
  unit::near(s.wp_T[0], p.c / p.G, 1e-12, 0.0, "within e_ini: slip beyond c / G is plastic");
  const double D_before = s.dissipation;
  // Beyond e_ini: traction free; the stored shear energy c^2 / 2G is lost with the bond.
  step2(law, s, 0.0, 1e-4);
  unit::check(s.status == InterfaceStatus::Open && s.sigma_T[0] == 0.0 && s.sigma_N == 0.0,
              "beyond e_ini: open and traction free");
  unit::near(s.dissipation - D_before, p.c * p.c / (2 * p.G), 1e-12, 0.0, "opening: stored energy c^2/2G booked as dissipated");
  step2(law, s, 5e-3, -1e-4); // back to u = 0.05 mm, large shear: no contact yet
  unit::check(s.status == InterfaceStatus::Open && s.sigma_T[0] == 0.0 && s.sigma_N == 0.0,
              "open: closing without touching carries no traction");
  // From u = 0.05 mm a normal step of -0.1 mm touches at beta = 1/2; the rest of the step
  // (dw_T = 1e-5 / 2, dw_N = -0.05 mm) acts from zero traction: sigma_N = -E 0.05 mm,
  // sigma_T = G 0.5e-5 (no memory of the c reached before opening), inside the strength.
  step2(law, s, 1e-5, -1e-4);
  unit::near(s.sigma_N, -p.E * 0.5e-4, 1e-12, 0.0, "re-contact: sigma_N = E x penetration");
  unit::near(s.sigma_T[0], p.G * 0.5e-5, 1e-12, 0.0, "re-contact: shear restarts from the current w_T");
  unit::check(s.status == InterfaceStatus::Stick, "re-contact: stick");
}

// Tension cut-off and cohesion: sigma_t = 1 kPa, c = 2 kPa, phi = 30 (c / tan phi = 3.46 kPa),
// psi = 0 so that H = G and the slip plateau is flat.
void testTensionCutoffAndCohesion() {
  InterfaceParams p = baseParams();
  p.psi = 0.0;
  p.tensile_strength = 1e3;
  p.e_ini = 1e-3;
  const InterfaceLaw law(p);
  auto s = interfaceInitialState<2>(law, 0.0);
  step2(law, s, 0.0, 2e-5); // E x 2e-5 = 2 kPa > sigma_t
  unit::near(s.sigma_N, p.tensile_strength, 1e-14, 0.0, "tension cut-off: sigma_N capped at sigma_t");
  step2(law, s, 2.0 * 1e3 / p.G, 0.0);
  const double R = p.c - p.tensile_strength * law.tan_phi; // strength under tension
  unit::near(s.sigma_T[0], R, 1e-12, 0.0, "tension: shear strength c - sigma_t tan(phi)");
  step2(law, s, 0.0, -2e-5); // back to the zero-stress opening: the plateau is reversible
  unit::near(s.sigma_N, 0.0, 0.0, 1e-9, "tension cut-off: closing back to u = 0 gives sigma_N = 0");
  unit::check(yield2(law, s) <= 1e-12 * p.c, "tension: f <= 0 after closing");
  // Pulled beyond e_ini = 1 mm to u = 2 mm: open and traction-free, so it holds no energy (the
  // plateau's sigma_t u_t / 2 + sigma_t (u - u_t) = 2.0 J/m^2 belongs to a pair still bonded).
  step2(law, s, 0.0, 2e-3);
  unit::check(s.status == InterfaceStatus::Open && detail::storedEnergy<2>(law, s) == 0.0, "tension: an open pair stores no energy");

  // phi = 0: Tresca, strength c whatever the normal traction.
  InterfaceParams q = baseParams();
  q.phi = q.psi = 0.0;
  const InterfaceLaw tresca(q);
  auto t = interfaceInitialState<2>(tresca, -1e6);
  step2(tresca, t, 10.0 * q.c / q.G, -1e-4);
  unit::near(t.sigma_T[0], q.c, 1e-12, 0.0, "phi = 0: shear strength is c under any compression");
}

// Apex: sigma_t = c / tan(phi). Pulled onto the plateau sigma_N = sigma_t the strength is
// c - sigma_t tan(phi) = 0: any shear is all plastic slip, sigma_T stays 0, the dissipation
// rate lambda (c - sigma_N (tan phi - tan psi)) is 0 with psi = 0.
void testApex() {
  InterfaceParams p = baseParams();
  p.psi = 0.0;
  p.e_ini = 1.0;
  p.tensile_strength = p.c / std::tan(p.phi);
  const InterfaceLaw law(p);
  auto s = interfaceInitialState<3>(law, 0.0);
  const double none[2] = {0.0, 0.0};
  interfaceUpdate<3>(law, s, none, 1e-3); // far beyond sigma_t / E: on the plateau
  unit::near(s.sigma_N, p.tensile_strength, 1e-14, 0.0, "apex: sigma_N = sigma_t = c / tan(phi)");
  const double shear[2] = {3e-4, -4e-4};
  interfaceUpdate<3>(law, s, shear, 0.0);
  interfaceUpdate<3>(law, s, shear, 1e-5);
  const bool finite = std::isfinite(s.sigma_T[0]) && std::isfinite(s.sigma_T[1]) && std::isfinite(s.dissipation);
  unit::check(finite, "apex: no NaN");
  unit::near(std::hypot(s.sigma_T[0], s.sigma_T[1]), 0.0, 0.0, 1e-9 * p.c, "apex: sigma_T stays 0");
  unit::near(s.slip, 2.0 * 5e-4, 1e-9, 0.0, "apex: the whole shear jump is plastic slip");
  unit::near(s.dissipation, 0.0, 0.0, 1e-9 * p.c * 1e-3, "apex: zero dissipation (zero strength)");
}

// The geostatic static solve treats every pair as the linear spring sigma_N = sigma_N0 + E w_N,
// sigma_T = G w_T and keeps that answer only where interfaceOnLinearStickBranch holds after one
// law increment by the whole static jump: there the law must give exactly the spring's
// traction, and elsewhere (slip, the tension plateau, open) the predicate must be false.
void testLinearStickBranch() {
  InterfaceParams p = baseParams();
  p.e_ini = 1e-3;
  p.tensile_strength = 1e3; // below c / tan(phi) = 3464 Pa
  const InterfaceLaw law(p);
  const double sN0 = -1e5, strength = p.c - sN0 * std::tan(p.phi); // 59735 Pa
  auto s = interfaceInitialState<2>(law, sN0);
  unit::check(interfaceOnLinearStickBranch<2>(law, s), "linear branch: the initial compressed state");
  const double dwT = 0.5 * strength / p.G, dwN = 2e-4; // half the strength; less compression
  step2(law, s, dwT, dwN);
  unit::check(interfaceOnLinearStickBranch<2>(law, s), "linear branch: half the shear strength");
  unit::near(s.sigma_T[0], p.G * dwT, 1e-14, 0.0, "linear branch: sigma_T = G w_T");
  unit::near(s.sigma_N, sN0 + p.E * dwN, 1e-14, 0.0, "linear branch: sigma_N = sigma_N0 + E w_N");
  auto slipping = interfaceInitialState<2>(law, sN0);
  step2(law, slipping, 2.0 * strength / p.G, 0.0);
  unit::check(!interfaceOnLinearStickBranch<2>(law, slipping), "off the linear branch: twice the shear strength (slip)");
  auto plateau = interfaceInitialState<2>(law, 0.0);
  step2(law, plateau, 0.0, 2e3 / p.E); // E u = 2 sigma_t, below e_ini
  unit::check(plateau.status == InterfaceStatus::Stick && !interfaceOnLinearStickBranch<2>(law, plateau), "off the linear branch: on the tension plateau");
  auto tension = interfaceInitialState<2>(law, 0.0);
  step2(law, tension, 0.0, 0.5e3 / p.E); // E u = sigma_t / 2
  unit::check(interfaceOnLinearStickBranch<2>(law, tension), "linear branch: tension below the cut-off");
  auto open = interfaceInitialState<2>(law, 0.0);
  step2(law, open, 0.0, 2e-3);
  unit::check(!interfaceOnLinearStickBranch<2>(law, open), "off the linear branch: open beyond e_ini");
}

} // namespace

int main() {
  testDirectShearConstantLoad();
  testDirectShearConstantDisplacement();
  testLargeIncrements2D();
  testPlanar3DMatches2D();
  testTurning3D();
  testDriftReturn();
  testOpeningAndRecontact();
  testTensionCutoffAndCohesion();
  testApex();
  testLinearStickBranch();
  return unit::failures();
}
