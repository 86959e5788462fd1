// The stable time step of the explicit central difference, in one place: every contribution
// (bulk Gershgorin rows, interface penalty springs, contact dashpots, Rayleigh stiffness
// damping, free-field columns) gathered into one limit and what governs it, and the choice of
// the run's step from -ts_dt / -ts_max_time / -time_step_safety with the check against that
// limit. The closed forms of one row or mode are physics/stable_time_step.hpp.
#pragma once
#include <petscts.h>

#include <string>

#include "slipwave/fem/bulk_operator.hpp"
#include "slipwave/problem/elastodynamics.hpp"
#include "slipwave/problem/interface_mass_scaling.hpp"

namespace slipwave::problem {

struct StableStep {
  double omega_max_bulk = 0; // Gershgorin bound on the largest angular frequency [rad/s]
  double dt_bulk = 0;        // critical step of the bulk (with stiffness damping) [s]
  double dt_cfl = 0;         // h_min / vp_max, for comparison only [s]
  double dt_limit = 0;       // the limit a run must respect [s]
  double dt_without_interfaces = 0; // the bulk alone, to report what the penalty costs [s]
  double dt_free_field = 1e300; // the free-field columns' own limit (normally above the bulk's) [s]
  double dt_without_stiffness_damping = 0; // the same bound with beta = 0, to report what Rayleigh costs [s]
  double dt_drained = 1e300;  // saturated scenes: the bulk bound without the undrained stiffening alpha^2 Q^T S^-1 Q [s]
  double dt_diffusion = 1e300; // saturated scenes: the explicit pore-pressure diffusion limit [s]
  double coupling_factor = 1;  // saturated scenes: c of K + c alpha^2 Q^T S^-1 Q (porous::PorePressureCouplingFactor)
  std::string governing;     // which constraint sets dt_limit
  // The fourth-order integrator (-ts_cd_order 4): its limit and what sets it. The bulk alone
  // (no interfaces, contact or absorbing dashpots, rigid bodies) gets the scheme's own range,
  // physics::fourthOrderStableStep (sqrt(3) x without stiffness damping); otherwise the
  // central-difference bound: sufficient with interfaces and rigid bodies (the scheme is
  // central differences with the larger mass M (I - h^2/12 M^-1 K)^-1), and with absorbing
  // dashpots, whose share of the correction is explicit, measured to hold with a margin of
  // 1.1 or more (time/central_difference.cpp). The free-field columns step by central
  // differences whatever the order, so their limit is the same.
  double dt_limit_fourth_order = 0;
  std::string governing_fourth_order;
  // -time_step_mass_scaling interface: the mass added, and the limit the nodes' own mass gave
  // (0 when nothing was scaled).
  MassScalingResult mass_scaling;
  double            dt_own_mass = 0;
};

// Default fraction of the stable step with contact interfaces. The open/close switching of a
// pair is not covered by the linear bound: in the two-bar impact (penalty factor 1) the energy
// grew by 2.5 % at 0.9 of the limit, 1.1 % at 0.7 and 0.5 % at 0.5 (the spec saw +0.09 % at
// half the limit and +180 % at it). A scene whose pairs never open may ask for more; the run
// report warns when pairs opened or closed under a larger fraction.
inline constexpr PetscReal kSafetyInterfaces = 0.5;

enum class MassScaling { None, Interface };
extern const char *const kMassScalingNames[2]; // none, interface (-time_step_mass_scaling)

struct TimeStepOptions {
  PetscReal   safety       = -1; // fraction of the limit; default kSafetyBulk, or kSafetyInterfaces with interfaces
  PetscBool   safety_set   = PETSC_FALSE;
  MassScaling mass_scaling = MassScaling::None;
};

// rows_i with K <= diag(rows) for the bulk stiffness (global vector laid out like u,
// overwritten; fem::BulkOperator::addStiffnessRowBounds): max rows_i / m_i bounds omega_max^2,
// for the stable step and the constant-Q reference frequencies.
// The limit of the whole model (interfaces and free field set up). With
// -time_step_mass_scaling interface the nodes of interface pairs first take the mass that
// keeps the limit at the bulk's own (InterfaceMassScale; the model's mass changes).
PetscErrorCode StableStepCompute(Elastodynamics *model, const TimeStepOptions &options, StableStep *step);
// -time_step_safety, -time_step_mass_scaling (read before the heavy setup, so a bad value stops early).
PetscErrorCode TimeStepOptionsRead(MPI_Comm comm, TimeStepOptions *options);
// The fraction of the stable limit: -time_step_safety, or the default (kSafetyBulk, or
// kSafetyInterfaces with interfaces).
PetscReal TimeStepSafety(const TimeStepOptions &options, bool interfaces);
struct IntegratorStep; // problem/integrator_step.hpp
// Sets the TS's step (after TSSetFromOptions and IntegratorStepChoose): -ts_dt when given,
// else the choice's step shortened to a whole number of equal steps to -ts_max_time; stops
// with one line when the step is above the order's limit or not positive, or the end time is
// not positive.
PetscErrorCode TimeStepChoose(TS ts, const IntegratorStep &choice);

} // namespace slipwave::problem
