// The hysteretic (Masing) soil kernel (physics/hysteretic_soil.hpp) in strain-controlled cyclic
// simple shear, for every backbone kind, in 2D plane strain, in 3D, and in 3D with the shear
// in a rotated frame. The expected values come from:
// - the backbone itself (soil_backbone.hpp, tested against the papers in test_soil_backbone):
//   at the knot strains the model's first loading equals it;
// - Masing's rules: the first unloading from (gamma_a, tau_a) is tau_a - 2 F((gamma_a - gamma)/2),
//   exactly with the model's piecewise-linear F_N and within 2 max|F - F_N| (the N-surface
//   error, measured here on a dense grid) with the continuous F;
// - the closed-form Masing damping (2/pi)(2 int_0^gamma_a F / (gamma_a tau_a) - 1): of F_N
//   exactly, and of F within (4/pi) int |F - F_N| / (gamma_a tau_a), the same N-surface error;
// - energy: the response is linear between kinks, so the trapezoid work over steps that end
//   at the kinks is exact, and it must equal stored-energy change + booked dissipation.
#include "slipwave/physics/hysteretic_soil.hpp"

#include "unit_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

using namespace slipwave::physics;

namespace {

constexpr double kGmax = 4e7;   // vs = 150 m/s, rho = 1800 kg/m^3 [Pa]
constexpr double kBulk = 3.87e8; // nu = 0.45: K = 2 G (1 + nu) / (3 (1 - 2 nu)) [Pa]

struct Case {
  std::string  name;
  SoilBackbone backbone;
};

std::vector<Case> backbones() {
  const double theta[5] = {-2.28, -5.54, 1, 1, 0.99}; // Groholski et al. (2016) form, MASTODON's example
  DarendeliSoil clay;
  clay.plasticity_index = 15;
  clay.ocr = 2;
  clay.mean_effective_stress = 50e3;
  // An illustrative table shaped like a PI ~ 15 clay's curve (not a published one). Its
  // log-log slope falls from row to row (-0.004 .. -0.88), so tau is concave: the model holds
  // it exactly at the knots.
  std::vector<double> strain = {1e-6, 1e-5, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 1e-1};
  std::vector<double> ratio = {1.0, 0.99, 0.90, 0.76, 0.52, 0.29, 0.13, 0.055, 0.019};
  return {{"hyperbolic", mkzBackbone(5e-4)},
          {"MKZ s=0.8 beta=1.2", mkzBackbone(3e-4, 0.8, 1.2)},
          {"Darendeli PI 15", darendeliBackbone(clay)},
          {"GQ/H", gqhBackbone(kGmax, 6e4, theta)},
          {"table", tableBackbone(strain, ratio)},
          {"hyperbolic capped at 15 kPa", mkzBackbone(5e-4, 1, 1, 1.5e4 / kGmax)}};
}

// A rotation (Rodrigues) about the axis (1, 2, 3) by 0.9 rad: an arbitrary frame.
struct Rotation {
  double R[3][3];
  explicit Rotation(bool identity) {
    const double n[3] = {1 / std::sqrt(14.0), 2 / std::sqrt(14.0), 3 / std::sqrt(14.0)}, a = identity ? 0.0 : 0.9, c = std::cos(a), s = std::sin(a);
    const double K[3][3] = {{0, -n[2], n[1]}, {n[2], 0, -n[0]}, {-n[1], n[0], 0}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) R[i][j] = (i == j ? c : 0) + s * K[i][j] + (1 - c) * n[i] * n[j];
  }
  // R A R^T (to the global frame) or R^T A R (back to the local one).
  void apply(const double A[3][3], double B[3][3], bool to_global) const {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double s = 0;
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) s += (to_global ? R[i][k] * R[j][l] : R[k][i] * R[l][j]) * A[k][l];
        B[i][j] = s;
      }
  }
};

// One quadrature point under a strain history: the state, and the work done on it by the
// trapezoid rule over the updates.
template <int Dim>
struct Point {
  using Layout = HystereticLayout<Dim>;
  const HystereticSoilModel &model;
  Rotation                   frame;
  std::vector<double>        state;
  double                     E[3][3] = {}, S[3][3] = {}; // global strain and stress
  double                     dissipated = 0, work = 0, last_dissipation = 0, last_work = 0, updates = 0;

  Point(const HystereticSoilModel &m, bool rotated) : model(m), frame(!rotated), state(hystereticStateSize<Dim>(m), 0.0) {}

  void apply(const double E_new[3][3]) {
    double strain[Layout::kStrain], stress[Layout::kStress];
    if constexpr (Dim == 2) {
      strain[0] = E_new[0][0], strain[1] = E_new[1][1], strain[2] = E_new[0][1];
    } else {
      strain[0] = E_new[0][0], strain[1] = E_new[1][1], strain[2] = E_new[2][2];
      strain[3] = E_new[0][1], strain[4] = E_new[1][2], strain[5] = E_new[0][2];
    }
    last_dissipation = hystereticUpdate<Dim>(model, state.data(), strain, stress, state.data(), ++updates);
    double S_new[3][3] = {};
    if constexpr (Dim == 2) {
      S_new[0][0] = stress[0], S_new[1][1] = stress[1], S_new[0][1] = S_new[1][0] = stress[2], S_new[2][2] = stress[3];
    } else {
      S_new[0][0] = stress[0], S_new[1][1] = stress[1], S_new[2][2] = stress[2];
      S_new[0][1] = S_new[1][0] = stress[3], S_new[1][2] = S_new[2][1] = stress[4], S_new[0][2] = S_new[2][0] = stress[5];
    }
    last_work = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) last_work += 0.5 * (S[i][j] + S_new[i][j]) * (E_new[i][j] - E[i][j]);
    work += last_work;
    dissipated += last_dissipation;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) E[i][j] = E_new[i][j], S[i][j] = S_new[i][j];
  }
  // Simple shear gamma in the local x-y plane; returns the local stress.
  void shear(double gamma, double local_stress[3][3]) {
    double El[3][3] = {}, Eg[3][3];
    El[0][1] = El[1][0] = gamma / 2;
    frame.apply(El, Eg, true);
    apply(Eg);
    frame.apply(S, local_stress, false);
  }
  double shear(double gamma) {
    double s[3][3];
    shear(gamma, s);
    return s[0][1];
  }
  double stored() const {
    double strain[Layout::kStrain];
    if constexpr (Dim == 2) {
      strain[0] = E[0][0], strain[1] = E[1][1], strain[2] = E[0][1];
    } else {
      strain[0] = E[0][0], strain[1] = E[1][1], strain[2] = E[2][2], strain[3] = E[0][1], strain[4] = E[1][2], strain[5] = E[0][2];
    }
    return hystereticStoredEnergy<Dim>(model, state.data(), strain);
  }
};

// Strains of a monotone branch from `from` to `to` that every kink of the response lies on
// (first loading: the yield strains; a branch from a reversal at g_r: g_r -+ 2 gamma_i), with
// the midpoints between them, so that the response is linear within each step.
std::vector<double> branchPath(const HystereticSoilModel &m, double from, double to, bool virgin) {
  std::vector<double> p = {to};
  const double        dir = to > from ? 1 : -1;
  for (double y : m.elementYieldStrain()) {
    const double g = virgin ? dir * y : from + dir * 2 * y;
    if ((g - from) * dir > 0 && (to - g) * dir > 0) p.push_back(g);
  }
  std::sort(p.begin(), p.end(), [&](double a, double b) { return (a - b) * dir < 0; });
  std::vector<double> out;
  double              prev = from;
  for (double g : p) {
    out.push_back(0.5 * (prev + g));
    out.push_back(g);
    prev = g;
  }
  return out;
}

// max |F - F_N| and int |F - F_N| over [0, gamma_a] on a dense grid (log-spaced from 1e-9,
// so both ends of every segment are resolved).
struct DiscretisationError {
  double sup, integral, sup_relative;
};
DiscretisationError discretisationError(const HystereticSoilModel &m, const SoilBackbone &b, double gamma_a) {
  DiscretisationError e{0, 0, 0};
  const int           n = 40000;
  double              prev_g = 0, prev_err = 0;
  for (int k = 0; k <= n; ++k) {
    const double g = 1e-9 * std::pow(gamma_a / 1e-9, (double)k / n), f = backboneStress(b, kGmax, g);
    const double err = std::fabs(f - m.backboneStress(g));
    e.sup = std::fmax(e.sup, err);
    e.sup_relative = std::fmax(e.sup_relative, err / f);
    e.integral += 0.5 * (err + prev_err) * (g - prev_g);
    prev_g = g;
    prev_err = err;
  }
  return e;
}

// int_0^gamma_a F_N, exactly: sum_i G_i int_0^gamma_a min(g, gamma_i) dg.
double integralOfModelBackbone(const HystereticSoilModel &m, double gamma_a) {
  double s = 0;
  for (int i = 0; i < m.surfaces(); ++i) {
    const double y = m.elementYieldStrain()[i], G = m.elementModulus()[i];
    s += y < gamma_a ? G * (y * gamma_a - 0.5 * y * y) : G * 0.5 * gamma_a * gamma_a;
  }
  return s;
}

// The knot nearest to a target strain.
double knotNear(const HystereticSoilModel &m, double target) {
  double best = m.knotStrains()[0];
  for (double k : m.knotStrains())
    if (std::fabs(std::log(k / target)) < std::fabs(std::log(best / target))) best = k;
  return best;
}

// The cyclic simple-shear checks of one backbone in one frame.
template <int Dim>
void cyclicShear(const Case &c, bool rotated) {
  const HystereticSoilModel m(kGmax, kBulk, c.backbone);
  const std::string         tag = c.name + (Dim == 2 ? " [2D]: " : rotated ? " [3D rotated]: " : " [3D]: ");
  const SoilBackbone       &b = c.backbone;
  unit::check(m.knotDeviation() <= 1e-12, tag + "a concave backbone: the model keeps it at every knot (no majorant)");

  // First loading through every kink: the stress at each knot is the backbone's, and the local
  // stress is pure shear (no other component beyond round-off).
  {
    Point<Dim> p(m, rotated);
    bool       knots_ok = true, pure_ok = true;
    double     worst = 0;
    for (double g : branchPath(m, 0, m.knotStrains().back(), true)) {
      double s[3][3];
      p.shear(g, s);
      const double tau = s[0][1];
      for (double k : m.knotStrains())
        if (k == g) {
          const double want = backboneStress(b, kGmax, k);
          worst = std::fmax(worst, std::fabs(tau - want) / want);
          knots_ok = knots_ok && std::fabs(tau - want) <= 1e-12 * want;
        }
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          if (!((i == 0 && j == 1) || (i == 1 && j == 0))) pure_ok = pure_ok && std::fabs(s[i][j]) <= 1e-11 * std::fabs(tau);
    }
    char what[200];
    std::snprintf(what, sizeof what, "%sfirst loading: tau = F(knot) at all %d knots (worst %.1e)", tag.c_str(), m.surfaces(), worst);
    unit::check(knots_ok, what);
    unit::check(pure_ok, tag + "first loading: the local stress is pure shear");
  }
  // G/Gmax = 1 at 1e-6 (the elastic limit): tau = Gmax gamma exactly, nothing dissipated.
  {
    Point<Dim>   p(m, rotated);
    const double tau = p.shear(1e-6);
    unit::near(tau / (kGmax * 1e-6), 1.0, 1e-12, 0, tag + "G/Gmax at 1e-6 is 1");
    unit::check(p.dissipated == 0, tag + "no dissipation at 1e-6");
  }
  // A closed cycle at three amplitudes (knots near 1e-4, 1e-3, 1e-2): Masing's first
  // unloading, the loop's damping, and the energy.
  for (double target : {1e-4, 1e-3, 1e-2}) {
    const double gamma_a = knotNear(m, target), tau_a = backboneStress(b, kGmax, gamma_a);
    char         amp[40];
    std::snprintf(amp, sizeof amp, "gamma_a = %.3g: ", gamma_a);
    Point<Dim> p(m, rotated);
    for (double g : branchPath(m, 0, gamma_a, true)) p.shear(g);
    const DiscretisationError err = discretisationError(m, b, gamma_a);
    bool   exact_ok = true, masing_ok = true, step_energy_ok = true;
    double worst_masing = 0;
    const double stored_at_start = p.stored(), dissipated_at_start = p.dissipated, work_at_start = p.work;
    auto step = [&](double g, bool check_branch) {
      const double stored_before = p.stored();
      const double tau = p.shear(g);
      // Per step: trapezoid work = stored-energy change + dissipation (linear within the step).
      const double balance = p.last_work - (p.stored() - stored_before) - p.last_dissipation;
      step_energy_ok = step_energy_ok && std::fabs(balance) <= 1e-9 * tau_a * gamma_a;
      if (!check_branch) return;
      const double half = 0.5 * (gamma_a - g);
      const double exact = tau_a - 2 * m.backboneStress(half), masing = tau_a - 2 * backboneStress(b, kGmax, half);
      exact_ok = exact_ok && std::fabs(tau - exact) <= 1e-11 * tau_a;
      worst_masing = std::fmax(worst_masing, std::fabs(tau - masing));
      masing_ok = masing_ok && std::fabs(tau - masing) <= 2 * err.sup * 1.001 + 1e-11 * tau_a;
    };
    for (double g : branchPath(m, gamma_a, -gamma_a, false)) step(g, true);
    for (double g : branchPath(m, -gamma_a, gamma_a, false)) step(g, false);
    char what[240];
    unit::check(exact_ok, tag + amp + "first unloading = tau_a - 2 F_N((gamma_a - gamma)/2) (Masing on the N-surface backbone)");
    std::snprintf(what, sizeof what, "%s%sfirst unloading within 2 max|F - F_N| = %.3g of tau_a - 2 F((gamma_a - gamma)/2) (worst %.3g; max |F - F_N|/F = %.4f)", tag.c_str(), amp,
                  2 * err.sup / tau_a, worst_masing / tau_a, err.sup_relative);
    unit::check(masing_ok, what);
    // The loop: from gamma_a to -gamma_a and back, the dissipation booked over the loop is its area.
    const double area = p.dissipated - dissipated_at_start, xi = area / (2 * M_PI * tau_a * gamma_a);
    const double xi_model = 2 / M_PI * (2 * integralOfModelBackbone(m, gamma_a) / (gamma_a * tau_a) - 1);
    const double xi_curve = masingDampingRatio(b, gamma_a), bound = 4 / M_PI * err.integral / (gamma_a * tau_a);
    unit::near(xi, xi_model, 1e-10, 0, tag + amp + "loop damping = (2/pi)(2 int F_N / (gamma_a tau_a) - 1)");
    std::snprintf(what, sizeof what, "%s%sloop damping %.5f within (4/pi) int|F - F_N| / (gamma_a tau_a) = %.5f of the backbone's Masing damping %.5f", tag.c_str(), amp, xi,
                  bound, xi_curve);
    unit::check(std::fabs(xi - xi_curve) <= bound * 1.001 + 1e-10, what);
    // Energy over the closed loop: work done = dissipation booked; the stored energy returns.
    unit::near(p.work - work_at_start, area, 1e-10, 0, tag + amp + "closed loop: work done = dissipation booked");
    unit::near(p.stored(), stored_at_start, 1e-10, 0, tag + amp + "closed loop: stored energy returns");
    unit::check(step_energy_ok, tag + amp + "every step: trapezoid work = stored-energy change + dissipation");
    unit::check(area > 0, tag + amp + "the loop dissipates");
  }
  // Beyond the last knot every element has yielded: tau = the strength.
  {
    Point<Dim> p(m, rotated);
    for (double g : branchPath(m, 0, 0.3, true)) p.shear(g);
    double s[3][3];
    p.shear(0.3, s);
    unit::near(s[0][1], m.strength(), 1e-12, 0, tag + "beyond the last knot: tau = the strength sum G_i gamma_i");
    unit::near(m.strength(), backboneStress(b, kGmax, m.knotStrains().back()), 1e-12, 0, tag + "the strength = F(last knot)");
  }
}

// With steps that do not end at the kinks (what a time integrator takes), the trapezoid work
// of a step with a kink inside differs from the exact path work (stored-energy change + the
// dissipation booked, exact for a straight step) by O(step^2): measured over one closed loop
// with M uniform steps, the mismatch is small and falls ~4x when M doubles.
void energyWithUniformSteps() {
  const HystereticSoilModel m(kGmax, kBulk, darendeliBackbone(DarendeliSoil{}));
  const double              gamma_a = 1e-3;
  double                    mismatch[2] = {0, 0}, area = 0;
  for (int level = 0; level < 2; ++level) {
    const int steps = 100 << level;
    Point<2>  p(m, false);
    for (int k = 1; k <= steps / 4; ++k) p.shear(gamma_a * k / (steps / 4.0)); // first loading
    const double w0 = p.work, d0 = p.dissipated, psi0 = p.stored();
    for (int k = 1; k <= steps; ++k) p.shear(gamma_a * std::cos(2 * M_PI * k / steps)); // uniform in phase: one closed loop
    area = p.dissipated - d0;
    mismatch[level] = std::fabs((p.work - w0) - (p.stored() - psi0) - area);
  }
  char what[200];
  std::snprintf(what, sizeof what, "uniform steps: trapezoid work - (stored change + dissipation) over a loop = %.2e (100 steps), %.2e (200) of the loop's area", mismatch[0] / area,
                mismatch[1] / area);
  unit::check(mismatch[0] <= 1e-3 * area && mismatch[1] <= mismatch[0] / 3, what);
}

// 2D plane strain is 3D with eps_zz = eps_xz = eps_yz = 0: a path with normal and shear
// strains in the plane gives the same stresses (sigma_zz included) and dissipation.
void planeStrainIs3D() {
  const HystereticSoilModel m(kGmax, kBulk, darendeliBackbone(DarendeliSoil{}));
  std::vector<double>       s2(hystereticStateSize<2>(m), 0.0), s3(hystereticStateSize<3>(m), 0.0);
  bool                      ok = true;
  double                    total = 0;
  for (int k = 1; k <= 400; ++k) {
    const double t = 0.05 * k, a = 2e-3 * std::sin(t) * (1 + 0.3 * std::sin(0.13 * t));
    const double exx = 0.4 * a * std::cos(1.7 * t), eyy = -0.25 * a * std::sin(0.6 * t), exy = 0.5 * a;
    const double e2[3] = {exx, eyy, exy}, e3[6] = {exx, eyy, 0, exy, 0, 0};
    double       st2[4], st3[6];
    const double d2 = hystereticUpdate<2>(m, s2.data(), e2, st2, s2.data(), k);
    const double d3 = hystereticUpdate<3>(m, s3.data(), e3, st3, s3.data(), k);
    total += d2;
    const double scale = 1e-13 * (std::fabs(st3[0]) + std::fabs(st3[1]) + std::fabs(st3[3]) + 1.0);
    ok = ok && std::fabs(st2[0] - st3[0]) <= scale && std::fabs(st2[1] - st3[1]) <= scale && std::fabs(st2[2] - st3[3]) <= scale &&
         std::fabs(st2[3] - st3[2]) <= scale && st3[4] == 0 && st3[5] == 0 && std::fabs(d2 - d3) <= 1e-13 * (d3 + 1e-30);
  }
  unit::check(ok, "plane strain = 3D with eps_zz = 0 along an in-plane path (sigma_xx, yy, xy, zz and dissipation)");
  unit::check(total > 0, "that path yields (the comparison covers the plastic branch)");
}

// Volumetric strain is elastic: sigma = K tr(eps) I on a virgin point, and on a sheared point
// it changes the mean stress only, dissipating nothing.
void volumetricIsElastic() {
  const HystereticSoilModel m(kGmax, kBulk, mkzBackbone(5e-4));
  std::vector<double>       state(hystereticStateSize<3>(m), 0.0), before;
  const double              ev = -1e-2; // 1 % compression: far beyond every yield strain in shear
  const double              iso[6] = {ev / 3, ev / 3, ev / 3, 0, 0, 0};
  double                    st[6];
  const double              d = hystereticUpdate<3>(m, state.data(), iso, st, state.data(), 1);
  unit::check(d == 0, "volumetric: no dissipation");
  unit::near(st[0], kBulk * ev, 1e-15, 0, "volumetric: sigma_xx = K tr(eps)");
  unit::check(st[0] == st[1] && st[1] == st[2] && st[3] == 0 && st[4] == 0 && st[5] == 0, "volumetric: isotropic stress");
  bool virgin = true;
  for (int c = 0; c < HystereticLayout<3>::kDeviator; ++c)
    for (int i = 0; i < m.surfaces(); ++i) virgin = virgin && plasticStrain<3>(m, state.data(), c, i) == 0;
  unit::check(virgin && maxShearStrain<3>(m, state.data()) == 0, "volumetric: the plastic strains stay zero");
  // Shear to 2e-3, then compress on top.
  const double shear[6] = {0, 0, 0, 1e-3, 0, 0};
  double       st_shear[6];
  hystereticUpdate<3>(m, state.data(), shear, st_shear, state.data(), 2);
  before = state;
  const double both[6] = {ev / 3, ev / 3, ev / 3, 1e-3, 0, 0};
  const double d2 = hystereticUpdate<3>(m, state.data(), both, st, state.data(), 3);
  // Elements left on their yield surface by the shear sit there to round-off (|d| = r(1 + 1e-16)),
  // so an update with the same deviator may book ~1e-16 of tau gamma; nothing more.
  unit::check(d2 >= 0 && d2 <= 1e-14 * st_shear[3] * 2e-3, "volumetric on a sheared point: no dissipation beyond round-off");
  unit::near(st[3], st_shear[3], 1e-14, 0, "volumetric on a sheared point: the shear stress unchanged");
  unit::near((st[0] + st[1] + st[2]) / 3, kBulk * ev, 1e-13, 0, "volumetric on a sheared point: mean stress K tr(eps)");
  bool same = true;
  for (int c = 0; c < HystereticLayout<3>::kDeviator; ++c)
    for (int i = 0; i < m.surfaces(); ++i) same = same && std::fabs(plasticStrain<3>(m, state.data(), c, i) - plasticStrain<3>(m, before.data(), c, i)) <= 1e-18;
  unit::check(same, "volumetric on a sheared point: the plastic strains unchanged");
}

// Below the elastic limit the point is linear with Gmax for any number of cycles.
void elasticBelowLimit() {
  const HystereticSoilModel m(kGmax, kBulk, darendeliBackbone(DarendeliSoil{}));
  Point<2>                  p(m, false);
  bool                      ok = true;
  for (int k = 0; k <= 200; ++k) {
    const double g = 0.999e-6 * std::sin(0.3 * k);
    ok = ok && std::fabs(p.shear(g) - kGmax * g) <= 1e-15 * kGmax * 1e-6;
  }
  unit::check(ok && p.dissipated == 0, "below the elastic limit: tau = Gmax gamma over 200 steps, nothing dissipated");
}

// The calling conventions: evaluate only (null state_out), a separate trial state, the largest
// strain kept, the mobilised strength.
void callingConventions() {
  const HystereticSoilModel m(kGmax, kBulk, mkzBackbone(5e-4));
  std::vector<double>       committed(hystereticStateSize<3>(m), 0.0), trial(committed.size(), -1.0);
  const double              e1[6] = {1e-4, -2e-4, 0, 8e-4, -3e-4, 2e-4};
  double                    st_eval[6], st_trial[6], st_place[6];
  const double              d_eval = hystereticUpdate<3>(m, committed.data(), e1, st_eval, nullptr, 0);
  unit::check(std::all_of(committed.begin(), committed.end(), [](double x) { return x == 0; }), "state_out = null: nothing written");
  const double d_trial = hystereticUpdate<3>(m, committed.data(), e1, st_trial, trial.data(), 1);
  unit::check(std::all_of(committed.begin(), committed.end(), [](double x) { return x == 0; }), "separate state_out: the committed state untouched");
  const double d_place = hystereticUpdate<3>(m, committed.data(), e1, st_place, committed.data(), 1);
  bool same = d_eval == d_trial && d_trial == d_place && committed == trial;
  for (int k = 0; k < 6; ++k) same = same && st_eval[k] == st_trial[k] && st_trial[k] == st_place[k];
  unit::check(same, "evaluate-only, trial and in-place updates agree bit for bit");
  unit::near(maxShearStrain<3>(m, committed.data()), equivalentShearStrain<3>(e1), 1e-15, 0, "the state keeps the largest equivalent shear strain");
  const double e0[6] = {0, 0, 0, 0, 0, 0};
  hystereticUpdate<3>(m, committed.data(), e0, st_place, committed.data(), 2);
  unit::near(maxShearStrain<3>(m, committed.data()), equivalentShearStrain<3>(e1), 1e-15, 0, "... and keeps it after unloading");
  const double simple[6] = {0, 0, 0, 1.5e-3, 0, 0};
  unit::near(equivalentShearStrain<3>(simple), 3e-3, 1e-15, 0, "equivalent shear strain of simple shear gamma = gamma");
  const double tau[6] = {5, 5, 5, 0, 0, 7};
  unit::near(equivalentShearStress<3>(tau), 7, 1e-15, 0, "equivalent shear stress of shear tau plus a mean stress = |tau|");
  double big[6];
  std::vector<double> fresh(committed.size(), 0.0);
  const double        far[6] = {0, 0, 0, 0.25, 0, 0};
  hystereticUpdate<3>(m, fresh.data(), far, big, fresh.data(), 1);
  unit::near(mobilisedStrengthRatio<3>(m, big), 1.0, 1e-12, 0, "mobilised strength ratio 1 once every element yields");
  unit::near(m.secantModulusRatio(1e-3), backboneStress(mkzBackbone(5e-4), kGmax, 1e-3) / (kGmax * 1e-3), 0.02, 0, "secant G/Gmax of the model within the N-surface error");
}

// The tail (hysteretic_soil.hpp, "Cost"): the kernel visits only the elements that can yield,
// so along any path it must give what the model's definition gives element by element. The
// oracle below is that definition (every element's radial return, every update); a 3D path
// that turns, with cycles from below the elastic limit to 3e-3 and pauses, must agree with it
// to round-off in stress and plastic strains, the tail must have been used (a head short of N
// on most updates), and an evaluation in the tail must be the update's stress bit for bit.
template <int Dim>
struct Oracle {
  const HystereticSoilModel &model;
  std::vector<double>        p;
  explicit Oracle(const HystereticSoilModel &m) : model(m), p(HystereticLayout<Dim>::kDeviator * m.surfaces(), 0.0) {}
  // The deviatoric stress s (kDeviator components) at the deviatoric strain e, p updated.
  void update(const double *e, double *s) {
    constexpr int kDev = HystereticLayout<Dim>::kDeviator;
    const int     n = model.surfaces();
    for (int c = 0; c < kDev; ++c) s[c] = 0;
    for (int i = 0; i < n; ++i) {
      double d[kDev], dd = 0;
      for (int c = 0; c < kDev; ++c) d[c] = e[c] - p[c * n + i];
      // d:d with d_zz = -(d_xx + d_yy) and the shears counted twice.
      for (int c = 0; c < kDev; ++c) dd += (c < 2 ? 1.0 : 2.0) * d[c] * d[c];
      dd += (d[0] + d[1]) * (d[0] + d[1]);
      const double r = model.radius()[i];
      if (dd > r * r)
        for (int c = 0; c < kDev; ++c) {
          d[c] *= r / std::sqrt(dd);
          p[c * n + i] = e[c] - d[c];
        }
      for (int c = 0; c < kDev; ++c) s[c] += model.twiceModulus()[i] * d[c];
    }
  }
};

template <int Dim>
void tailIsTheModel() {
  using L = HystereticLayout<Dim>;
  const HystereticSoilModel m(kGmax, kBulk, darendeliBackbone(DarendeliSoil{}));
  std::vector<double>       state(hystereticStateSize<Dim>(m), 0.0);
  Oracle<Dim>               oracle(m);
  double                    worst_stress = 0, worst_plastic = 0, worst_energy = 0, scale = 0;
  int                       held = 0, steps = 0;
  double                    visits = 0;
  bool                      same_bits = true;
  for (int k = 1; k <= 6000; ++k, ++steps) {
    // Cycles of 200 updates whose amplitude walks from 5e-7 to 3e-3 and back, the direction
    // turning slowly, a pause (the same strain) every 500 updates.
    const double t = k % 500 < 20 ? 500.0 * (k / 500) : k, amp = 3e-3 * std::pow(6e-4, 0.5 + 0.5 * std::cos(2 * M_PI * t / 3000));
    const double a = amp * std::sin(2 * M_PI * t / 200), turn = 1e-3 * t;
    double       strain[L::kStrain] = {}, e[L::kDeviator], stress[L::kStress], eval[L::kStress], s_ref[L::kDeviator];
    strain[0] = 0.3 * a * std::cos(turn), strain[1] = -0.2 * a * std::sin(0.7 * turn);
    if constexpr (Dim == 2) {
      strain[2] = 0.5 * a;
    } else {
      strain[2] = 0.1 * a * std::sin(turn), strain[3] = 0.5 * a, strain[4] = 0.2 * a * std::cos(1.3 * turn), strain[5] = -0.15 * a;
    }
    const double head = state[L::kHead];
    hystereticUpdate<Dim>(m, state.data(), strain, eval, nullptr, 0);
    hystereticUpdate<Dim>(m, state.data(), strain, stress, state.data(), k);
    // A sweep of every element sets the tail at this update.
    const bool holds = state[L::kSince] != k;
    held += holds;
    visits += holds ? head : m.surfaces();
    for (int c = 0; c < L::kStress; ++c) same_bits = same_bits && eval[c] == stress[c];
    // The oracle's deviator: the kernel's stress less its mean part, in the state's components.
    const double tr = Dim == 2 ? strain[0] + strain[1] : strain[0] + strain[1] + strain[2];
    e[0] = strain[0] - tr / 3, e[1] = strain[1] - tr / 3;
    if constexpr (Dim == 2) {
      e[2] = strain[2];
    } else {
      e[2] = strain[3], e[3] = strain[4], e[4] = strain[5];
    }
    oracle.update(e, s_ref);
    // The stored energy, its tail from the header: the oracle's K tr^2 / 2 + sum_i G_i |e - p_i|^2.
    double w_ref = 0.5 * kBulk * tr * tr;
    for (int i = 0; i < m.surfaces(); ++i) {
      double d[L::kDeviator], dd = 0;
      for (int c = 0; c < L::kDeviator; ++c) d[c] = e[c] - oracle.p[c * m.surfaces() + i];
      for (int c = 0; c < L::kDeviator; ++c) dd += (c < 2 ? 1.0 : 2.0) * d[c] * d[c];
      w_ref += 0.5 * m.twiceModulus()[i] * (dd + (d[0] + d[1]) * (d[0] + d[1]));
    }
    worst_energy = std::max(worst_energy, std::fabs(hystereticStoredEnergy<Dim>(m, state.data(), strain) - w_ref));
    const double got[3] = {stress[0] - kBulk * tr, stress[1] - kBulk * tr, Dim == 2 ? stress[2] : stress[3]};
    for (int c = 0; c < 3; ++c) worst_stress = std::max(worst_stress, std::fabs(got[c] - s_ref[c]));
    if constexpr (Dim == 3) worst_stress = std::max({worst_stress, std::fabs(stress[4] - s_ref[3]), std::fabs(stress[5] - s_ref[4])});
    scale = std::max(scale, kGmax * amp);
    for (int c = 0; c < L::kDeviator; ++c)
      for (int i = 0; i < m.surfaces(); ++i)
        worst_plastic = std::max(worst_plastic, std::fabs(plasticStrain<Dim>(m, state.data(), c, i) - oracle.p[c * m.surfaces() + i]));
  }
  char what[240];
  std::snprintf(what, sizeof what, "%dD tail = the model's definition over %d updates: stress within %.1e of 2 Gmax e, plastic strains within %.1e (of 3e-3)", Dim, steps,
                worst_stress / scale, worst_plastic);
  // Round-off: the tail's stress is one product T e - P instead of N terms (1e-15 relative
  // each, N = 24 of them), and the plastic strains carry the returns' rounding.
  unit::check(worst_stress <= 1e-12 * scale && worst_plastic <= 1e-15, what);
  // The tail's energy T |e|^2 / 2 - e:P + E cancels: round-off of the terms, G (3e-3)^2 each.
  std::snprintf(what, sizeof what, "%dD stored energy with the tail from the header: within %.1e of Gmax (3e-3)^2 of the definition's", Dim,
                worst_energy / (kGmax * 9e-6));
  unit::check(worst_energy <= 1e-12 * kGmax * 9e-6, what);
  std::snprintf(what, sizeof what, "%dD the tail held on %d of %d updates; elements visited per update %.1f of %d", Dim, held, steps, visits / steps, m.surfaces());
  unit::check(held > steps / 2, what);
  unit::check(same_bits, "evaluate-only gives the in-place update's stress bit for bit, in the tail too");
}

// The bulk force's step (medium/hysteresis.cpp): the state settled to the accepted strain and
// the stress at the next one evaluated, fused into one pass, must be the two updates it
// replaces bit for bit (state, stress, dissipation). A random walk of the strain (steps from
// 1e-7 to 1e-3, log-uniform, in turning directions, within 3e-3) takes each branch of the
// fused pass often: the settle leaving the tail (a sweep and a new tail), the settle in the
// tail with the evaluation in it, and with the evaluation outside it.
template <int Dim>
void settleEvaluateIsTwoUpdates() {
  using L = HystereticLayout<Dim>;
  // Knots up to 1e-3 only, so that the walk's jumps reach past every tail; N = 22, not a
  // multiple of four, for the elements past the groups of four.
  HystereticSurfaces surfaces;
  surfaces.count     = 22;
  surfaces.last_knot = 1e-3;
  const HystereticSoilModel m(kGmax, kBulk, darendeliBackbone(DarendeliSoil{}), surfaces);
  const int                 size = hystereticStateSize<Dim>(m);
  std::vector<double>       fused(size, 0.0), apart(size, 0.0);
  double                    settled[L::kStrain] = {}, strain[L::kStrain] = {};
  unsigned long long        seed = 12345;
  auto uniform = [&seed] { // [0, 1), a 64-bit LCG (Knuth's MMIX constants)
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(seed >> 11) / 9007199254740992.0;
  };
  // |e - e_ref|^2 of a strain against the header's reference (e_zz = -(e_xx + e_yy), the
  // shears counted twice): which branch the step takes.
  auto drift2 = [&](const double *eps) {
    const double tr = Dim == 2 ? eps[0] + eps[1] : eps[0] + eps[1] + eps[2];
    double       d[L::kDeviator] = {eps[0] - tr / 3, eps[1] - tr / 3}, sum = 0;
    for (int c = 2; c < L::kDeviator; ++c) d[c] = eps[c + L::kStrain - L::kDeviator];
    for (int c = 0; c < L::kDeviator; ++c) {
      d[c] -= apart[L::kReference + c];
      sum += (c < 2 ? 1.0 : 2.0) * d[c] * d[c];
    }
    return sum + (d[0] + d[1]) * (d[0] + d[1]);
  };
  bool same = true;
  int  leaves = 0, both_in = 0, evaluation_out = 0;
  for (int k = 1; k <= 20000; ++k) {
    // A jump to a strain of amplitude 1e-6 to 3e-3 (log-uniform) on one update in four, else a
    // creep of 1e-9.
    const bool   jump = uniform() < 0.25;
    const double amp = 1e-6 * std::pow(3e3, uniform());
    for (int c = 0; c < L::kStrain; ++c) strain[c] = jump ? amp * (2 * uniform() - 1) : settled[c] + 1e-9 * (2 * uniform() - 1);
    const double d1 = drift2(settled), d2 = drift2(strain), slack2 = apart[L::kSlack] * apart[L::kSlack];
    leaves += d1 > slack2;
    both_in += d1 <= slack2 && d2 <= slack2;
    evaluation_out += d1 <= slack2 && d2 > slack2;
    double       s_fused[L::kStress], s_apart[L::kStress];
    const double w_fused = hystereticSettleEvaluate<Dim>(m, fused.data(), fused.data() + L::kPlastic, settled, k, strain, s_fused);
    const double w_apart = hystereticUpdate<Dim>(m, apart.data(), settled, nullptr, apart.data(), k);
    hystereticUpdate<Dim>(m, apart.data(), strain, s_apart, nullptr, 0);
    same = same && w_fused == w_apart && fused == apart;
    for (int c = 0; c < L::kStress; ++c) same = same && s_fused[c] == s_apart[c];
    std::copy(strain, strain + L::kStrain, settled);
  }
  char what[200];
  std::snprintf(what, sizeof what, "%dD settle + evaluate in one pass = the two updates bit for bit (20000 steps: the settle leaves the tail %d, both in it %d, evaluation out %d)",
                Dim, leaves, both_in, evaluation_out);
  unit::check(same, what);
  unit::check(leaves > 1000 && both_in > 1000 && evaluation_out > 1000, "each branch of the fused pass taken over 1000 times");
}

// The element set: moduli >= 0 summing to Gmax, yield strains ascending from the elastic limit,
// the state size, and the backbones it must refuse.
void elementSet() {
  const HystereticSoilModel m(kGmax, kBulk, darendeliBackbone(DarendeliSoil{}));
  double                    sum = 0;
  bool                      ok = true;
  for (int i = 0; i < m.surfaces(); ++i) {
    sum += m.elementModulus()[i];
    ok = ok && m.elementModulus()[i] >= 0 && (i == 0 || m.elementYieldStrain()[i] > m.elementYieldStrain()[i - 1]);
  }
  unit::near(sum, kGmax, 1e-14, 0, "sum of the element moduli = Gmax (the stable step's modulus)");
  unit::check(ok, "element moduli >= 0, yield strains ascending");
  unit::check(m.elementYieldStrain()[0] >= 1e-6 && m.elementYieldStrain()[0] <= 1e-6 * (1 + 1e-12), "first yield at the elastic limit 1e-6");
  unit::check(m.surfaces() == 24 && (int)m.knotStrains().size() == 24, "default N = 24 surfaces");
  unit::check(hystereticStateSize<2>(m) == 83 && hystereticStateSize<3>(m) == 135, "state: 3N + 11 doubles in 2D, 5N + 15 in 3D");
  auto throws = [](auto f) {
    try {
      f();
    } catch (const std::invalid_argument &) {
      return true;
    }
    return false;
  };
  HystereticSurfaces one;
  one.count = 1;
  unit::check(throws([&] { HystereticSoilModel(kGmax, kBulk, mkzBackbone(5e-4), one); }), "N = 1 rejected");
  unit::check(throws([] { HystereticSoilModel(0, kBulk, mkzBackbone(5e-4)); }), "Gmax = 0 rejected");
}

// Backbones a parallel Iwan model cannot hold as given: the model takes their least concave
// majorant on the knots and says how far it moved them.
void nonConcaveBackbones() {
  // A table whose log-log slope rises at 1e-4 (-0.30, then -0.10, then -0.60): a convex kink
  // in tau there. Its knots away from the kink stay exact.
  const SoilBackbone table = tableBackbone({1e-5, 1e-4, 1e-3, 1e-2}, {1.0, 0.5, 0.4, 0.1});
  const HystereticSoilModel m(kGmax, kBulk, table);
  bool                      above = true, exact_far = true;
  for (double k : m.knotStrains()) {
    const double given = backboneStress(table, kGmax, k), held = m.backboneStress(k);
    above = above && held >= given * (1 - 1e-12);
    if (k >= 3e-3) exact_far = exact_far && std::fabs(held - given) <= 1e-12 * given;
  }
  char what[160];
  std::snprintf(what, sizeof what, "non-concave table: the majorant moves knots (by %.4f)", m.knotDeviation());
  unit::check(m.knotDeviation() > 1e-3, what);
  unit::check(above, "non-concave table: the model's backbone at the knots is on or above the table's");
  unit::check(exact_far, "non-concave table: exact at the knots from 3e-3 on, past the majorant's bridge");
  // A curve that stiffens (G/Gmax flat at 0.3 after falling to it: the chord slope rises from
  // ~0.2 Gmax to 0.3 Gmax): held as its majorant, and knotDeviation reports a large move.
  const SoilBackbone        stiff = tableBackbone({1e-5, 1e-4, 1e-2}, {1.0, 0.3, 0.3});
  const HystereticSoilModel ms(kGmax, kBulk, stiff);
  bool                      nonnegative = true;
  for (double g : ms.elementModulus()) nonnegative = nonnegative && g >= 0;
  unit::check(nonnegative && ms.knotDeviation() > 0.05, "a stiffening table: element moduli stay >= 0 and knotDeviation reports the move");
}

} // namespace

int main() {
  for (const Case &c : backbones()) {
    cyclicShear<2>(c, false);
    cyclicShear<3>(c, false);
    cyclicShear<3>(c, true);
  }
  energyWithUniformSteps();
  planeStrainIs3D();
  volumetricIsElastic();
  elasticBelowLimit();
  callingConventions();
  tailIsTheModel<2>();
  tailIsTheModel<3>();
  settleEvaluateIsTwoUpdates<2>();
  settleEvaluateIsTwoUpdates<3>();
  elementSet();
  nonConcaveBackbones();
  return unit::failures();
}
