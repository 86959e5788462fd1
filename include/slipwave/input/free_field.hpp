// Free-field lateral boundaries (-bc_<side>_type freefield), as in FLAC: each such side gets
// a 1D soil column (physics::FreeFieldColumn) driven by the same incident wave as the base,
// and every main-mesh node of the side receives
//     F = -C (v - v_ff) + sum over its faces of w_a sigma_ff . n_out
// C: the Lysmer dashpot block of the node (rho vp normal, rho vs tangential, from the face's
// region), v_ff: the column's velocity at the node's height, sigma_ff: the column's stress in
// the segment the face spans, w_a: the lumped face weight, n_out: the outward normal.
// Beside saturated soil sigma_ff is the total stress, the effective one less alpha p I, with
// p the column's excess pore pressure integrated against the face's shape function
// (FreeFieldColumn::poreStress); the hydrostatic part is in the geostatic reaction below.
//
// Why it is split this way:
//  - -C v is a dashpot like an absorbing boundary's: it is assembled into
//    bc.absorbing_blocks (BoundaryConditionsCreate), so the TS treats it centred (it does not
//    lower the stable step) and the energy ledger books it as "absorbed";
//  - C v_ff + A t_ff is known at t_{n+1} once the column has stepped: an external force added
//    to the RHS's f_external (booked as external work).
//  - The traction is applied face by face with the segment's constant stress, which is what
//    the missing neighbour cells would have contributed to the boundary nodes (the main mesh's
//    cell stress of a height-only motion is constant per cell too), so a scatterer-free model
//    with free-field sides moves exactly like the column: no spurious reflection from the
//    sides in the 1D case, only round-off.
//  - One-way coupling: the column does not feel the main mesh. It is tiny, so it is built and
//    stepped on every rank (replicated): no communication, the same numbers on any number of
//    ranks.
//  - The column carries only the dynamic part (no gravity): the geostatic stress is the
//    initial stress of the main mesh, and the free-field side acts as a roller during the
//    geostatic stage (problem/geostatic.cpp), then its reaction becomes a constant load. So
//    its pore pressure is the excess one, as the main mesh's unknown, whose hydrostatic
//    load alpha Q^T p_h is constant and in that reaction.
//  - The side's pore pressure nodes keep the noflow condition: exact for the free field,
//    which has no horizontal flow (a height-only p), and then the side node's storage,
//    coupling and Darcy rows are half an interior node's, so its p follows the interior's.
//    A drained or flux side would drain the free field sideways: refused.
// The RHS brings a trial copy of each column from its committed time to t (with the TS's
// step), so asking again at the same time gives the same force; FreeFieldCommit, after the
// step is accepted, makes the trial the committed column.
#pragma once
#include <petscts.h>

#include <string>
#include <utility>
#include <vector>

#include "slipwave/input/boundary_conditions.hpp"
#include "slipwave/medium/materials.hpp"
#include "slipwave/physics/free_field_column.hpp"
#include "slipwave/physics/rayleigh_damping.hpp"

namespace slipwave::medium {
struct Attenuation; // medium/attenuation.hpp
} // namespace slipwave::medium

namespace slipwave::input {

// What the columns' pore pressure takes from the main mesh's (porous/pore_pressure.hpp;
// problem/elastodynamics.cpp fills it): per region its fluid (saturated or not, Biot numbers),
// the pressure layout with its global nodal storage, free mask (1 where p evolves),
// hydrostatic pressure and inflow, the boundaries whose fluid condition is not noflow
// (name, condition), and the diffusion and cavitation rules.
struct FreeFieldFluid {
  std::vector<physics::ColumnFluidSegment>         region;
  DM                                               pdm = nullptr;
  Vec                                              storage = nullptr, free_mask = nullptr, p_hydrostatic = nullptr, inflow = nullptr;
  std::vector<std::pair<std::string, std::string>> fluid_boundaries;
  physics::ColumnFluidRules                        rules;
};

struct FreeFieldTerm {
  PetscInt offset;      // local-vector offset of the node's first dof
  int      node;        // column node at the vertex's height
  int      segment;     // column segment the face spans
  double   weight;      // lumped face weight of the vertex
  double   normal[3];   // outward unit normal of the face
  double   theta;       // the other height's share in the face's mean pore pressure on N_a (poreStress)
  double   C[9];        // Lysmer dashpot block of this face-vertex pair
};

struct FreeFieldSide {
  std::string                 name;
  physics::FreeFieldColumn    column; // committed
  physics::FreeFieldColumn    trial;  // the last FreeFieldUpdate's
  std::vector<FreeFieldTerm>  terms; // this rank's faces
};

struct FreeField {
  PetscInt                   dim = 0;
  std::vector<FreeFieldSide> sides;
  Vec                        force = nullptr;       // global: C v_ff + A t_ff of the last update [N]
  Vec                        force_local = nullptr;
  bool                       has_trial = false;
};

// Builds the columns of every boundary of type freefield (bc must be created). h_min: the
// smallest cell size (the height-matching tolerance is 1e-9 of it). attenuation (or null):
// the constant-Q damping the columns' segments take from their regions. fluid (or null: a dry
// scene): the main mesh's pore pressure, as its interfaces left it, which saturated segments'
// columns carry.
PetscErrorCode FreeFieldCreate(DM dm, const BoundaryConditions &bc, const std::vector<medium::RegionMaterialInfo> &materials, const physics::RayleighCoefficients &rayleigh,
                               const medium::Attenuation *attenuation, const FreeFieldFluid *fluid, double h_min, FreeField **ff);
// Brings trial copies of the columns to time t (starting them on the first call, stepping them
// when t is new) and assembles the force into ff->force. enabled = false (geostatic stage): the
// force is zero and the columns stay unstarted. ts may be null; it supplies the step when given.
PetscErrorCode FreeFieldUpdate(FreeField *ff, DM dm, TS ts, PetscReal t, double v_in, bool enabled);
// The trial columns of the last FreeFieldUpdate become the committed ones (no-op without one).
void           FreeFieldCommit(FreeField *ff);
// Smallest stable step of the columns (1e300 if none), their saturated segments' undrained
// stiffening counted coupling_factor times (the main mesh's, problem/stable_step.hpp).
double         FreeFieldStableStep(const FreeField *ff, double coupling_factor);
PetscErrorCode FreeFieldDestroy(FreeField **ff);

} // namespace slipwave::input
