// The rigid bodies' motion as station-like histories: for every rigid region r
// (-material_<r>_model rigid), OUTPUT_DIR/rigid_<r>.csv with columns t,u_x,u_y,theta_z (2D) or
// t,u_x,u_y,u_z,theta_x,theta_y,theta_z (3D): the displacement of its mass centre [m] and its
// small rotation [rad] (problem::RigidBodiesMotion), at the stations' sample times
// (-station_interval). Written by rank 0 at the stations' flushes, each flush in one write,
// so a killed run keeps every row up to its last output time; a restart copies the rows up
// to the restart time from the checkpoint's folder.
#pragma once
#include <petscsys.h>

#include <string>
#include <vector>

#include "slipwave/problem/rigid_bodies.hpp"

namespace slipwave::app {

class RigidHistories {
public:
  // rank 0 writes; previous: the checkpoint's folder on a restart ("" otherwise), t_restart its time.
  PetscErrorCode Open(const problem::RigidBodies *rigid, PetscMPIInt rank, const std::string &dir, const std::string &previous, double t_restart);
  // motion: problem::RigidBodiesMotion's 6 values per body.
  void           Sample(double t, const std::vector<double> &motion);
  PetscErrorCode Flush();

private:
  std::vector<std::string> paths_, pending_;
  PetscInt                 dim_ = 0;
};

} // namespace slipwave::app
