#include "slipwave/model/time_function.hpp"

#include <cstdio>
#include <variant>

#include "slipwave/physics/source_time_function.hpp"

namespace slipwave::model {

struct TimeFunction::Impl {
  std::variant<std::monostate, physics::RickerWavelet, physics::GaborWavelet, physics::TabulatedHistory> f;
  std::string description = "none";
};

TimeFunction::TimeFunction() : impl_(std::make_unique<Impl>()) {}
TimeFunction::~TimeFunction() = default;
TimeFunction::TimeFunction(TimeFunction &&) noexcept = default;
TimeFunction &TimeFunction::operator=(TimeFunction &&) noexcept = default;

PetscErrorCode TimeFunction::Read(MPI_Comm comm, const std::string &prefix, PetscOptionItems *PetscOptionsObject) {
  const char *const kinds[] = {"none", "ricker", "gabor", "record", "TimeFunctionKind", "", nullptr};
  PetscInt          kind = 0;
  PetscReal         amplitude = 0.1, f0 = 2.0, t0 = -1, gamma = 4.0, phase = 0;
  const std::string p = "-" + prefix;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsEList((p + "stf").c_str(), "velocity history: none, ricker, gabor, record", "TimeFunction::Read", kinds, 4, kinds[0], &kind, nullptr));
  if (kind == 0) PetscFunctionReturn(0);
  PetscCall(PetscOptionsReal((p + "amplitude").c_str(), "peak particle velocity [m/s]", "TimeFunction::Read", amplitude, &amplitude, nullptr));
  if (kind == 1 || kind == 2) {
    PetscCall(PetscOptionsReal((p + "f0").c_str(), "central frequency [Hz]", "TimeFunction::Read", f0, &f0, nullptr));
    PetscCall(PetscOptionsReal((p + "t0").c_str(), "time of the peak [s] (default 1.2/f0 for ricker, gamma/(2 f0) for gabor)", "TimeFunction::Read", t0, &t0,
                               nullptr));
    PetscCheck(f0 > 0, comm, PETSC_ERR_USER_INPUT, "%sf0 = %g; allowed: > 0 Hz", p.c_str(), (double)f0);
  }
  char buf[256];
  if (kind == 1) {
    if (t0 < 0) t0 = 1.2 / f0;
    impl_->f = physics::RickerWavelet{amplitude, f0, t0};
    std::snprintf(buf, sizeof buf, "Ricker wavelet, peak velocity %g m/s, f0 %g Hz, t0 %g s", (double)amplitude, (double)f0, (double)t0);
  } else if (kind == 2) {
    PetscCall(PetscOptionsReal((p + "gamma").c_str(), "Gabor envelope width [periods]", "TimeFunction::Read", gamma, &gamma, nullptr));
    PetscCall(PetscOptionsReal((p + "phase").c_str(), "Gabor phase [rad]", "TimeFunction::Read", phase, &phase, nullptr));
    PetscCheck(gamma > 0, comm, PETSC_ERR_USER_INPUT, "%sgamma = %g; allowed: > 0", p.c_str(), (double)gamma);
    if (t0 < 0) t0 = gamma / (2 * f0);
    impl_->f = physics::GaborWavelet{amplitude, f0, t0, gamma, phase};
    std::snprintf(buf, sizeof buf, "Gabor wavelet, amplitude %g m/s, f0 %g Hz, t0 %g s, gamma %g", (double)amplitude, (double)f0, (double)t0, (double)gamma);
  } else {
    SETERRQ(comm, PETSC_ERR_USER_INPUT, "%sstf = record is not available yet; allowed: ricker, gabor", p.c_str());
  }
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
  return std::visit(
    [t](const auto &w) -> double {
      using W = std::decay_t<decltype(w)>;
      if constexpr (std::is_same_v<W, std::monostate>) return 0.0;
      else if constexpr (std::is_same_v<W, physics::TabulatedHistory>) {
        // Central difference of the tabulated velocity: what the explicit scheme would integrate.
        const double h = 1e-4;
        return (physics::velocity(w, t + h) - physics::velocity(w, t - h)) / (2 * h);
      } else return physics::acceleration(w, t);
    },
    impl_->f);
}

double TimeFunction::topFrequency() const {
  return std::visit(
    [](const auto &w) -> double {
      if constexpr (std::is_same_v<std::decay_t<decltype(w)>, std::monostate>) return 0.0;
      else return physics::topFrequency(w);
    },
    impl_->f);
}

std::string TimeFunction::describe() const { return impl_->description; }

} // namespace slipwave::model
