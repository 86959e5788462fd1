// What the bulk operators need of a region's material: its density and the Lame pair of its
// element moduli (unrelaxed ones in a region with constant-Q damping), and whether it
// deforms: a rigid region (problem/rigid_bodies.hpp) keeps its stiffness for static solves
// but has no vibration of its own, so the stable-step bounds leave it out; and where its
// elements take the volumetric strain (fem/element_kernels.hpp; degree 1 only).
#pragma once
#include "slipwave/fem/element_kernels.hpp"
#include "slipwave/physics/elastic_material.hpp"

namespace slipwave::fem {

struct RegionMaterial {
  double                  rho;
  physics::LameParameters lame;
  bool                    deforms = true;
  Dilatation              dilatation = Dilatation::Gauss;
};

} // namespace slipwave::fem
