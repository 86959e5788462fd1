// The options that define a run's scene (mesh, regions, materials, boundaries, input,
// interfaces, damping, time step, stations), as a checkpoint records them: a restart with
// another scene would continue a state that belongs to different physics, so it is refused,
// naming what differs. Options that only steer the run (output, duration, progress, logging,
// checkpoints) may change between the two runs.
#pragma once
#include <petscsys.h>

#include <string>

namespace slipwave::app {

// This run's scene options, one "-name value" per line, sorted by name.
PetscErrorCode SceneOptionsText(std::string *text);

// What differs between two texts of SceneOptionsText, as "-name a there, b here; ..." (at most
// a few entries), or "" when they are the same.
std::string SceneOptionsDifference(const std::string &there, const std::string &here);

} // namespace slipwave::app
