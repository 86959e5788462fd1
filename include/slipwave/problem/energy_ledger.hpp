// The energy budget of a run. Central difference conserves, for a linear system at constant
// step h, the shadow energy W_{n+1/2} = ½ v_{n+1/2}ᵀ M v_{n+1/2} + ½ u_nᵀ K u_{n+1}, and
//   W_{n+1/2} − W_{n−1/2} = h v_n · f_n,   f_n = M a_n + K u_n (all non-internal forces).
// The ledger books h v_n·f_n term by term (incident-wave input, gravity and tractions,
// reactions of held dofs, interface forces, minus dashpot absorption, Rayleigh damping, the
// work of the constant-Q memory forces and the interfaces' contact dashpots, the hysteretic
// dissipation), so
//   balance error = W_{n+1/2} − W_{1/2} − Σ booked work
// is round-off for a consistent discretisation, and a growth of it flags an instability.
// The fourth-order integrator (-ts_cd_order 4) is the same kick-drift-kick with the
// acceleration a + c: the identity holds with f_n = M (a_n + c_n) + K u_n, so the work of its
// correction force M c is booked too (integrator_correction). In a closed system that work is
// the change of (h^2/24) (K u_{n+1})^T M^{-1} K u_n, which bounds it: the scheme conserves
// W_{n+1/2} minus that term (its modified energy), and the ledger closes with it to round-off.
#pragma once
#include <petscts.h>

#include <vector>

#include "slipwave/problem/elastodynamics.hpp"

namespace slipwave::problem {

struct EnergyLedger {
  double kinetic = 0;   // ½ v_nᵀ M v_n
  double strain  = 0;   // ½ u_nᵀ K u_n
  double input   = 0;   // cumulative work of the incident-wave traction
  double external = 0;  // cumulative work of gravity, tractions, point and body forces
  double external_gross = 0; // cumulative |work| of those per step: what a load that reverses
                             // (a Ricker force) put in, though its net work falls back
  double reactions = 0; // cumulative work of held dofs (prescribed velocity)
  double absorbed  = 0; // cumulative energy taken by absorbing dashpots
  double damped    = 0; // cumulative Rayleigh dissipation
  double anelastic = 0; // cumulative work done against the constant-Q memory forces (energy
                        // the mechanisms hold or dissipated)
  double interface_work = 0; // cumulative work of the interface forces on the bulk (minus what
                             // the interfaces store and dissipate)
  double contact_damped = 0; // cumulative energy taken by the interfaces' contact dashpots
  // Hysteretic regions (medium/hysteresis.hpp): the bulk applies the linear K and the
  // relaxation force f_hy gives back what the soil does not carry. Its work is booked every
  // step like the constant-Q forces'. The internal work of the soil's own stress is the change
  // of its stored energy plus its dissipation D, and that of K u the change of 1/2 u.K u, so
  // the work done against f_hy is D - E_r, with E_r = 1/2 u.K u - the soil's stored energy
  // (the relaxation energy). At an evaluation E_r leaves the stored energies (strain and
  // shadow are then the soil's own) and D = hysteretic_work + E_r is booked.
  double hysteretic_work = 0;        // cumulative work done against f_hy
  double hysteretic_dissipated = 0;  // D = hysteretic_work + E_r, at the last evaluation
  double integrator_correction = 0;  // cumulative work of the fourth-order correction force M c (zero at order 2)
  // Saturated scenes (porous/pore_pressure.hpp): the pore pressure's work on the skeleton is
  // internal; the fluid's shadow storage energy F_{n+1/2} joins the stored energy.
  bool   fluid = false;
  double fluid_stored = 0;   // F_{n+1/2} ≈ ½ pᵀ S p, S = ∫N/M
  double darcy = 0;          // cumulative Darcy (viscous) dissipation, h ½ p_n H (p_n + p_{n-1})
  double fluid_inflow = 0;   // cumulative work of the prescribed boundary inflow, h p_n q
  double cavitation = 0;     // cumulative work of the fluid on its cavities, -(p_n + p_{n+1})/2 (V_{n+1} - V_n) (physics/cavitation.hpp)
  double shadow    = 0; // W_{n+1/2}
  double shadow_start = 0;
  double balance_error = 0;
  double scale = 0;     // largest energy magnitude seen, to make the error relative
  double h_prev = 0;    // the step before the current one
  bool   started = false;
  bool   evaluated = false; // the last update evaluated the stored energies (see below)
  // The dashpot blocks C of model->absorbing_nodes, bs x bs each, zero in the rows and columns
  // of held dofs: contiguous, so the per-step absorbed power does not gather them from the
  // whole-mesh vector of blocks (built at the first update of a run).
  std::vector<double> absorbing_free_blocks;

  double relativeError() const { return scale > 0 ? balance_error / scale : 0.0; }
};

// Call once at t_0 (after the initial acceleration) and after every step, with the step size
// h that the next step will use. Work is booked with the mean of the steps before and after
// t_n, which keeps the identity to O(Δh) when the step changes. The work is booked at every
// call (cheap: boundary sums where the scene allows); the stored energies (kinetic, strain,
// shadow) and the balance only when `evaluate` (and at the first call): a sweep of every dof
// that costs about a third of a step, so runs evaluate every -energy_interval steps. The
// balance at an evaluation is the same as if every step had been evaluated.
PetscErrorCode EnergyLedgerUpdate(Elastodynamics *model, TS ts, PetscReal h, bool evaluate, EnergyLedger *ledger);

} // namespace slipwave::problem
