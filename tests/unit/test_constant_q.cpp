// The constant-Q kernel against its definitions: fit quality over the band, the limits of the
// complex modulus, the exact memory update against the closed-form relaxation, and the
// reference frequency for a 2 % step drop.
#include "slipwave/physics/constant_q.hpp"

#include "unit_check.hpp"

#include <cmath>
#include <complex>

using namespace slipwave::physics;

int main() {
  // Default band 0.5-20 Hz, 3 mechanisms; Q within 5 % of Q0 = 1/(2 xi) for xi up to 0.1
  // (the bound); measured on a 2001-point log grid of the band.
  for (double xi : {0.01, 0.05, 0.1}) {
    const ConstantQModel m = constantQFit(xi, 0.5, 20.0, 3);
    double               worst = 0;
    for (int k = 0; k <= 2000; ++k) {
      const double f = 0.5 * std::pow(40.0, k / 2000.0);
      worst          = std::fmax(worst, std::fabs(constantQQuality(m, f) * 2 * xi - 1));
    }
    char what[120];
    std::snprintf(what, sizeof what, "xi = %.2f: Q within 5 %% of 1/(2 xi) over 0.5-20 Hz (worst %.4f)", xi, worst);
    unit::check(worst <= 0.05, what);
    unit::check(m.weight[0] > 0 && m.weight[1] > 0 && m.weight[2] > 0, "every Y_l > 0 (a dissipative body)");
  }
  const ConstantQModel m = constantQFit(0.05, 0.5, 20.0, 3);
  // M(0)/M_U = 1 - sum Y_l (relaxed), M(inf)/M_U = 1 (unrelaxed); Im M > 0 (causal, dissipative).
  const double relaxed = 1 - (m.weight[0] + m.weight[1] + m.weight[2]);
  unit::near(constantQModulusRatio(m, 0.0).real(), relaxed, 1e-14, 0, "M(0)/M_U = 1 - sum Y_l");
  unit::near(std::abs(constantQModulusRatio(m, 1e9)), 1.0, 1e-8, 0, "M(f -> inf)/M_U = 1");
  unit::check(constantQModulusRatio(m, 2.0).imag() > 0, "Im M > 0");
  // Kramers-Kronig dispersion of a constant-Q body, c(f2)/c(f1) = 1 + ln(f2/f1)/(pi Q) to
  // first order in 1/Q: between 1 and 10 Hz, 1 + ln(10)/(10 pi) = 1.0733; the fit's Q varies
  // by 3 % and the second-order term is (ln(10)/(10 pi))^2/2 = 2.7e-3, so 0.5 % of it.
  unit::near(constantQSpeedRatio(m, 10.0) / constantQSpeedRatio(m, 1.0), 1 + std::log(10.0) / (10 * M_PI), 5e-3, 0, "dispersion c(10)/c(1) ~ 1 + ln 10/(pi Q)");
  // The unrelaxed factor makes the speed at f_r the given one: factor * (c/c_U)^2 = 1.
  const double fac = constantQUnrelaxedFactor(m, 3.0), r = constantQSpeedRatio(m, 3.0);
  unit::near(fac * r * r, 1.0, 1e-14, 0, "unrelaxed factor: c(f_r) = the given speed");
  // Reference for a 2 % step drop: exactly 2 % there (bisection), below f_max the drop is larger.
  const double fr = constantQReferenceForStepDrop(m, 20.0, 0.02);
  unit::near(1 - 1 / std::sqrt(constantQUnrelaxedFactor(m, fr)), 0.02, 1e-9, 0, "step drop 2 % at the chosen reference");
  unit::check(fr > 20.0, "xi = 0.05 needs a reference above the 20 Hz band top for a 2 % drop");
  unit::near(constantQReferenceForStepDrop(constantQFit(0.01, 0.5, 20.0, 3), 20.0, 0.02), 20.0, 0, 0, "xi = 0.01: the band top already drops < 2 %");

  // Memory update against the closed form of dz/dt = w (g(t) - z) with g linear,
  // g(t) = g0 + (g1 - g0) t/h: z(h) = z0 e^{-wh} + g1 - (g1 - g0)/(wh) + (g0 - (g1 - g0)/(wh)) ... written
  // out: z(h) = g(h) - (g1 - g0)/(w h) + (z0 - g0 + (g1 - g0)/(w h)) e^{-w h}.
  const double w = 2 * M_PI * 3.0, h = 0.013, z0 = 0.7, g0 = -0.2, g1 = 1.3;
  const double exact = g1 - (g1 - g0) / (w * h) + (z0 - g0 + (g1 - g0) / (w * h)) * std::exp(-w * h);
  const MemoryUpdate c = memoryUpdate(w, h);
  unit::near(c.decay * z0 + c.end * g1 + c.start * g0, exact, 1e-14, 1e-15, "memory update = closed-form relaxation for a linear drive");
  // Composition: two half steps with g linear equal one full step (exactness).
  const MemoryUpdate half = memoryUpdate(w, h / 2);
  const double       gm = 0.5 * (g0 + g1), z_half = half.decay * z0 + half.end * gm + half.start * g0;
  unit::near(half.decay * z_half + half.end * g1 + half.start * gm, exact, 1e-14, 1e-15, "two half steps = one step");
  const MemoryUpdate zero = memoryUpdate(w, 0.0);
  unit::check(zero.decay == 1.0 && zero.end == 0.0 && zero.start == 0.0, "h = 0: identity (an RHS at the committed time changes nothing)");
  // Small w h: the series branch against the closed form just above its switch (x = 1e-3)
  // and the leading terms far below it (no cancellation).
  const double x = 0.99e-3, xa = 1.01e-3;
  const MemoryUpdate below = memoryUpdate(x / h, h), above = memoryUpdate(xa / h, h);
  unit::near(below.end / x, above.end / xa, 1e-4, 0, "series and closed form agree at the switch (end weight / x varies by x/3)");
  const MemoryUpdate tiny = memoryUpdate(w, 1e-12);
  unit::near(tiny.end, w * 1e-12 / 2, 1e-9, 0, "tiny w h: end weight w h/2");
  unit::near(tiny.start, w * 1e-12 / 2, 1e-9, 0, "tiny w h: start weight w h/2");
  unit::check(memoryUpdate(w, 1e3).decay >= 0 && memoryUpdate(w, 1e3).decay < 1, "large w h: decay in [0, 1) (unconditionally stable)");

  return unit::failures();
}
