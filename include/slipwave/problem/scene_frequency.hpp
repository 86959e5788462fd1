// The highest frequency any time history of the scene puts into the model: the incident wave
// (absorbing-base input or DRM), prescribed-velocity boundaries and every timed load (point
// forces, tractions, the body force, structure loads), each by TimeFunction::topFrequency
// (a wavelet's 1 % spectral criterion, a record's spectral 1 % limit). The mesh must carry
// waves up to it, so the run report's points per wavelength and its under-resolution warning
// are taken at it, whichever source it comes from.
#pragma once
#include <string>

#include "slipwave/problem/elastodynamics.hpp"

namespace slipwave::problem {

struct SceneFrequency {
  double      hz = 0;   // 0: no time history (a static or free-vibration scene)
  std::string source;   // what sets it: "the input wave", "point force src", ...
};

SceneFrequency SceneTopFrequency(const Elastodynamics &model);

// GLL nodes per S wavelength at frequency f in region r, p vs / (f h) with the region's
// largest element h (its corners' shortest edge or diagonal; p = 1: the cell, and the count is
// the usual points per wavelength): on a graded mesh the coarse cells, not the fine ones,
// limit what the region carries.
double RegionNodesPerWavelength(const Elastodynamics &model, PetscInt region, double f);

} // namespace slipwave::problem
