#include "slipwave/problem/integrator_step.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "slipwave/numerics/spectral_dispersion.hpp"
#include "slipwave/physics/time_dispersion.hpp"
#include "slipwave/problem/scene_frequency.hpp"
#include "slipwave/time/central_difference.hpp"

namespace slipwave::problem {
namespace {

// Bulk-force passes per step of order 4 against order 2 (integrator_step.hpp).
constexpr double kFourthOrderCost = 2.0;
// Where the errors are balanced: at this fraction of the top frequency, the middle of the
// band a wavelet or a record fills (a Ricker's spectrum peaks at 1/2.76 of its top frequency).
// At the top frequency itself, where the elements' error (~ f^(2p)) is largest and the signal
// weakest, the balance let central differences run at 0.72 and 0.9 of their limit on Lamb's
// problem at p = 4 with 5 and 4 nodes per wavelength: 5.6 % and 16.5 % error, against 3.6 %
// and 8.4 % at 0.45 (their error, ~ f^2, dominates below the top; bench/cases/sem_speed_error.sh).
constexpr double kBalanceFraction = 0.5;
// The phase error [rad] that the step may add at that frequency over the whole run,
// e 2 pi f T, where the space error asks for less: a relative error of 1e-4 in the answers,
// a tenth of the finest accuracy the spectral-element benchmark aims at (0.1 %,
// docs/spectral-elements.md). Without it a mesh finer than the waves need (its space error
// 1e-8 at 20 nodes per wavelength and p = 4) would force a step far below the stable one to
// buy an accuracy no answer shows.
constexpr double kPhaseErrorFloor = 1e-4;

// The step of `order`: the safety fraction of its limit, shortened to the accuracy step.
struct OrderStep {
  double limit, accuracy, dt;
};
OrderStep orderStep(int order, const StableStep &step, double safety, double frequency, double time_error) {
  OrderStep s;
  s.limit    = order == 4 ? step.dt_limit_fourth_order : step.dt_limit;
  s.accuracy = time_error > 0 ? physics::integratorStepForError(order, 2 * M_PI * frequency, time_error) : 1e300;
  s.dt       = std::min(safety * s.limit, s.accuracy);
  return s;
}

} // namespace

PetscErrorCode IntegratorStepChoose(const Elastodynamics &m, const StableStep &step, const TimeStepOptions &options, TS ts, IntegratorStep *c) {
  PetscInt  order;
  PetscBool given;
  PetscFunctionBeginUser;
  PetscCall(time::CentralDifferenceGetOrder(ts, &order, &given));
  c->order_given = given;
  c->degree      = m.bulk.degree();
  c->safety      = TimeStepSafety(options, !m.interfaces.empty());
  // The accuracy step: at p > 1, with a scene frequency, unless -time_step_safety sets the step.
  const SceneFrequency top = SceneTopFrequency(m);
  c->no_accuracy_step     = m.bulk.degree() == 1 ? "degree 1" : top.hz == 0 ? "no scene frequency" : options.safety_set ? "-time_step_safety given" : "";
  if (c->no_accuracy_step.empty()) {
    for (size_t r = 0; r < m.materials.size(); ++r) {
      if (m.materials[r].model == medium::MaterialModel::Rigid) continue; // carries no waves
      const double n = RegionNodesPerWavelength(m, (PetscInt)r, top.hz);
      if (c->region.empty() || n < c->nodes_per_wavelength) c->region = m.materials[r].region, c->nodes_per_wavelength = n;
    }
    PetscReal duration;
    PetscCall(TSGetMaxTime(ts, &duration));
    if (!c->region.empty()) {
      c->frequency        = kBalanceFraction * top.hz;
      c->top_frequency    = top.hz;
      c->frequency_source = top.source;
      c->space_error      = numerics::spectralDispersionBound((int)m.bulk.degree(), c->nodes_per_wavelength / kBalanceFraction);
      c->time_error       = std::max(c->space_error, kPhaseErrorFloor / (2 * M_PI * c->frequency * duration));
    }
  }
  const OrderStep second = orderStep(2, step, c->safety, c->frequency, c->time_error);
  const OrderStep fourth = orderStep(4, step, c->safety, c->frequency, c->time_error);
  // With -ts_dt the user's step is taken whatever the order: the comparison of the orders'
  // steps does not apply, and central differences cost half as much per step.
  PetscBool user_dt;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-ts_dt", &user_dt));
  if (!given) order = !user_dt && fourth.dt > kFourthOrderCost * second.dt ? 4 : 2;
  PetscCall(time::CentralDifferenceSetOrder(ts, order));
  const OrderStep &chosen = order == 4 ? fourth : second;
  c->order       = order;
  c->user_dt     = user_dt;
  c->dt_limit    = chosen.limit;
  c->governing   = order == 4 ? step.governing_fourth_order : step.governing;
  c->dt_accuracy = chosen.accuracy;
  c->dt          = chosen.dt;
  c->dt_other    = order == 4 ? second.dt : fourth.dt;
  PetscFunctionReturn(0);
}

std::string IntegratorStepSummary(const IntegratorStep &c) {
  return std::string(c.order == 4 ? "fourth-order integrator (-ts_cd_order 4" : "central difference (-ts_cd_order 2") + (c.order_given ? "" : ", the default") +
         "), limited by " + (c.accuracyLimits() ? "accuracy" : "stability");
}

std::string IntegratorStepDetail(const IntegratorStep &c) {
  const double dt4 = c.order == 4 ? c.dt : c.dt_other, dt2 = c.order == 4 ? c.dt_other : c.dt;
  char         why[200], limit[640];
  if (c.order_given) std::snprintf(why, sizeof why, "order %" PetscInt_FMT " as asked", c.order);
  else if (c.user_dt) std::snprintf(why, sizeof why, "order 2, the default with -ts_dt");
  else
    std::snprintf(why, sizeof why, "order %" PetscInt_FMT ": the order-4 step %.4e s is %s %g x the order-2 step %.4e s", c.order, dt4,
                  c.order == 4 ? "more than" : "not more than", kFourthOrderCost, dt2);
  // The accuracy step's error: the space error, or the floor over the run (kPhaseErrorFloor).
  char target[96];
  if (c.time_error > c.space_error) std::snprintf(target, sizeof target, "%.2e (%g rad over the run)", c.time_error, kPhaseErrorFloor);
  else std::snprintf(target, sizeof target, "%.2e", c.time_error);
  if (c.dt_accuracy >= 1e300) std::snprintf(limit, sizeof limit, "no accuracy step (%s)", c.no_accuracy_step.c_str());
  else
    std::snprintf(limit, sizeof limit,
                  "accuracy step %.4e s: a phase-speed error of %s at %.2f Hz (half the top frequency %.2f Hz of %s), the space error %.2e of degree %" PetscInt_FMT
                  " there (%.3g GLL nodes per S wavelength at the top, region %s)",
                  c.dt_accuracy, target, c.frequency, c.top_frequency, c.frequency_source.c_str(), c.space_error, c.degree, c.nodes_per_wavelength, c.region.c_str());
  return std::string("time integrator: ") + why + "; " + limit;
}

} // namespace slipwave::problem
