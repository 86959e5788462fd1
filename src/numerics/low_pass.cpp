#include "slipwave/numerics/low_pass.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include "slipwave/numerics/fft.hpp"

namespace slipwave::numerics {

std::vector<double> uniformRecord(const std::vector<double> &t, const std::vector<double> &a, double *dt) {
  const size_t n = t.size();
  *dt            = (t[n - 1] - t[0]) / (double)(n - 1);
  bool uniform   = true;
  for (size_t k = 1; k < n && uniform; ++k) uniform = std::fabs((t[k] - t[k - 1]) - *dt) <= 1e-6 * std::fabs(*dt);
  if (uniform) return a;
  std::vector<double> out(n);
  size_t              j = 0;
  for (size_t k = 0; k < n; ++k) {
    const double tk = std::min(t[0] + *dt * (double)k, t[n - 1]);
    while (j + 2 < n && t[j + 1] < tk) ++j;
    const double w = (tk - t[j]) / (t[j + 1] - t[j]);
    out[k]         = (1 - w) * a[j] + w * a[j + 1];
  }
  return out;
}

std::vector<double> lowPassed(const std::vector<double> &a, double dt, double f_c) {
  const size_t                      n = a.size(), nfft = fftLength(std::max<size_t>(2 * n, 2));
  std::vector<std::complex<double>> x(nfft, 0.0);
  std::copy(a.begin(), a.end(), x.begin());
  fft(x, false);
  for (size_t j = 0; j < nfft; ++j) {
    const double f = (double)std::min(j, nfft - j) / ((double)nfft * dt); // the bin's |frequency|
    x[j] /= 1.0 + std::pow(f / f_c, 8);
  }
  fft(x, true);
  std::vector<double> out(n);
  for (size_t k = 0; k < n; ++k) out[k] = x[k].real();
  return out;
}

double lowPassedPeak(const std::vector<double> &t, const std::vector<double> &a, double f_c) {
  if (t.size() < 2) return 0.0;
  double                    dt = 0;
  const std::vector<double> record = uniformRecord(t, a, &dt); // sets dt: before lowPassed reads it
  const std::vector<double> y      = lowPassed(record, dt, f_c);
  double                    peak = 0;
  for (double v : y) peak = std::max(peak, std::fabs(v));
  return peak;
}

} // namespace slipwave::numerics
