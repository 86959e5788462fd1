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

// The unit of a record's acceleration values in the file; Factor: a dimensionless load factor
// history (its header is not read for a unit).
enum class AccelerationUnit { FromHeader, MetresPerSecondSquared, G, CentimetresPerSecondSquared, Factor };

// Larger record values are refused at read time, naming the line: no soil, rock or structure
// accelerates at 1e6 m/s^2 (1e5 g), and such a value (1e200) would overflow the energy sums.
constexpr double kMaxRecordMagnitude = 1e6; // m/s^2, or a load factor

// "g", "m/s^2", "cm/s^2" ("-" for a factor).
const char *AccelerationUnitName(AccelerationUnit unit);

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
// blank lines ignored; at least two samples; times strictly increasing, any spacing. The
// header's acceleration column may name its unit, in brackets ("a (g)", "acc [m/s^2]") or after
// the quantity words ("acceleration_g", "acceleration_cm_s2", "ground acceleration gal"): g;
// m/s^2 (m/s2, m_s2, mps2, m/s/s); cm/s^2 (cm/s2, cm_s2, gal). The values are read in that
// unit; m/s^2 when it names none or there is no header; a unit word not in that list, or a unit
// other than the one asked for (not FromHeader), is an error: a record read in the wrong unit
// is off by a factor 9.8 or 100. Values beyond kMaxRecordMagnitude are refused with their line.
// Values are converted to m/s^2 (Factor: kept as they are); record->file_unit says what the
// file held.
ReadStatus readAccelerationCsv(const std::string &path, GroundMotionRecord *record,
                               AccelerationUnit unit = AccelerationUnit::FromHeader);

// PEER NGA .AT2: three free header lines, the fourth giving NPTS and DT as
// "NPTS=  5590, DT=   .0050 SEC" or "5590 0.0050 NPTS, DT"; then NPTS values in g, any
// number per line. Sample k is at time k*DT. A header line "... UNITS OF <unit>" names their
// unit (PEER writes G); a unit slipwave does not read is an error, and so is one other than
// `asked` (unless FromHeader).
ReadStatus readPeerAt2(const std::string &path, GroundMotionRecord *record, AccelerationUnit asked = AccelerationUnit::FromHeader);

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
