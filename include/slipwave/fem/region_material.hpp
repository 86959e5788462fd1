// What the bulk operators need of a region's material: its density and the Lame pair of its
// element moduli (unrelaxed ones in a region with constant-Q damping), and whether it
// deforms: a rigid region (problem/rigid_bodies.hpp) keeps its stiffness for static solves
// but has no vibration of its own, so the stable-step bounds leave it out.
#pragma once
#include "slipwave/physics/elastic_material.hpp"

namespace slipwave::fem {

struct RegionMaterial {
  double                  rho;
  physics::LameParameters lame;
  bool                    deforms = true;
};

} // namespace slipwave::fem
