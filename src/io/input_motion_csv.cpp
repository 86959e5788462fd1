#include "slipwave/io/input_motion_csv.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace slipwave::io {

double InputMotionInterval(double top_frequency_hz) {
  // 20 samples per period of the top frequency, and at most 2 ms (10 per period of the
  // shortest spectral period plotted, 0.02 s).
  const double interval = 2e-3;
  return top_frequency_hz > 0 ? std::min(interval, 1.0 / (20.0 * top_frequency_hz)) : interval;
}

bool WriteInputMotion(const std::string &output_dir, const input::TimeFunction &incident, int component, double max_time) {
  FILE *f = std::fopen((output_dir + "/input_motion.csv").c_str(), "w");
  if (!f) return false;
  const char   c  = "xyz"[component];
  const double dt = InputMotionInterval(incident.topFrequency());
  const long   n  = (long)std::ceil(max_time / dt - 1e-9);
  std::fprintf(f, "t,a_outcrop_%c,v_outcrop_%c\n", c, c);
  for (long k = 0; k <= n; ++k) {
    const double t = std::min(k * dt, max_time);
    std::fprintf(f, "%.10g,%.10g,%.10g\n", t, 2.0 * incident.acceleration(t), 2.0 * incident.velocity(t));
  }
  return std::fclose(f) == 0;
}

} // namespace slipwave::io
