#include "slipwave/numerics/fft.hpp"

#include <cmath>
#include <utility>

namespace slipwave::numerics {

size_t fftLength(size_t n) {
  size_t m = 1;
  while (m < n) m <<= 1;
  return m;
}

// Iterative Cooley-Tukey: bit-reversal permutation, then log2(n) butterfly passes.
void fft(std::vector<std::complex<double>> &x, bool inverse) {
  const size_t n = x.size();
  for (size_t i = 1, j = 0; i < n; ++i) {
    size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(x[i], x[j]);
  }
  const double sign = inverse ? 1.0 : -1.0;
  for (size_t len = 2; len <= n; len <<= 1) {
    const double angle = sign * 2 * M_PI / (double)len;
    for (size_t start = 0; start < n; start += len)
      for (size_t k = 0; k < len / 2; ++k) {
        // The twiddle from cos/sin each time, not a running product, so round-off does not grow with n.
        const std::complex<double> w(std::cos(angle * (double)k), std::sin(angle * (double)k));
        const std::complex<double> a = x[start + k], b = w * x[start + k + len / 2];
        x[start + k]           = a + b;
        x[start + k + len / 2] = a - b;
      }
  }
  if (inverse)
    for (auto &v : x) v /= (double)n;
}

} // namespace slipwave::numerics
