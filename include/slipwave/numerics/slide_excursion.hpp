// The largest one-way slide of a history s(t) (the mean slip of an interface), kept sample
// by sample: s's turning points are all that the answer needs, so the history itself is not
// stored. The answer is the largest |s_j - s_i| between consecutive reversals of s, where
// the reversals are its turning points (first and last sample included) after every
// back-and-forth smaller than a gate (a share of the range of s) has been removed, smallest
// first: the range filter of rainflow counting, so that the elastic jitter of the jump
// during stick does not cut one slide in two. The same definition as
// scripts/scene_metrics.py's largest_excursion.
#pragma once
#include <vector>

namespace slipwave::numerics {

class TurningPoints {
public:
  // The next sample. A plateau counts once; a sample continuing the last leg's direction
  // moves that leg's end.
  void add(double s);
  // The turning points so far, the first and the latest sample included.
  const std::vector<double> &values() const { return points_; }

private:
  std::vector<double> points_;
};

// The reversals of the turning points `points` once every leg below gate is removed,
// smallest first (an interior leg takes both its ends; the first or the last leg its inner
// end: the record's first and last samples stay).
std::vector<double> gatedReversals(std::vector<double> points, double gate);

// The largest |difference| between consecutive gated reversals, the gate being gate_share
// times the range of the points (0 for a constant history).
double largestExcursion(const std::vector<double> &points, double gate_share);

} // namespace slipwave::numerics
