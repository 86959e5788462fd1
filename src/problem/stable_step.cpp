#include "slipwave/problem/stable_step.hpp"

#include "slipwave/problem/integrator_step.hpp"

#include <algorithm>
#include <cmath>

#include "slipwave/core/option_choice.hpp"
#include "slipwave/input/free_field.hpp"
#include "slipwave/physics/stable_time_step.hpp"
#include "slipwave/porous/pore_pressure.hpp"
#include "slipwave/problem/interface_mass_scaling.hpp"
#include "slipwave/problem/rigid_bodies.hpp"

namespace slipwave::problem {

const char *const kMassScalingNames[2] = {"none", "interface"};

namespace {

// Default fraction of the stable step without interfaces (with them: kSafetyInterfaces).
constexpr PetscReal kSafetyBulk = 0.9;

// K <= diag(rows) (Gershgorin row sums, or the spectral element bound times M): every
// eigenvalue omega^2 of M^{-1} K is at most max_i rows_i / m_i. Held dofs do not vibrate.
PetscErrorCode omegaMax(const Elastodynamics *m, Vec rows, PetscReal *omega) {
  Vec w;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(rows, &w));
  PetscCall(VecPointwiseMult(w, rows, m->inv_mass));
  PetscCall(VecPointwiseMult(w, w, m->bc.free_mask));
  PetscReal omega2;
  PetscCall(VecMax(w, nullptr, &omega2));
  PetscCall(VecDestroy(&w));
  *omega = std::sqrt(std::max(omega2, (PetscReal)0));
  PetscFunctionReturn(0);
}

// Contact dashpots are not proportional to K: the bound is taken row by row, with the Rayleigh
// beta K rows added to the dashpot rows (every pair counted as closed). *dt: 1e300 without
// dashpots. Rigid bodies (their stiffness rows already taken out, omega2_rigid their bound)
// are bounded as wholes: their dashpot rows are summed like their springs.
PetscErrorCode dashpotRowsStep(Elastodynamics *m, Vec stiffness_rows, double omega2_rigid, double *dt, bool *dashpots) {
  Vec       dashpot_rows;
  PetscReal dashpot_max;
  PetscFunctionBeginUser;
  *dt = 1e300;
  PetscCall(VecDuplicate(stiffness_rows, &dashpot_rows));
  PetscCall(VecZeroEntries(dashpot_rows));
  for (auto &iface : m->interfaces) PetscCall(iface.AddDampingRowAbsSums(dashpot_rows));
  PetscCall(VecMax(dashpot_rows, nullptr, &dashpot_max));
  *dashpots = dashpot_max > 0;
  if (*dashpots && m->rigid) {
    double c_rigid;
    PetscCall(RigidBodiesRowBound(m->rigid, dashpot_rows, &c_rigid));
    if (omega2_rigid + c_rigid > 0) *dt = physics::centralDifferenceStableStepOfRow(omega2_rigid, m->rayleigh.beta * omega2_rigid + c_rigid);
  }
  if (*dashpots) {
    PetscInt           n;
    const PetscScalar *k, *c, *im, *mask;
    PetscCall(VecGetLocalSize(stiffness_rows, &n));
    PetscCall(VecGetArrayRead(stiffness_rows, &k));
    PetscCall(VecGetArrayRead(dashpot_rows, &c));
    PetscCall(VecGetArrayRead(m->inv_mass, &im));
    PetscCall(VecGetArrayRead(m->bc.free_mask, &mask));
    for (PetscInt i = 0; i < n; ++i)
      if (PetscRealPart(mask[i]) > 0 && PetscRealPart(k[i]) + PetscRealPart(c[i]) > 0)
        *dt = std::min(*dt, physics::centralDifferenceStableStepOfRow(PetscRealPart(k[i] * im[i]), PetscRealPart((m->rayleigh.beta * k[i] + c[i]) * im[i])));
    PetscCall(VecRestoreArrayRead(m->bc.free_mask, &mask));
    PetscCall(VecRestoreArrayRead(m->inv_mass, &im));
    PetscCall(VecRestoreArrayRead(dashpot_rows, &c));
    PetscCall(VecRestoreArrayRead(stiffness_rows, &k));
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, dt, 1, MPI_DOUBLE, MPI_MIN, m->comm));
  }
  PetscCall(VecDestroy(&dashpot_rows));
  PetscFunctionReturn(0);
}

// The factor c with which saturated regions' undrained rows enter (porous::
// PorePressureCouplingFactor): c(h) grows with h and the limit of the bulk rows plus c
// undrained falls with c, so the steps h within limit(c(h)) form an interval. Bisection keeps
// hi at or past its end (hi >= limit(c(hi)); limit(1) is) and returns c(hi): the limit with it
// is at most hi, and every step up to it has c(h) <= c(hi).
PetscErrorCode couplingFactor(Elastodynamics *m, Vec bulk_rows, Vec undrained, double *c) {
  Vec rows;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(bulk_rows, &rows));
  auto limit = [&](double factor, double *dt) -> PetscErrorCode {
    PetscReal omega;
    PetscFunctionBeginUser;
    PetscCall(VecWAXPY(rows, std::isfinite(factor) ? factor : 0.0, undrained, bulk_rows));
    PetscCall(omegaMax(m, rows, &omega));
    *dt = !std::isfinite(factor) ? 0.0 : omega > 0 ? physics::centralDifferenceStableStep(omega, m->rayleigh.beta) : 1e300;
    PetscFunctionReturn(0);
  };
  double lo = 0, hi = 0;
  PetscCall(limit(1.0, &hi));
  for (int k = 0; k < 60 && porous::PorePressureCouplingFactor(m->pore, hi) > 1; ++k) {
    const double mid = 0.5 * (lo + hi);
    double       dt = 0;
    PetscCall(limit(porous::PorePressureCouplingFactor(m->pore, mid), &dt));
    (mid <= dt ? lo : hi) = mid;
  }
  *c = porous::PorePressureCouplingFactor(m->pore, hi);
  PetscCall(VecDestroy(&rows));
  PetscFunctionReturn(0);
}

// The bulk's rows (rowabs, laid out like u): its Gershgorin rows, and in saturated regions
// those of the undrained stiffness K + c alpha^2 Q^T S^-1 Q (c = 1 at degree 1; at p > 1 the
// split step's factor, step->coupling_factor; step->dt_drained without them).
PetscErrorCode bulkRows(Elastodynamics *m, Vec rowabs, StableStep *step) {
  PetscFunctionBeginUser;
  PetscCall(fem::BulkStiffnessRowBounds(m->dm, m->bulk, rowabs));
  if (m->pore) {
    PetscReal omega_drained;
    Vec       undrained;
    PetscCall(omegaMax(m, rowabs, &omega_drained));
    step->dt_drained = omega_drained > 0 ? physics::centralDifferenceStableStep(omega_drained, m->rayleigh.beta) : 1e300;
    PetscCall(VecDuplicate(rowabs, &undrained));
    PetscCall(VecZeroEntries(undrained));
    PetscCall(porous::PorePressureAddUndrainedRows(m->pore, m->dm, undrained));
    PetscCall(couplingFactor(m, rowabs, undrained, &step->coupling_factor));
    PetscCall(VecAXPY(rowabs, step->coupling_factor, undrained));
    PetscCall(VecDestroy(&undrained));
  }
  PetscFunctionReturn(0);
}

// The limit of the model with its masses as they are.
PetscErrorCode limitOf(Elastodynamics *m, StableStep *step) {
  Vec rowabs;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(m->mass, &rowabs));
  PetscCall(bulkRows(m, rowabs, step));
  // K is the bulk and the interface springs together (adding the rows, not taking the larger
  // of two frequencies).
  PetscReal omega_bulk = 0, omega_all = 0;
  PetscCall(omegaMax(m, rowabs, &omega_bulk));
  for (auto &iface : m->interfaces) PetscCall(iface.AddStiffnessRowAbsSums(rowabs));
  // Rigid bodies vibrate only as wholes, on the springs their rows hold.
  double omega2_rigid = 0;
  if (m->rigid) PetscCall(RigidBodiesRowBound(m->rigid, rowabs, &omega2_rigid));
  PetscCall(omegaMax(m, rowabs, &omega_all));
  const bool rigid_governs = std::sqrt(omega2_rigid) > omega_all;
  omega_all                = std::max(omega_all, (PetscReal)std::sqrt(omega2_rigid));
  auto dtOf = [&](double omega) { return omega > 0 ? physics::centralDifferenceStableStep(omega, m->rayleigh.beta) : 1e300; };
  step->omega_max_bulk        = omega_all;
  step->dt_bulk               = dtOf(omega_all);
  step->dt_without_interfaces = dtOf(omega_bulk);
  step->dt_without_stiffness_damping = omega_all > 0 ? physics::centralDifferenceStableStep(omega_all, 0.0) : 1e300;
  double dt_rows;
  bool   dashpots = false;
  PetscCall(dashpotRowsStep(m, rowabs, omega2_rigid, &dt_rows, &dashpots));
  if (dashpots) step->dt_bulk = std::min(step->dt_bulk, dt_rows);
  PetscCall(VecDestroy(&rowabs));
  double vp_max = 0;
  for (const auto &info : m->materials)
    if (info.model != medium::MaterialModel::Rigid) vp_max = std::max({vp_max, info.elastic.vp, info.vp_undrained});
  step->dt_cfl   = vp_max > 0 ? m->bulk.minCellSize() / vp_max : 1e300;
  step->dt_limit = step->dt_bulk;
  // The free-field columns are the 1D version of the side's elements, so their bound
  // (Gershgorin at degree 1, the element eigenvalue at p > 1) is normally below the mesh's;
  // checked anyway, since they step with the same dt.
  step->dt_free_field           = input::FreeFieldStableStep(m->free_field, step->coupling_factor);
  const bool free_field_governs = step->dt_free_field < step->dt_limit;
  step->dt_limit                = std::min(step->dt_limit, step->dt_free_field);
  const bool interfaces_matter  = step->dt_bulk < step->dt_without_interfaces * (1 - 1e-12);
  step->governing = std::string(interfaces_matter ? "bulk stiffness and interface penalty springs" : "bulk stiffness") +
                    (m->rayleigh.beta > 0 ? " with stiffness-proportional damping" : "") + (dashpots ? " and contact dashpots" : "") +
                    (m->bulk.degree() > 1 ? " (certified element bound, degree " + std::to_string(m->bulk.degree()) + ")" : " (Gershgorin bound)");
  if (rigid_governs) step->governing = std::string("rigid bodies on their supports (trace bound)") + (dashpots ? " and contact dashpots" : "");
  const std::string bulk_governing = step->governing;
  const std::string free_field     = m->bulk.degree() > 1 ? "free-field column (element bound)" : "free-field column (Gershgorin bound)";
  if (free_field_governs) step->governing = free_field;
  // The fourth-order limit (StableStep::dt_limit_fourth_order).
  // Absorbing dashpots: the correction takes their force at v_{n+1/2} (time/
  // central_difference.cpp), an explicit term that the centred damping outweighs only up to
  // about 1.1 (p = 2) .. 1.3 (p = 8) x the central-difference bound (measured,
  // tests/unit/test_fourth_order.cpp): that bound is kept.
  const bool   bulk_alone     = m->interfaces.empty() && !m->rigid && !dashpots && !m->bc.has_absorbing;
  const double dt_bulk_fourth = bulk_alone && omega_all > 0 ? physics::fourthOrderStableStep(omega_all, m->rayleigh.beta) : step->dt_bulk;
  step->dt_limit_fourth_order  = std::min(dt_bulk_fourth, step->dt_free_field);
  step->governing_fourth_order = dt_bulk_fourth > step->dt_free_field ? free_field + ", stepped by central differences"
                                 : bulk_alone ? bulk_governing + ", fourth-order range"
                                              : bulk_governing + ", the central-difference bound (interfaces, dashpots or rigid bodies)";
  // Saturated regions: the pore-pressure diffusion limits the step unless it is sub-stepped.
  if (m->pore) {
    step->dt_diffusion    = m->pore->dt_diffusion;
    // Without sub-cycling at p > 1 the diffusion also governs where it pulls the wave's bound
    // down (coupling factor above 2: its step overshoots, porous::PorePressureCouplingFactor).
    const bool diffusion  = !m->pore->subcycle && (step->dt_diffusion < step->dt_limit || step->coupling_factor > 2);
    step->governing       = diffusion ? std::string("pore-pressure diffusion (explicit, Gershgorin bound on S^-1 H)") : "undrained " + step->governing;
    if (!m->pore->subcycle) step->dt_limit = std::min(step->dt_limit, step->dt_diffusion);
    // Saturated regions step by central differences only (-ts_cd_order 4 is refused with
    // them): no fourth-order range, so the default order stays 2 and the diffusion counts.
    step->dt_limit_fourth_order  = step->dt_limit;
    step->governing_fourth_order = step->governing;
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode StableStepCompute(Elastodynamics *m, const TimeStepOptions &options, StableStep *step) {
  PetscFunctionBeginUser;
  PetscCall(limitOf(m, step));
  if (options.mass_scaling == MassScaling::Interface && !m->interfaces.empty()) {
    // The scaled nodes may have held the bulk's largest row: the bulk's own limit then rises,
    // and the nodes are scaled again to it (a few rounds: each moves the largest row to
    // another node).
    Vec physical, rows;
    PetscCall(VecDuplicate(m->mass, &physical));
    PetscCall(VecCopy(m->mass, physical));
    PetscCall(VecDuplicate(m->mass, &rows));
    const double dt_own = step->dt_limit;
    for (int round = 0; round < 8; ++round) {
      StableStep bulk;
      PetscInt   nodes;
      PetscCall(bulkRows(m, rows, &bulk));
      PetscCall(InterfaceMassScale(m, rows, step->dt_without_interfaces, &nodes));
      if (nodes == 0) break;
      PetscCall(limitOf(m, step));
    }
    PetscCall(MassScalingSummarize(m, physical, &step->mass_scaling));
    step->dt_own_mass = dt_own;
    PetscCall(VecDestroy(&rows));
    PetscCall(VecDestroy(&physical));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode TimeStepOptionsRead(MPI_Comm comm, TimeStepOptions *o) {
  PetscFunctionBeginUser;
  PetscInt scaling = (PetscInt)o->mass_scaling;
  PetscOptionsBegin(comm, "", "Time step", "slipwave");
  PetscCall(PetscOptionsReal("-time_step_safety",
                             "time step as a fraction of the stable limit, used when -ts_dt is not given (0 < s <= 1; default 0.9, 0.5 with interfaces)", "SimulationRun",
                             o->safety, &o->safety, &o->safety_set));
  PetscCall(core::OptionsChoice(PetscOptionsObject, "-time_step_mass_scaling",
                              "none (default): every node its own lumped mass; interface: the nodes of interface pairs take the mass dt^2 K/4 + dt C/2 their rows need "
                              "to be stable at the bulk's own step (at most dt^2 k/4 per spring: Newmark's beta = 1/4 on the penalty), so the penalty does not lower the step "
                              "(problem/interface_mass_scaling.hpp; the run reports the mass added)",
                              kMassScalingNames, 2, &scaling, nullptr));
  PetscOptionsEnd();
  o->mass_scaling = (MassScaling)scaling;
  PetscCheck(!o->safety_set || (o->safety > 0 && o->safety <= 1), comm, PETSC_ERR_USER_INPUT, "-time_step_safety = %g; allowed: 0 < s <= 1", (double)o->safety);
  PetscFunctionReturn(0);
}

PetscReal TimeStepSafety(const TimeStepOptions &o, bool interfaces) { return o.safety_set ? o.safety : interfaces ? kSafetyInterfaces : kSafetyBulk; }

PetscErrorCode TimeStepChoose(TS ts, const IntegratorStep &choice) {
  MPI_Comm  comm = PetscObjectComm((PetscObject)ts);
  PetscBool user_dt;
  PetscReal dt, max_time;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-ts_dt", &user_dt));
  PetscCall(TSGetMaxTime(ts, &max_time));
  // A whole number of equal steps: a shortened last step would break the constant-step
  // energy identity the ledger checks.
  if (!user_dt) PetscCall(TSSetTimeStep(ts, max_time > 0 ? max_time / std::ceil(max_time / choice.dt) : choice.dt));
  PetscCall(TSGetTimeStep(ts, &dt));
  PetscCheck(dt <= choice.dt_limit, comm, PETSC_ERR_USER_INPUT,
             "-ts_dt = %.6g s is above the stable limit %.6g s (%s, -ts_cd_order %" PetscInt_FMT "); allowed: 0 < dt <= %.6g s (omit -ts_dt to use %.2f of the limit)", (double)dt,
             choice.dt_limit, choice.governing.c_str(), choice.order, choice.dt_limit, (double)choice.safety);
  PetscCheck(dt > 0, comm, PETSC_ERR_USER_INPUT, "-ts_dt = %g; allowed: 0 < dt <= %.6g s", (double)dt, choice.dt_limit);
  // The user's step too, where the run reaches max_time (not where -ts_max_steps ends it
  // first): rounded down to the nearest step that divides it, and said. (Kept, the last step
  // was shortened and the ledger's balance error rose from round-off to ~1e-6.)
  PetscInt max_steps;
  PetscCall(TSGetMaxSteps(ts, &max_steps));
  const double steps = max_time > 0 && dt > 0 ? std::ceil(max_time / dt * (1 - 1e-12)) : 0;
  if (user_dt && steps > 0 && steps <= max_steps && std::fabs(steps * dt - max_time) > 1e-12 * max_time) {
    PetscCall(PetscPrintf(comm, "  -ts_dt = %g s rounded down to %.9g s: %.0f equal steps to -ts_max_time %g s (a shortened last step would break the energy balance)\n",
                          (double)dt, (double)(max_time / steps), steps, (double)max_time));
    dt = max_time / steps;
    PetscCall(TSSetTimeStep(ts, dt));
  }
  PetscCheck(max_time > 0, comm, PETSC_ERR_USER_INPUT, "-ts_max_time = %g; allowed: > 0 s", (double)max_time);
  PetscFunctionReturn(0);
}

} // namespace slipwave::problem
