// One validation layer over every option given: before any module reads its options, each
// value in the options database is checked against the rule for its name (src/core/
// option_rules.cpp holds the table; `-help` prints it). A rule gives the kind (number,
// integer, list, name, file, choice), the number of list entries and the physically
// plausible range, so inf, nan, 1e308, a third value of a two-value list, a station name
// that would leave the output folder or a directory given as a file stop the run at once
// with one line naming the option, the value and what is allowed. The modules keep their
// own finer checks (vp >= sqrt(2) vs, ...); the table catches what is absurd for any scene.
// A value that no rule covers is still refused when it is a non-finite number.
#pragma once
#include <petscsys.h>

#include <string>
#include <vector>

namespace slipwave::core {

// Stops with PETSC_ERR_USER_INPUT at the first option whose value breaks its rule.
PetscErrorCode OptionsValidate(MPI_Comm comm);

// The lists whose length is the space dimension (vectors, box corners, region boxes): once
// the mesh's dimension is known, a third value in 2D stops the run instead of being ignored.
// box_mesh: the mesh is the built-in box (false: the -mesh_box_* options are not checked).
PetscErrorCode OptionsValidateForDimension(MPI_Comm comm, PetscInt dim, bool box_mesh);

// The option names the table covers, as fnmatch patterns ("-material_*_rho": * is a region,
// interface or boundary name), for suggestions on a misspelled option.
std::vector<std::string> OptionRulePatterns();

// Prints the rule table (option, entries, allowed values) for -help.
PetscErrorCode OptionsPrintRules(MPI_Comm comm);

// True if name may become (part of) a file name: only [A-Za-z0-9_.-], not empty, no
// leading dot, no "..". Names of stations, regions and interfaces go through it.
bool IsSafeFileName(const std::string &name);

// The allowed alphabet of IsSafeFileName, for messages.
extern const char *const kSafeFileNameRule;

} // namespace slipwave::core
