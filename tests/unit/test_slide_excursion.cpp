// The largest one-way slide (numerics/slide_excursion.hpp): hand-worked histories, and a
// long random one against the definition evaluated directly on the whole history (every
// sample kept, the smallest leg removed one at a time by a plain scan, as
// scripts/scene_metrics.py does it).
#include "slipwave/numerics/slide_excursion.hpp"

#include "unit_check.hpp"

#include <algorithm>
#include <cmath>
#include <random>

using namespace slipwave::numerics;

namespace {

double fromSamples(const std::vector<double> &s, double share) {
  TurningPoints tp;
  for (double x : s) tp.add(x);
  return largestExcursion(tp.values(), share);
}

// The definition on the full history: turning points by index (a plateau at its first
// sample, the ends included), then the gate by a quadratic scan.
double reference(const std::vector<double> &s, double share) {
  std::vector<size_t> runs = {0};
  for (size_t i = 1; i < s.size(); ++i)
    if (s[i] != s[i - 1]) runs.push_back(i);
  std::vector<double> keep = {s[0]};
  for (size_t i = 1; i + 1 < runs.size(); ++i)
    if ((s[runs[i]] > s[runs[i - 1]]) != (s[runs[i + 1]] > s[runs[i]])) keep.push_back(s[runs[i]]);
  keep.push_back(s.back());
  const double span = *std::max_element(s.begin(), s.end()) - *std::min_element(s.begin(), s.end()), gate = share * span;
  while (keep.size() > 2) {
    size_t k = 0;
    for (size_t i = 1; i + 1 < keep.size(); ++i)
      if (std::fabs(keep[i + 1] - keep[i]) < std::fabs(keep[k + 1] - keep[k])) k = i;
    if (std::fabs(keep[k + 1] - keep[k]) >= gate) break;
    if (k == 0) keep.erase(keep.begin() + 1);
    else if (k + 2 == keep.size()) keep.erase(keep.end() - 2);
    else keep.erase(keep.begin() + (long)k, keep.begin() + (long)k + 2);
  }
  double largest = 0;
  for (size_t i = 1; i < keep.size(); ++i) largest = std::max(largest, std::fabs(keep[i] - keep[i - 1]));
  return largest;
}

} // namespace

int main() {
  // 0 -> 1, a 0.02 dip (below the gate 0.05 x 2), on to 2, back to 0: one slide of 2 and one of -2.
  unit::near(fromSamples({0, 0.5, 1, 0.98, 1.5, 2, 1, 0}, 0.05), 2.0, 1e-15, 0, "a jitter below the gate does not cut a slide in two");
  // The same dip at 0.2 (above the gate): the slides are 1, 1.02 and 2.
  unit::near(fromSamples({0, 1, 0.8, 2, 0}, 0.05), 2.0, 1e-15, 0, "the largest of the slides 1, 0.2, 1.2, 2 is the last");
  unit::near(fromSamples({0, 1, 0.8, 1.5}, 0.05), 1.0, 1e-15, 0, "0 -> 1 -> 0.8 -> 1.5: a dip of 0.2 above the gate 0.075 cuts the slide: largest 1");
  // Jitter at the start (first leg below the gate): the start stays, the jitter goes.
  unit::near(fromSamples({0, 0.01, 0, 3, 1}, 0.05), 3.0, 1e-15, 0, "a first leg below the gate loses its inner end: 0 -> 3");
  unit::near(fromSamples({0, 0, 1, 1, 1}, 0.05), 1.0, 1e-15, 0, "plateaus count once");
  unit::near(fromSamples({2, 2, 2}, 0.05), 0.0, 0, 0, "a constant history: 0");
  TurningPoints tp;
  for (double x : {0.0, 1.0, 2.0, 2.0, 1.0, 3.0}) tp.add(x);
  unit::check(tp.values() == std::vector<double>{0, 2, 1, 3}, "turning points of 0,1,2,2,1,3: 0, 2, 1, 3");

  // A random walk with a drift reversal: 20000 samples, jitter and slides mixed.
  std::mt19937                     gen(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double>              s = {0};
  for (int i = 1; i < 20000; ++i) s.push_back(s.back() + (i < 12000 ? 0.02 : -0.03) + noise(gen));
  unit::near(fromSamples(s, 0.05), reference(s, 0.05), 0, 0, "random walk of 20000 samples: equal to the definition on the whole history");
  unit::near(fromSamples(s, 0.001), reference(s, 0.001), 0, 0, "and with a gate of 0.1 % of the range");
  return unit::failures();
}
