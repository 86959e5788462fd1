// Geostatic stage: gravity equilibrium of soil, structure and interfaces before shaking. The
// absorbing and free-field boundaries are held along their normal (a dashpot carries no
// static load) and the incident wave is off.
//  - method static (default): one linear solve K u = f with every interface pair as its
//    stick spring (problem/static_equilibrium.hpp), equilibrium to the solver's round-off, so
//    the state is the same on any number of ranks. Every pair is then checked against the
//    Mohr-Coulomb law with the static jump; if one would slip, open or reach the tension
//    cut-off, the linear answer is not the equilibrium, and relaxation continues from it.
//  - method relaxation (and the fallback; also with tied lateral sides, a constraint the
//    linear solve does not carry): explicit steps with local damping (each dof's unbalanced
//    force is reduced by 0.8 of its size against the velocity) until the unbalanced-force
//    ratio   max |M a| / max |f_applied|   over the free dofs is below the tolerance. Where
//    it stops depends on the rounding, so its state differs between rank counts by about
//    the tolerance.
// That state becomes the reference of the dynamic stage:
//  - displacements start again from zero, and the cell stresses of the geostatic state are
//    added to the output stress;
//  - the constant loads become what the geostatic state leaves unbalanced (f - K u_geo), and
//    at the held absorbing nodes the support reactions become constant forces, so the model
//    starts at rest in equilibrium;
//  - interfaces keep their tractions and state, with the jump measured from the new zero.
#pragma once
#include <petscksp.h>

#include <string>
#include <vector>

#include "slipwave/problem/elastodynamics.hpp"

namespace slipwave::problem {

enum class GeostaticMethod { Static, Relaxation };

struct GeostaticOptions {
  PetscBool       enabled   = PETSC_FALSE;
  GeostaticMethod method    = GeostaticMethod::Static;
  PetscReal       tolerance = 1e-5;
  PetscInt        max_steps = 1000000;
  KSP             ksp       = nullptr; // the static solver (-geostatic_ksp_*), when enabled and static
};

struct GeostaticReport {
  bool        solved_static = false; // the static solve ran
  bool        interfaces = false;    // the model has interface pairs (for the report's wording)
  PetscInt    ksp_iterations = 0;
  double      static_ratio = 0;      // unbalanced-force ratio right after the static solve
  PetscInt    pairs_off_stick = 0;   // pairs the law does not keep in linear stick there
  std::string solver;                // "KSP cg + gamg"
  std::string fallback;              // why relaxation ran after the static solve; empty if not
  PetscInt    steps = 0;             // relaxation steps (0: none)
  double      ratio = 0;             // final unbalanced-force ratio
  double      wall  = 0;
};

PetscErrorCode GeostaticOptionsRead(MPI_Comm comm, GeostaticOptions *options);
PetscErrorCode GeostaticOptionsDestroy(GeostaticOptions *options);
// One report line (no newline) for the run log.
std::string GeostaticReportLine(const GeostaticOptions &options, const GeostaticReport &report);
// geostatic_u: if not null, a global vector that receives the geostatic displacement (the
// settlement under gravity) before the dynamic stage's displacements start again from zero.
PetscErrorCode GeostaticStage(Elastodynamics *model, const GeostaticOptions &options, double dt, GeostaticReport *report, Vec geostatic_u = nullptr);

} // namespace slipwave::problem
