// Contact damping: the dashpot coefficient against the closed-form decay of a two-mass
// spring-dashpot, and the damping traction's rules (resists closing, never glues, dissipates).
#include "slipwave/physics/contact_damping.hpp"

#include "unit_check.hpp"

#include <cmath>
#include <string>

using namespace slipwave::physics;

namespace {

// Two masses joined by the spring k and the dashpot c, integrated by RK4 with a step far
// below the period (exact to 1e-10 here). Returns the relative displacement w = x2 - x1 at
// the times asked, from w = 1 at rest; the masses start with zero total momentum.
struct Pair {
  double m1, m2, k, c;
  void rhs(const double *s, double *d) const {
    const double w = s[1] - s[0], wd = s[3] - s[2], f = k * w + c * wd; // pulls them together
    d[0] = s[2], d[1] = s[3], d[2] = f / m1, d[3] = -f / m2;
  }
  double relative(double t_end, int steps) const {
    double s[4] = {-m2 / (m1 + m2), m1 / (m1 + m2), 0, 0}, k1[4], k2[4], k3[4], k4[4], tmp[4];
    const double h = t_end / steps;
    for (int n = 0; n < steps; ++n) {
      rhs(s, k1);
      for (int i = 0; i < 4; ++i) tmp[i] = s[i] + 0.5 * h * k1[i];
      rhs(tmp, k2);
      for (int i = 0; i < 4; ++i) tmp[i] = s[i] + 0.5 * h * k2[i];
      rhs(tmp, k3);
      for (int i = 0; i < 4; ++i) tmp[i] = s[i] + h * k3[i];
      rhs(tmp, k4);
      for (int i = 0; i < 4; ++i) s[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    }
    return s[1] - s[0];
  }
};

} // namespace

int main() {
  // c = 2 zeta sqrt(k m1 m2 / (m1 + m2)): k = 4e8, m1 = 1200, m2 = 600 -> m_eff = 400,
  // sqrt(k m_eff) = 4e5, zeta = 0.1 -> c = 8e4.
  unit::near(contactDashpotCoefficient(0.1, 4e8, 1200, 600), 8e4, 1e-14, 0, "c = 2 zeta sqrt(k m_eff), m_eff = m1 m2/(m1+m2)");
  unit::near(contactDashpotCoefficient(0.1, 4e8, 600, 1200), 8e4, 1e-14, 0, "c is symmetric in the two masses");
  unit::near(contactDashpotCoefficient(0.0, 4e8, 1200, 600), 0, 0, 0, "zeta = 0: no dashpot");

  // Closed-form decay of the relative motion w'' + 2 zeta wn w' + wn^2 w = 0, wn^2 = k/m_eff,
  // from w(0) = 1 at rest: w(t) = e^{-zeta wn t} (cos wd t + zeta wn/wd sin wd t),
  // wd = wn sqrt(1 - zeta^2). At t = 2 pi/wd (one damped period) w = e^{-2 pi zeta/sqrt(1-zeta^2)}.
  const double k = 4e8, m1 = 1200, m2 = 600, m_eff = m1 * m2 / (m1 + m2), wn = std::sqrt(k / m_eff);
  for (double zeta : {0.05, 0.1, 0.3}) {
    const Pair   pair{m1, m2, k, contactDashpotCoefficient(zeta, k, m1, m2)};
    const double wd = wn * std::sqrt(1 - zeta * zeta), period = 2 * M_PI / wd;
    const double want = std::exp(-zeta * wn * period);
    unit::near(pair.relative(period, 20000), want, 1e-8, 1e-12, "zeta = " + std::to_string(zeta).substr(0, 4) + ": w after one damped period = e^{-2 pi zeta/sqrt(1-zeta^2)}");
  }
  // zeta = 1 is critical: w(t) = (1 + wn t) e^{-wn t}, never crossing zero.
  {
    const Pair pair{m1, m2, k, contactDashpotCoefficient(1.0, k, m1, m2)};
    for (double wt : {1.0, 3.0, 8.0}) {
      const double t = wt / wn;
      unit::near(pair.relative(t, 20000), (1 + wt) * std::exp(-wt), 1e-8, 1e-14, "zeta = 1: w = (1 + wn t) e^{-wn t} at wn t = " + std::to_string((int)wt));
    }
  }

  // Traction rules (c/A = 1e5 Pa s/m).
  unit::near(contactDampingTraction(1e5, -2e-3, -300), -200, 1e-15, 0, "closing: sigma_d = (c/A) w_dot, compressive");
  unit::near(contactDampingTraction(1e5, -2e-3, 50), -200, 1e-15, 0, "closing under tension: still resists");
  unit::near(contactDampingTraction(1e5, 1e-3, -300), 100, 1e-15, 0, "opening, small: (c/A) w_dot");
  unit::near(contactDampingTraction(1e5, 5e-3, -300), 300, 1e-15, 0, "opening, large: capped so sigma_N + sigma_d = 0 (no glue)");
  unit::near(contactDampingTraction(1e5, 5e-3, 40), 0, 0, 0, "opening with the spring in tension: no extra pull");
  bool dissipates = true;
  for (double wd : {-1e-2, -1e-4, 0.0, 1e-4, 1e-2})
    for (double sn : {-1e3, 0.0, 1e3}) dissipates = dissipates && contactDampingTraction(1e5, wd, sn) * wd >= 0;
  unit::check(dissipates, "sigma_d w_dot >= 0 for every sign of w_dot and sigma_N");
  return unit::failures();
}
