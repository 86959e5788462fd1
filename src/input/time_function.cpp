#include "slipwave/input/time_function.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <variant>

#include "slipwave/core/option_choice.hpp"
#include "slipwave/core/warnings.hpp"
#include "slipwave/physics/plausible_values.hpp"
#include "slipwave/input/ground_motion_record.hpp"
#include "slipwave/physics/source_time_function.hpp"

namespace slipwave::input {
namespace {

// Linear interpolation of samples (t_k, y_k); zero outside [t_0, t_last].
double interpolateInside(const std::vector<double> &t, const std::vector<double> &y, double x) {
  if (t.empty() || x < t.front() || x > t.back()) return 0;
  if (x == t.back()) return y.back();
  const size_t k = std::upper_bound(t.begin(), t.end(), x) - t.begin(); // x in [t_{k-1}, t_k)
  const double s = (x - t[k - 1]) / (t[k] - t[k - 1]);
  return (1 - s) * y[k - 1] + s * y[k];
}

// Slope of physics::velocity(TabulatedHistory) on the interval holding t: the exact
// derivative of the linear interpolation (right-continuous at the samples; zero before
// the first sample and after the last, where the velocity is held constant).
double tabulatedSlope(const physics::TabulatedHistory &h, double t) {
  if (h.times.size() < 2 || t < h.times.front() || t >= h.times.back()) return 0;
  const size_t k = std::upper_bound(h.times.begin(), h.times.end(), t) - h.times.begin();
  return (h.values[k] - h.values[k - 1]) / (h.times[k] - h.times[k - 1]);
}

// Highest frequency at which the velocity's amplitude spectrum still reaches 1% of its peak
// (the criterion physics::topFrequency uses for the wavelets), from a direct Fourier sum
// with trapezoid weights on at most 2000 frequencies up to the Nyquist frequency of the
// coarsest sampling interval. Zero-padded to 4x the duration so the grid resolves the peak.
double spectralTopFrequency(const physics::TabulatedHistory &h) {
  const std::vector<double> &t = h.times, &v = h.values;
  const size_t               n = t.size();
  const double               f_nyquist = physics::topFrequency(h);
  if (n < 2 || !(f_nyquist > 0)) return f_nyquist;
  const double duration = t.back() - t.front();
  const int    nf       = (int)std::min(2000.0, std::ceil(4 * duration * f_nyquist));
  const double df       = f_nyquist / nf;
  std::vector<double> w(n, 0.0);
  for (size_t k = 0; k + 1 < n; ++k) w[k] += 0.5 * (t[k + 1] - t[k]), w[k + 1] += 0.5 * (t[k + 1] - t[k]);
  std::vector<double> amplitude(nf + 1);
  double              peak = 0;
  for (int j = 0; j <= nf; ++j) {
    const double omega = 2 * M_PI * j * df;
    double       re = 0, im = 0;
    for (size_t k = 0; k < n; ++k) re += w[k] * v[k] * std::cos(omega * t[k]), im -= w[k] * v[k] * std::sin(omega * t[k]);
    amplitude[j] = std::hypot(re, im);
    peak         = std::max(peak, amplitude[j]);
  }
  for (int j = nf; j >= 0; --j)
    if (amplitude[j] >= 0.01 * peak) return std::min(f_nyquist, (j + 1) * df);
  return f_nyquist;
}

std::string lowerExtension(const std::string &path) {
  const size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  for (char &c : ext) c = (char)std::tolower((unsigned char)c);
  return ext;
}

// Rank 0 reads the file; the status and the samples are broadcast so every rank raises the
// same error or holds the same record.
PetscErrorCode readRecordCollective(MPI_Comm comm, const std::string &path, bool at2, AccelerationUnit unit, GroundMotionRecord *record,
                                    ReadStatus *status) {
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) *status = at2 ? readPeerAt2(path, record, unit) : readAccelerationCsv(path, record, unit);
  int ok = status->ok ? 1 : 0;
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm));
  status->ok = ok;
  if (!ok) {
    int len = (int)status->message.size();
    PetscCallMPI(MPI_Bcast(&len, 1, MPI_INT, 0, comm));
    status->message.resize(len);
    PetscCallMPI(MPI_Bcast(status->message.data(), len, MPI_CHAR, 0, comm));
    PetscFunctionReturn(0);
  }
  long n = (long)record->time.size();
  PetscCallMPI(MPI_Bcast(&n, 1, MPI_LONG, 0, comm));
  record->time.resize(n), record->acceleration.resize(n);
  PetscCallMPI(MPI_Bcast(record->time.data(), (int)n, MPI_DOUBLE, 0, comm));
  PetscCallMPI(MPI_Bcast(record->acceleration.data(), (int)n, MPI_DOUBLE, 0, comm));
  int file_unit = (int)record->file_unit;
  PetscCallMPI(MPI_Bcast(&file_unit, 1, MPI_INT, 0, comm));
  record->file_unit = (AccelerationUnit)file_unit;
  PetscFunctionReturn(0);
}

// Inside PetscOptionsBegin(comm, block_prefix, ...) the PetscOptions* calls prepend the
// block's prefix; `prefix` is the full one (e.g. "bc_bottom_" read inside the "bc_bottom_"
// block, or "input_" inside a block without prefix), so the names passed there are "-" plus
// what the block does not already supply.
std::string relativeName(const std::string &prefix, PetscOptionItems *PetscOptionsObject) {
  const std::string block = PetscOptionsObject && PetscOptionsObject->prefix ? PetscOptionsObject->prefix : "";
  if (!block.empty() && prefix.compare(0, block.size(), block) == 0) return "-" + prefix.substr(block.size());
  return "-" + prefix;
}

} // namespace

struct TimeFunction::Impl {
  std::variant<std::monostate, physics::RickerWavelet, physics::GaborWavelet, physics::HarmonicWave, physics::TabulatedHistory> f;
  // For a record: the (scaled, baseline-corrected) acceleration samples at the velocity's
  // times. The tabulated velocity is their trapezoid integral, i.e. the exact integral of
  // their linear interpolation at every sample, so this interpolation is the velocity's own
  // derivative (continuous, second-order consistent with the central-difference step).
  std::vector<double> record_acceleration;
  double              record_top_frequency = 0;  // spectral 1% criterion, see spectralTopFrequency
  std::string         description = "none";
};

PetscErrorCode RecordFileRead(MPI_Comm comm, const std::string &prefix, const RecordFile &f, GroundMotionRecord *record, bool *at2_out) {
  const std::string  p = "-" + prefix;
  const char        *file = f.path.c_str();
  ReadStatus         status;
  PetscFunctionBeginUser;
  if (f.load) {
    PetscCall(readRecordCollective(comm, f.path, false, AccelerationUnit::Factor, record, &status));
    PetscCheck(status.ok, comm, PETSC_ERR_FILE_OPEN, "%srecord (CSV): %s; allowed: a CSV file of lines \"time,factor\", optional header, at least 2 samples, times increasing",
               p.c_str(), status.message.c_str());
    PetscFunctionReturn(0);
  }
  bool at2;
  if (f.format >= 0) {
    at2 = f.format == 1;
  } else {
    const std::string ext = lowerExtension(f.path);
    PetscCheck(ext == "csv" || ext == "at2", comm, PETSC_ERR_USER_INPUT,
               "%srecord = %s: cannot tell the format from the extension '%s'; allowed: a .csv or .at2 file, or %srecord_format csv|at2", p.c_str(), file, ext.c_str(),
               p.c_str());
    at2 = ext == "at2";
  }
  const AccelerationUnit units[kRecordUnitCount] = {AccelerationUnit::FromHeader, AccelerationUnit::G, AccelerationUnit::MetresPerSecondSquared,
                                                    AccelerationUnit::CentimetresPerSecondSquared};
  const AccelerationUnit unit = units[f.units];
  PetscCall(readRecordCollective(comm, f.path, at2, unit, record, &status));
  const std::string allowed = at2 ? "a PEER NGA .AT2 file: 3 header lines, a 4th with NPTS and DT, then NPTS accelerations in g (or the unit its header names)"
                                  : "a CSV file of lines \"time,acceleration\" [s; m/s^2, or the unit the header's acceleration column names, or " + p +
                                      "record_units], optional header, at least 2 samples, times increasing";
  PetscCheck(status.ok, comm, PETSC_ERR_FILE_OPEN, "%srecord (%s): %s; allowed: %s", p.c_str(), at2 ? "PEER .AT2" : "CSV", status.message.c_str(), allowed.c_str());
  PetscCheck(!f.baseline || record->time.size() >= kBaselineMinSamples, comm, PETSC_ERR_USER_INPUT,
             "%srecord = %s has %zu samples; allowed: at least %zu for the baseline correction (or %sbaseline_correction false)", p.c_str(), file, record->time.size(),
             kBaselineMinSamples, p.c_str());
  if (at2_out) *at2_out = at2;
  PetscFunctionReturn(0);
}

TimeFunction::TimeFunction() : impl_(std::make_unique<Impl>()) {}
TimeFunction::~TimeFunction() = default;
TimeFunction::TimeFunction(TimeFunction &&) noexcept = default;
TimeFunction &TimeFunction::operator=(TimeFunction &&) noexcept = default;

PetscErrorCode TimeFunction::Read(MPI_Comm comm, const std::string &prefix, HistoryRole role, PetscOptionItems *PetscOptionsObject) {
  const char *const kinds[] = {"none", "ricker", "gabor", "harmonic", "record"};
  enum Kind { None, Ricker, Gabor, Harmonic, Record };
  const bool        load = role == HistoryRole::Load;
  PetscInt          kind = None;
  PetscReal         amplitude = load ? 1.0 : 0.1, f0 = 2.0, t0 = -1, gamma = 4.0, phase = 0;
  const std::string p = "-" + prefix, q = relativeName(prefix, PetscOptionsObject);
  const char       *unit = load ? "" : " m/s";
  PetscFunctionBeginUser;
  PetscCall(core::OptionsChoice(PetscOptionsObject, (q + "stf").c_str(), load ? "load factor history: none, ricker, gabor, harmonic, record" : "velocity history: none, ricker, gabor, harmonic, record",
                                kinds, 5, &kind, nullptr));
  if (kind == None) PetscFunctionReturn(0);
  char buf[1024];
  if (kind == Record) {
    PetscCall(load ? readLoadRecord(comm, prefix, PetscOptionsObject) : readRecord(comm, prefix, role, PetscOptionsObject));
    PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsReal((q + "amplitude").c_str(),
                             load ? "peak factor on the load [-] (ricker, gabor, harmonic; a record is scaled with -record_scale)"
                                  : "peak particle velocity [m/s] (ricker, gabor, harmonic; a record is scaled with -record_scale or -record_pga)",
                             "TimeFunction::Read", amplitude, &amplitude, nullptr));
  PetscCall(PetscOptionsReal((q + "f0").c_str(), "central frequency [Hz]", "TimeFunction::Read", f0, &f0, nullptr));
  PetscCall(PetscOptionsReal((q + "t0").c_str(), "time of the peak [s] (default 1.2/f0 for ricker, gamma/(2 f0) for gabor); harmonic: switch-on time (default 0)",
                             "TimeFunction::Read", t0, &t0, nullptr));
  PetscCheck(f0 > 0, comm, PETSC_ERR_USER_INPUT, "%sf0 = %g; allowed: > 0 Hz", p.c_str(), (double)f0);
  if (kind == Ricker) {
    if (t0 < 0) t0 = 1.2 / f0;
    impl_->f = physics::RickerWavelet{amplitude, f0, t0};
    std::snprintf(buf, sizeof buf, "Ricker wavelet, peak %g%s, f0 %g Hz, t0 %g s", (double)amplitude, unit, (double)f0, (double)t0);
  } else if (kind == Harmonic) {
    if (t0 < 0) t0 = 0;
    impl_->f = physics::HarmonicWave{amplitude, f0, t0};
    std::snprintf(buf, sizeof buf, "harmonic, amplitude %g%s, f0 %g Hz, from t0 %g s", (double)amplitude, unit, (double)f0, (double)t0);
  } else {
    PetscCall(PetscOptionsReal((q + "gamma").c_str(), "Gabor envelope width [periods]", "TimeFunction::Read", gamma, &gamma, nullptr));
    PetscCall(PetscOptionsReal((q + "phase").c_str(), "Gabor phase [rad]", "TimeFunction::Read", phase, &phase, nullptr));
    PetscCheck(gamma > 0, comm, PETSC_ERR_USER_INPUT, "%sgamma = %g; allowed: > 0", p.c_str(), (double)gamma);
    if (t0 < 0) t0 = gamma / (2 * f0);
    impl_->f = physics::GaborWavelet{amplitude, f0, t0, gamma, phase};
    std::snprintf(buf, sizeof buf, "Gabor wavelet, amplitude %g%s, f0 %g Hz, t0 %g s, gamma %g", (double)amplitude, unit, (double)f0, (double)t0, (double)gamma);
  }
  impl_->description = buf;
  PetscFunctionReturn(0);
}

// -<prefix>stf record: an acceleration record (CSV time,acceleration in s and m/s^2 or g, or
// PEER .AT2 in g), baseline-corrected unless told otherwise, scaled by a factor or to a
// target peak, halved when it is an outcrop motion driving the incident wave, integrated
// with the trapezoid rule into the velocity history.
PetscErrorCode TimeFunction::readRecord(MPI_Comm comm, const std::string &prefix, HistoryRole role, PetscOptionItems *PetscOptionsObject) {
  const std::string p = "-" + prefix, q = relativeName(prefix, PetscOptionsObject);
  char              file[PETSC_MAX_PATH_LEN] = "";
  PetscReal         scale = 1.0, pga_g = 0;
  PetscInt          motion = 0, format = 0, units = 0; // indices in motions[], kRecordFormats[], kRecordUnits[]
  PetscBool         baseline = PETSC_TRUE, has_file, has_format, has_amplitude, has_scale, has_pga;
  const char *const motions[] = {"outcrop", "incident"};
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, (p + "amplitude").c_str(), &has_amplitude));
  PetscCheck(!has_amplitude, comm, PETSC_ERR_USER_INPUT,
             "%samplitude does not apply to %sstf record (the record's own amplitude is used); allowed: %srecord_scale <factor> or %srecord_pga <peak in g>",
             p.c_str(), p.c_str(), p.c_str(), p.c_str());
  PetscCall(PetscOptionsString((q + "record").c_str(), "acceleration record: CSV time,acceleration [s; m/s^2 or g] or PEER NGA .AT2 [g]", "TimeFunction::Read", file,
                               file, sizeof file, &has_file));
  PetscCall(core::OptionsChoice(PetscOptionsObject, (q + "record_format").c_str(), "format of the record: csv or at2 (default: from the file extension)", kRecordFormats, 2,
                                &format, &has_format));
  PetscCall(core::OptionsChoice(PetscOptionsObject, (q + "record_units").c_str(),
                                "unit of the record's acceleration: auto (the one its header names: a CSV's acceleration column, an .AT2's UNITS OF; else m/s^2 for a CSV, g for an .AT2), g, m/s^2, cm/s^2; a header naming another unit is refused", kRecordUnits, kRecordUnitCount,
                                &units, nullptr));
  PetscCall(PetscOptionsReal((q + "record_scale").c_str(), "factor on the record's acceleration [-] (not with -record_pga)", "TimeFunction::Read", scale, &scale,
                             &has_scale));
  PetscCall(PetscOptionsReal((q + "record_pga").c_str(), "scale the record to this peak ground acceleration [g] (> 0; not with -record_scale)", "TimeFunction::Read",
                             pga_g, &pga_g, &has_pga));
  if (role == HistoryRole::IncidentWave) {
    PetscCall(core::OptionsChoice(PetscOptionsObject, (q + "record_motion").c_str(),
                                  "what the record is: outcrop (motion of a rock outcrop = 2 x the incident wave) or incident (the upgoing wave itself)", motions, 2, &motion,
                                  nullptr));
  }
  PetscCall(PetscOptionsBool((q + "baseline_correction").c_str(),
                             "subtract c0 + c1 t from the acceleration so that the integrated velocity and displacement end at zero", "TimeFunction::Read",
                             baseline, &baseline, nullptr));
  PetscCheck(has_file && file[0], comm, PETSC_ERR_USER_INPUT, "%sstf record needs the file; allowed: %srecord <file.csv|file.at2>", p.c_str(), p.c_str());
  PetscCheck(!(has_scale && has_pga), comm, PETSC_ERR_USER_INPUT,
             "%srecord_scale and %srecord_pga are both given; allowed: one of them (a factor, or a target peak ground acceleration in g)", p.c_str(), p.c_str());
  char scale_text[32]; // formatted here: PETSc's own %g would print 0 as "0."
  std::snprintf(scale_text, sizeof scale_text, "%g", (double)(has_pga ? pga_g : scale));
  PetscCheck(std::isfinite(scale) && scale != 0, comm, PETSC_ERR_USER_INPUT, "%srecord_scale = %s; allowed: a finite factor other than 0", p.c_str(), scale_text);
  PetscCheck(!has_pga || (std::isfinite(pga_g) && pga_g > 0), comm, PETSC_ERR_USER_INPUT, "%srecord_pga = %s; allowed: a peak ground acceleration > 0 in g",
             p.c_str(), scale_text);
  GroundMotionRecord record;
  bool               at2;
  PetscCall(RecordFileRead(comm, prefix, RecordFile{file, false, has_format ? (int)format : -1, (int)units, (bool)baseline}, &record, &at2));
  if (baseline) removeBaselineDrift(&record);
  double record_peak = 0;
  for (double a : record.acceleration) record_peak = std::max(record_peak, std::fabs(a));
  PetscCheck(!has_pga || record_peak > 0, comm, PETSC_ERR_USER_INPUT, "%srecord_pga = %s: the record %s has no acceleration to scale; allowed: a record with a nonzero sample",
             p.c_str(), scale_text, file);
  // The factor that gives the applied (baseline-corrected) motion exactly the asked peak.
  const double factor = has_pga ? pga_g * kStandardGravity / record_peak : (double)scale;
  const bool   outcrop = role == HistoryRole::IncidentWave && motion == 0;
  // A vertically incident wave doubles at a free surface: an outcrop record is twice the
  // incident wave that produces it, so the incident wave is half of it.
  const double incident_share = outcrop ? 0.5 : 1.0;
  for (double &a : record.acceleration) a *= factor * incident_share;
  const std::string implausible = physics::PgaImplausible(std::fabs(factor) * record_peak / kStandardGravity);
  if (!implausible.empty() && role != HistoryRole::Load) {
    char scale_read[64];
    std::snprintf(scale_read, sizeof scale_read, ", scale factor %g)", factor);
    PetscCall(core::WarningPrint(comm, p + "record: " + implausible + " (" + file + " read in " + AccelerationUnitName(record.file_unit) + scale_read));
  }
  physics::TabulatedHistory history = velocityHistory(record);
  double pgv = 0; // of the motion the record describes (as the PGA), not of the incident wave
  for (double v : history.values) pgv = std::max(pgv, std::fabs(v) / incident_share);
  const size_t n = record.time.size();
  const char  *what = role == HistoryRole::BoundaryVelocity ? "the boundary's own motion"
                      : outcrop ? "outcrop motion (a rock outcrop moves 2 x the incident wave): the incident wave is half of it"
                                : "the incident wave itself (a rock outcrop would move twice as much)";
  char buf[PETSC_MAX_PATH_LEN + 512];
  std::snprintf(buf, sizeof buf, "record %s (%s in %s, %zu samples, %g to %g s)%s; PGA %.4g g (scale factor %.4g on the record's %.4g g); PGV %.4g m/s; %s", file,
                at2 ? "AT2" : "CSV", AccelerationUnitName(record.file_unit), n, record.time.front(), record.time.back(),
                baseline ? ", baseline-corrected" : "", std::fabs(factor) * record_peak / kStandardGravity, factor, record_peak / kStandardGravity, pgv,
                what);
  impl_->record_acceleration  = record.acceleration;
  impl_->record_top_frequency = spectralTopFrequency(history);
  impl_->f                   = std::move(history);
  impl_->description         = buf;
  PetscFunctionReturn(0);
}

// -<prefix>stf record for a load: the factor itself, sampled in a CSV "time,factor" file.
PetscErrorCode TimeFunction::readLoadRecord(MPI_Comm comm, const std::string &prefix, PetscOptionItems *PetscOptionsObject) {
  const std::string p = "-" + prefix, q = relativeName(prefix, PetscOptionsObject);
  char              file[PETSC_MAX_PATH_LEN] = "";
  PetscReal         scale = 1.0;
  PetscBool         has_file;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsString((q + "record").c_str(), "load factor history: CSV time,factor [s; -]", "TimeFunction::Read", file, file, sizeof file, &has_file));
  PetscCall(PetscOptionsReal((q + "record_scale").c_str(), "factor on the recorded load factor [-]", "TimeFunction::Read", scale, &scale, nullptr));
  PetscCheck(has_file && file[0], comm, PETSC_ERR_USER_INPUT, "%sstf record needs the file; allowed: %srecord <file.csv>", p.c_str(), p.c_str());
  PetscCheck(std::isfinite(scale), comm, PETSC_ERR_USER_INPUT, "%srecord_scale is not finite; allowed: a finite factor", p.c_str());
  GroundMotionRecord record;
  PetscCall(RecordFileRead(comm, prefix, RecordFile{file, true}, &record, nullptr));
  for (double &a : record.acceleration) a *= scale;
  char buf[PETSC_MAX_PATH_LEN + 128];
  std::snprintf(buf, sizeof buf, "recorded load factor %s (%zu samples, %g to %g s, scale %g)", file, record.time.size(), record.time.front(), record.time.back(),
                (double)scale);
  impl_->f           = physics::TabulatedHistory{record.time, record.acceleration};
  impl_->description = buf;
  PetscFunctionReturn(0);
}

bool TimeFunction::active() const { return !std::holds_alternative<std::monostate>(impl_->f); }

double TimeFunction::velocity(double t) const {
  return std::visit(
    [t](const auto &w) -> double {
      if constexpr (std::is_same_v<std::decay_t<decltype(w)>, std::monostate>) return 0.0;
      else return physics::velocity(w, t);
    },
    impl_->f);
}

double TimeFunction::acceleration(double t) const {
  const Impl &impl = *impl_;
  return std::visit(
    [t, &impl](const auto &w) -> double {
      using W = std::decay_t<decltype(w)>;
      if constexpr (std::is_same_v<W, std::monostate>) return 0.0;
      else if constexpr (std::is_same_v<W, physics::TabulatedHistory>) {
        // A record: its own acceleration, linearly interpolated (the exact derivative of the
        // trapezoid velocity through the samples). Zero after the last sample, where the
        // velocity is held. Without acceleration samples: the slope of the linear velocity.
        if (impl.record_acceleration.size() == w.times.size()) return t < w.times.back() ? interpolateInside(w.times, impl.record_acceleration, t) : 0.0;
        return tabulatedSlope(w, t);
      } else return physics::acceleration(w, t);
    },
    impl.f);
}

double TimeFunction::topFrequency() const {
  if (impl_->record_top_frequency > 0) return impl_->record_top_frequency;
  return std::visit(
    [](const auto &w) -> double {
      if constexpr (std::is_same_v<std::decay_t<decltype(w)>, std::monostate>) return 0.0;
      else return physics::topFrequency(w);
    },
    impl_->f);
}

std::string TimeFunction::describe() const { return impl_->description; }

} // namespace slipwave::input
