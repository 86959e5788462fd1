#include "slipwave/time/central_difference.hpp"

#include <petsc/private/tsimpl.h>

#include <vector>

namespace slipwave::time {
namespace {

struct CentralDifference {
  Vec       accel       = nullptr; // a_n
  Vec       accel_star  = nullptr; // RHS result a*
  Vec       v_half      = nullptr; // v_{n+1/2}
  Vec       damping     = nullptr; // nodal blocks of M^{-1} C, or null
  PetscInt  damping_bs  = 0;
  PetscBool have_accel  = PETSC_FALSE;
  PetscErrorCode (*commit)(void *) = nullptr;
  void     *commit_ctx  = nullptr;
};

CentralDifference *data(TS ts) { return static_cast<CentralDifference *>(ts->data); }

// Solves (I + s D_i) v_i = r_i for every node block (s = h/2), and forms a = a* - D v.
// Blocks are at most 3x3: Gaussian elimination with partial pivoting in place.
PetscErrorCode dampedVelocity(CentralDifference *cd, PetscReal s, Vec v, Vec a) {
  PetscFunctionBeginUser;
  if (!cd->damping) {
    PetscCall(VecCopy(cd->accel_star, a));
    PetscFunctionReturn(0);
  }
  const PetscInt bs = cd->damping_bs;
  PetscInt       n;
  PetscScalar   *vv, *aa;
  const PetscScalar *dd, *as;
  PetscCall(VecGetLocalSize(v, &n));
  PetscCall(VecGetArray(v, &vv));
  PetscCall(VecGetArray(a, &aa));
  PetscCall(VecGetArrayRead(cd->damping, &dd));
  PetscCall(VecGetArrayRead(cd->accel_star, &as));
  double A[9], r[3], x[3];
  for (PetscInt node = 0; node < n / bs; ++node) {
    const PetscScalar *D = dd + node * bs * bs;
    PetscScalar       *vi = vv + node * bs;
    bool               zero = true;
    for (PetscInt k = 0; k < bs * bs; ++k) zero = zero && D[k] == 0.0;
    if (zero) {
      for (PetscInt i = 0; i < bs; ++i) aa[node * bs + i] = as[node * bs + i];
      continue;
    }
    for (PetscInt i = 0; i < bs; ++i) {
      r[i] = vi[i];
      for (PetscInt j = 0; j < bs; ++j) A[i * bs + j] = (i == j ? 1.0 : 0.0) + s * D[i * bs + j];
    }
    for (PetscInt c = 0; c < bs; ++c) {
      PetscInt p = c;
      for (PetscInt i = c + 1; i < bs; ++i)
        if (PetscAbsReal(A[i * bs + c]) > PetscAbsReal(A[p * bs + c])) p = i;
      if (p != c) {
        for (PetscInt j = 0; j < bs; ++j) std::swap(A[c * bs + j], A[p * bs + j]);
        std::swap(r[c], r[p]);
      }
      for (PetscInt i = c + 1; i < bs; ++i) {
        const double f = A[i * bs + c] / A[c * bs + c];
        for (PetscInt j = c; j < bs; ++j) A[i * bs + j] -= f * A[c * bs + j];
        r[i] -= f * r[c];
      }
    }
    for (PetscInt i = bs - 1; i >= 0; --i) {
      double sum = r[i];
      for (PetscInt j = i + 1; j < bs; ++j) sum -= A[i * bs + j] * x[j];
      x[i] = sum / A[i * bs + i];
    }
    for (PetscInt i = 0; i < bs; ++i) {
      vi[i] = x[i];
      double Dv = 0;
      for (PetscInt j = 0; j < bs; ++j) Dv += D[i * bs + j] * x[j];
      aa[node * bs + i] = as[node * bs + i] - Dv;
    }
  }
  PetscCall(VecRestoreArrayRead(cd->accel_star, &as));
  PetscCall(VecRestoreArrayRead(cd->damping, &dd));
  PetscCall(VecRestoreArray(a, &aa));
  PetscCall(VecRestoreArray(v, &vv));
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
  PetscCall(VecWAXPY(cd->v_half, 0.5 * h, cd->accel, v));
  PetscCall(VecAXPY(u, h, cd->v_half));
  PetscCall(TSComputeRHSFunction(ts, ts->ptime + h, u, cd->accel_star));
  PetscCall(VecWAXPY(v, 0.5 * h, cd->accel_star, cd->v_half));
  PetscCall(dampedVelocity(cd, 0.5 * h, v, cd->accel));
  PetscCall(TSPostStage(ts, ts->ptime + h, 0, &u));
  PetscCall(commitState(cd));

  ts->ptime += h;
  ts->time_step = next_h;
  PetscFunctionReturn(0);
}

PetscErrorCode setUpCentralDifference(TS ts) {
  CentralDifference *cd = data(ts);
  PetscFunctionBeginUser;
  if (!cd->accel) PetscCall(VecDuplicate(ts->vec_sol, &cd->accel));
  if (!cd->accel_star) PetscCall(VecDuplicate(ts->vec_sol, &cd->accel_star));
  if (!cd->v_half) PetscCall(VecDuplicate(ts->vec_sol, &cd->v_half));
  PetscFunctionReturn(0);
}

PetscErrorCode resetCentralDifference(TS ts) {
  CentralDifference *cd = data(ts);
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&cd->accel));
  PetscCall(VecDestroy(&cd->accel_star));
  PetscCall(VecDestroy(&cd->v_half));
  cd->have_accel = PETSC_FALSE;
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
    PetscCall(PetscViewerASCIIPrintf(viewer, "  central difference (velocity-Verlet form), lumped mass, %s nodal damping\n",
                                     data(ts)->damping ? "centred" : "no"));
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
  Vec v_copy;
  PetscCall(VecDuplicate(v, &v_copy));
  PetscCall(VecCopy(v, v_copy));
  if (cd->damping) {
    // a_0 = a* - D v_0 with v_0 fixed: reuse the block solve with s = 0.
    PetscCall(dampedVelocity(cd, 0.0, v_copy, cd->accel));
  } else {
    PetscCall(VecCopy(cd->accel_star, cd->accel));
  }
  PetscCall(VecDestroy(&v_copy));
  PetscCall(commitState(cd));
  cd->have_accel = PETSC_TRUE;
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
