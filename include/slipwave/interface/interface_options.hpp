// Command-line options of one interface law: -<prefix>E, -<prefix>G, -<prefix>phi,
// -<prefix>psi, -<prefix>c, -<prefix>e_ini, -<prefix>tensile_strength, -<prefix>sigma_N0,
// and, for an interface of a mesh, -<prefix>penalty_rule, -<prefix>penalty_length,
// -<prefix>penalty_factor, -<prefix>contact_damping, -<prefix>friction_slip_length and
// -<prefix>friction_reference_velocity;
// default prefix "interface_" (a simulation with several interfaces passes its own). The
// interface's geometry (-interfaces, -interface_<n>_regions, _faces) is the mesh's: see
// meshing/mesh_builder.hpp.
#pragma once

#include "slipwave/physics/friction_lag.hpp"
#include "slipwave/physics/mohr_coulomb_interface.hpp"

#include <petscsys.h>

#include <string>

namespace slipwave::interface {

// How E, G given as `auto` are chosen (docs/convergence-study.md):
//  Physical (the default): E = (lambda+2mu)/L, G = mu/L of the softer side,
//            L = -<prefix>penalty_length [m]: the interface is as compliant as a layer of the
//            softer material L thick, whatever the mesh. Default L: the interface's width
//            (2D: its length; 3D: the square root of its area) x kDefaultPenaltyLengthFraction.
//            Its stiff contact makes each landing of an elastic block ring the block's own
//            modes far above what the soil mesh resolves: model such a structure rigid
//            (-material_<r>_model rigid), as the default scene does.
//  Mesh:     factor x (lambda+2mu)/h and factor x mu/h (h: the smallest cell size; at
//            -element_degree p, 3 h_e/(p^2+p+1)): as stiff as one layer of cells, so it
//            changes with the mesh; for interfaces that are no footing (a bar end, a layer
//            boundary) where a width means nothing.
enum class PenaltyRule { Physical = 0, Mesh = 1 };
// Default penalty length as a fraction of the interface's width: the first length at which
// every answer of the default scene (rigid block, docs/convergence-study.md) moves by less
// than 5 % when the stiffness is doubled. Halving L from width/200 moves the slip path by
// 4.7 % and the largest excursion by 3.9 % (slip converges as O(L)), everything else by at
// most 1.5 %; from width/100 the slip path moved 7.7 %. The step it costs there: the
// springs and contact dashpots set it, 0.39 x the bulk's at h = 1 m (width/100: 0.55 x).
constexpr double kDefaultPenaltyLengthFraction = 1.0 / 200.0;

struct InterfaceOptions {
  physics::InterfaceParams params; // angles converted to radians
  double sigma_N0 = 0.0;           // initial normal traction [Pa], tension positive
  // E or G given as `auto`: the caller derives them from the mesh, then calls
  // InterfaceOptionsCheck; params holds 0 for them until then.
  PetscBool E_auto = PETSC_FALSE;
  PetscBool G_auto = PETSC_FALSE;
  PenaltyRule penalty_rule = PenaltyRule::Physical;
  double      penalty_length = 0.0;          // [m], physical rule; 0: not given (default from the width)
  double      penalty_factor = 1.0;          // mesh rule: factor x (lambda+2mu)/h and x mu/h of the softer side
  // Fraction of each closed pair's critical normal damping. 0.1 removes the contact stress
  // ripple of the two-bar impact (48 % -> 0.02 %) and the energy the switching created
  // (2.3e-4 -> 0) while moving the exit velocities by 0.1 % and the step by 1.4 % in the
  // default scene; larger ratios cost more step and raised the block's peaks there (docs/features.md,
  // interfaces).
  double contact_damping = 0.1;
  // The friction's lag behind the effective normal traction (physics/friction_lag.hpp):
  // L = 5 mm (the thickness of a sand-structure shear band, ~10 grain diameters), V* = 1 m/s,
  // so a sticking pair follows its normal traction within 5 ms. Docs: docs/features.md.
  physics::FrictionLag friction_lag{0.005, 1.0};
};

// Where the law is used: alone (slipwave-law: one pair, no mesh) or on the split pairs of a
// mesh, which adds the penalty factor and the contact damping.
enum class InterfaceUse { LawAlone, Mesh };

// Reads and validates the options (stiffnesses given as `auto` are left unchecked).
// prefix nullptr means "interface_".
PetscErrorCode InterfaceOptionsRead(MPI_Comm comm, const char *prefix, InterfaceUse use, InterfaceOptions *options);

// The `auto` stiffnesses of an interface of a mesh from the softer side's moduli m_soft =
// lambda+2mu and mu_soft [Pa], the mesh's h [m] (mesh rule) and the interface's width [m]
// (physical rule's default length); E and G given as numbers are kept. Fills options->params
// and a one-line description for the run report. Collective only for errors.
PetscErrorCode InterfaceAutoPenalty(MPI_Comm comm, const char *prefix, double m_soft, double mu_soft, double h, double width,
                                    InterfaceOptions *options, std::string *note);

// Stops with a user-input error naming the first option out of range, its value and the
// allowed range.
PetscErrorCode InterfaceOptionsCheck(MPI_Comm comm, const char *prefix, const InterfaceOptions &options);

} // namespace slipwave::interface
