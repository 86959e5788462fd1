// A load that follows a time history: a fixed nodal force pattern F (global displacement
// layout) times a dimensionless factor s(t) from a TimeFunction (HistoryRole::Load):
// f(t) = s(t) F. Point forces, tractions and body forces with -<prefix>stf become timed
// loads; without a history they are constant loads (BoundaryConditions::constant_force) and
// take part in the geostatic stage. Timed loads act only in the dynamic stage. Their work
// is the ledger's external work (they are part of f_external).
#pragma once
#include <petscvec.h>

#include <string>
#include <vector>

#include "slipwave/input/time_function.hpp"

namespace slipwave::input {

struct TimedLoad {
  std::string  name;            // for the run report: "point force src", "traction top"
  Vec          pattern = nullptr; // F [N]
  TimeFunction history;         // s(t) [-]
};

// f += sum over the loads of s(t) F.
PetscErrorCode TimedLoadsAdd(const std::vector<TimedLoad> &loads, double t, Vec f);
PetscErrorCode TimedLoadsDestroy(std::vector<TimedLoad> *loads);
// The pattern goes to `constant` when the history is inactive, else into a new timed load.
// "(a, b[, c])" with %g, for the run report's load lines.
std::string LoadVectorText(const double *v, PetscInt n);
PetscErrorCode TimedLoadAdopt(const std::string &name, Vec pattern, TimeFunction history, Vec constant, std::vector<TimedLoad> *loads);

} // namespace slipwave::input
