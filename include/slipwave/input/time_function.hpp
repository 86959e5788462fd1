// A scalar history read from options with a prefix: the incident wave's particle velocity,
// a prescribed boundary velocity, or the factor on a load (HistoryRole::Load: a point force,
// a traction, a body force). -<prefix>stf none|ricker|gabor|harmonic|record and its
// parameters (harmonic: A sin(2 pi f0 (t - t0)) from t0 on, t0 default 0). Velocity is the primary quantity; acceleration drives prescribed dofs.
// -<prefix>stf record reads -<prefix>record FILE (CSV time,acceleration [s; m/s^2 or g, from
// the header or -<prefix>record_units] or PEER .AT2 [g], by extension or
// -<prefix>record_format csv|at2), removes the baseline drift unless
// -<prefix>baseline_correction false, scales the acceleration by -<prefix>record_scale, or
// to the peak -<prefix>record_pga [g] (exclusive; -<prefix>amplitude is rejected for
// records), and integrates it (trapezoid) into the velocity; acceleration() then returns the
// record's own acceleration, linearly interpolated, which is the exact derivative of that
// velocity at the samples.
// For the incident wave (HistoryRole::IncidentWave) -<prefix>record_motion says what the
// record is: outcrop (default: the motion at the free surface of the rock, which doubles the
// incident wave, so the incident wave is half the record) or incident (the upgoing wave
// itself). A prescribed boundary velocity is the record itself.
// For a load the value is a dimensionless factor on the load vector (-<prefix>amplitude,
// default 1), and a record is that factor sampled: CSV "time,factor", linear between the
// samples, scaled by -<prefix>record_scale, neither integrated nor baseline-corrected.
// A record with fewer than kBaselineMinSamples samples cannot be baseline-corrected and is
// refused unless -<prefix>baseline_correction false.
#pragma once
#include <petscsys.h>

#include <memory>
#include <string>

#include "slipwave/input/ground_motion_record.hpp"

namespace slipwave::input {

// The choices of -<prefix>record_format and -<prefix>record_units, in index order.
inline const char *const kRecordFormats[] = {"csv", "at2"};
inline const char *const kRecordUnits[]   = {"auto", "g", "m/s^2", "cm/s^2"};
inline constexpr int     kRecordUnitCount = 4;

// The file of -<prefix>stf record and how its options say to read it.
struct RecordFile {
  std::string path;
  bool        load     = false; // a load factor: CSV "time,factor", no unit, no baseline correction
  int         format   = -1;    // index in kRecordFormats; -1: from the extension
  int         units    = 0;     // index in kRecordUnits
  bool        baseline = true;  // -<prefix>baseline_correction: needs kBaselineMinSamples samples
};

// Rank 0 parses the file, every rank gets the samples (accelerations in m/s^2, or the load
// factor) or the same one-line error naming -<prefix>record, the file, the line and what is
// allowed. The one parser of record files: TimeFunction::Read, and RecordFilesCheck before the
// mesh is built. *at2 (may be null) says which format was read.
PetscErrorCode RecordFileRead(MPI_Comm comm, const std::string &prefix, const RecordFile &f, GroundMotionRecord *record, bool *at2);

enum class HistoryRole { IncidentWave, BoundaryVelocity, Load };

class TimeFunction {
public:
  TimeFunction();
  ~TimeFunction();
  TimeFunction(TimeFunction &&) noexcept;
  TimeFunction &operator=(TimeFunction &&) noexcept;

  // Reads -<prefix>stf and its parameters inside the caller's options block.
  PetscErrorCode Read(MPI_Comm comm, const std::string &prefix, HistoryRole role, PetscOptionItems *PetscOptionsObject);
  bool        active() const;
  double      velocity(double t) const;
  double      acceleration(double t) const;
  double      topFrequency() const;
  std::string describe() const;

private:
  PetscErrorCode readRecord(MPI_Comm comm, const std::string &prefix, HistoryRole role, PetscOptionItems *PetscOptionsObject);
  PetscErrorCode readLoadRecord(MPI_Comm comm, const std::string &prefix, PetscOptionItems *PetscOptionsObject);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace slipwave::input
