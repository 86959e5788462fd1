// input_motion.csv: the outcrop motion of the incident plane wave (-input_wave sv|p) as the run
// applies it, so that plots and scripts compare the site's response with its input without
// re-reading and re-scaling the record. The outcrop motion is twice the incident wave (a rock
// outcrop's free surface doubles it), whatever -input_record_motion said the record was.
#pragma once
#include <string>

#include "slipwave/input/time_function.hpp"

namespace slipwave::io {

// Sampling interval of the file: fine enough for the input's content and for response
// spectra down to 0.02 s (the acceleration is piecewise linear between these samples).
double InputMotionInterval(double top_frequency_hz);

// Writes OUTPUT_DIR/input_motion.csv, header "t,a_outcrop_<c>,v_outcrop_<c>" (c the particle
// motion's component x, y or z; s, m/s^2, m/s), rows from t = 0 to max_time every
// InputMotionInterval(incident.topFrequency()). False if the file could not be written.
bool WriteInputMotion(const std::string &output_dir, const input::TimeFunction &incident, int component, double max_time);

} // namespace slipwave::io
