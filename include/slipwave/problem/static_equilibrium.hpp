// Static equilibrium of the model as a linear problem: K u = f with K the bulk stiffness plus
// every interface pair as its stick spring A (E n n + G (I - n n)), f the constant loads plus
// the interface tractions at u = 0 (sigma_N0), and the dofs where `free` is 0 held at zero.
// Solved with a PETSc KSP (options prefix -geostatic_; CG with GAMG and the rigid-body modes
// as near-null space by default, relative residual 1e-12), so the result is the same on any
// number of ranks up to the solver tolerance, with no relaxation tolerance in between.
#pragma once
#include <petscksp.h>

#include "slipwave/problem/elastodynamics.hpp"

namespace slipwave::problem {

struct StaticSolveReport {
  PetscInt           iterations = 0;
  KSPConvergedReason reason     = KSP_CONVERGED_ITERATING;
  char               method[64] = ""; // KSP and PC type, for the report
};

// The solver, configured from the options (-geostatic_ksp_*, -geostatic_pc_*); created while
// the options are read, so that a misspelled one stops the run before any work.
PetscErrorCode StaticSolverCreate(MPI_Comm comm, KSP *ksp);
// u: global displacement (output). free: 1 on the dofs that move, 0 on the held ones.
PetscErrorCode StaticEquilibriumSolve(Elastodynamics *model, KSP ksp, Vec free, Vec u, StaticSolveReport *report);

} // namespace slipwave::problem
