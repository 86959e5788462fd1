#include "slipwave/problem/static_equilibrium.hpp"

#include <cstdio>
#include <vector>

namespace slipwave::problem {
namespace {

// Adds the element matrices of the bulk operator (the very matrices the explicit steps apply)
// and the interface stick springs to K; with_values false adds zeros (for the pattern).
PetscErrorCode addStiffness(Elastodynamics *m, bool with_values, Mat K) {
  PetscFunctionBeginUser;
  const PetscInt        nen = m->bulk.nodesPerElement(), dim = m->dim, n = nen * dim;
  std::vector<PetscInt> rows(n);
  std::vector<double>   Ke((size_t)n * n, 0.0);
  for (PetscInt e = 0; e < m->bulk.elementCount(); ++e) {
    for (PetscInt a = 0; a < nen; ++a)
      for (PetscInt i = 0; i < dim; ++i) rows[a * dim + i] = m->bulk.elementNodeOffset(e, a) + i;
    if (with_values) m->bulk.elementStiffness(e, Ke.data());
    PetscCall(MatSetValuesLocal(K, n, rows.data(), n, rows.data(), Ke.data(), ADD_VALUES));
  }
  for (const auto &iface : m->interfaces) PetscCall(iface.AddStickStiffness(K));
  PetscFunctionReturn(0);
}

// K preallocated from its own entries: the DM's preallocation covers the DM cells' adjacency,
// which misses the couplings inside a spectral element (its nodes share no sub-cell) and
// those of the interface pairs; entries allocated on the fly cost a copy each (40 x 40
// elements at p = 4: 460 s, against 3.3 s preallocated). A MATPREALLOCATOR pass records the
// exact pattern first.
PetscErrorCode assembleStiffness(Elastodynamics *m, Mat *K) {
  Mat                    pattern;
  PetscInt               rows_local, cols_local, rows, cols;
  ISLocalToGlobalMapping l2g;
  PetscFunctionBeginUser;
  PetscCall(DMSetMatrixPreallocateSkip(m->dm, PETSC_TRUE));
  PetscCall(DMCreateMatrix(m->dm, K));
  PetscCall(DMSetMatrixPreallocateSkip(m->dm, PETSC_FALSE));
  PetscCall(MatGetLocalSize(*K, &rows_local, &cols_local));
  PetscCall(MatGetSize(*K, &rows, &cols));
  PetscCall(MatGetLocalToGlobalMapping(*K, &l2g, nullptr));
  PetscCall(MatCreate(m->comm, &pattern));
  PetscCall(MatSetType(pattern, MATPREALLOCATOR));
  PetscCall(MatSetSizes(pattern, rows_local, cols_local, rows, cols));
  PetscCall(MatSetLocalToGlobalMapping(pattern, l2g, l2g));
  PetscCall(MatSetUp(pattern));
  PetscCall(addStiffness(m, false, pattern));
  PetscCall(MatAssemblyBegin(pattern, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(pattern, MAT_FINAL_ASSEMBLY));
  PetscCall(MatPreallocatorPreallocate(pattern, PETSC_FALSE, *K));
  PetscCall(MatDestroy(&pattern));
  // The pattern is complete: an entry outside it would be a bug, not a slow path.
  PetscCall(MatSetOption(*K, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  PetscCall(addStiffness(m, true, *K));
  PetscCall(MatAssemblyBegin(*K, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*K, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

// Rigid-body modes from the node coordinates (in the displacement layout), so that GAMG
// coarsens elasticity well.
PetscErrorCode setRigidBodyModes(Elastodynamics *m, Mat K) {
  Vec          local, coords;
  PetscScalar *x;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(m->dm, &local));
  PetscCall(VecGetArray(local, &x));
  const PetscInt nen = m->bulk.nodesPerCell(), dim = m->dim;
  for (PetscInt c = 0; c < m->bulk.cellCount(); ++c) {
    const double *xc = m->bulk.cellCoordinates(c);
    for (PetscInt a = 0; a < nen; ++a)
      for (PetscInt i = 0; i < dim; ++i) x[m->bulk.cellNodeOffset(c, a) + i] = xc[a * dim + i];
  }
  PetscCall(VecRestoreArray(local, &x));
  PetscCall(DMCreateGlobalVector(m->dm, &coords));
  PetscCall(DMLocalToGlobal(m->dm, local, INSERT_VALUES, coords));
  PetscCall(DMRestoreLocalVector(m->dm, &local));
  PetscCall(VecSetBlockSize(coords, dim));
  MatNullSpace modes;
  PetscCall(MatNullSpaceCreateRigidBody(coords, &modes));
  PetscCall(MatSetNearNullSpace(K, modes));
  PetscCall(MatNullSpaceDestroy(&modes));
  PetscCall(VecDestroy(&coords));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode StaticSolverCreate(MPI_Comm comm, KSP *ksp) {
  PC pc;
  PetscFunctionBeginUser;
  PetscCall(KSPCreate(comm, ksp));
  PetscCall(KSPSetOptionsPrefix(*ksp, "geostatic_"));
  PetscCall(KSPSetType(*ksp, KSPCG));
  PetscCall(KSPGetPC(*ksp, &pc));
  PetscCall(PCSetType(pc, PCGAMG));
  // The true residual |f - K u| / |f|, not the preconditioned one, so that the tolerance means
  // the same with any preconditioner and partition.
  PetscCall(KSPSetNormType(*ksp, KSP_NORM_UNPRECONDITIONED));
  PetscCall(KSPSetTolerances(*ksp, 1e-12, 0.0, PETSC_DEFAULT, 10000));
  // A bad -geostatic_ksp_* / -geostatic_pc_* value stops with one line, not PETSc's traceback.
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  const PetscErrorCode bad = KSPSetFromOptions(*ksp);
  PetscCall(PetscPopErrorHandler());
  if (bad) {
    const char *text;
    char       *specific;
    PetscCall(PetscErrorMessage(bad, &text, &specific));
    SETERRQ(comm, PETSC_ERR_USER_INPUT, "-geostatic_ksp_* / -geostatic_pc_*: %s; allowed: a KSP and PC PETSc provides (see -help)", specific ? specific : text);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode StaticEquilibriumSolve(Elastodynamics *m, KSP ksp, Vec free, Vec u, StaticSolveReport *report) {
  Mat K;
  Vec f;
  PetscFunctionBeginUser;
  PetscCall(assembleStiffness(m, &K));
  PetscCall(setRigidBodyModes(m, K));
  // f: the constant loads and the interface tractions at zero jump (sigma_N0); evaluating the
  // interface forces at u = 0 is a zero increment, so it leaves the pairs' states as they are.
  PetscCall(VecDuplicate(u, &f));
  PetscCall(VecZeroEntries(u));
  PetscCall(VecZeroEntries(f));
  for (auto &iface : m->interfaces) PetscCall(iface.AddForces(u, f, NAN));
  PetscCall(VecAXPY(f, 1.0, m->bc.constant_force));
  // Held dofs: identity rows and columns, zero load (they stay at zero).
  {
    PetscInt           n, lo;
    const PetscScalar *mk;
    std::vector<PetscInt> held;
    PetscCall(VecGetLocalSize(free, &n));
    PetscCall(VecGetOwnershipRange(free, &lo, nullptr));
    PetscCall(VecGetArrayRead(free, &mk));
    for (PetscInt i = 0; i < n; ++i)
      if (PetscRealPart(mk[i]) == 0) held.push_back(lo + i);
    PetscCall(VecRestoreArrayRead(free, &mk));
    PetscCall(MatZeroRowsColumns(K, (PetscInt)held.size(), held.data(), 1.0, nullptr, nullptr));
    PetscCall(VecPointwiseMult(f, f, free));
  }
  PetscCall(KSPSetOperators(ksp, K, K));
  PetscCall(KSPSolve(ksp, f, u));
  PetscCall(KSPGetIterationNumber(ksp, &report->iterations));
  PetscCall(KSPGetConvergedReason(ksp, &report->reason));
  KSPType ktype;
  PCType  ptype;
  PC      pc;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(KSPGetType(ksp, &ktype));
  PetscCall(PCGetType(pc, &ptype));
  std::snprintf(report->method, sizeof report->method, "KSP %s + %s", ktype, ptype);
  PetscCall(VecDestroy(&f));
  PetscCall(MatDestroy(&K));
  PetscFunctionReturn(0);
}

} // namespace slipwave::problem
