#include "slipwave/core/option_choice.hpp"

#include <string>

namespace slipwave::core {

PetscErrorCode OptionsChoice(PetscOptionItems *PetscOptionsObject, const char *name, const char *help, const char *const *choices, PetscInt n,
                             PetscInt *index, PetscBool *set) {
  char      value[256] = "";
  PetscBool given = PETSC_FALSE, known = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(PetscOptionsObject->options, PetscOptionsObject->prefix, name, value, sizeof value, &given));
  std::string allowed;
  for (PetscInt i = 0; i < n; ++i) {
    PetscBool same = PETSC_FALSE;
    if (given) PetscCall(PetscStrcasecmp(value, choices[i], &same));
    known = (PetscBool)(known || same);
    allowed += (i ? ", " : "") + std::string(choices[i]);
  }
  const char *prefix = PetscOptionsObject->prefix ? PetscOptionsObject->prefix : "";
  PetscCheck(!given || known, PetscOptionsObject->comm, PETSC_ERR_USER_INPUT, "-%s%s = %s; allowed: %s", prefix, name + 1, value, allowed.c_str());
  PetscCall(PetscOptionsEList(name, help, "slipwave", choices, n, choices[*index], index, set));
  PetscFunctionReturn(0);
}

} // namespace slipwave::core
