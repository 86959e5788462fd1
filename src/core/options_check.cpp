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

// Options renamed for the consistent prefix scheme (see docs/options.md): the old name is
// accepted, and reported, until the next release.
struct RenamedOption {
  const char *old_name, *new_name;
};
const RenamedOption kRenamed[] = {{"-stations_file", "-station_file"}};

} // namespace

PetscErrorCode OptionsApplyRenames(MPI_Comm comm) {
  PetscFunctionBeginUser;
  for (const RenamedOption &r : kRenamed) {
    const char *old_value = nullptr, *new_value = nullptr;
    PetscBool   old_set = PETSC_FALSE, new_set = PETSC_FALSE;
    PetscCall(PetscOptionsFindPair(nullptr, nullptr, r.old_name, &old_value, &old_set));
    if (!old_set) continue;
    PetscCall(PetscOptionsFindPair(nullptr, nullptr, r.new_name, &new_value, &new_set));
    PetscCheck(!new_set, comm, PETSC_ERR_USER_INPUT, "%s and %s are both given (%s is the old name of %s); allowed: only %s", r.old_name, r.new_name, r.old_name,
               r.new_name, r.new_name);
    const std::string value = old_value ? old_value : "";
    PetscCall(PetscOptionsSetValue(nullptr, r.new_name, old_value ? value.c_str() : nullptr));
    PetscCall(PetscOptionsClearValue(nullptr, r.old_name));
    PetscCall(PetscPrintf(comm, "%s is renamed %s; the old name is accepted until the next release\n", r.old_name, r.new_name));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode OptionsNotYetRead(std::map<std::string, std::string> *given) {
  PetscInt n = 0;
  char   **names = nullptr, **values = nullptr;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsLeftGet(nullptr, &n, &names, &values));
  for (PetscInt i = 0; i < n; ++i) (*given)[names[i]] = values[i] ? values[i] : "";
  PetscCall(PetscOptionsLeftRestore(nullptr, &n, &names, &values));
  PetscFunctionReturn(0);
}

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
