// A radix-2 complex FFT, enough for synthesising free-field histories (no FFT library is a
// dependency of slipwave). Convention of numpy.fft: forward X_j = sum_k x_k e^{-2 pi i jk/n},
// inverse x_k = (1/n) sum_j X_j e^{+2 pi i jk/n}, so e^{i w t} is the time dependence.
#pragma once
#include <complex>
#include <vector>

namespace slipwave::numerics {

// Smallest power of two >= n (n >= 1).
size_t fftLength(size_t n);
// In place; data.size() must be a power of two.
void fft(std::vector<std::complex<double>> &data, bool inverse);

} // namespace slipwave::numerics
