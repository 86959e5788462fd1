// Source time functions: closed-form values, derivative consistency, and the spectral
// criterion behind topFrequency checked by numerical Fourier integrals.
#include "slipwave/physics/source_time_function.hpp"

#include "unit_check.hpp"

#include <cmath>
#include <complex>

using namespace slipwave::physics;

namespace {

// |V(f)| = |int v(t) exp(-2 pi i f t) dt| by the trapezoid rule on [a, b]; for smooth
// functions decayed to round-off at both ends the rule converges geometrically.
template <class F> double spectrum(F v, double f, double a, double b) {
  const int n = 40000;
  const double h = (b - a) / n;
  std::complex<double> s = 0;
  for (int k = 0; k <= n; ++k) {
    const double t = a + k * h;
    s += (k == 0 || k == n ? 0.5 : 1.0) * v(t) * std::exp(std::complex<double>(0, -2 * M_PI * f * t));
  }
  return std::abs(s) * h;
}

// Central difference: error <= h^2/6 max|f'''| + eps max|f| / h; with the step used below
// (1e-6 s, signals of at most a few Hz) both terms are below 1e-9 of max |f'|.
template <class F> double derivative(F f, double t) {
  const double h = 1e-6;
  return (f(t + h) - f(t - h)) / (2 * h);
}

} // namespace

int main() {
  const RickerWavelet r{0.2, 2.0, 1.0};
  const double a = M_PI * M_PI * r.frequency * r.frequency;
  unit::near(velocity(r, 1.0), 0.2, 1e-15, 0, "Ricker peak velocity A at t0");
  // Zero crossings where 1 - 2 a tau^2 = 0: tau = 1/(sqrt(2) pi f0).
  unit::near(velocity(r, 1.0 + 1 / (std::sqrt(2.0) * M_PI * 2.0)), 0, 0, 1e-16, "Ricker velocity zero crossing");
  unit::near(displacement(r, 1.0), 0, 0, 0, "Ricker displacement zero at t0 (odd antiderivative)");
  unit::near(displacement(r, -20.0), 0, 0, 1e-300, "Ricker displacement vanishes long before t0");
  // Acceleration zero where 2 a tau^2 = 3.
  unit::near(acceleration(r, 1.0 + std::sqrt(1.5 / a)), 0, 0, 1e-15, "Ricker acceleration zero at tau^2 = 3/(2a)");
  double worst_d = 0, worst_a = 0;
  for (double t = 0.5; t < 1.5; t += 0.0123) {
    worst_d = std::fmax(worst_d, std::fabs(derivative([&](double s) { return displacement(r, s); }, t) - velocity(r, t)));
    worst_a = std::fmax(worst_a, std::fabs(derivative([&](double s) { return velocity(r, s); }, t) - acceleration(r, t)));
  }
  // Scales: max |v| = A = 0.2, max |a| = A * 2a * O(1) ~ 0.2 * 79 * 1.4 ~ 22.
  unit::near(worst_d, 0, 0, 1e-9 * 0.2, "Ricker d(displacement)/dt = velocity");
  unit::near(worst_a, 0, 0, 1e-9 * 22, "Ricker d(velocity)/dt = acceleration");
  // Criterion: |V(top)| = 1% of |V(f0)|, by numerical Fourier integrals.
  auto rv = [&](double t) { return velocity(r, t); };
  const double top = topFrequency(r);
  unit::near(top, 2.763756875702675 * 2.0, 1e-15, 0, "Ricker top frequency = 2.7638 f0");
  unit::near(spectrum(rv, top, -4, 6) / spectrum(rv, r.frequency, -4, 6), 0.01, 1e-9, 0,
             "Ricker spectrum at top frequency is 1% of its peak (numerical Fourier integral)");
  unit::check(spectrum(rv, 0.99 * r.frequency, -4, 6) < spectrum(rv, r.frequency, -4, 6) &&
                  spectrum(rv, 1.01 * r.frequency, -4, 6) < spectrum(rv, r.frequency, -4, 6),
              "Ricker spectrum peaks at f0");

  const GaborWavelet g{0.1, 3.0, 2.0, 4.0, 0.3};
  unit::near(velocity(g, 2.0), 0.1 * std::cos(0.3), 1e-15, 0, "Gabor v(t0) = A cos(theta)");
  double worst_g = 0;
  for (double t = 1.0; t < 3.0; t += 0.0173)
    worst_g = std::fmax(worst_g, std::fabs(derivative([&](double s) { return velocity(g, s); }, t) - acceleration(g, t)));
  // max |a| ~ A 2 pi f0 = 1.9.
  unit::near(worst_g, 0, 0, 1e-9 * 1.9, "Gabor d(velocity)/dt = acceleration");
  auto gv = [&](double t) { return velocity(g, t); };
  // The image at -f0 adds exp(-gamma^2) = 1e-7 relative at f0; nothing else is neglected.
  unit::near(spectrum(gv, topFrequency(g), -2, 6) / spectrum(gv, g.frequency, -2, 6), 0.01, 1e-6, 0,
             "Gabor spectrum at top frequency is 1% of its value at f0 (numerical Fourier integral)");

  const HarmonicWave hw{2.0, 1.5, 0.4};
  unit::near(velocity(hw, 0.39), 0, 0, 0, "harmonic: zero before t0");
  unit::near(acceleration(hw, 0.39), 0, 0, 0, "harmonic: no acceleration before t0");
  unit::near(velocity(hw, 0.4 + 1 / (4 * 1.5)), 2.0, 1e-15, 0, "harmonic: A at a quarter period after t0");
  unit::near(acceleration(hw, 0.4), 2.0 * 2 * M_PI * 1.5, 1e-15, 0, "harmonic: slope A 2 pi f0 at the switch-on");
  double worst_h = 0;
  for (double t = 0.41; t < 3.0; t += 0.0173)
    worst_h = std::fmax(worst_h, std::fabs(derivative([&](double s) { return velocity(hw, s); }, t) - acceleration(hw, t)));
  // max |a| = A 2 pi f0 = 18.8.
  unit::near(worst_h, 0, 0, 1e-9 * 18.8, "harmonic: d(velocity)/dt = acceleration after t0");
  unit::near(topFrequency(hw), 3.0, 1e-15, 0, "harmonic: top frequency 2 f0");

  const TabulatedHistory h{{0.0, 0.1, 0.3}, {1.0, 3.0, -1.0}};
  unit::near(velocity(h, -0.01), 0, 0, 0, "tabulated: zero before the first time");
  unit::near(velocity(h, 0.0), 1.0, 1e-15, 0, "tabulated: first sample");
  unit::near(velocity(h, 0.05), 2.0, 1e-15, 0, "tabulated: linear between samples (midpoint 2)");
  unit::near(velocity(h, 0.1), 3.0, 1e-15, 0, "tabulated: interior sample");
  unit::near(velocity(h, 0.25), 0.0, 0, 1e-15, "tabulated: 3/4 of the way from 3 to -1 is 0");
  unit::near(velocity(h, 0.3), -1.0, 1e-15, 0, "tabulated: last sample");
  unit::near(velocity(h, 7.0), -1.0, 1e-15, 0, "tabulated: holds the last value after the record");
  unit::near(topFrequency(h), 0.5 / 0.2, 1e-15, 0, "tabulated: Nyquist of the coarsest interval 0.2 s");
  return unit::failures();
}
