#include "slipwave/core/options_check.hpp"

#include <cstring>
#include <string>

namespace slipwave::core {
namespace {

// Options that PETSc reads only in PetscFinalize or that are pure reporting requests.
const char *const kReadAtExit[] = {"options_left", "options_view", "log_view", "log_summary", "memory_view",
                                   "malloc_dump", "malloc_view", "objects_dump", "help", "options_monitor", "fp_trap"};

bool readAtExit(const char *name) {
  for (const char *known : kReadAtExit)
    if (std::strcmp(name, known) == 0 || std::strncmp(name, "log_view", 8) == 0) return true;
  return false;
}

} // namespace

PetscErrorCode OptionsErrorIfUnused(MPI_Comm comm) {
  PetscInt n = 0;
  char   **names = nullptr, **values = nullptr;
  PetscBool help = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(nullptr, &help));
  if (help) PetscFunctionReturn(0); // -help lists the options; nothing runs.
  PetscCall(PetscOptionsLeftGet(nullptr, &n, &names, &values));
  std::string unused;
  for (PetscInt i = 0; i < n; ++i) {
    if (readAtExit(names[i])) continue;
    if (!unused.empty()) unused += ", ";
    unused += std::string("-") + names[i];
    if (values[i]) unused += std::string(" ") + values[i];
  }
  PetscCall(PetscOptionsLeftRestore(nullptr, &n, &names, &values));
  PetscCheck(unused.empty(), comm, PETSC_ERR_USER_INPUT,
             "unknown or unused option(s): %s; none of them is read by this run (misspelled, or not valid for this scene); run with -help to list the options",
             unused.c_str());
  PetscFunctionReturn(0);
}

} // namespace slipwave::core
