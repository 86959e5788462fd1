#include "slipwave/time/central_difference.hpp"

#include <petsc/private/tsimpl.h>

#include "slipwave/numerics/dense_solve.hpp"

#include <algorithm>
#include <initializer_list>
#include <utility>
#include <vector>

namespace slipwave::time {
namespace {

struct CentralDifference {
  Vec       accel       = nullptr; // a_n
  Vec       accel_star  = nullptr; // RHS result a*
  Vec       v_half      = nullptr; // v_{n+1/2}
  PetscInt  order       = 2;
  PetscBool order_from_options = PETSC_FALSE;
  PetscErrorCode (*correction)(void *, PetscReal, PetscReal, Vec, Vec) = nullptr;
  void     *correction_ctx = nullptr;
  // Order 4 only (null at order 2):
  Vec       corr        = nullptr; // c added at the current time
  std::vector<PetscScalar> damped_saved; // a* at the damped nodes while c is computed from a* - D v
  Vec       accel_prev  = nullptr, accel_prev2 = nullptr; // a_{n-1}, a_{n-2}
  PetscInt  history     = 0;       // how many of them the run has taken (0 .. 2)
  Vec       v_report    = nullptr, a_report = nullptr;
  Vec       damping     = nullptr; // nodal blocks of M^{-1} C, or null
  PetscInt  damping_bs  = 0;
  std::vector<PetscInt> diagonal_nodes; // local nodes with a diagonal damping block
  std::vector<PetscInt> coupled_nodes;  // local nodes with off-diagonal damping terms
  PetscBool have_accel  = PETSC_FALSE;
  PetscErrorCode (*commit)(void *) = nullptr;
  void     *commit_ctx  = nullptr;
};

CentralDifference *data(TS ts) { return static_cast<CentralDifference *>(ts->data); }

// Solves (I + s D_i) v_i = r_i for node block i (s = h/2), and forms a_i = a*_i - D_i v_i in
// place (a holds a* on entry). Blocks are at most 3x3.
void solveDampedBlock(PetscInt bs, const PetscScalar *D, PetscReal s, PetscScalar *vi, PetscScalar *ai) {
  const int n = (int)bs;
  double    A[9], r[3], x[3];
  for (int i = 0; i < n; ++i) {
    r[i] = vi[i];
    for (int j = 0; j < n; ++j) A[i * n + j] = (i == j ? 1.0 : 0.0) + s * D[i * n + j];
  }
  numerics::solveDense(n, A, r, x);
  for (int i = 0; i < n; ++i) {
    vi[i] = x[i];
    double Dv = 0;
    for (int j = 0; j < n; ++j) Dv += D[i * n + j] * x[j];
    ai[i] -= Dv;
  }
}

// The nodes whose damping block is not zero, split into diagonal blocks (Rayleigh alpha, a
// dashpot aligned with the axes) and full ones. Most nodes of a model with absorbing sides
// have none, so the step visits only these instead of every node.
PetscErrorCode classifyDampedNodes(CentralDifference *cd) {
  PetscFunctionBeginUser;
  cd->diagonal_nodes.clear();
  cd->coupled_nodes.clear();
  if (!cd->damping) PetscFunctionReturn(0);
  const PetscInt     bs = cd->damping_bs;
  PetscInt           n;
  const PetscScalar *dd;
  PetscCall(VecGetLocalSize(cd->damping, &n));
  PetscCall(VecGetArrayRead(cd->damping, &dd));
  for (PetscInt node = 0; node < n / (bs * bs); ++node) {
    const PetscScalar *D = dd + node * bs * bs;
    bool               any = false, off = false;
    for (PetscInt i = 0; i < bs; ++i)
      for (PetscInt j = 0; j < bs; ++j) {
        any = any || D[i * bs + j] != 0.0;
        off = off || (i != j && D[i * bs + j] != 0.0);
      }
    if (off) cd->coupled_nodes.push_back(node);
    else if (any) cd->diagonal_nodes.push_back(node);
  }
  PetscCall(VecRestoreArrayRead(cd->damping, &dd));
  PetscFunctionReturn(0);
}

// At the damped nodes only: v = (I + s D)^{-1} v and a = a - D v (a holds a* on entry). A
// diagonal block is the same elimination with nothing to eliminate: one division per dof.
PetscErrorCode dampedVelocity(CentralDifference *cd, PetscReal s, Vec v, Vec a) {
  PetscFunctionBeginUser;
  if (!cd->damping) PetscFunctionReturn(0);
  const PetscInt     bs = cd->damping_bs;
  PetscScalar       *vv, *aa;
  const PetscScalar *dd;
  PetscCall(VecGetArray(v, &vv));
  PetscCall(VecGetArray(a, &aa));
  PetscCall(VecGetArrayRead(cd->damping, &dd));
  for (PetscInt node : cd->diagonal_nodes)
    for (PetscInt i = 0; i < bs; ++i) {
      const PetscScalar Dii = dd[node * bs * bs + i * bs + i];
      const PetscScalar x   = vv[node * bs + i] / (1.0 + s * Dii);
      vv[node * bs + i]     = x;
      aa[node * bs + i] -= Dii * x;
    }
  for (PetscInt node : cd->coupled_nodes) solveDampedBlock(bs, dd + node * bs * bs, s, vv + node * bs, aa + node * bs);
  PetscCall(VecRestoreArrayRead(cd->damping, &dd));
  PetscCall(VecRestoreArray(a, &aa));
  PetscCall(VecRestoreArray(v, &vv));
  PetscFunctionReturn(0);
}

// The two nodal passes of a step, each one loop over the local dofs:
// before the force, v_half = v + h/2 a and u += h v_half;
PetscErrorCode predict(PetscReal h, Vec u, Vec v, Vec a, Vec v_half) {
  PetscInt           n;
  PetscScalar       *uu, *vh;
  const PetscScalar *vv, *aa;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(u, &n));
  PetscCall(VecGetArray(u, &uu));
  PetscCall(VecGetArrayWrite(v_half, &vh));
  PetscCall(VecGetArrayRead(v, &vv));
  PetscCall(VecGetArrayRead(a, &aa));
  for (PetscInt i = 0; i < n; ++i) {
    vh[i] = 0.5 * h * aa[i] + vv[i];
    uu[i] += h * vh[i];
  }
  PetscCall(VecRestoreArrayRead(a, &aa));
  PetscCall(VecRestoreArrayRead(v, &vv));
  PetscCall(VecRestoreArrayWrite(v_half, &vh));
  PetscCall(VecRestoreArray(u, &uu));
  PetscFunctionReturn(0);
}

// after it, v = v_half + h/2 a* (the damped nodes are corrected after).
PetscErrorCode correct(PetscReal h, Vec v_half, Vec a_star, Vec v) {
  PetscInt           n;
  PetscScalar       *vv;
  const PetscScalar *vh, *as;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(v, &n));
  PetscCall(VecGetArrayWrite(v, &vv));
  PetscCall(VecGetArrayRead(v_half, &vh));
  PetscCall(VecGetArrayRead(a_star, &as));
  for (PetscInt i = 0; i < n; ++i) vv[i] = 0.5 * h * as[i] + vh[i];
  PetscCall(VecRestoreArrayRead(a_star, &as));
  PetscCall(VecRestoreArrayRead(v_half, &vh));
  PetscCall(VecRestoreArrayWrite(v, &vv));
  PetscFunctionReturn(0);
}

// a* -= D w at the damped nodes (the acceleration with the nodal damping at the velocity w last
// known: v_{n+1/2} within a step, v_0 at the start), their values before kept in `saved`; and
// back (restore: a* as it was, bit for bit).
PetscErrorCode dampedAcceleration(CentralDifference *cd, Vec w, Vec a_star, std::vector<PetscScalar> *saved, bool restore) {
  PetscFunctionBeginUser;
  if (!cd->damping) PetscFunctionReturn(0);
  const PetscInt     bs = cd->damping_bs;
  const PetscScalar *ww, *dd;
  PetscScalar       *aa;
  PetscCall(VecGetArrayRead(w, &ww));
  PetscCall(VecGetArrayRead(cd->damping, &dd));
  PetscCall(VecGetArray(a_star, &aa));
  if (!restore) saved->clear();
  size_t k = 0;
  for (const std::vector<PetscInt> *nodes : {&cd->diagonal_nodes, &cd->coupled_nodes})
    for (PetscInt node : *nodes)
      for (PetscInt i = 0; i < bs; ++i) {
        PetscScalar &a = aa[node * bs + i];
        if (restore) {
          a = (*saved)[k++];
          continue;
        }
        saved->push_back(a);
        for (PetscInt j = 0; j < bs; ++j) a -= dd[node * bs * bs + i * bs + j] * ww[node * bs + j];
      }
  PetscCall(VecRestoreArray(a_star, &aa));
  PetscCall(VecRestoreArrayRead(cd->damping, &dd));
  PetscCall(VecRestoreArrayRead(w, &ww));
  PetscFunctionReturn(0);
}

// Order 4: a* += c, c from the model's hook applied to a* - D w (dampedAcceleration), kept for
// the ledger; order 2: nothing. The hook corrects the whole acceleration, nodal damping
// included: at an absorbing side the dashpot force is as large as the elastic one, and K
// applied to a* alone sees a spike there (a* lacks -D v on the side's nodes) while
// h^2 K / 12 is O(1): the SV column at p = 2 then reflected 2.2e-3 of its peak from its
// absorbing base, 32 x central differences (6.9e-5), and its surface motion erred by 3.6e-3
// (central differences 8.7e-4); with the damping at v_{n+1/2} 5.5e-5 and 1.2e-4. That share,
// (h^2/12) M^-1 K D v_{n+1/2}, is explicit and opposes the centred damping on the highest
// modes of the damped nodes: measured stable up to 1.1 (p = 2) .. 1.3 (p = 8) x the
// central-difference bound, which is the limit with dashpots (problem/stable_step.hpp). At the
// predicted velocity v_{n+1/2} + h/2 a* it failed from 0.8 of the bound sqrt(12)/omega even on
// a single mode. The damping itself stays second order.
PetscErrorCode addCorrection(TS ts, PetscReal t, PetscReal h, Vec w, Vec a_star) {
  CentralDifference *cd = data(ts);
  PetscFunctionBeginUser;
  if (cd->order != 4) PetscFunctionReturn(0);
  PetscCheck(cd->correction, PetscObjectComm((PetscObject)ts), PETSC_ERR_ORDER, "TS type cd of order 4 needs CentralDifferenceSetCorrection before TSSolve");
  PetscCall(dampedAcceleration(cd, w, a_star, &cd->damped_saved, false));
  PetscCall(cd->correction(cd->correction_ctx, t, h, a_star, cd->corr));
  PetscCall(dampedAcceleration(cd, w, a_star, &cd->damped_saved, true));
  PetscCall(VecAXPY(a_star, 1.0, cd->corr));
  PetscFunctionReturn(0);
}

PetscErrorCode commitState(CentralDifference *cd) {
  PetscFunctionBeginUser;
  if (cd->commit) PetscCall(cd->commit(cd->commit_ctx));
  PetscFunctionReturn(0);
}

PetscErrorCode velocityVector(TS ts, Vec *v) {
  PetscFunctionBeginUser;
  *v = ts->vec_dot;
  PetscCheck(*v, PetscObjectComm((PetscObject)ts), PETSC_ERR_ORDER,
             "TS type cd needs the velocity: call TS2SetSolution(ts, u, v) before TSSolve");
  PetscFunctionReturn(0);
}

PetscErrorCode stepCentralDifference(TS ts) {
  CentralDifference *cd = data(ts);
  const PetscReal    h  = ts->time_step;
  Vec                u  = ts->vec_sol, v;
  PetscReal          next_h = h;
  PetscBool          accept = PETSC_TRUE;

  PetscFunctionBeginUser;
  PetscCall(velocityVector(ts, &v));
  if (!cd->have_accel) PetscCall(CentralDifferenceComputeInitialAcceleration(ts));
  // Choose the next step before advancing the time, so a matched final time is honoured.
  PetscCall(TSAdaptChoose(ts->adapt, ts, h, nullptr, &next_h, &accept));

  PetscCall(TSPreStage(ts, ts->ptime));
  PetscCall(predict(h, u, v, cd->accel, cd->v_half));
  PetscCall(TSComputeRHSFunction(ts, ts->ptime + h, u, cd->accel_star));
  PetscCall(addCorrection(ts, ts->ptime + h, h, cd->v_half, cd->accel_star));
  PetscCall(correct(h, cd->v_half, cd->accel_star, v));
  // a_{n+1} = a* at undamped nodes: the vectors swap roles instead of copying (at order 4
  // a_n moves down the history, and a_{n-2}'s vector takes the next RHS result).
  if (cd->order == 4) {
    std::swap(cd->accel_prev2, cd->accel_prev);
    std::swap(cd->accel_prev, cd->accel);
    std::swap(cd->accel, cd->accel_star);
    cd->history = std::min<PetscInt>(cd->history + 1, 2);
  } else std::swap(cd->accel, cd->accel_star);
  PetscCall(dampedVelocity(cd, 0.5 * h, v, cd->accel));
  PetscCall(TSPostStage(ts, ts->ptime + h, 0, &u));
  PetscCall(commitState(cd));

  ts->ptime += h;
  ts->time_step = next_h;
  PetscFunctionReturn(0);
}

// The vectors of order 4 (each created once, with the solution's layout).
std::vector<Vec *> fourthOrderVectors(CentralDifference *cd) { return {&cd->corr, &cd->accel_prev, &cd->accel_prev2, &cd->v_report, &cd->a_report}; }

PetscErrorCode setUpCentralDifference(TS ts) {
  CentralDifference *cd = data(ts);
  PetscFunctionBeginUser;
  if (!cd->accel) PetscCall(VecDuplicate(ts->vec_sol, &cd->accel));
  if (!cd->accel_star) PetscCall(VecDuplicate(ts->vec_sol, &cd->accel_star));
  if (!cd->v_half) PetscCall(VecDuplicate(ts->vec_sol, &cd->v_half));
  if (cd->order == 4)
    for (Vec *x : fourthOrderVectors(cd))
      if (!*x) {
        PetscCall(VecDuplicate(ts->vec_sol, x));
        PetscCall(VecZeroEntries(*x));
      }
  PetscFunctionReturn(0);
}

PetscErrorCode resetCentralDifference(TS ts) {
  CentralDifference *cd = data(ts);
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&cd->accel));
  PetscCall(VecDestroy(&cd->accel_star));
  PetscCall(VecDestroy(&cd->v_half));
  for (Vec *x : fourthOrderVectors(cd)) PetscCall(VecDestroy(x));
  cd->have_accel = PETSC_FALSE;
  cd->history    = 0;
  PetscFunctionReturn(0);
}

PetscErrorCode setFromOptionsCentralDifference(TS ts, PetscOptionItems *PetscOptionsObject) {
  CentralDifference *cd = data(ts);
  PetscInt           order = cd->order;
  PetscBool          set;
  PetscFunctionBeginUser;
  PetscOptionsHeadBegin(PetscOptionsObject, "Central difference (TS type cd) options");
  PetscCall(PetscOptionsInt("-ts_cd_order",
                            "order of the time integrator: 2 (central difference) or 4 (fourth-order modified equation, two bulk-force passes per step, stable to a "
                            "sqrt(3) x longer step); default: the cheaper of the two at the step that accuracy needs (docs/spectral-elements.md)",
                            "CentralDifferenceSetOrder", order, &order, &set));
  PetscOptionsHeadEnd();
  if (set) {
    PetscCall(CentralDifferenceSetOrder(ts, order));
    cd->order_from_options = PETSC_TRUE;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode destroyCentralDifference(TS ts) {
  PetscFunctionBeginUser;
  PetscCall(resetCentralDifference(ts));
  PetscCall(VecDestroy(&data(ts)->damping));
  delete data(ts);
  ts->data = nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode viewCentralDifference(TS ts, PetscViewer viewer) {
  PetscBool ascii;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  if (ascii) {
    PetscCall(PetscViewerASCIIPrintf(viewer, "  %s (velocity-Verlet form), lumped mass, %s nodal damping\n",
                                     data(ts)->order == 4 ? "fourth-order modified-equation scheme" : "central difference", data(ts)->damping ? "centred" : "no"));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode createCentralDifference(TS ts) {
  PetscFunctionBeginUser;
  ts->ops->step    = stepCentralDifference;
  ts->ops->setup   = setUpCentralDifference;
  ts->ops->reset   = resetCentralDifference;
  ts->ops->destroy = destroyCentralDifference;
  ts->ops->view    = viewCentralDifference;
  ts->ops->setfromoptions = setFromOptionsCentralDifference;
  ts->usessnes     = PETSC_FALSE;
  ts->default_adapt_type = TSADAPTNONE;
  ts->data = new CentralDifference();
  PetscFunctionReturn(0);
}

PetscErrorCode requireCentralDifference(TS ts) {
  PetscBool is_cd;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)ts, kTSCentralDifference, &is_cd));
  PetscCheck(is_cd, PetscObjectComm((PetscObject)ts), PETSC_ERR_ARG_WRONG, "TS type is not %s", kTSCentralDifference);
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode CentralDifferenceRegister() {
  PetscFunctionBeginUser;
  PetscCall(TSRegister(kTSCentralDifference, createCentralDifference));
  PetscFunctionReturn(0);
}

PetscErrorCode CentralDifferenceSetNodalDamping(TS ts, PetscInt bs, Vec blocks) {
  PetscFunctionBeginUser;
  PetscCall(requireCentralDifference(ts));
  CentralDifference *cd = data(ts);
  if (blocks) PetscCall(PetscObjectReference((PetscObject)blocks));
  PetscCall(VecDestroy(&cd->damping));
  cd->damping    = blocks;
  cd->damping_bs = bs;
  cd->have_accel = PETSC_FALSE;
  PetscCall(classifyDampedNodes(cd));
  PetscFunctionReturn(0);
}

PetscErrorCode CentralDifferenceSetCommit(TS ts, PetscErrorCode (*commit)(void *ctx), void *ctx) {
  PetscFunctionBeginUser;
  PetscCall(requireCentralDifference(ts));
  data(ts)->commit     = commit;
  data(ts)->commit_ctx = ctx;
  PetscFunctionReturn(0);
}

PetscErrorCode CentralDifferenceGetHalfStepVelocity(TS ts, Vec *v_half) {
  PetscFunctionBeginUser;
  PetscCall(requireCentralDifference(ts));
  *v_half = data(ts)->v_half;
  PetscFunctionReturn(0);
}

PetscErrorCode CentralDifferenceGetAcceleration(TS ts, Vec *a) {
  PetscFunctionBeginUser;
  PetscCall(requireCentralDifference(ts));
  *a = data(ts)->accel;
  PetscFunctionReturn(0);
}

PetscErrorCode CentralDifferenceComputeInitialAcceleration(TS ts) {
  Vec v;
  PetscFunctionBeginUser;
  PetscCall(requireCentralDifference(ts));
  PetscCall(TSSetUp(ts));
  CentralDifference *cd = data(ts);
  PetscCall(velocityVector(ts, &v));
  // At t_0 the velocity is known exactly, so the damping terms use it directly.
  PetscCall(VecCopy(v, cd->v_half));
  PetscCall(TSComputeRHSFunction(ts, ts->ptime, ts->vec_sol, cd->accel_star));
  PetscCall(addCorrection(ts, ts->ptime, ts->time_step, v, cd->accel_star));
  Vec v_copy;
  PetscCall(VecDuplicate(v, &v_copy));
  PetscCall(VecCopy(v, v_copy));
  PetscCall(VecCopy(cd->accel_star, cd->accel));
  // a_0 = a* - D v_0 with v_0 fixed: the block solve with s = 0.
  PetscCall(dampedVelocity(cd, 0.0, v_copy, cd->accel));
  PetscCall(VecDestroy(&v_copy));
  PetscCall(commitState(cd));
  cd->have_accel = PETSC_TRUE;
  cd->history    = 0;
  PetscFunctionReturn(0);
}

PetscErrorCode CentralDifferenceSetOrder(TS ts, PetscInt order) {
  PetscFunctionBeginUser;
  PetscCall(requireCentralDifference(ts));
  PetscCheck(order == 2 || order == 4, PetscObjectComm((PetscObject)ts), PETSC_ERR_USER_INPUT, "-ts_cd_order = %" PetscInt_FMT "; allowed: 2 or 4", order);
  CentralDifference *cd = data(ts);
  PetscCheck(!cd->accel || order == cd->order, PetscObjectComm((PetscObject)ts), PETSC_ERR_ORDER, "the order of TS type cd is set before TSSetUp");
  cd->order = order;
  PetscFunctionReturn(0);
}

PetscErrorCode CentralDifferenceGetOrder(TS ts, PetscInt *order, PetscBool *from_options) {
  PetscFunctionBeginUser;
  PetscCall(requireCentralDifference(ts));
  *order = data(ts)->order;
  if (from_options) *from_options = data(ts)->order_from_options;
  PetscFunctionReturn(0);
}

PetscErrorCode CentralDifferenceSetCorrection(TS ts, PetscErrorCode (*correction)(void *ctx, PetscReal t, PetscReal h, Vec a_star, Vec c), void *ctx) {
  PetscFunctionBeginUser;
  PetscCall(requireCentralDifference(ts));
  data(ts)->correction     = correction;
  data(ts)->correction_ctx = ctx;
  PetscFunctionReturn(0);
}

PetscErrorCode CentralDifferenceGetCorrection(TS ts, Vec *c) {
  PetscFunctionBeginUser;
  PetscCall(requireCentralDifference(ts));
  *c = data(ts)->corr;
  PetscFunctionReturn(0);
}

PetscErrorCode CentralDifferenceGetReportedState(TS ts, Vec *v, Vec *a) {
  Vec v_ts;
  PetscFunctionBeginUser;
  PetscCall(requireCentralDifference(ts));
  CentralDifference *cd = data(ts);
  PetscCall(velocityVector(ts, &v_ts));
  if (cd->order != 4) {
    *v = v_ts;
    *a = cd->accel;
    PetscFunctionReturn(0);
  }
  const PetscReal h = ts->time_step;
  // u''' by the backward difference of the accelerations, second order with three of them
  // (first order with two: then its h^2 error term is h^3).
  PetscCall(VecCopy(v_ts, cd->v_report));
  if (cd->history >= 2) {
    const PetscScalar w[3] = {-3 * h / 12, 4 * h / 12, -h / 12};
    Vec               x[3] = {cd->accel, cd->accel_prev, cd->accel_prev2};
    PetscCall(VecMAXPY(cd->v_report, 3, w, x));
  } else if (cd->history == 1) {
    const PetscScalar w[2] = {-h / 6, h / 6};
    Vec               x[2] = {cd->accel, cd->accel_prev};
    PetscCall(VecMAXPY(cd->v_report, 2, w, x));
  }
  PetscCall(VecWAXPY(cd->a_report, -1.0, cd->corr, cd->accel));
  *v = cd->v_report;
  *a = cd->a_report;
  PetscFunctionReturn(0);
}

PetscErrorCode CentralDifferenceGetHistory(TS ts, Vec *previous, Vec *before_previous) {
  PetscFunctionBeginUser;
  PetscCall(requireCentralDifference(ts));
  *previous        = data(ts)->accel_prev;
  *before_previous = data(ts)->accel_prev2;
  PetscFunctionReturn(0);
}

PetscErrorCode CentralDifferenceSetHistory(TS ts, Vec previous, Vec before_previous, PetscInt count) {
  PetscFunctionBeginUser;
  PetscCall(requireCentralDifference(ts));
  PetscCall(TSSetUp(ts));
  CentralDifference *cd = data(ts);
  PetscCheck(cd->order == 4, PetscObjectComm((PetscObject)ts), PETSC_ERR_ORDER, "TS type cd keeps an acceleration history at order 4 only");
  PetscCall(VecCopy(previous, cd->accel_prev));
  PetscCall(VecCopy(before_previous, cd->accel_prev2));
  cd->history = std::min<PetscInt>(count, 2);
  PetscFunctionReturn(0);
}

PetscErrorCode CentralDifferenceSetAcceleration(TS ts, Vec a) {
  PetscFunctionBeginUser;
  PetscCall(requireCentralDifference(ts));
  PetscCall(TSSetUp(ts));
  PetscCall(VecCopy(a, data(ts)->accel));
  data(ts)->have_accel = PETSC_TRUE;
  PetscFunctionReturn(0);
}

} // namespace slipwave::time
