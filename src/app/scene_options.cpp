#include "slipwave/app/scene_options.hpp"

#include <cctype>
#include <map>
#include <sstream>

namespace slipwave::app {
namespace {

// Options that steer the run but not its physics or mesh (names without the dash), and
// dm_plex_gmsh_use_regions, which the mesh builder sets itself for every Gmsh file
// (meshing/mesh_builder.cpp): the checkpoint's run had set it, the restart compares before its
// mesh is read.
bool steersOnly(const std::string &name) {
  static const char *const exact[] = {"output_dir", "output_overwrite", "output_interval", "output_fields", "progress_interval", "checkpoint_interval", "energy_interval",
                                      "restart",    "ts_max_time",      "ts_max_steps",    "dry_run",       "energy_growth_limit", "help",
                                      "options_file", "no_signal_handler", "info",        "version",      "dm_plex_gmsh_use_regions"};
  for (const char *e : exact)
    if (name == e) return true;
  static const char *const prefixes[] = {"log", "malloc", "options_", "on_error", "memory_", "fp_trap", "check"};
  for (const char *p : prefixes)
    if (name.rfind(p, 0) == 0) return true;
  // Monitors and viewers (-ts_monitor, -geostatic_ksp_monitor, -ts_view, ...) only print.
  return name.find("monitor") != std::string::npos || name.find("_view") != std::string::npos;
}

std::map<std::string, std::string> parse(const std::string &text) {
  std::map<std::string, std::string> options;
  std::istringstream                 lines(text);
  for (std::string line; std::getline(lines, line);) {
    const size_t space = line.find(' ');
    options[line.substr(0, space)] = space == std::string::npos ? "" : line.substr(space + 1);
  }
  return options;
}

} // namespace

PetscErrorCode SceneOptionsText(std::string *text) {
  char *all = nullptr;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetAll(nullptr, &all));
  std::map<std::string, std::string> options;
  std::istringstream                 tokens(all ? all : "");
  std::string                        token, name;
  // A name is "-" and a letter; a following token that is not a name is its value (a
  // negative number starts with "-" and a digit or a dot).
  auto isName = [](const std::string &t) { return t.size() > 1 && t[0] == '-' && std::isalpha((unsigned char)t[1]); };
  while (tokens >> token) {
    if (isName(token)) {
      name = token.substr(1);
      if (!steersOnly(name)) options[name] = "";
    } else if (!name.empty() && !steersOnly(name)) {
      options[name] = token;
      name.clear();
    }
  }
  PetscCall(PetscFree(all));
  text->clear();
  for (const auto &[key, value] : options) *text += "-" + key + (value.empty() ? "" : " " + value) + "\n";
  PetscFunctionReturn(0);
}

std::string SceneOptionsDifference(const std::string &there, const std::string &here) {
  const auto  a = parse(there), b = parse(here);
  std::map<std::string, std::pair<std::string, std::string>> differ;
  for (const auto &[name, value] : a)
    if (!b.count(name) || b.at(name) != value) differ[name] = {value.empty() ? "given" : value, b.count(name) ? (b.at(name).empty() ? "given" : b.at(name)) : "not given"};
  for (const auto &[name, value] : b)
    if (!a.count(name)) differ[name] = {"not given", value.empty() ? "given" : value};
  std::string text;
  int         shown = 0;
  for (const auto &[name, values] : differ) {
    if (shown++ == 3) {
      text += "; and " + std::to_string(differ.size() - 3) + " more";
      break;
    }
    text += (text.empty() ? "" : "; ") + name + " " + values.first + " there, " + values.second + " here";
  }
  return text;
}

} // namespace slipwave::app
