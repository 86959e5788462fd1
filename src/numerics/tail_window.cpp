#include "slipwave/numerics/tail_window.hpp"

#include <algorithm>

namespace slipwave::numerics {

TailWindow tailWindow(const std::vector<double> &t, const std::vector<double> &v, double window) {
  TailWindow w;
  const size_t n = std::min(t.size(), v.size());
  if (n == 0) return w;
  const double start = t[n - 1] - window;
  // The first sample inside the window; the window's start interpolated on the segment before it.
  size_t first = n - 1;
  while (first > 0 && t[first - 1] > start) --first;
  double t0 = t[first], v0 = v[first];
  if (first > 0 && t[first] > start) {
    const double s = (start - t[first - 1]) / (t[first] - t[first - 1]);
    t0 = start, v0 = v[first - 1] + s * (v[first] - v[first - 1]);
  }
  double lo = v0, hi = v0, area = 0, tp = t0, vp = v0;
  for (size_t k = first; k < n; ++k) {
    area += 0.5 * (v[k] + vp) * (t[k] - tp);
    lo = std::min(lo, v[k]), hi = std::max(hi, v[k]);
    tp = t[k], vp = v[k];
  }
  const double span = t[n - 1] - t0;
  w.mean            = span > 0 ? area / span : v[n - 1];
  w.half_range      = 0.5 * (hi - lo);
  return w;
}

} // namespace slipwave::numerics
