// The semi-discrete elastodynamic system M a + C v + K u = f(t) on the mesh: lumped mass,
// bulk stiffness (our element loop), boundary conditions and loads, Rayleigh damping.
// ElastodynamicsRHS is the TS right-hand side for the "cd" type: it returns
// a* = M^{-1}(f_ext - K u - beta K v_{n+1/2} + f_anelastic + f_hysteretic) on free dofs and the prescribed acceleration
// on held ones; the nodal part of C (dashpots, alpha M) goes to the TS as damping blocks.
// It is a function of (t, u, v_{n+1/2}) and the committed history (interface pairs, free-field
// columns, constant-Q memory, hysteretic soil), which it advances into trial states only; ElastodynamicsCommit,
// the TS's commit hook, accepts them after each step.
#pragma once
#include <petscts.h>

#include <string>
#include <vector>

#include "slipwave/fem/bulk_operator.hpp"
#include "slipwave/input/boundary_conditions.hpp"
#include "slipwave/interface/interface_assembler.hpp"
#include "slipwave/medium/materials.hpp"
#include "slipwave/meshing/mesh_builder.hpp"
#include "slipwave/physics/rayleigh_damping.hpp"
#include "slipwave/problem/nodal_acceleration.hpp"

namespace slipwave::input {
struct FreeField;  // input/free_field.hpp
struct LateralTie; // input/lateral_tie.hpp
struct Drm;        // input/drm.hpp
} // namespace slipwave::input
namespace slipwave::medium {
struct Attenuation; // medium/attenuation.hpp
struct Hysteresis;  // medium/hysteresis.hpp
} // namespace slipwave::medium
namespace slipwave::porous {
struct PorePressure; // porous/pore_pressure.hpp
} // namespace slipwave::porous
namespace slipwave::problem {
struct RigidBodies; // problem/rigid_bodies.hpp
} // namespace slipwave::problem

namespace slipwave::problem {

struct Elastodynamics {
  MPI_Comm                        comm = MPI_COMM_NULL;
  DM                              dm   = nullptr;
  PetscInt                        dim  = 0;
  meshing::MeshDescription           mesh;
  std::vector<medium::RegionMaterialInfo> materials;
  fem::BulkOperator               bulk;
  input::BoundaryConditions              bc;
  double                          damping_ratio = 0, damping_f1 = 0, damping_f2 = 0;
  physics::RayleighCoefficients   rayleigh{0, 0};
  std::vector<interface::InterfaceAssembler> interfaces;
  std::vector<std::string>        penalty_notes; // how each auto penalty was chosen, for the report

  Vec mass = nullptr, inv_mass = nullptr; // lumped, per dof
  Vec damping_blocks = nullptr;           // per node (C_abs + alpha M)/m, held dofs decoupled; null if none
  std::vector<PetscInt> absorbing_nodes;  // owned nodes (global-vector order) with a dashpot
  Vec u_local = nullptr, f_local = nullptr;
  // Parts of the last RHS evaluation, for the energy ledger.
  Vec       f_internal = nullptr, f_external = nullptr, f_input = nullptr, f_stiffness_damping = nullptr, f_interface = nullptr;
  Vec       f_anelastic = nullptr; // + sum of the constant-Q memory forces (zero without attenuation)
  Vec       f_contact_damping = nullptr; // the interfaces' contact dashpots (zero without them)
  bool      input_enabled = true;       // off during the geostatic stage
  std::vector<double> initial_stress;   // 6 per local cell: the geostatic state, added to the output
  input::FreeField  *free_field = nullptr; // free-field lateral columns (-bc_<side>_type freefield), or null
  input::LateralTie *tie        = nullptr; // tied lateral sides (-bc_<side>_type tied), or null
  medium::Attenuation *attenuation = nullptr; // constant-Q damping of regions with a damping ratio, or null
  medium::Hysteresis  *hysteresis  = nullptr; // hysteretic regions (-material_<r>_model hysteretic), or null
  Vec       f_hysteretic = nullptr; // + their relaxation force: the internal force is f_internal - f_hysteretic (null without them)
  input::Drm *drm        = nullptr; // Domain Reduction Method input (-input_method drm), or null
  porous::PorePressure *pore = nullptr; // pore pressure of saturated regions, or null (dry scenes)
  Vec       f_pore = nullptr;   // + alpha Q^T p, the pore pressure's force on the skeleton (saturated scenes only)
  NodalAcceleration nodal;      // a* from the force parts, and where f_ext can be nonzero
  RigidBodies *rigid = nullptr; // regions of -material_<r>_model rigid, or null
  // The fourth-order integrator's correction (ElastodynamicsFourthOrderCorrection): K a*
  // (global), and the local vectors it is gathered in, apart from u_local and f_local, which
  // hold the RHS's u for what reads it after the step.
  Vec correction_force = nullptr, correction_local = nullptr, correction_f_local = nullptr;
};

PetscErrorCode ElastodynamicsCreate(MPI_Comm comm, Elastodynamics *model);
PetscErrorCode ElastodynamicsDestroy(Elastodynamics *model);
// Adds `added` (laid out like u) to the lumped mass after the set-up (mass scaling,
// problem/interface_mass_scaling.hpp): the inverse mass and the tied sides' weights follow;
// gravity, the contact dashpots and the absorbing dashpots keep the physical mass they were
// built with.
PetscErrorCode ElastodynamicsAddMass(Elastodynamics *model, Vec added);
PetscErrorCode ElastodynamicsRHS(TS ts, PetscReal t, Vec u, Vec a, void *ctx);
// The trial states of the last RHS evaluation become the committed ones.
PetscErrorCode ElastodynamicsCommit(Elastodynamics *model);
// Saturated soil under noflow interfaces: the soil nodes of the committed open pairs drain
// into their gaps for the next step (porous::PorePressureDrainOpenGaps). Part of the commit;
// a restart calls it once the interface states are loaded. No-op without such interfaces.
PetscErrorCode ElastodynamicsDrainOpenGaps(Elastodynamics *model);
// The correction of the fourth-order integrator (time/central_difference.hpp, -ts_cd_order 4)
// of the acceleration a* = RHS(t, u) at step h, on free dofs:
//   c = M^{-1} (-(h^2/12) K a* + (1/12) (f(t+h) - 2 f(t) + f(t-h))),
// K the linear bulk stiffness (unrelaxed moduli; no interfaces, memory or relaxation forces),
// f the loads that are known functions of time (timed loads, the incident-wave force), whose
// second difference is h^2 f'' to O(h^4). Tied sides and rigid bodies constrain c as they
// constrain a*; held dofs get none (their motion is prescribed).
PetscErrorCode ElastodynamicsFourthOrderCorrection(Elastodynamics *model, PetscReal t, PetscReal h, Vec a_star, Vec c);
// A "cd" TS (type set, options read) gets the RHS, the commit hook, the correction of order 4
// and the nodal damping.
PetscErrorCode ElastodynamicsSetUpTS(Elastodynamics *model, TS ts);
// -input_method drm on a saturated site: the free field at t and the pore pressure's volume
// source of the step from the committed time to t (porous/pore_pressure_drm.hpp). The RHS
// calls it at its t, the energy ledger at t_n + h first (the step's fluid storage energy
// needs it). No-op otherwise.
PetscErrorCode ElastodynamicsDrmPoreSource(Elastodynamics *model, TS ts, PetscReal t);
// Global f = K x by the element loop (ghost exchange included), as the RHS computes it.
PetscErrorCode ElastodynamicsStiffnessTimes(Elastodynamics *model, Vec x, Vec f);
// Stores the cell stresses of the global displacement u as the initial stress.
PetscErrorCode ElastodynamicsSetInitialStress(Elastodynamics *model, Vec u);

} // namespace slipwave::problem
