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
#pragma once
#include <string>

namespace slipwave::core {

std::string OptionFilesCheck(int argc, const char *const *argv);

// For main, before PetscInitialize: false (after printing "<program>: error: <problem>" once,
// from the launcher's rank 0) when OptionFilesCheck finds a problem.
bool OptionFilesAcceptable(int argc, const char *const *argv, const char *program);

} // namespace slipwave::core
