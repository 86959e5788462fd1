// The end of a history (numerics/tail_window.hpp): a rocking block's mean tilt and its swing
// over the last window. Expected values are closed forms: the mean of an offset sine over
// whole periods is the offset, its half range the amplitude; a line's mean over the window is
// its value at the window's middle (trapezoids are exact for it, the window's start
// interpolated on a segment); a history shorter than the window is taken whole.
#include "slipwave/numerics/tail_window.hpp"

#include "unit_check.hpp"

#include <cmath>
#include <vector>

using namespace slipwave::numerics;

int main() {
  // An offset sine, c + A sin(2 pi f t), f = 1.5 Hz, over 0..10 s at dt = 1e-3: the last 2 s
  // hold 3 whole periods (trapezoids of a sampled sine over whole periods sum to zero).
  const double dt = 1e-3, c = 1.5e-4, A = 1.5e-3, f = 1.5;
  std::vector<double> t, v;
  for (int k = 0; k <= 10000; ++k) t.push_back(k * dt), v.push_back(c + A * std::sin(2 * M_PI * f * k * dt));
  TailWindow w = tailWindow(t, v, 2.0);
  unit::near(w.mean, c, 0, 1e-12 * A, "offset sine: the mean over whole periods is the offset");
  // The crests lie within (2 pi f dt)^2 / 8 of a sample (1.1e-5 of A).
  unit::near(w.half_range, A, std::pow(2 * M_PI * f * dt, 2) / 8, 0, "offset sine: the half range is the amplitude");
  // A line v = 2 + 3 t on uneven samples, window 1.3 s ending at 4: the window starts inside a
  // segment; the mean is the value at t = 3.35, the half range 3 x 1.3 / 2.
  std::vector<double> tl = {0, 0.7, 1.9, 2.5, 2.9, 3.6, 4.0}, vl;
  for (double x : tl) vl.push_back(2 + 3 * x);
  w = tailWindow(tl, vl, 1.3);
  unit::near(w.mean, 2 + 3 * 3.35, 1e-14, 0, "line: the mean is its value at the window's middle");
  unit::near(w.half_range, 1.5 * 1.3, 1e-14, 0, "line: the half range spans the window from its interpolated start");
  // A window longer than the history: the whole of it (mean of the line over 0..4: at t = 2).
  w = tailWindow(tl, vl, 10.0);
  unit::near(w.mean, 2 + 3 * 2.0, 1e-14, 0, "window longer than the history: the whole history");
  unit::near(w.half_range, 6.0, 1e-14, 0, "window longer than the history: its whole range");
  // One sample: its own mean, no swing; none: zeros.
  w = tailWindow({1.0}, {7.0}, 2.0);
  unit::check(w.mean == 7.0 && w.half_range == 0.0, "one sample: its own mean, no swing");
  w = tailWindow({}, {}, 2.0);
  unit::check(w.mean == 0.0 && w.half_range == 0.0, "no samples: zeros");
  return unit::failures();
}
