// A scalar history read from options with a prefix: the incident wave's particle velocity,
// or a prescribed boundary velocity. -<prefix>stf none|ricker|gabor|record and its
// parameters. Velocity is the primary quantity; acceleration drives prescribed dofs.
#pragma once
#include <petscsys.h>

#include <memory>
#include <string>

namespace slipwave::model {

class TimeFunction {
public:
  TimeFunction();
  ~TimeFunction();
  TimeFunction(TimeFunction &&) noexcept;
  TimeFunction &operator=(TimeFunction &&) noexcept;

  // Reads -<prefix>stf and its parameters inside the caller's options block.
  PetscErrorCode Read(MPI_Comm comm, const std::string &prefix, PetscOptionItems *PetscOptionsObject);
  bool        active() const;
  double      velocity(double t) const;
  double      acceleration(double t) const;
  double      topFrequency() const;
  std::string describe() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace slipwave::model
