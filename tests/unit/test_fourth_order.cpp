// The fourth-order integrator (-ts_cd_order 4, time/central_difference.hpp) on the real model
// and TS: its order of convergence in time and its stability limit, against central
// differences (issue 25).
//
// Scene: a 20 m x 40 m box of 2 x 2 elements of degree 6, fixed at the base, the other sides
// free (vp 400, vs 200 m/s, 2000 kg/m3), in free vibration from a displacement at rest.
//
// Order. u_x(0) = sin(pi y / 80 m) (the quarter wave of a fixed-free shear column), with the
// modes the steps below cannot resolve filtered out (the element bound omega_b bounds every
// mode: (I - M^-1 K / omega_b^2)^300 leaves a mode with omega^2 = 5 % of omega_b^2 at
// 2e-7 of its start, the smooth ones at 0.5 .. 1, so the error measured is that of the modes
// the steps resolve, which converge at the scheme's rate). Stepped to T = 2 s (1.25 periods of
// the fixed-free column, omega = 7.9 rad/s) with h0, h0/2, h0/4, h0/8, h0 = 0.9 of each order's
// limit rounded to whole steps; error: the relative L2 (all dofs) distance of u(T) to a
// reference run of order 4 at h0/64 (its own error 64^-4 = 6e-8 of the coarsest order-4
// error). Rates log2(e_k / e_k+1): 4 +- 0.2 for order 4, 2 +- 0.1 for order 2.
//
// Stability. A random displacement holds every mode, the highest included; a step is
// unstable when max |u| grows beyond 1e3 of its start within 600 steps (a step 0.2 % above
// the limit grows by 1.2 per step at order 4, 1.06 at order 2). Bisection to 0.1 % for each
// order; the measured limit must lie within [1, 1.02] of the bound the code uses
// (StableStep: 2/omega_b and sqrt(12)/omega_b, omega_b the certified element bound).
#include "slipwave/fem/node_fields.hpp"
#include "slipwave/problem/elastodynamics.hpp"
#include "slipwave/problem/stable_step.hpp"
#include "slipwave/time/central_difference.hpp"

#include "petsc_test_main.hpp"

#include <petscts.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

using namespace slipwave;

const char *kScene = "-regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -mesh_box_faces 2,2 -mesh_box_upper 20,40 "
                     "-element_degree 6 -bc_bottom_type fixed";

struct Scene {
  problem::Elastodynamics m;
  problem::StableStep     step;
  Vec                     smooth = nullptr, noise = nullptr; // the two initial displacements
};

PetscErrorCode sceneCreate(Scene *s, const std::string &more = "") {
  MPI_Comm comm = PETSC_COMM_WORLD;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsClear(nullptr));
  PetscCall(PetscOptionsInsertString(nullptr, (kScene + more).c_str()));
  PetscCall(problem::ElastodynamicsCreate(comm, &s->m));
  PetscCall(problem::StableStepCompute(&s->m, problem::TimeStepOptions(), &s->step));
  problem::Elastodynamics &m = s->m;
  // Node coordinates in the displacement layout.
  Vec coords;
  PetscCall(VecDuplicate(m.mass, &coords));
  {
    PetscScalar *xl;
    PetscCall(VecGetArray(m.u_local, &xl));
    m.bulk.nodeCoordinates(xl);
    PetscCall(VecRestoreArray(m.u_local, &xl));
    PetscCall(DMLocalToGlobal(m.dm, m.u_local, INSERT_VALUES, coords));
  }
  PetscCall(VecDuplicate(m.mass, &s->smooth));
  {
    const PetscScalar *x, *mask;
    PetscScalar       *u;
    PetscInt           n;
    PetscCall(VecGetLocalSize(coords, &n));
    PetscCall(VecGetArrayRead(coords, &x));
    PetscCall(VecGetArrayRead(m.bc.free_mask, &mask));
    PetscCall(VecGetArray(s->smooth, &u));
    for (PetscInt i = 0; i < n; i += 2) u[i] = 1e-3 * std::sin(M_PI * PetscRealPart(x[i + 1]) / 80.0) * PetscRealPart(mask[i]), u[i + 1] = 0;
    PetscCall(VecRestoreArray(s->smooth, &u));
    PetscCall(VecRestoreArrayRead(m.bc.free_mask, &mask));
    PetscCall(VecRestoreArrayRead(coords, &x));
  }
  // The filter (I - M^-1 K / omega_b^2)^300 on the free dofs.
  Vec Ku, scale;
  PetscCall(VecDuplicate(m.mass, &Ku));
  PetscCall(VecDuplicate(m.mass, &scale));
  PetscCall(VecPointwiseMult(scale, m.inv_mass, m.bc.free_mask));
  PetscCall(VecScale(scale, -1.0 / (s->step.omega_max_bulk * s->step.omega_max_bulk)));
  for (int k = 0; k < 300; ++k) {
    PetscCall(problem::ElastodynamicsStiffnessTimes(&m, s->smooth, Ku));
    PetscCall(VecPointwiseMult(Ku, Ku, scale));
    PetscCall(VecAXPY(s->smooth, 1.0, Ku));
  }
  PetscCall(VecDuplicate(m.mass, &s->noise));
  PetscRandom rnd;
  PetscCall(PetscRandomCreate(comm, &rnd));
  PetscCall(PetscRandomSetInterval(rnd, -1e-3, 1e-3));
  PetscCall(VecSetRandom(s->noise, rnd));
  PetscCall(VecPointwiseMult(s->noise, s->noise, m.bc.free_mask));
  PetscCall(PetscRandomDestroy(&rnd));
  for (Vec *x : {&coords, &Ku, &scale}) PetscCall(VecDestroy(x));
  PetscFunctionReturn(0);
}

PetscErrorCode sceneDestroy(Scene *s) {
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&s->smooth));
  PetscCall(VecDestroy(&s->noise));
  PetscCall(problem::ElastodynamicsDestroy(&s->m));
  PetscFunctionReturn(0);
}

// Steps `steps` steps of h from u0 at rest with the given order; u_end: u at the end (may be
// null); *growth: max over the steps of max|u| / max|u0|.
PetscErrorCode stepFrom(Scene *s, Vec u0, PetscInt order, PetscReal h, PetscInt steps, Vec u_end, PetscReal *growth) {
  TS        ts;
  Vec       u, v;
  PetscReal start;
  PetscFunctionBeginUser;
  PetscCall(TSCreate(s->m.comm, &ts));
  PetscCall(TSSetType(ts, time::kTSCentralDifference));
  PetscCall(time::CentralDifferenceSetOrder(ts, order));
  PetscCall(TSSetTimeStep(ts, h));
  PetscCall(TSSetMaxTime(ts, 1e30));
  PetscCall(problem::ElastodynamicsSetUpTS(&s->m, ts));
  PetscCall(VecDuplicate(u0, &u));
  PetscCall(VecDuplicate(u0, &v));
  PetscCall(VecCopy(u0, u));
  PetscCall(VecZeroEntries(v));
  PetscCall(TS2SetSolution(ts, u, v));
  PetscCall(time::CentralDifferenceComputeInitialAcceleration(ts));
  PetscCall(VecNorm(u0, NORM_INFINITY, &start));
  *growth = 1;
  for (PetscInt k = 0; k < steps && *growth < 1e3; ++k) {
    PetscReal now;
    PetscCall(TSStep(ts));
    PetscCall(VecNorm(u, NORM_INFINITY, &now));
    *growth = std::max(*growth, now / start);
  }
  if (u_end) PetscCall(VecCopy(u, u_end));
  PetscCall(VecDestroy(&u));
  PetscCall(VecDestroy(&v));
  PetscCall(TSDestroy(&ts));
  PetscFunctionReturn(0);
}

PetscErrorCode checkOrder(Scene *s) {
  const PetscReal T = 2.0;
  PetscReal       growth;
  Vec             ref, u;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(s->smooth, &ref));
  PetscCall(VecDuplicate(s->smooth, &u));
  for (PetscInt order : {4, 2}) {
    const PetscReal limit = order == 4 ? s->step.dt_limit_fourth_order : s->step.dt_limit;
    const PetscInt  n0    = (PetscInt)std::ceil(T / (0.9 * limit));
    if (order == 4) PetscCall(stepFrom(s, s->smooth, 4, T / (64 * n0), 64 * n0, ref, &growth));
    PetscReal ref_norm;
    PetscCall(VecNorm(ref, NORM_2, &ref_norm));
    std::vector<double> errors;
    for (PetscInt k = 1; k <= 8; k *= 2) {
      PetscCall(stepFrom(s, s->smooth, order, T / (k * n0), k * n0, u, &growth));
      PetscCall(VecAXPY(u, -1.0, ref));
      PetscReal e;
      PetscCall(VecNorm(u, NORM_2, &e));
      errors.push_back(e / ref_norm);
    }
    std::string line;
    bool        ok = true;
    for (size_t k = 0; k + 1 < errors.size(); ++k) {
      const double rate = std::log2(errors[k] / errors[k + 1]);
      ok                = ok && std::fabs(rate - order) <= (order == 4 ? 0.2 : 0.1);
      line += " " + std::to_string(rate).substr(0, 5);
    }
    char errs[160];
    std::snprintf(errs, sizeof errs, "%.3e %.3e %.3e %.3e", errors[0], errors[1], errors[2], errors[3]);
    unit::check(ok, "order " + std::to_string(order) + ", " + std::to_string(n0) + " to " + std::to_string(8 * n0) + " steps to 2 s: errors " + errs + ", rates" + line +
                        (order == 4 ? " (bound 4 +- 0.2)" : " (bound 2 +- 0.1)"));
  }
  PetscCall(VecDestroy(&ref));
  PetscCall(VecDestroy(&u));
  PetscFunctionReturn(0);
}

PetscErrorCode checkStability(Scene *s) {
  PetscFunctionBeginUser;
  for (PetscInt order : {2, 4}) {
    const PetscReal bound = order == 4 ? s->step.dt_limit_fourth_order : s->step.dt_limit;
    PetscReal       lo = 0.9 * bound, hi = 1.1 * bound, growth;
    PetscCall(stepFrom(s, s->noise, order, lo, 600, nullptr, &growth));
    const bool stable_low = growth < 1e3;
    PetscCall(stepFrom(s, s->noise, order, hi, 600, nullptr, &growth));
    const bool unstable_high = growth >= 1e3;
    while (hi - lo > 1e-3 * bound) {
      const PetscReal mid = 0.5 * (lo + hi);
      PetscCall(stepFrom(s, s->noise, order, mid, 600, nullptr, &growth));
      (growth < 1e3 ? lo : hi) = mid;
    }
    const double measured = 0.5 * (lo + hi) / bound;
    unit::check(stable_low && unstable_high && measured >= 1 - 1e-3 && measured <= 1.02,
                "order " + std::to_string(order) + ": largest stable step by bisection " + std::to_string(measured).substr(0, 6) + " x the code's bound " +
                    std::to_string(bound) + " s (allowed 1 .. 1.02)");
  }
  const double ratio = s->step.dt_limit_fourth_order / s->step.dt_limit;
  unit::near(ratio, std::sqrt(3.0), 1e-12, 0, "the fourth-order bound is sqrt(3) x central differences' (bulk alone, no stiffness damping)");
  PetscFunctionReturn(0);
}

// The modified energy. In a closed undamped system the scheme is central differences with
// the stiffness K~ = K - (h^2/12) K M^-1 K, which conserve
//   W'_{n+1/2} = 1/2 v_{n+1/2}^T M v_{n+1/2} + 1/2 u_{n+1}^T K u_n - (h^2/24) (K u_{n+1})^T M^-1 K u_n
// exactly (M^-1 on the free dofs). The two-material box of tests/cases/energy_closed.sh at
// p = 4 (3 x 2 elements, the stiff block one element), base fixed, released with the uniform
// velocity (0.1, 0.05) m/s, 10,000 steps at 0.9 of the fourth-order limit: W' must stay
// within 1e-9 of its start (round-off; the plain W drifts by O(h^2 omega^2) of it, also shown).
PetscErrorCode checkModifiedEnergy() {
  problem::Elastodynamics m;
  problem::StableStep     step;
  TS                      ts;
  Vec                     u, v, u_prev, Ku, Ku_prev, w;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsClear(nullptr));
  PetscCall(PetscOptionsInsertString(nullptr, "-mesh_box_faces 3,2 -element_degree 4 -mesh_box_upper 30,20 -regions soil,block -region_block_box 10,20,10,20 "
                                              "-material_soil_rho 1800 -material_soil_vp 600 -material_soil_vs 250 -material_block_rho 2500 -material_block_E 3e10 "
                                              "-material_block_nu 0.2 -bc_bottom_type fixed"));
  PetscCall(problem::ElastodynamicsCreate(PETSC_COMM_WORLD, &m));
  PetscCall(problem::StableStepCompute(&m, problem::TimeStepOptions(), &step));
  const PetscReal h = 0.9 * step.dt_limit_fourth_order;
  PetscCall(TSCreate(m.comm, &ts));
  PetscCall(TSSetType(ts, time::kTSCentralDifference));
  PetscCall(time::CentralDifferenceSetOrder(ts, 4));
  PetscCall(TSSetTimeStep(ts, h));
  PetscCall(TSSetMaxTime(ts, 1e30));
  PetscCall(problem::ElastodynamicsSetUpTS(&m, ts));
  for (Vec *x : {&u, &v, &u_prev, &Ku, &Ku_prev, &w}) PetscCall(VecDuplicate(m.mass, x));
  PetscCall(VecZeroEntries(u));
  {
    PetscScalar *vv;
    PetscInt     n;
    PetscCall(VecGetLocalSize(v, &n));
    PetscCall(VecGetArray(v, &vv));
    for (PetscInt i = 0; i < n; i += 2) vv[i] = 0.1, vv[i + 1] = 0.05;
    PetscCall(VecRestoreArray(v, &vv));
    PetscCall(VecPointwiseMult(v, v, m.bc.free_mask));
  }
  PetscCall(TS2SetSolution(ts, u, v));
  PetscCall(time::CentralDifferenceComputeInitialAcceleration(ts));
  // W' after each step n+1 from u_n, u_{n+1} and their K u.
  auto energies = [&](PetscReal *modified, PetscReal *plain) -> PetscErrorCode {
    PetscReal kinetic, coupling, correction;
    PetscFunctionBeginUser;
    PetscCall(VecWAXPY(w, -1.0, u_prev, u)); // h v_{n+1/2}
    PetscCall(VecPointwiseMult(Ku_prev, Ku_prev, m.nodal.free_inv_mass));
    PetscCall(VecDot(Ku, Ku_prev, &correction)); // (K u_{n+1})^T M^-1 K u_n
    PetscCall(VecPointwiseMult(Ku_prev, Ku_prev, m.mass));
    PetscCall(VecDot(u, Ku_prev, &coupling));
    PetscCall(VecPointwiseMult(w, w, w));
    PetscCall(VecDot(w, m.mass, &kinetic));
    *plain    = 0.5 * kinetic / (h * h) + 0.5 * coupling;
    *modified = *plain - h * h / 24 * correction;
    PetscFunctionReturn(0);
  };
  PetscCall(problem::ElastodynamicsStiffnessTimes(&m, u, Ku));
  PetscReal start = 0, plain_start = 0, worst = 0, plain_worst = 0;
  for (PetscInt k = 0; k < 10000; ++k) {
    PetscCall(VecCopy(u, u_prev));
    PetscCall(VecCopy(Ku, Ku_prev));
    PetscCall(TSStep(ts));
    PetscCall(problem::ElastodynamicsStiffnessTimes(&m, u, Ku));
    PetscReal modified = 0, plain = 0;
    PetscCall(energies(&modified, &plain));
    if (k == 0) start = modified, plain_start = plain;
    worst       = std::max(worst, std::fabs(modified - start) / start);
    plain_worst = std::max(plain_worst, std::fabs(plain - plain_start) / plain_start);
  }
  char line[200];
  std::snprintf(line, sizeof line, "p = 4, 10,000 steps of order 4: modified energy W' within %.2e of its start (bound 1e-9); the plain shadow energy moves by %.2e", worst,
                plain_worst);
  unit::check(worst <= 1e-9 && plain_worst > 1e3 * worst, line);
  for (Vec *x : {&u, &v, &u_prev, &Ku, &Ku_prev, &w}) PetscCall(VecDestroy(x));
  PetscCall(TSDestroy(&ts));
  PetscCall(problem::ElastodynamicsDestroy(&m));
  PetscFunctionReturn(0);
}

// With absorbing sides (Lysmer dashpots, whose share of the correction is explicit, at
// v_{n+1/2}) the fourth-order limit is central differences' bound (problem/stable_step.hpp),
// which must hold with a margin: the scene of the order test at p = 2 and 6 with its sides and
// base absorbing, from the random displacement, 4000 steps: bounded at the bound, and the
// onset of growth, by bisection to 1 %, at least 1.05 x the bound (measured at commit: about
// 1.1 at p = 2, 1.3 at p = 6 and 8).
PetscErrorCode checkAbsorbingStability() {
  PetscFunctionBeginUser;
  for (const char *degree : {"2", "6"}) {
    Scene     s;
    PetscReal growth;
    PetscCall(sceneCreate(&s, std::string(" -bc_bottom_type absorbing -bc_left_type absorbing -bc_right_type absorbing -mesh_box_faces 3,2 -element_degree ") + degree));
    const PetscReal bound = s.step.dt_limit_fourth_order;
    PetscCall(stepFrom(&s, s.noise, 4, bound, 4000, nullptr, &growth));
    const bool at_bound = growth < 1e3;
    PetscReal  lo = bound, hi = 2 * bound;
    while (hi - lo > 0.01 * bound) {
      const PetscReal mid = 0.5 * (lo + hi);
      PetscCall(stepFrom(&s, s.noise, 4, mid, 4000, nullptr, &growth));
      (growth < 1e3 ? lo : hi) = mid;
    }
    unit::check(at_bound && lo >= 1.05 * bound && std::fabs(bound / s.step.dt_limit - 1) < 1e-12,
                std::string("absorbing sides, p = ") + degree + ", order 4: the central-difference bound " + std::to_string(bound) + " s holds; growth sets in at " +
                    std::to_string(lo / bound).substr(0, 5) + " x it (allowed >= 1.05)");
    PetscCall(sceneDestroy(&s));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Run(bool) {
  Scene s;
  PetscFunctionBeginUser;
  PetscCall(time::CentralDifferenceRegister());
  PetscCall(sceneCreate(&s));
  PetscCall(checkOrder(&s));
  PetscCall(checkStability(&s));
  PetscCall(sceneDestroy(&s));
  PetscCall(checkAbsorbingStability());
  PetscCall(checkModifiedEnergy());
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char **argv) { return unit::runPetscTest(argc, argv, Run); }
