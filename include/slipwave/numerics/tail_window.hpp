// What a history does at its end, over a final window: its time mean (the offset it settles
// about, e.g. a rocking block's tilt) and its half range (how far it still swings about it).
// A run that ends while the structure still rocks has no permanent tilt in its last sample:
// the last sample is a point of the swing. The same definition as scripts/scene_metrics.py's
// tail_window.
#pragma once
#include <vector>

namespace slipwave::numerics {

struct TailWindow {
  double mean       = 0; // (1 / W) integral of v over [t_end - W, t_end], trapezoidal
  double half_range = 0; // (max - min) / 2 of v over the window's samples (its start interpolated)
};

// The window [t_end - window, t_end] of the history (t, v), t increasing; the whole history
// when it is shorter than the window; a single sample is its own mean; empty: zeros.
TailWindow tailWindow(const std::vector<double> &t, const std::vector<double> &v, double window);

} // namespace slipwave::numerics
