#include "slipwave/numerics/slide_excursion.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <tuple>

namespace slipwave::numerics {

void TurningPoints::add(double s) {
  const size_t n = points_.size();
  if (n > 0 && s == points_.back()) return;
  if (n >= 2 && (points_[n - 1] - points_[n - 2] > 0) == (s - points_[n - 1] > 0)) points_.back() = s;
  else points_.push_back(s);
}

std::vector<double> gatedReversals(std::vector<double> p, double gate) {
  // A linked list of the points and a heap of its legs (size, left point): n log n, since a
  // long run has tens of thousands of turning points. Heap entries whose left point is gone
  // or whose right point changed are stale and skipped.
  const size_t n = p.size();
  if (n <= 2) return p;
  std::vector<size_t> prev(n), next(n);
  std::vector<bool>   alive(n, true);
  for (size_t i = 0; i < n; ++i) {
    prev[i] = i - 1; // wraps at 0: never read for the head
    next[i] = i + 1;
  }
  using Leg = std::tuple<double, size_t, size_t>; // |p_j - p_i|, i, j: the smallest, then the leftmost
  std::priority_queue<Leg, std::vector<Leg>, std::greater<Leg>> legs;
  for (size_t i = 0; i + 1 < n; ++i) legs.emplace(std::fabs(p[i + 1] - p[i]), i, i + 1);
  size_t       count = n;
  const size_t head = 0, tail = n - 1;
  while (count > 2 && !legs.empty()) {
    const auto [size, i, j] = legs.top();
    legs.pop();
    if (!alive[i] || next[i] != j) continue;
    if (size >= gate) break;
    auto unlink = [&](size_t k) {
      alive[k]       = false;
      next[prev[k]]  = next[k];
      prev[next[k]]  = prev[k];
      --count;
    };
    // An interior leg takes both its ends (its neighbours' legs join and still alternate);
    // the first or the last leg its inner end, so that the record's ends stay.
    if (i == head) {
      unlink(j);
      legs.emplace(std::fabs(p[next[i]] - p[i]), i, next[i]);
    } else if (j == tail) {
      const size_t before = prev[i];
      unlink(i);
      legs.emplace(std::fabs(p[j] - p[before]), before, j);
    } else {
      const size_t before = prev[i], after = next[j];
      unlink(i);
      unlink(j);
      legs.emplace(std::fabs(p[after] - p[before]), before, after);
    }
  }
  std::vector<double> kept;
  for (size_t i = head;; i = next[i]) {
    kept.push_back(p[i]);
    if (i == tail) break;
  }
  return kept;
}

double largestExcursion(const std::vector<double> &points, double gate_share) {
  if (points.size() < 2) return 0.0;
  const auto [lo, hi] = std::minmax_element(points.begin(), points.end());
  const double span   = *hi - *lo;
  if (span == 0.0) return 0.0;
  const std::vector<double> r = gatedReversals(points, gate_share * span);
  double                    largest = 0;
  for (size_t i = 1; i < r.size(); ++i) largest = std::max(largest, std::fabs(r[i] - r[i - 1]));
  return largest;
}

} // namespace slipwave::numerics
