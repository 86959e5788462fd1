// Option files are checked before PetscInitialize reads them: PETSc stops on a missing,
// malformed or binary file with a multi-line traceback, and it acts on its debugger and
// display options (which start a program named in the file) while it initialises, before
// any check of ours could run. OptionFilesCheck reads the same files PETSc will read
// (-options_file and -options_file_yaml on the command line, the files they include, and the
// .petscrc files unless -skip_petscrc) and returns the problem as one line, or "" when PETSc
// may read them.
//
// Options that run programs, and viewers and logs that write a file named in the option, are
// refused in files but allowed on the command line: whoever types the command chooses the
// program and the file, while a scene file may come from someone else and is read as data.
//
// The check also notes where each option of a file is given (file and line): an option given
// twice in one file is an error naming both lines; messages about an option name its file and
// line (OptionOrigin); input files named in an option file are found from that file's folder
// (OptionFilePathsResolve), so a scene runs from any working folder.
#pragma once
#include <string>

namespace slipwave::core {

std::string OptionFilesCheck(int argc, const char *const *argv);

// For main, before PetscInitialize: false (after printing "<program>: error: <problem>" once,
// from the launcher's rank 0) when OptionFilesCheck finds a problem.
bool OptionFilesAcceptable(int argc, const char *const *argv, const char *program);

// After PetscInitialize: "file:line" of the option file that gives -option its current value,
// or "" (given on the command line, or nowhere).
std::string OptionOrigin(const std::string &option);

// After PetscInitialize: every input-file option (names ending in _file or _record, -restart)
// whose relative path comes from an option file in another folder becomes that folder's
// path, normalised ("../records/x.csv" in config/scenes/default.yaml: config/records/x.csv). Paths on the command line stay relative to the
// working folder. Returns a PETSc error code.
int OptionFilePathsResolve(int argc, const char *const *argv);

} // namespace slipwave::core
