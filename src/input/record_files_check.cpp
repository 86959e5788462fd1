#include "slipwave/input/record_files_check.hpp"

#include <strings.h>

#include <map>
#include <string>

#include "slipwave/core/options_check.hpp"
#include "slipwave/input/time_function.hpp"

namespace slipwave::input {
namespace {

// Index of the option's value among choices (case-insensitive, as PETSc's choice options):
// fallback when it is not given, -2 when it is none of them (the module's reader says so).
int choiceIndex(const std::map<std::string, std::string> &given, const std::string &name, const char *const *choices, int n, int fallback) {
  const auto it = given.find(name);
  if (it == given.end()) return fallback;
  for (int k = 0; k < n; ++k)
    if (strcasecmp(it->second.c_str(), choices[k]) == 0) return k;
  return -2;
}

// Whether the history of this prefix is a load factor (HistoryRole::Load in the modules that
// read it: input/point_force, body_force, structure_load, and a bc_<b>_ side of type
// traction) rather than a velocity (input_, drm_, a bc_<b>_ side of type velocity).
bool isLoad(const std::map<std::string, std::string> &given, const std::string &prefix) {
  if (prefix == "body_force_" || prefix == "structure_load_" || prefix.rfind("point_force_", 0) == 0) return true;
  const auto type = given.find(prefix + "type");
  return prefix.rfind("bc_", 0) == 0 && type != given.end() && strcasecmp(type->second.c_str(), "traction") == 0;
}

bool falseWord(const std::string &v) {
  for (const char *w : {"false", "no", "off", "0"})
    if (strcasecmp(v.c_str(), w) == 0) return true;
  return false;
}

} // namespace

PetscErrorCode RecordFilesCheck(MPI_Comm comm) {
  std::map<std::string, std::string> given;
  PetscFunctionBeginUser;
  PetscCall(core::OptionsNotYetRead(&given));
  for (const auto &[name, value] : given) {
    if (name.size() < 4 || name.compare(name.size() - 3, 3, "stf") != 0 || strcasecmp(value.c_str(), "record") != 0) continue;
    const std::string prefix = name.substr(0, name.size() - 3);
    const auto        file   = given.find(prefix + "record");
    if (file == given.end() || file->second.empty()) continue; // the module says what is missing
    RecordFile f{file->second, isLoad(given, prefix)};
    f.format = choiceIndex(given, prefix + "record_format", kRecordFormats, 2, -1);
    f.units  = choiceIndex(given, prefix + "record_units", kRecordUnits, kRecordUnitCount, 0);
    if (f.format == -2 || f.units == -2) continue;
    const auto baseline = given.find(prefix + "baseline_correction");
    f.baseline = !f.load && !(baseline != given.end() && falseWord(baseline->second));
    GroundMotionRecord record;
    PetscCall(RecordFileRead(comm, prefix, f, &record, nullptr));
  }
  PetscFunctionReturn(0);
}

} // namespace slipwave::input
