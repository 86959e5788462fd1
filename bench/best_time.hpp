// Timing for the micro-benchmarks: seconds per call of f, f run in a loop sized to ~target
// seconds, the best of 3 such loops (other processes on the machine disturb the best least).
#pragma once
#include <algorithm>
#include <chrono>
#include <cmath>

namespace bench {

inline double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

template <class F>
double bestTime(F &&f, double target = 0.3) {
  const double t0 = now();
  f();
  const double once = std::max(now() - t0, 1e-7);
  const int    reps = std::max(1, (int)std::lround(target / once));
  double       best = 1e300;
  for (int k = 0; k < 3; ++k) {
    const double t = now();
    for (int r = 0; r < reps; ++r) f();
    best = std::min(best, (now() - t) / reps);
  }
  return best;
}

} // namespace bench
