// Recorded ground accelerations (two-column CSV or PEER NGA .AT2) turned into the incident
// velocity history the absorbing base needs. No exceptions: readers return a status whose
// message names the file, the line and what is wrong, for the caller to raise as a user
// input error.
#pragma once
#include "slipwave/physics/source_time_function.hpp"

#include <string>
#include <vector>

namespace slipwave::io {

constexpr double kStandardGravity = 9.80665;  // m/s^2, converts .AT2 values given in g

struct GroundMotionRecord {
  std::vector<double> time;          // s, strictly increasing
  std::vector<double> acceleration;  // m/s^2
};

struct ReadStatus {
  bool ok = true;
  std::string message;  // "<file>:<line>: <what is wrong>" (no line when it is the whole file)
};

// Lines "time,acceleration" in s and m/s^2; an optional non-numeric header line first;
// blank lines ignored; at least two samples; times strictly increasing, any spacing.
ReadStatus readAccelerationCsv(const std::string &path, GroundMotionRecord *record);

// PEER NGA .AT2: three free header lines, the fourth giving NPTS and DT as
// "NPTS=  5590, DT=   .0050 SEC" or "5590 0.0050 NPTS, DT"; then NPTS values in g, any
// number per line. Sample k is at time k*DT.
ReadStatus readPeerAt2(const std::string &path, GroundMotionRecord *record);

// Cumulative trapezoid rule, starting from 0 at the first time: second-order accurate.
std::vector<double> integrateTrapezoid(const std::vector<double> &time, const std::vector<double> &values);

// Subtracts c0 + c1 (t - t_first) from the acceleration with c0, c1 chosen so that the
// trapezoid-integrated velocity and displacement both end at zero (the record ends at
// rest where it started, instead of drifting away with the base).
void removeBaselineDrift(GroundMotionRecord *record);

// The velocity history (trapezoid integral of the acceleration) for the incident wave.
physics::TabulatedHistory velocityHistory(const GroundMotionRecord &record);

} // namespace slipwave::io
