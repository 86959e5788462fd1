// Pore pressure of the saturated regions: Biot's u-p equations integrated explicitly
// (docs/saturated-soil.md). porous/pore_pressure.cpp: layout, update, stable-step rows,
// energy, water table; porous/pore_fluid.cpp: the per-region options and the report;
// porous/pore_pressure_bc.cpp: the fluid boundary conditions. The pressure is a nodal scalar on its own node layout (a clone
// of the mesh DM with one dof per vertex, node i of it is node i of the displacement), so the
// displacement layout, the "cd" TS and every dry-scene pass stay as they are; a dry scene
// never creates this object. At element degree p > 1 the nodes are the elements' GLL nodes
// (the mesh's vertices there), the element operators those of fem/spectral_biot.hpp applied
// from each geometry's GLL factors, and the sub-steps and the wave step's coupling factor
// those of physics/split_diffusion_step.hpp (docs/saturated-soil.md, "At element degree p > 1").
//
// One step, with S the lumped storage (integral of N_a / M), Q the coupling
// (integral of N_a div), H the Darcy matrix (integral of kappa grad N_a . grad N_b), split:
//   p*      = p_n after m explicit diffusion sub-steps S (p^{k+1} - p^k) = -(h/m) H p^k
//             (m = 1, or with -pore_pressure_subcycle enough that h/m is within the
//             diffusion limit), so S (p* - p_n) = -h Hbar, Hbar the mean of H p^k;
//   p_{n+1} = p* - S^{-1} [ alpha Q (u_{n+1} - u_n) - h q ]            on free pressure nodes,
//   f_pore  = alpha Q^T p                                             (force on the skeleton),
// so total stress = effective stress - alpha p I. p* depends on p_n and h only: it is
// computed once per step (cached for that h) by whichever needs it first, the RHS or the
// energy ledger. p_{n+1} is a trial state of the RHS (it needs u_{n+1}, which the RHS
// receives) that PorePressureCommit accepts.
//
// Options per region r (prefix -material_r_): saturated, porosity, fluid_bulk_modulus,
// grain_bulk_modulus, hydraulic_conductivity, fluid_density. Per boundary b: -bc_b_fluid
// noflow|drained|flux, -bc_b_fluid_flux q [m/s]. With gravity, -water_table z [m]: the
// hydrostatic pressure p_h = rho_f g (z - elevation)+ below it. The unknown p is the excess
// pore pressure over p_h (p_h drives no flow); its force on the skeleton, alpha Q^T p_h, is
// a constant load (PorePressureAddHydrostaticForce); outputs give p_h + p and p.
#pragma once
#include <petscdmplex.h>

#include <string>
#include <vector>

#include "slipwave/fem/bulk_operator.hpp"
#include "slipwave/medium/materials.hpp"
#include "slipwave/physics/biot.hpp"

namespace slipwave::porous {

struct SaturatedRegion {
  bool                 saturated = false;
  physics::BiotMaterial biot{};
  double               alpha = 0, M = 0, kappa = 0; // Biot coefficient [-], modulus [Pa], mobility [m^2/(Pa s)]
};

struct PorePressure {
  DM                           pdm = nullptr;    // one dof per vertex
  std::vector<SaturatedRegion> regions;          // per region, in materials order
  // Element matrices per distinct bulk element matrix (region and geometry,
  // BulkOperator::elementMatrix). Degree 1: alpha Q and kappa H, dense. Degree p > 1
  // (fem/spectral_biot.hpp): what they are applied from, per node alpha w|J| and kappa w|J|
  // and J^{-1}, with the 1D GLL derivative matrix. Both: the storage S per node.
  std::vector<double>   coupling, diffusion, storage_element;
  PetscInt              degree = 1;
  std::vector<double>   coupling_weight, diffusion_weight, inverse_jacobian, gll_derivative;
  std::vector<PetscInt> matrix_region;           // per distinct matrix: its region
  fem::EigenBoundKind   bound_kind = fem::EigenBoundKind::Certified; // degree > 1: the bulk's kind, for the undrained rows
  std::vector<PetscInt> cells;                   // local elements of saturated regions (degree 1: cells)
  std::vector<PetscInt> cell_matrix;             // per element of `cells`: its distinct-matrix index
  std::vector<PetscInt> cell_p, cell_u;          // per element node: local offset in p, in u
  PetscInt              nen = 0, dim = 0;        // nodes per element, dimension
  Vec storage = nullptr, inv_storage = nullptr;  // lumped S per node (0 off the saturated regions)
  Vec free_mask = nullptr;                       // 1 where p evolves: S > 0 and not drained
  Vec inflow = nullptr;                          // q: prescribed boundary inflow per node [m^3/s]
  Vec p = nullptr, p_trial = nullptr;            // committed p_n and the RHS's trial p_{n+1} [Pa]
  Vec Qu = nullptr, Qu_trial = nullptr;          // alpha Q u at the same two states [m^3]
  Vec p_star = nullptr, Hbar = nullptr;          // the diffusion part of the step from p_n: p*, mean H p^k [m^3/s]
  Vec Hbar_trial = nullptr, Hbar_previous = nullptr; // Hbar the trial used; that of the step before
  Vec Hp = nullptr, Hp_trial = nullptr;          // H p_n and H p_trial, from the pass that forms f_pore [m^3/s]
  Vec p_local = nullptr, q_local = nullptr;
  double t = 0, t_trial = 0;
  bool   started = false;                        // Qu holds the initial state
  double diffused_h = -1;                        // the step p_star and Hbar are for; < 0: none since the commit
  double dt_diffusion = 1e300;                   // explicit diffusion limit [s]
  bool   subcycle = true;                        // -pore_pressure_subcycle: sub-steps instead of a smaller step
  PetscInt substeps = 1;                         // sub-steps of the last diffusion part
  double vp_undrained_max = 0;                   // [m/s], for the report
  std::vector<std::string> drained, flux;        // boundary names, for the report
  Vec    p_hydrostatic = nullptr;                // p_h per node [Pa]; zero without a water table
  Vec    p_total = nullptr;                      // p_h + p (p_h where drained), refreshed by PorePressureTotal
  Vec    p_total_trial = nullptr;                // p_h + p_trial, what interfaces on saturated soil read
  bool   water_table = false;
  Vec    at_water_table = nullptr;               // 1 at free nodes the water table drained because they lie on it
                                                 // (not above): a noflow interface seals those of its soil side
  double water_table_elevation = 0;              // [m] along minus the gravity direction
  // Interfaces whose gaps drain (-interface_<n>_fluid gap, PorePressureDrainOpenGaps): their names,
  // and the fluid conditions without any gap (free_mask, inv_storage as set up).
  std::vector<std::string> sealed_interfaces;
  Vec    sealed_free_mask = nullptr, sealed_inv_storage = nullptr;
  // Cavitation (-fluid_cavitation_pressure, physics/cavitation.hpp): the total pore pressure
  // p_h + p is held at or above cavitation_pressure [Pa gauge] (none: not at all); where it
  // would fall below, the pore volume the water does not follow is a cavity, per node.
  bool     cavitation          = true;
  double   cavitation_pressure = -100e3;
  Vec      cavity = nullptr, cavity_trial = nullptr; // committed V_n and the trial's V_{n+1} [m^3; m^2 per m in 2D]
  double   cavity_work_step = 0;                     // this rank's work on its cavities in the last committed step [J], for the ledger
  PetscInt cavities_local   = 0;                     // this rank's nodes with a cavity in the committed state
  // For the run report: when cavities were open (t < 0: never), the most nodes at once, the
  // largest cavity and where (this rank's; reduced by PorePressureCavitationReport).
  double   cavitation_first = -1, cavitation_last = -1;
  PetscInt cavities_max = 0, cavities_now = 0;
  double   largest_cavity = 0, largest_cavity_time = 0, largest_cavity_at[3] = {0, 0, 0};
  // -input_method drm on a saturated site (porous/pore_pressure_drm.hpp): the layer's pressure
  // rows as a volume source W of each step, S (p_{n+1} - p*) = ... + W, from G = the split
  // alpha Q u0 and r = the split H p0 (committed, t_n, and the trial's); W of the trial step
  // and of the last committed one (the ledger books 1/2 p_n (W_{n+1/2} + W_{n-1/2})). Null
  // without DRM.
  Vec      drm_volume = nullptr, drm_volume_trial = nullptr;   // G [m^3]
  Vec      drm_flow = nullptr, drm_flow_trial = nullptr;       // r [m^3/s]
  Vec      drm_source = nullptr, drm_source_previous = nullptr; // W [m^3]
  std::vector<PetscInt> drm_cell;                              // per DRM layer element: its index in cells, -1 if dry
  Vec      node_coordinates[3] = {nullptr, nullptr, nullptr}; // x, y (, z) per pressure node (global layout)
  Vec      node_volume = nullptr;                    // the saturated volume each node stands for (lumped) [m^3; m^2 in 2D]
  Vec      cavity_fraction = nullptr;                // V / node_volume, refreshed by PorePressureCavityFraction [-]
};

// Reads the per-region options after MaterialsRead; sets vp_undrained of saturated regions
// (the absorbing boundaries match it). *any: whether some region is saturated.
PetscErrorCode PorePressureReadMaterials(MPI_Comm comm, std::vector<medium::RegionMaterialInfo> *materials, std::vector<SaturatedRegion> *regions, bool *any);
// Builds the layout, element matrices, storage, fluid boundary conditions and diffusion
// limit; reads -pore_pressure_subcycle.
// gravity [m/s^2] along the unit vector gravity_direction (the scene's -gravity).
PetscErrorCode PorePressureCreate(DM dm, const fem::BulkOperator &bulk, const std::vector<std::string> &boundaries, std::vector<SaturatedRegion> regions,
                                  double gravity, const double *gravity_direction, PorePressure **pore);
// f += alpha Q^T p_h (global, displacement layout): the hydrostatic pressure's load.
PetscErrorCode PorePressureAddHydrostaticForce(PorePressure *pore, DM dm, Vec f);
// p_h + p of the committed state (p_h on drained nodes), in pore->p_total.
PetscErrorCode PorePressureTotal(PorePressure *pore);
// An interface whose soil side is saturated: -interface_<name>_fluid noflow (default) or
// drained, which holds the excess pore pressure at zero at its soil nodes (soil_dofs: global
// indices of their x components), or gap: noflow while in contact, drained where a pair opens
// (it joins sealed_interfaces).
PetscErrorCode PorePressureInterfaceFluid(PorePressure *pore, MPI_Comm comm, const std::string &name, const std::vector<PetscInt> &soil_dofs);
PetscErrorCode PorePressureDestroy(PorePressure **pore);
// Trial state at time t from the ghosted displacement u_local: p_trial, and the force on the
// skeleton f_pore = alpha Q^T p_trial (global, displacement layout, overwritten).
PetscErrorCode PorePressureTrial(PorePressure *pore, DM dm, const PetscScalar *u_local, PetscReal t, Vec f_pore);
// The trial becomes the committed state; books this rank's work on its cavities in the step.
PetscErrorCode PorePressureCommit(PorePressure *pore);
// The diffusion part (p*, Hbar) of the coming step of size h from the committed p_n, as the
// energy ledger computes it first in every step; a restart calls it with the checkpoint's
// step (whose monitor, and so the ledger, it skips), so the continued run repeats the
// uninterrupted one bit for bit (the RHS's own h = t_{n+1} - t_n differs by round-off).
PetscErrorCode PorePressureDiffuseStep(PorePressure *pore, PetscReal h);
// -interface_<n>_fluid gap: the interface seals the soil it rests on only while in contact: where a pair opens,
// water (below the water table) or air (above it) fills the gap, so the soil node's total
// pressure is the hydrostatic one there, as on a drained surface (excess 0), until the pair
// closes again. open_marker: 1 at the soil nodes of the open pairs of the interfaces in
// sealed_interfaces (pressure layout, global), 0 elsewhere; called after each commit, so the
// next step (its ledger and its RHS) drains them. A node that drains with p != 0 releases its
// pressure's energy (PorePressureEnergy books it with the Darcy dissipation).
PetscErrorCode PorePressureDrainOpenGaps(PorePressure *pore, Vec open_marker);

// Adds to the row bounds of K (global, displacement layout; K <= diag(rows)) those of the
// undrained stiffening alpha^2 Q^T S^{-1} Q that the wave step must cover. Degree 1: its
// Gershgorin rows |Q|^T S^{-1} |Q| 1 (rows of drained nodes do not stiffen). Degree p > 1: per
// element, its own stiffening Q_e^T S_e^{-1} Q_e (S_e its share of the storage; their sum bounds
// the assembled one) is the elastic element with lambda = alpha^2 M, mu = 0
// (fem/spectral_biot.hpp), at most lambda_e diag(alpha w|J|) with lambda_e its eigenvalue bound
// (the bulk's kind), so each node's rows get lambda_e alpha w|J| from each of its elements.
PetscErrorCode PorePressureAddUndrainedRows(PorePressure *pore, DM dm, Vec rows);

// Report lines: per saturated region its Biot numbers, the fluid boundaries, and what the
// pore pressure costs in step: dt_drained (bulk without the undrained stiffening),
// dt_undrained (with it, counted coupling_factor times: PorePressureCouplingFactor),
// dt_diffusion, and the run's limit.
std::vector<std::string> PorePressureReport(const PorePressure *pore, const std::vector<medium::RegionMaterialInfo> &materials, double dt_drained, double dt_undrained,
                                            double coupling_factor, double dt_limit, double dt);

// Within the module (porous/pore_pressure_bc.cpp): -bc_<b>_fluid of every boundary, drained
// nodes into drained_local (1) and the inflow integral of N_a q into inflow_local (local
// vectors of the pressure layout).
PetscErrorCode PorePressureReadFluidBoundaries(DM dm, DM pdm, const std::vector<std::string> &boundaries, const std::vector<SaturatedRegion> &regions,
                                               Vec drained_local, Vec inflow_local, PorePressure *pore);
// Holds the excess pore pressure at zero where the global marker (pressure layout) is > 0.
PetscErrorCode PorePressureDrainNodes(PorePressure *pore, Vec marker);

// Sub-steps per step of size h: 1 without sub-cycling (the step is then within the limit).
// Degree p > 1: 1 while h is within half the diffusion limit, else an even count
// (physics/split_diffusion_step.hpp).
PetscInt PorePressureSubsteps(const PorePressure *pore, double h);
// The factor c by which the wave step's bound counts the undrained stiffening for a step h
// (K + c alpha^2 Q^T S^-1 Q; physics/split_diffusion_step.hpp): at degree p > 1 the split
// step's, 1 <= c <= 2 with sub-cycling, growing without bound as h nears the diffusion limit
// without it; 1 at degree 1, whose stable step takes the undrained rows as they are (their
// Gershgorin bound is loose, and Q1's fastest-diffusing pressure modes, the node-alternating
// ones, are those Q^T hardly sees: measured stable, docs/saturated-soil.md).
double PorePressureCouplingFactor(const PorePressure *pore, double h);

// The fluid's terms of the energy budget at t_n (docs/saturated-soil.md): the shadow storage
// energy F_{n+1/2} = ½ p_n S p_{n+1}, and this step's Darcy dissipation
// ½ h p_n (Hbar_n + Hbar_{n-1}) and work of the prescribed inflow h p_n q.
// held_power = v_n . f_pore on held dofs: the part of the supports' reaction power that the
// pore pressure supplies, which the ledger takes out of the reactions (it is internal work).
// cavitation: the work the fluid did on its cavities in the last committed step
// (physics::cavityWork on the free nodes), which the shadow storage energy lacks.
// drm_input: the DRM's volume source's work, 1/2 p_n (W_{n+1/2} + W_{n-1/2}) (input work, as
// the DRM's forces are).
struct PoreEnergy {
  double storage = 0, darcy = 0, inflow = 0, held_power = 0, cavitation = 0, drm_input = 0;
};
// v, a: v_n and a_n; f_pore at t_n; free_mask of the displacement dofs; dm the displacement
// layout. A node held this step (drained) that still holds p_n != 0 (a gap just opened over
// it: PorePressureDrainOpenGaps) stores nothing from now on: the energy the storage equation
// would have given it, (1/2) [p S p - h p (alpha Q v_{n+1/2}) - h p Hbar + h p q] at that node,
// leaves with the water and is booked in darcy.
PetscErrorCode PorePressureEnergy(PorePressure *pore, DM dm, PetscReal h, Vec v, Vec a, Vec f_pore, Vec free_mask, PoreEnergy *e);

// The volume output's cavity_fraction: each node's cavity over the volume it stands for (the
// volumetric strain the cavity takes), in pore->cavity_fraction. With cavitation only.
PetscErrorCode PorePressureCavityFraction(PorePressure *pore);

// The run report's line on cavitation (collective): when and where cavities were open, the
// most nodes at once, the largest cavity, and the work (work: the ledger's cavitation_work).
PetscErrorCode PorePressureCavitationReport(const PorePressure *pore, MPI_Comm comm, double work, std::string *line);

} // namespace slipwave::porous
