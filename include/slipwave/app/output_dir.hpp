// The output folder (-output_dir), checked before the heavy work (mesh, geostatic stage), so a
// folder that cannot hold the output stops the run at once with one line, not after the set-up.
// A folder holding an earlier run's files is refused: the new files would sit beside the old
// ones (a shorter run leaves the old frames, stations and checkpoint in place) with nothing
// said. -output_overwrite deletes those files first, and only those (a run's file names:
// OutputDirRunFiles), never anything else in the folder. A restart may continue in the folder of
// its checkpoint (that is the series it extends).
#pragma once
#include <petscsys.h>

#include <string>
#include <vector>

namespace slipwave::app {

struct OutputDirRequest {
  std::string dir;              // -output_dir
  bool        overwrite = false; // -output_overwrite
  bool        create    = true;  // false for a dry run: check only, write nothing
  std::string restart;          // -restart file, or empty
};

// Collective. Checks (rank 0) and prepares the folder; a failure is one PETSC_ERR_USER_INPUT
// line naming -output_dir, the value and what is allowed.
PetscErrorCode OutputDirPrepare(MPI_Comm comm, const OutputDirRequest &request);

// The names of the earlier run's files in dir (relative, sorted); empty when there are none.
std::vector<std::string> OutputDirRunFiles(const std::string &dir);

} // namespace slipwave::app
