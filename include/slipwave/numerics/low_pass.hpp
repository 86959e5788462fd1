// The peak of a record after a zero-phase low-pass: what an engineer reads as the peak
// acceleration a mesh resolves (a landing or a yielding soil's corners put power above the
// frequency the mesh carries, and that power moves with every refinement). The filter's gain
// is 1 / (1 + (f/f_c)^8), the squared magnitude of a 4th-order Butterworth filter (that
// filter run forward and backward), applied in the frequency domain to the record padded with
// zeros to a power of two at least twice its length, so that its end does not wrap onto its
// start. The same definition as scripts/scene_metrics.py's low_passed.
#pragma once
#include <vector>

namespace slipwave::numerics {

// The record a(t) on a uniform grid: t's own samples when its steps are equal (within 1e-6
// of their mean, round-off in t), else a linear interpolation at t_0 + k dt, dt the mean step
// (a shorter last step). *dt: the step. t strictly increasing, at least 2 samples.
std::vector<double> uniformRecord(const std::vector<double> &t, const std::vector<double> &a, double *dt);

// a (uniform step dt) low-passed at f_c [Hz] (f_c > 0), zero phase.
std::vector<double> lowPassed(const std::vector<double> &a, double dt, double f_c);

// max |a| of the record (t, a) made uniform and low-passed at f_c; 0 for fewer than 2 samples.
double lowPassedPeak(const std::vector<double> &t, const std::vector<double> &a, double f_c);

} // namespace slipwave::numerics
