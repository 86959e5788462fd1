// Regions of -material_<r>_model rigid move as rigid bodies. A concrete foundation on soft
// soil is 100-1000 times stiffer than the soil: modelled elastically, its own modes ring at
// hundreds of Hz when it lands (above anything the soil mesh carries) and its wave speed sets
// the stable step. As a rigid body it keeps its mass and inertia and loses both.
//
// Each step, the accelerations of the body's nodes (f_i / m_i, every force included) are
// replaced by the rigid-body motion of their resultant: with F = sum f_i and M = sum r_i x f_i
// about the mass centroid, a_i = F / m + J^-1 M x r_i (physics/rigid_body.hpp). That is the
// lumped-mass projection onto rigid motions, so the constraint forces it adds do no work on
// the body's velocity and the energy balance stays closed. Kinematics are linearised (small
// rotations, like the rest of the code): a rigid displacement has no strain, so the body's
// own elastic forces (kept for the geostatic stage's static solve) add nothing to F and M.
// Bodies are the regions, nodes shared by two rigid regions are refused, and nodes that a
// boundary condition holds or damps are refused: a body's supports are its interfaces and
// the regions it is welded to (their nodes on the body move with it). A component held at
// every node (-constrain_components y for a 1D model) fixes the motions that move it.
#pragma once
#include <petscdm.h>

#include <string>
#include <vector>

#include "slipwave/fem/bulk_operator.hpp"
#include "slipwave/input/boundary_conditions.hpp"
#include "slipwave/medium/materials.hpp"

namespace slipwave::problem {

struct RigidBody {
  std::string           region;
  PetscInt              nodes = 0;          // over all ranks
  double                mass  = 0;          // [kg; kg/m in 2D]
  double                centroid[3] = {0, 0, 0};
  double                inertia[9]  = {};   // about the centroid [kg m^2; kg m^2/m in 2D]
  double                inverse_inertia[9] = {}; // on the free rotations (physics::rigidInertiaInverse)
  bool                  fixed[3] = {false, false, false};      // components held at every node (-constrain_components)
  bool                  translates[3] = {false, false, false}; // free translations
  bool                  rotates[3]    = {false, false, false}; // free rotations (about x, y, z)
  std::vector<PetscInt> dofs;               // owned nodes: offset of the x component in a global vector's array
  std::vector<double>   arm;                // per owned node: r = x - centroid, 3 values
};

struct RigidBodies {
  MPI_Comm               comm = MPI_COMM_NULL;
  PetscInt               dim  = 0;
  std::vector<RigidBody> bodies;
  std::vector<double>    resultants; // per body F (3) and M (3): the per-step reduction buffer
};

// The rigid regions' bodies (null when no region is rigid). mass: the lumped mass (global).
// Stops with one line on a node shared by two rigid regions or held or damped by a boundary.
PetscErrorCode RigidBodiesCreate(DM dm, const fem::BulkOperator &bulk, const std::vector<medium::RegionMaterialInfo> &materials, const input::BoundaryConditions &bc,
                                 Vec mass, RigidBodies **rigid);
PetscErrorCode RigidBodiesDestroy(RigidBodies **rigid);
// a (global) on the bodies' nodes := the rigid-body acceleration of the resultant of m a there.
PetscErrorCode RigidBodiesProject(RigidBodies *rigid, Vec mass, Vec a);
// Collective: each body's motion from the displacement u (global), 6 values per body: the
// mass centre's displacement U (3) and the small rotation theta (3, about x, y, z) [m, rad]
// (physics::rigidMotionOf; exact for the rigid field the bodies move with).
PetscErrorCode RigidBodiesMotion(const RigidBodies *rigid, Vec mass, Vec u, std::vector<double> *motion);
// For the stable step: rows (global, K <= diag(rows)) on the bodies' dofs hold the springs
// that support them (interfaces, welded neighbours); *omega2 = the largest, over the bodies,
// of sum_i rows_i / m_eff,i (physics::rigidDofCompliance), a bound on the body's frequencies
// on those springs, and the rows there are zeroed (the nodes do not vibrate on their own).
PetscErrorCode RigidBodiesRowBound(const RigidBodies *rigid, Vec rows, double *omega2);
// One line per body for the run report.
std::string RigidBodiesDescribe(const RigidBodies *rigid);

} // namespace slipwave::problem
