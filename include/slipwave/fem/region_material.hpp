// What the bulk operators need of a region's material: its density and the Lame pair of its
// element moduli (unrelaxed ones in a region with constant-Q damping).
#pragma once
#include "slipwave/physics/elastic_material.hpp"

namespace slipwave::fem {

struct RegionMaterial {
  double                  rho;
  physics::LameParameters lame;
};

} // namespace slipwave::fem
