// Cavitation of the pore water (docs/saturated-soil.md, Cavitation): water cannot hold an
// absolute pressure below its cavitation limit (about its vapour pressure, -100 kPa gauge at
// atmospheric pressure on the water table). The model is a pressure floor at each pressure
// node: where the storage equation would take the pressure below the limit, it is held at
// the limit and the pore volume the fluid does not follow opens as a cavity (vapour); the
// cavity closes first when the pore space shrinks again, so the pressure rises above the
// limit only once the cavity has closed. In the lumped storage equation of one step,
//   S (p_{n+1} - p*) = -[alpha Q (u_{n+1} - u_n) - h q] + (V_{n+1} - V_n),   V >= 0,
//   p_{n+1} >= floor,   V_{n+1} (p_{n+1} - floor) = 0,
// solved per node in closed form. Plain doubles, no PETSc.
#pragma once

namespace slipwave::physics {

struct CavitatedPressure {
  double p;      // the node's pressure after the step [Pa]
  double cavity; // the cavity's volume after the step, V_{n+1} >= 0 [m^3; m^2 per m in 2D]
};

// p_closed: the pressure the step gives the node with its cavity closed, that is with the
// cavity's volume V_n given back to the fluid as expansion, p* - S^{-1}[alpha Q du - h q + V_n];
// floor: the limit in the same measure as p (the excess over the hydrostatic pressure:
// limit - p_h); storage: the node's lumped S = integral of N / M (> 0).
inline CavitatedPressure cavitationFloor(double p_closed, double floor, double storage) {
  if (p_closed >= floor) return {p_closed, 0.0};
  return {floor, storage * (floor - p_closed)};
}

// Work the fluid pressure does on a node's cavity over one step, -(p_n + p_{n+1})/2 (V_{n+1} - V_n)
// (trapezoid: the pressure is linear in the step): positive while a cavity opens under
// suction, given back as it closes. It is the term by which the fluid's shadow storage energy
// differs from the cavity-free balance (docs/saturated-soil.md, Energy budget).
inline double cavityWork(double p_n, double p_next, double cavity_n, double cavity_next) { return -0.5 * (p_n + p_next) * (cavity_next - cavity_n); }

} // namespace slipwave::physics
