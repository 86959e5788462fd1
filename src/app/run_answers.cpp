#include "slipwave/app/run_answers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "slipwave/app/run_report.hpp"
#include "slipwave/numerics/low_pass.hpp"
#include "slipwave/numerics/tail_window.hpp"
#include "slipwave/problem/rigid_bodies.hpp"

namespace slipwave::app {
namespace {

constexpr double kGravity    = 9.80665; // standard gravity, for the table's g [m/s^2]
constexpr double kSlideGate  = 0.05;    // back-and-forth below this share of the range is not a reversal (as scene_metrics.py)
constexpr PetscInt kMaxPeriods = 32;
// The final window over which the tilt after shaking is the mean angle and the rocking left its
// half range: several periods of a rocking structure (0.2-1 s), as scene_metrics.py's.
constexpr double kSettleWindow = 2.0;

// The index of station `name`, or -1.
int stationIndex(const io::Stations &stations, const std::string &name) {
  const auto &names = stations.names();
  const auto  it    = std::find(names.begin(), names.end(), name);
  return it == names.end() ? -1 : (int)(it - names.begin());
}

// A station option: the named station (it must exist) or the default one when the run has it.
PetscErrorCode stationOption(MPI_Comm comm, const io::Stations &stations, const char *option, const char *value, PetscBool given, int *index) {
  PetscFunctionBeginUser;
  *index = stationIndex(stations, value);
  PetscCheck(*index >= 0 || !given, comm, PETSC_ERR_USER_INPUT, "%s = %s: no station of that name; allowed: a station of -station_coordinates/-station_names or -station_file", option,
             value);
  PetscFunctionReturn(0);
}

// Per pair of this rank (io fields of interface::InterfaceAssembler::pairFields): 0 the
// opening, 1 the slip's x component, 9 the accumulated slip, 10 the status.
constexpr int kOpening = 0, kSlipX = 1, kAccumulated = 9, kStatus = 10;

std::string periodKey(const std::string &station, double T) {
  char key[128];
  std::snprintf(key, sizeof key, "%s_psa_%gs", station.c_str(), T);
  return key;
}

// The vertical displacement component: y in 2D, z in 3D.
int verticalComponent(const problem::Elastodynamics &model) { return (int)model.dim - 1; }

} // namespace

PetscErrorCode RunAnswers::Setup(const problem::Elastodynamics &model, const io::Stations &stations) {
  MPI_Comm  comm     = model.comm;
  const int vertical = verticalComponent(model);
  char      iface[256] = "base", structure[256] = "block_top", free_field[256] = "free_field", body[256] = "";
  char     *rocking[2] = {nullptr, nullptr};
  PetscInt  nrock = 2, nperiods = kMaxPeriods;
  PetscReal periods[kMaxPeriods] = {0.05, 0.1, 0.2, 0.3, 0.5, 1.0, 2.0};
  PetscBool has_iface, has_structure, has_free_field, has_body, has_rocking, has_periods;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "The run's answers (stated at the end of a run with an interface)", "slipwave");
  PetscCall(PetscOptionsString("-answer_interface", "interface whose slip and uplift are stated (default base, or the first)", "RunAnswers::Setup", iface, iface, sizeof iface,
                               &has_iface));
  PetscCall(PetscOptionsString("-answer_structure_station", "station of the structure: floor spectrum, peak acceleration, settlement (default block_top)", "RunAnswers::Setup",
                               structure, structure, sizeof structure, &has_structure));
  PetscCall(PetscOptionsString("-answer_free_field_station", "station of the free field: PGA and spectrum (default free_field)", "RunAnswers::Setup", free_field, free_field,
                               sizeof free_field, &has_free_field));
  PetscCall(PetscOptionsString("-answer_rigid_body", "rigid region whose rotation is the rocking angle (default the first rigid region)", "RunAnswers::Setup", body, body,
                               sizeof body, &has_body));
  PetscCall(PetscOptionsStringArray("-answer_rocking_stations", "two stations left,right whose vertical displacements give the rocking angle without a rigid body (default block_base_left,block_base_right)",
                                    "RunAnswers::Setup", rocking, &nrock, &has_rocking));
  PetscCall(PetscOptionsRealArray("-answer_periods", "periods of the stated 5 %-damped spectra [s], each > 0 (default 0.05,0.1,0.2,0.3,0.5,1,2)", "RunAnswers::Setup", periods, &nperiods,
                                  &has_periods));
  PetscOptionsEnd();
  if (!has_periods) nperiods = 7;
  const std::string rock_left = has_rocking && nrock > 0 ? rocking[0] : "block_base_left", rock_right = has_rocking && nrock > 1 ? rocking[1] : "block_base_right";
  for (PetscInt k = 0; k < (has_rocking ? nrock : 0); ++k) PetscCall(PetscFree(rocking[k]));
  PetscCheck(!has_rocking || nrock == 2, comm, PETSC_ERR_USER_INPUT, "-answer_rocking_stations has %" PetscInt_FMT " names; allowed: two stations, left,right", nrock);
  for (PetscInt k = 0; k < nperiods; ++k)
    PetscCheck(periods[k] > 0 && std::isfinite(periods[k]), comm, PETSC_ERR_USER_INPUT, "-answer_periods: %g; allowed: periods > 0 s", (double)periods[k]);
  counts_.assign(model.interfaces.size(), {});
  if (model.interfaces.empty()) {
    PetscCheck(!has_iface, comm, PETSC_ERR_USER_INPUT, "-answer_interface = %s: the model has no interface; allowed: the name of one of -interfaces", iface);
    PetscFunctionReturn(0);
  }
  active_    = true;
  interface_ = 0;
  bool found = false;
  for (size_t k = 0; k < model.interfaces.size(); ++k)
    if (model.interfaces[k].spec().name == iface) {
      interface_ = k;
      found      = true;
    }
  PetscCheck(found || !has_iface, comm, PETSC_ERR_USER_INPUT, "-answer_interface = %s: no interface of that name; allowed: one of -interfaces", iface);
  periods_.assign(periods, periods + nperiods);
  corner_hz_ = LowPassCornerFrequency(model);
  PetscCall(stationOption(comm, stations, "-answer_structure_station", structure, has_structure, &structure_));
  PetscCall(stationOption(comm, stations, "-answer_free_field_station", free_field, has_free_field, &free_field_));
  structure_name_  = structure;
  free_field_name_ = free_field;
  if (structure_ >= 0) {
    structure_spectrum_ = std::make_unique<numerics::ResponseSpectrum>(periods_, 0.05);
    probes_.push_back({structure_, 2, 0});
    probes_.push_back({structure_, 0, vertical});
  } else notes_.push_back("no station '" + structure_name_ + "': no floor spectrum, structure acceleration or settlement (-answer_structure_station)");
  if (free_field_ >= 0) {
    free_field_spectrum_ = std::make_unique<numerics::ResponseSpectrum>(periods_, 0.05);
    probes_.push_back({free_field_, 2, 0});
  } else notes_.push_back("no station '" + free_field_name_ + "': no free-field PGA or spectrum (-answer_free_field_station)");
  if (model.rigid)
    for (size_t b = 0; b < model.rigid->bodies.size(); ++b)
      if (body_ < 0 && (!has_body || model.rigid->bodies[b].region == body)) {
        body_      = (int)b;
        body_name_ = model.rigid->bodies[b].region;
      }
  PetscCheck(body_ >= 0 || !has_body, comm, PETSC_ERR_USER_INPUT, "-answer_rigid_body = %s: no rigid region of that name; allowed: a region of -material_<r>_model rigid", body);
  if (body_ < 0) {
    PetscCall(stationOption(comm, stations, "-answer_rocking_stations", rock_left.c_str(), has_rocking, &rock_left_));
    PetscCall(stationOption(comm, stations, "-answer_rocking_stations", rock_right.c_str(), has_rocking, &rock_right_));
    if (rock_left_ >= 0 && rock_right_ >= 0) {
      rock_span_ = std::fabs(stations.coordinates(rock_right_)[0] - stations.coordinates(rock_left_)[0]);
      PetscCheck(rock_span_ > 0, comm, PETSC_ERR_USER_INPUT, "-answer_rocking_stations %s,%s: the two stations have the same x; allowed: stations apart along x", rock_left.c_str(),
                 rock_right.c_str());
      probes_.push_back({rock_left_, 0, vertical});
      probes_.push_back({rock_right_, 0, vertical});
    } else notes_.push_back("neither a rigid body nor the stations " + rock_left + "," + rock_right + ": no rocking angle");
  }
  PetscFunctionReturn(0);
}

PetscErrorCode RunAnswers::SetGeostatic(const problem::Elastodynamics &model, io::Stations &stations, Vec u_geo) {
  std::vector<double> v;
  PetscFunctionBeginUser;
  if (!active_ || structure_ < 0) PetscFunctionReturn(0);
  PetscCall(stations.Values(model.dm, u_geo, u_geo, {{structure_, 0, verticalComponent(model)}}, &v));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, v.data(), 1, MPI_DOUBLE, MPI_SUM, model.comm));
  geostatic_vertical_ = v[0];
  geostatic_          = true;
  PetscFunctionReturn(0);
}

PetscErrorCode RunAnswers::Update(const problem::Elastodynamics &model, io::Stations &stations, double t, Vec u, Vec a, const std::vector<double> &motion) {
  const size_t        nif = model.interfaces.size();
  std::vector<double> sums(5 * nif, 0.0), probed, fields;
  PetscFunctionBeginUser;
  if (nif == 0) PetscFunctionReturn(0);
  for (size_t k = 0; k < nif; ++k) {
    int per_pair;
    model.interfaces[k].pairFields(&fields, &per_pair);
    double *s = &sums[5 * k];
    for (size_t p = 0; p * per_pair < fields.size(); ++p) {
      const double *f = &fields[p * per_pair];
      s[0] += f[kSlipX];
      s[1] += 1;
      s[2 + (int)f[kStatus]] += 1; // 0 stick, 1 slip, 2 open
      if (k == interface_) local_uplift_ = std::max(local_uplift_, f[kOpening]);
    }
  }
  PetscCall(stations.Values(model.dm, u, a, probes_, &probed));
  sums.insert(sums.end(), probed.begin(), probed.end());
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums.data(), (int)sums.size(), MPI_DOUBLE, MPI_SUM, model.comm));
  for (size_t k = 0; k < nif; ++k) counts_[k] = {sums[5 * k + 2], sums[5 * k + 3], sums[5 * k + 4]};
  const double *s = &sums[5 * interface_];
  net_slip_       = s[1] > 0 ? s[0] / s[1] : 0.0;
  times_.push_back(t);
  turning_.add(net_slip_);
  const double *v = &sums[5 * nif];
  if (structure_ >= 0) {
    structure_spectrum_->add(t, v[0]);
    structure_ax_.push_back(v[0]);
    structure_peak_ = std::max(structure_peak_, std::fabs(v[0]));
    structure_vertical_ = v[1];
    v += 2;
  }
  if (free_field_ >= 0) {
    free_field_spectrum_->add(t, v[0]);
    free_field_ax_.push_back(v[0]);
    free_field_peak_ = std::max(free_field_peak_, std::fabs(v[0]));
    v += 1;
  }
  if (body_ >= 0) {
    const double *theta = &motion[6 * body_ + 3];
    tilt_               = model.dim == 2 ? theta[2] : std::sqrt(theta[0] * theta[0] + theta[1] * theta[1] + theta[2] * theta[2]);
  } else if (rock_span_ > 0) tilt_ = (v[1] - v[0]) / rock_span_;
  rocking_ = std::max(rocking_, std::fabs(tilt_));
  if (body_ >= 0 || rock_span_ > 0) tilts_.push_back(tilt_);
  PetscFunctionReturn(0);
}

PetscErrorCode RunAnswers::Finish(const problem::Elastodynamics &model, bool restarted, const std::string &output_dir, std::string *json) {
  MPI_Comm comm = model.comm;
  PetscFunctionBeginUser;
  json->clear();
  if (!active_) PetscFunctionReturn(0);
  if (restarted) {
    PetscCall(PetscPrintf(comm, "answers: not stated after a restart (they accumulate from the first step); scripts/scene_metrics.py %s reads them from the output\n",
                          output_dir.c_str()));
    PetscFunctionReturn(0);
  }
  const auto &iface = model.interfaces[interface_];
  // The slip path: the largest over the pairs of each pair's accumulated slip.
  std::vector<double> fields;
  int                 per_pair;
  iface.pairFields(&fields, &per_pair);
  double path = 0, uplift = local_uplift_;
  for (size_t p = 0; p * per_pair < fields.size(); ++p) path = std::max(path, fields[p * per_pair + kAccumulated]);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &path, 1, MPI_DOUBLE, MPI_MAX, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &uplift, 1, MPI_DOUBLE, MPI_MAX, comm));
  const std::vector<double> &tp = turning_.values();
  const double range = tp.empty() ? 0.0 : *std::max_element(tp.begin(), tp.end()) - *std::min_element(tp.begin(), tp.end());

  char corner_text[64];
  std::snprintf(corner_text, sizeof corner_text, "%.3g Hz", corner_hz_);
  const std::string corner = corner_text;
  struct Answer {
    std::string key, unit, label;
    double      value;
  };
  std::vector<Answer> answers = {{"net_slip", "m", "net offset (mean slip at the end)", net_slip_},
                                 {"accumulated_slip", "m", "slip path (largest of a pair)", path},
                                 {"largest_slip_excursion", "m", "largest one-way slide", numerics::largestExcursion(tp, kSlideGate)},
                                 {"mean_slip_range", "m", "range of the mean slip (max - min)", range},
                                 {"peak_uplift", "m", "peak uplift (largest opening)", uplift}};
  if (body_ >= 0 || rock_span_ > 0) {
    const std::string by = body_ >= 0 ? "rigid body " + body_name_ : "base stations";
    answers.push_back({"peak_rocking_angle", "rad", "peak rocking angle (" + by + ")", rocking_});
    // The last angle is a point of the swing while the structure still rocks: the tilt is the
    // mean over the final window, and the swing left about it is stated beside it.
    const numerics::TailWindow end = numerics::tailWindow(times_, tilts_, kSettleWindow);
    answers.push_back({"tilt_after_shaking", "rad", "tilt after shaking (" + by + ", 2 s mean)", end.mean});
    answers.push_back({"rocking_at_end", "rad", "still rocking at the end (half range, last 2 s)", end.half_range});
    if (end.half_range > std::fabs(end.mean)) {
      char line[256];
      std::snprintf(line, sizeof line, "the structure still rocks by +-%.3g rad at the end, more than its mean tilt %.3g rad: the tilt is not settled (run past the end of the shaking, -ts_max_time, for a settled tilt)",
                    end.half_range, end.mean);
      notes_.push_back(line);
    }
  }
  if (structure_ >= 0) {
    if (geostatic_) answers.push_back({"settlement_gravity", "m", "settlement under gravity (" + structure_name_ + ")", -geostatic_vertical_});
    answers.push_back({"settlement_after_shaking", "m", "settlement after shaking (" + structure_name_ + ", from gravity's)", -structure_vertical_});
    answers.push_back({"peak_structure_acceleration", "m/s^2", "peak acceleration a_x at " + structure_name_ + " (unfiltered)", structure_peak_});
    answers.push_back({structure_name_ + "_peak_acceleration_lowpassed", "m/s^2", "peak a_x at " + structure_name_ + ", low-passed at " + corner, numerics::lowPassedPeak(times_, structure_ax_, corner_hz_)});
    for (size_t k = 0; k < periods_.size(); ++k)
      answers.push_back({periodKey(structure_name_, periods_[k]), "m/s^2", "", structure_spectrum_->pseudoAcceleration(k)});
  }
  if (free_field_ >= 0) {
    answers.push_back({"free_field_pga", "m/s^2", "free-field PGA a_x at " + free_field_name_ + " (unfiltered)", free_field_peak_});
    answers.push_back({free_field_name_ + "_peak_acceleration_lowpassed", "m/s^2", "free-field PGA at " + free_field_name_ + ", low-passed at " + corner, numerics::lowPassedPeak(times_, free_field_ax_, corner_hz_)});
    for (size_t k = 0; k < periods_.size(); ++k)
      answers.push_back({periodKey(free_field_name_, periods_[k]), "m/s^2", "", free_field_spectrum_->pseudoAcceleration(k)});
  }
  // The table: lengths in m (slides in cm too), angles in rad, accelerations in g.
  PetscCall(PetscPrintf(comm, "answers (interface %s, every step; run_info.json \"answers\"):\n", iface.spec().name.c_str()));
  for (const Answer &x : answers) {
    if (x.label.empty()) continue;
    if (x.unit == "m") PetscCall(PetscPrintf(comm, "  %-50s %10.4g m   (%.3g cm)\n", x.label.c_str(), x.value, 100 * x.value));
    else if (x.unit == "rad") PetscCall(PetscPrintf(comm, "  %-50s %10.4g rad (%.3g deg)\n", x.label.c_str(), x.value, x.value * 180 / M_PI));
    else PetscCall(PetscPrintf(comm, "  %-50s %10.4g g   (%.4g m/s^2)\n", x.label.c_str(), x.value / kGravity, x.value));
  }
  for (const auto &[spectrum, name] : {std::pair{structure_spectrum_.get(), structure_name_}, std::pair{free_field_spectrum_.get(), free_field_name_}}) {
    if (!spectrum) continue;
    std::string row;
    char        cell[64];
    for (size_t k = 0; k < periods_.size(); ++k) {
      std::snprintf(cell, sizeof cell, "%s%g s: %.3g", k ? ", " : "", periods_[k], spectrum->pseudoAcceleration(k) / kGravity);
      row += cell;
    }
    PetscCall(PetscPrintf(comm, "  5 %%-damped PSA at %s [g]: %s\n", name.c_str(), row.c_str()));
  }
  for (const std::string &n : notes_) PetscCall(PetscPrintf(comm, "  note: %s\n", n.c_str()));
  char cell[256];
  for (const Answer &x : answers) {
    std::snprintf(cell, sizeof cell, "%s\"%s\": {\"value\": %.17g, \"unit\": \"%s\"}", json->empty() ? "" : ", ", x.key.c_str(), x.value, x.unit.c_str());
    *json += cell;
  }
  *json = "{" + *json + "}";
  PetscFunctionReturn(0);
}

} // namespace slipwave::app
