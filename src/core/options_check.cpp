#include "slipwave/core/options_check.hpp"

#include <cctype>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "slipwave/core/nearest_name.hpp"
#include "slipwave/core/option_rules.hpp"

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

// Options users type often that the rule table (option_rules.cpp) does not list: PETSc's own
// run options and slipwave's choices and flags.
const char *const kCommonOptions[] = {"-ts_monitor", "-ts_view", "-log_view", "-options_left", "-options_view", "-help", "-version", "-info", "-malloc_debug",
                                      "-output_dir", "-output_fields", "-output_overwrite", "-dry_run", "-constrain_components", "-geostatic_stage",
                                      "-geostatic_method", "-station_side", "-petscpartitioner_type", "-*_stf", "-*_record_units", "-*_record_format",
                                      "-*_record_motion", "-*_baseline_correction", "-input_wave", "-input_boundary", "-input_method", "-bc_*_type",
                                      "-bc_*_components", "-bc_*_fluid", "-material_*_model", "-material_*_saturated", "-material_*_backbone",
                                      "-material_*_backbone_file", "-material_*_E", "-material_*_reference_strain", "-interface_*_faces", "-void_regions"};

std::vector<std::string> listValue(const char *option) {
  char      value[4096] = "";
  PetscBool set         = PETSC_FALSE;
  std::vector<std::string> out;
  if (PetscOptionsGetString(nullptr, nullptr, option, value, sizeof value, &set) || !set) return out;
  std::istringstream in(value);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

// The names a misspelled option may have meant: the rule table's and the common ones, their
// "*" replaced by this run's regions, interfaces, point forces, boundaries and history
// prefixes.
std::vector<std::string> knownNames() {
  std::vector<std::string> words = {"input", "drm", "body_force", "structure_load"};
  for (const char *b : {"bottom", "top", "left", "right", "front", "back"}) words.push_back(b), words.push_back(std::string("bc_") + b);
  for (const char *list : {"-regions", "-interfaces"})
    for (const std::string &name : listValue(list)) words.push_back(name);
  for (const std::string &name : listValue("-point_forces")) words.push_back("point_force_" + name);
  std::vector<std::string> patterns = OptionRulePatterns(), names;
  patterns.insert(patterns.end(), std::begin(kCommonOptions), std::end(kCommonOptions));
  for (const std::string &p : patterns) {
    const size_t star = p.find('*');
    if (star == std::string::npos) names.push_back(p);
    else
      for (const std::string &w : words) names.push_back(p.substr(0, star) + w + p.substr(star + 1));
  }
  return names;
}

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
    std::vector<std::string> known = knownNames(); // and the options given and read
    char                    *given_all = nullptr;
    PetscCall(PetscOptionsGetAll(nullptr, &given_all));
    std::istringstream tokens(given_all ? given_all : "");
    for (std::string t; tokens >> t;) {
      PetscBool was_used = PETSC_FALSE;
      if (t.size() > 1 && t[0] == '-' && std::isalpha((unsigned char)t[1]) && !PetscOptionsUsed(nullptr, t.c_str(), &was_used) && was_used) known.push_back(t);
    }
    PetscCall(PetscFree(given_all));
    const std::string nearest = NearestName(std::string("-") + names[i], known);
    if (!nearest.empty()) unused += " (did you mean " + nearest + "?)";
  }
  PetscCall(PetscOptionsLeftRestore(nullptr, &n, &names, &values));
  PetscCheck(unused.empty(), comm, PETSC_ERR_USER_INPUT,
             "unknown or unused option(s): %s; none of them is read by this run (misspelled, or not valid for this scene); run with -help to list the options",
             unused.c_str());
  PetscFunctionReturn(0);
}

} // namespace slipwave::core
