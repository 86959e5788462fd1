// Recorded ground accelerations (two-column CSV or PEER NGA .AT2) turned into the incident
// velocity history the absorbing base needs. No exceptions: readers return a status whose
// message names the file, the line and what is wrong, for the caller to raise as a user
// input error.
#pragma once
#include "slipwave/physics/source_time_function.hpp"

#include <string>
#include <vector>

namespace slipwave::input {

constexpr double kStandardGravity = 9.80665;  // m/s^2, converts .AT2 values given in g

// The unit of a record's acceleration values in the file.
enum class AccelerationUnit { FromHeader, MetresPerSecondSquared, G };

struct GroundMotionRecord {
  std::vector<double> time;          // s, strictly increasing
  std::vector<double> acceleration;  // m/s^2
  AccelerationUnit    file_unit = AccelerationUnit::MetresPerSecondSquared;  // what the file held
};

struct ReadStatus {
  bool ok = true;
  std::string message;  // "<file>:<line>: <what is wrong>" (no line when it is the whole file)
};

// Lines "time,acceleration" in s and `unit`; an optional non-numeric header line first;
// blank lines ignored; at least two samples; times strictly increasing, any spacing. With
// FromHeader the unit is the one the header's acceleration column names ("acceleration_g",
// "a (g)", "acc [g]": g; "m/s^2", "m/s2", "m/s/s", "mps2": m/s^2), m/s^2 when it names none
// or there is no header. A header naming another unit (cm/s^2, gal), or a unit other than
// the one asked for, is an error: a record read in the wrong unit is off by a factor 9.8.
// Values are converted to m/s^2; record->file_unit says what the file held.
ReadStatus readAccelerationCsv(const std::string &path, GroundMotionRecord *record,
                               AccelerationUnit unit = AccelerationUnit::FromHeader);

// PEER NGA .AT2: three free header lines, the fourth giving NPTS and DT as
// "NPTS=  5590, DT=   .0050 SEC" or "5590 0.0050 NPTS, DT"; then NPTS values in g, any
// number per line. Sample k is at time k*DT.
ReadStatus readPeerAt2(const std::string &path, GroundMotionRecord *record);

// Cumulative trapezoid rule, starting from 0 at the first time: second-order accurate.
std::vector<double> integrateTrapezoid(const std::vector<double> &time, const std::vector<double> &values);

// Subtracts c0 + c1 (t - t_first) from the acceleration with c0, c1 chosen so that the
// trapezoid-integrated velocity and displacement both end at zero (the record ends at
// rest where it started, instead of drifting away with the base).
// Needs kBaselineMinSamples samples: with two, the constant and the ramp integrate to
// proportional end values and the 2 x 2 system is singular.
void removeBaselineDrift(GroundMotionRecord *record);
constexpr size_t kBaselineMinSamples = 3;

// The velocity history (trapezoid integral of the acceleration) for the incident wave.
physics::TabulatedHistory velocityHistory(const GroundMotionRecord &record);

} // namespace slipwave::input
