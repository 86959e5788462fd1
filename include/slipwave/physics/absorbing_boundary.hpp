// Lysmer-Kuhlemeyer viscous boundary: a dashpot per boundary node that absorbs plane
// waves hitting the boundary at normal incidence, and the force that injects a
// vertically incident plane wave through that same boundary.
#pragma once
#include "slipwave/physics/elastic_material.hpp"

namespace slipwave::physics {

// C = area (rho vp n(x)n + rho vs (I - n(x)n)), dim x dim row-major. n: unit normal
// (either sense: C is even in n); area: the node's lumped face weight.
void lysmerDashpot(int dim, const double *n, double area, const ElasticMaterial &m, double *C);

// Traction [Pa] that, together with the dashpot, makes the boundary transmit an up-going
// plane wave of particle velocity v_in along the unit direction d: t = 2 rho c v_in d with
// c = vs for S waves (d tangential), vp for P waves (d normal). Derivation: below the
// boundary the field is the incident wave plus the outgoing one, whose tractions are
// rho c v_in and -rho c v_out; with v = v_in + v_out the traction on the model is
// rho c (v_in - v_out) = 2 rho c v_in - rho c v, and the dashpot supplies -rho c v.
void incidentWaveTraction(int dim, const double *d, double rho, double c, double v_in, double *t);

} // namespace slipwave::physics
