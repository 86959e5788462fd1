// The time integrator's order and the step of a run, from its stable limits and the accuracy
// its mesh has (issue 25). At degree p > 1 with a scene frequency (SceneTopFrequency f_top)
// and no -time_step_safety, the default step is the longest whose time error does not exceed
// the space error: both are relative phase-speed errors at f = f_top / 2 (integrator_step.cpp
// says why not at f_top), the space error that of degree p at the GLL nodes per S wavelength
// of the least-resolved region there (numerics/spectral_dispersion, the worst over the
// wavelengths it carries), the time error the integrator's (physics/time_dispersion); a
// floor keeps it from asking more than 1e-4 rad of phase at f over the whole run, where a fine
// mesh's space error would. The step is then the shorter of that accuracy step and the
// safety fraction of the order's stable limit, and the report says which limits it.
// The default order: 4 where its step is more than twice central differences' (two bulk-force
// passes per step against one; the rest of a step, loads, ledger, output, is not counted,
// which favours central differences), else 2; 2 also with -ts_dt (the step is the user's, so
// the comparison does not apply) and with -time_step_safety (no accuracy step). At p = 1 (the space and time errors of linear
// elements partly cancel, and their step is the stable one) and without a scene frequency the
// accuracy step is not applied, so central differences, whose stable step costs 1/2 pass per
// unit of 1/omega_max against 2/sqrt(12) = 0.58, are kept.
#pragma once
#include <petscts.h>

#include <string>

#include "slipwave/problem/elastodynamics.hpp"
#include "slipwave/problem/stable_step.hpp"

namespace slipwave::problem {

struct IntegratorStep {
  PetscInt    order       = 2;
  bool        order_given = false; // by -ts_cd_order
  bool        user_dt     = false; // -ts_dt given (the default order is then 2)
  double      safety      = 0;     // fraction of the stable limit
  double      dt_limit    = 0;     // the order's stable limit [s]
  std::string governing;           // what sets it
  double      dt_accuracy = 1e300; // the accuracy step [s]; 1e300 where it is not applied
  double      dt          = 0;     // min(safety x dt_limit, dt_accuracy) [s], before -ts_max_time's whole steps
  // The accuracy step's terms: the frequency where the errors are balanced [Hz] (half the
  // top frequency) and the top frequency and what sets it, the least-resolved region and its
  // GLL nodes per S wavelength at the top, the space error (relative phase speed) there.
  PetscInt    degree    = 1;
  double      frequency = 0, top_frequency = 0, nodes_per_wavelength = 0, space_error = 0;
  double      time_error = 0; // what the accuracy step allows: the space error, or the run's floor (integrator_step.cpp)
  std::string frequency_source, region;
  std::string no_accuracy_step; // why there is none: degree 1, no scene frequency, -time_step_safety given ("" where there is one)
  // The other order's step [s] (the default order's comparison, for the report).
  double      dt_other = 0;

  bool accuracyLimits() const { return dt_accuracy < safety * dt_limit; }
};

// Chooses the order (unless -ts_cd_order gave it) and the step; sets the order on the TS
// (type cd, after TSSetFromOptions). Then TimeStepChoose sets the step.
PetscErrorCode IntegratorStepChoose(const Elastodynamics &model, const StableStep &step, const TimeStepOptions &options, TS ts, IntegratorStep *choice);

// For the run report: the integrator and what limits the step ("central difference
// (-ts_cd_order 2, the default), limited by stability"), and the detail: why this order, the
// accuracy step and the errors it balances.
std::string IntegratorStepSummary(const IntegratorStep &choice);
std::string IntegratorStepDetail(const IntegratorStep &choice);

} // namespace slipwave::problem
