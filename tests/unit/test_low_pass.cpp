// The low-passed peak (numerics/low_pass.hpp): the gain 1/(1 + (f/f_c)^8) on tapered sines,
// the uniform resampling of a record with a shorter last step, and the peak. The run's
// low-passed answers equal scripts/scene_metrics.py's to 1e-9 (tests/cases/run_answers.sh).
#include "slipwave/numerics/low_pass.hpp"

#include "unit_check.hpp"

#include <cmath>
#include <vector>

using namespace slipwave::numerics;

namespace {

// A sine of frequency f [Hz] and unit amplitude over [0, T], with cosine tapers of 1 s at
// both ends: its spectrum is concentrated within ~1 Hz of f, so in the untapered middle the
// filtered record is the sine times the gain at f, to the leakage of the smooth envelope.
std::vector<double> taperedSine(double f, double T, double dt) {
  const size_t        n = (size_t)std::lround(T / dt) + 1;
  std::vector<double> a(n);
  for (size_t k = 0; k < n; ++k) {
    const double t = (double)k * dt, edge = std::min(t, T - t);
    const double w = edge >= 1.0 ? 1.0 : 0.5 * (1 - std::cos(M_PI * edge));
    a[k]           = w * std::sin(2 * M_PI * f * t);
  }
  return a;
}

// The largest |y| over the untapered middle [2 s, T - 2 s].
double middlePeak(const std::vector<double> &y, double T, double dt) {
  double peak = 0;
  for (size_t k = 0; k < y.size(); ++k)
    if ((double)k * dt >= 2 && (double)k * dt <= T - 2) peak = std::max(peak, std::fabs(y[k]));
  return peak;
}

} // namespace

int main() {
  const double dt = 1e-3, T = 20, f_c = 10;
  // The gain at f = f_c/2, f_c and 2 f_c: 1/(1 + 2^-8), 1/2, 1/257. The sine is sampled at
  // 1 kHz, so its crest lies within (2 pi f dt)^2/8 of a sample: 2e-4 at 20 Hz (the bound).
  for (double f : {5.0, 10.0, 20.0}) {
    const double gain = 1 / (1 + std::pow(f / f_c, 8));
    const double tol  = std::pow(2 * M_PI * f * dt, 2) / 8;
    unit::near(middlePeak(lowPassed(taperedSine(f, T, dt), dt, f_c), T, dt), gain, tol, 1e-9, "gain at " + std::to_string((int)f) + " Hz is 1/(1+(f/f_c)^8)");
  }
  // Zero phase: the filtered sine at f_c crosses zero where the sine does (t = 10 s, a sample).
  {
    const std::vector<double> y = lowPassed(taperedSine(f_c, T, dt), dt, f_c);
    unit::near(y[10000], 0.0, 0, 1e-9, "zero phase: the filtered sine crosses zero with the sine at 10 s");
  }
  // Uniform steps: the record is kept as is. A shorter last step: a linear record is
  // resampled exactly at t_0 + k dt_mean.
  {
    std::vector<double> t = {0, 0.1, 0.2, 0.3, 0.35}, a;
    for (double x : t) a.push_back(3 * x + 1);
    double                    step;
    const std::vector<double> u = uniformRecord(t, a, &step);
    unit::near(step, 0.0875, 1e-15, 0, "mean step of a record with a shorter last step");
    double worst = 0;
    for (size_t k = 0; k < u.size(); ++k) worst = std::max(worst, std::fabs(u[k] - (3 * 0.0875 * (double)k + 1)));
    unit::near(worst, 0, 0, 1e-14, "a linear record resampled at t_0 + k dt is exact");
    std::vector<double> tu = {0, 0.1, 0.2, 0.3}, au = {1, -2, 5, 0.5};
    unit::check(uniformRecord(tu, au, &step) == au, "a uniform record is kept as is");
  }
  // lowPassedPeak (resampling, then the filter) on a uniform record: max |lowPassed| exactly.
  {
    const std::vector<double> a = taperedSine(5, T, dt), y = lowPassed(a, dt, f_c);
    std::vector<double>       t(a.size());
    for (size_t k = 0; k < t.size(); ++k) t[k] = (double)k * dt;
    double peak = 0;
    for (double v : y) peak = std::max(peak, std::fabs(v));
    unit::near(lowPassedPeak(t, a, f_c), peak, 0, 0, "lowPassedPeak of a uniform record is max |lowPassed|");
  }
  // The peak of a record of zeros, and of a single sample (no record): 0.
  unit::near(lowPassedPeak({0, 1}, {0, 0}, 5), 0, 0, 0, "zeros give a peak of 0");
  unit::near(lowPassedPeak({0}, {3}, 5), 0, 0, 0, "one sample gives 0");
  return unit::failureCount();
}
