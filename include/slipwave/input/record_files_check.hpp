// Before the mesh is built: every record file an option names (-<prefix>stf record with
// -<prefix>record FILE; prefixes input_, drm_, bc_<b>_, point_force_<n>_, body_force_,
// structure_load_) is parsed in full with the options that say how (format, units, baseline
// correction), by the same reader TimeFunction::Read uses later (RecordFileRead), so a
// malformed record stops the run in a second instead of after the mesh and the operators. The
// samples are not kept: the modules read the file again when they read their options (a
// record is a few thousand lines).
// The options are looked at without marking them read (core::OptionsNotYetRead).
#pragma once
#include <petscsys.h>

namespace slipwave::input {

PetscErrorCode RecordFilesCheck(MPI_Comm comm);

} // namespace slipwave::input
