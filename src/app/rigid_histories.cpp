#include "slipwave/app/rigid_histories.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "slipwave/io/whole_write.hpp"

namespace slipwave::app {

PetscErrorCode RigidHistories::Open(const problem::RigidBodies *rigid, PetscMPIInt rank, const std::string &dir, const std::string &previous, double t_restart) {
  PetscFunctionBeginUser;
  if (!rigid || rank != 0) PetscFunctionReturn(0);
  dim_ = rigid->dim;
  const std::string header = dim_ == 2 ? "t,u_x,u_y,theta_z\n" : "t,u_x,u_y,u_z,theta_x,theta_y,theta_z\n";
  for (const problem::RigidBody &body : rigid->bodies) {
    const std::string name = "rigid_" + body.region + ".csv";
    std::string       kept = header;
    // A restart: the earlier run's rows up to the restart time (the rows after it are redone).
    if (!previous.empty()) {
      std::ifstream in(previous + "/" + name);
      std::string   line;
      if (std::getline(in, line))
        while (std::getline(in, line))
          if (std::strtod(line.c_str(), nullptr) <= t_restart * (1 + 1e-12)) kept += line + "\n";
    }
    paths_.push_back(dir + "/" + name);
    PetscCheck(io::AppendWhole(paths_.back(), kept, true), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "cannot write %s: %s", paths_.back().c_str(), std::strerror(errno));
    pending_.emplace_back();
  }
  PetscFunctionReturn(0);
}

void RigidHistories::Sample(double t, const std::vector<double> &motion) {
  char row[256];
  for (size_t b = 0; b < paths_.size(); ++b) {
    const double *U = &motion[6 * b], *theta = U + 3;
    if (dim_ == 2) std::snprintf(row, sizeof row, "%.17g,%.17g,%.17g,%.17g\n", t, U[0], U[1], theta[2]);
    else std::snprintf(row, sizeof row, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", t, U[0], U[1], U[2], theta[0], theta[1], theta[2]);
    pending_[b] += row;
  }
}

PetscErrorCode RigidHistories::Flush() {
  PetscFunctionBeginUser;
  for (size_t b = 0; b < paths_.size(); ++b) {
    PetscCheck(io::AppendWhole(paths_[b], pending_[b], false), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "cannot write %s: %s", paths_[b].c_str(), std::strerror(errno));
    pending_[b].clear();
  }
  PetscFunctionReturn(0);
}

} // namespace slipwave::app
