#include "slipwave/input/timed_load.hpp"

#include <cstdio>

namespace slipwave::input {

PetscErrorCode TimedLoadsAdd(const std::vector<TimedLoad> &loads, double t, Vec f) {
  PetscFunctionBeginUser;
  // velocity() is the history's value: the dimensionless factor for HistoryRole::Load.
  for (const TimedLoad &l : loads) PetscCall(VecAXPY(f, l.history.velocity(t), l.pattern));
  PetscFunctionReturn(0);
}

PetscErrorCode TimedLoadsDestroy(std::vector<TimedLoad> *loads) {
  PetscFunctionBeginUser;
  for (TimedLoad &l : *loads) PetscCall(VecDestroy(&l.pattern));
  loads->clear();
  PetscFunctionReturn(0);
}

std::string LoadVectorText(const double *v, PetscInt n) {
  std::string text = "(";
  for (PetscInt i = 0; i < n; ++i) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%s%g", i ? ", " : "", v[i]);
    text += buf;
  }
  return text + ")";
}

PetscErrorCode TimedLoadAdopt(const std::string &name, Vec pattern, TimeFunction history, Vec constant, std::vector<TimedLoad> *loads) {
  PetscFunctionBeginUser;
  if (!history.active()) {
    PetscCall(VecAXPY(constant, 1.0, pattern));
    PetscCall(VecDestroy(&pattern));
    PetscFunctionReturn(0);
  }
  loads->push_back({name, pattern, std::move(history)});
  PetscFunctionReturn(0);
}

} // namespace slipwave::input
