// Critical step: closed-form values, and the explicit recurrence itself run just below and
// just above the bound on a single-DOF oscillator.
#include "slipwave/physics/stable_time_step.hpp"

#include "unit_check.hpp"

#include <cmath>
#include <string>

using namespace slipwave::physics;

namespace {

// The scheme the bound is derived for (lagged half-step velocity in the damping term),
// started from u = 1 at rest. Returns max |u| over the first and over the last 1000 of
// n steps.
struct Envelope {
  double early, late;
};
Envelope run(double omega, double beta, double h, int n) {
  double u = 1, v = 0;
  Envelope e{0, 0};
  for (int k = 0; k < n; ++k) {
    v += h * (-omega * omega * u - beta * omega * omega * v);
    u += h * v;
    if (!(std::fabs(u) < 1e100)) {  // diverged: stop before overflow turns u into NaN
      e.late = HUGE_VAL;
      return e;
    }
    if (k < 1000) e.early = std::fmax(e.early, std::fabs(u));
    if (k >= n - 1000) e.late = std::fmax(e.late, std::fabs(u));
  }
  return e;
}

// The fourth-order scheme on the same oscillator: the kick-drift-kick of
// time/central_difference.hpp with the RHS a* = -w^2 u - beta w^2 v_{n-1/2} corrected by
// -(h^2/12) w^2 a* (K a* for the mode).
Envelope runFourthOrder(double omega, double beta, double h, int n) {
  const double w2 = omega * omega;
  double       u = 1, v = 0, a = (-w2 * u) * (1 - h * h * w2 / 12);
  Envelope     e{0, 0};
  for (int k = 0; k < n; ++k) {
    const double v_half = v + 0.5 * h * a;
    u += h * v_half;
    a = (-w2 * u - beta * w2 * v_half) * (1 - h * h * w2 / 12);
    v = v_half + 0.5 * h * a;
    if (!(std::fabs(u) < 1e100)) {
      e.late = HUGE_VAL;
      return e;
    }
    if (k < 1000) e.early = std::fmax(e.early, std::fabs(u));
    if (k >= n - 1000) e.late = std::fmax(e.late, std::fabs(u));
  }
  return e;
}

} // namespace

int main() {
  const double omega = 2 * M_PI * 50;
  unit::near(centralDifferenceStableStep(omega, 0), 2 / omega, 1e-15, 0, "undamped: 2/omega");
  // xi = beta omega / 2 = 0.75: (2/omega)(sqrt(1.5625) - 0.75) = (2/omega) * 0.5.
  const double beta_075 = 1.5 / omega;
  unit::near(centralDifferenceStableStep(omega, beta_075), 1 / omega, 1e-15, 0, "xi = 0.75: 1/omega");

  // Undamped, the scheme conserves u_n^2 + u_{n-1}^2 - (2 - W^2) u_n u_{n-1} = W^2 (from
  // u_0 = u_{-1} = 1), W = omega h; so |u| <= 2 / sqrt(4 - W^2) = 7.09 at W = 1.98.
  const double undamped_bound = 2 / std::sqrt(4 - 1.98 * 1.98);
  for (double xi : {0.0, 0.05, 0.3, 2.0}) {
    const double beta = 2 * xi / omega, dt = centralDifferenceStableStep(omega, beta);
    const std::string tag = "xi = " + std::to_string(xi).substr(0, 4);
    const Envelope below = run(omega, beta, 0.99 * dt, 10000), above = run(omega, beta, 1.01 * dt, 10000);
    // Stable: undamped within the invariant's bound; damped, the late envelope does not
    // exceed the early one.
    const double allowed = xi == 0 ? undamped_bound * (1 + 1e-9) : below.early * (1 + 1e-12);
    unit::check(below.late <= allowed, tag + ": bounded at 0.99 x bound (late max |u| = " +
                                           std::to_string(below.late) + ", allowed " + std::to_string(allowed) + ")");
    // Unstable: a root beyond -1 grows geometrically; x1e3 over 9000 steps is a low bar.
    unit::check(above.late > 1e3 * above.early,
                tag + ": grows at 1.01 x bound (late/early max |u| = " + std::to_string(above.late / above.early) + ")");
  }

  // Row form: rate = beta omega^2 is the single-mode bound; rate = 0 is 2/omega.
  for (double xi : {0.0, 0.05, 0.75, 2.0}) {
    const double beta = 2 * xi / omega;
    unit::near(centralDifferenceStableStepOfRow(omega * omega, beta * omega * omega), centralDifferenceStableStep(omega, beta), 1e-14, 0,
               "row bound with rate = beta omega^2 = mode bound, xi = " + std::to_string(xi).substr(0, 4));
  }
  // Two equal masses m joined by a spring k and a dashpot c (a contact pair): rows 2k/m and
  // 2c/m; the relative mode has omega^2 = 2k/m and rate 2c/m exactly, so the row bound is
  // sharp. Stepped by the lagged scheme (dashpot on v_{n-1/2}) from w = 1 at rest.
  for (double xi : {0.1, 1.0}) {
    const double m = 600, k = 4e8, wn = std::sqrt(2 * k / m), c = xi * wn * m; // 2c/m = 2 xi wn
    const double dt  = centralDifferenceStableStepOfRow(2 * k / m, 2 * c / m);
    auto         run = [&](double h, double mass) {
      double x1 = -0.5, x2 = 0.5, v1 = 0, v2 = 0, early = 0, late = 0;
      for (int n = 0; n < 20000; ++n) {
        const double f = k * (x2 - x1) + c * (v2 - v1);
        v1 += h * f / mass, v2 -= h * f / mass;
        x1 += h * v1, x2 += h * v2;
        if (!(std::fabs(x2 - x1) < 1e100)) return HUGE_VAL;
        if (n < 1000) early = std::fmax(early, std::fabs(x2 - x1));
        if (n >= 19000) late = std::fmax(late, std::fabs(x2 - x1));
      }
      return late / early;
    };
    const std::string tag = "contact pair xi = " + std::to_string(xi).substr(0, 3);
    unit::check(run(0.99 * dt, m) <= 1 + 1e-12, tag + ": bounded at 0.99 x the row bound");
    unit::check(run(1.01 * dt, m) > 1e3, tag + ": grows at 1.01 x the row bound");
    // Mass scaling to a step T three times the pair's own: the mass massForStableStep gives
    // (rows 2k and 2c) puts the row bound at T, and the pair is stable just below it only.
    const double T = 3 * dt, scaled = massForStableStep(2 * k, 2 * c, T);
    unit::near(centralDifferenceStableStepOfRow(2 * k / scaled, 2 * c / scaled), T, 1e-14, 0, tag + ": the scaled mass's row bound is the target step");
    unit::check(run(0.99 * T, scaled) <= 1 + 1e-12, tag + ": scaled mass, bounded at 0.99 x the target step");
    unit::check(run(1.01 * T, scaled) > 1e3, tag + ": scaled mass, grows at 1.01 x the target step");
  }

  // Fourth order: sqrt(12)/omega undamped (sqrt(3) x central differences); with damping the
  // Jury bound (1 - W^2/12)(W^2/4 + xi W) = 1, which holds at the returned step, is never
  // below central differences' (the modified mass M (I - h^2/12 M^-1 K)^-1 >= M), and is
  // sqrt(12) up to xi = 0.2007, the minimum of Xi(W) = (1/(1 - W^2/12) - W^2/4)/W.
  unit::near(fourthOrderStableStep(omega, 0), std::sqrt(12.0) / omega, 1e-15, 0, "fourth order, undamped: sqrt(12)/omega");
  {
    int    turns = 0;
    double previous = HUGE_VAL, slope = -1;
    for (int k = 1; k < 4000; ++k) {
      const double W = std::sqrt(12.0) * k / 4000, xi_w = (1 / (1 - W * W / 12) - W * W / 4) / W;
      const double s = xi_w < previous ? -1 : 1;
      turns += s != slope;
      slope = s, previous = xi_w;
    }
    unit::check(turns == 1, "Xi(W) falls then rises on (0, sqrt 12): one turn (" + std::to_string(turns) + ")");
  }
  unit::near(fourthOrderStableStep(omega, 2 * 0.2 / omega), std::sqrt(12.0) / omega, 1e-15, 0, "fourth order, xi = 0.2 < 0.2007: still sqrt(12)/omega");
  for (double xi : {0.05, 0.25, 0.75, 2.0}) {
    const double beta = 2 * xi / omega, dt = fourthOrderStableStep(omega, beta), W = omega * dt;
    const std::string tag = "fourth order, xi = " + std::to_string(xi).substr(0, 4);
    unit::check(dt >= centralDifferenceStableStep(omega, beta), tag + ": not below central differences");
    if (xi > 0.2007) unit::near((1 - W * W / 12) * (W * W / 4 + xi * W), 1.0, 1e-12, 0, tag + ": the Jury bound holds with equality");
    const Envelope below = runFourthOrder(omega, beta, 0.99 * dt, 10000);
    unit::check(below.late <= below.early * (1 + 1e-12) || (xi < 0.2007 && below.late < 1e3), tag + ": bounded at 0.99 x bound");
    if (xi > 0.2007) {
      const Envelope above = runFourthOrder(omega, beta, 1.01 * dt, 10000);
      unit::check(above.late > 1e3 * above.early, tag + ": grows at 1.01 x bound (late/early " + std::to_string(above.late / above.early) + ")");
    }
  }
  {
    const Envelope below = runFourthOrder(omega, 0, 0.995 * std::sqrt(12.0) / omega, 10000), above = runFourthOrder(omega, 0, 1.005 * std::sqrt(12.0) / omega, 10000);
    unit::check(below.late <= 1e3 && above.late > 1e3 * above.early, "fourth order, undamped: bounded at 0.995, grows at 1.005 x sqrt(12)/omega");
  }
  return unit::failures();
}
