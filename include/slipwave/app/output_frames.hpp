// The output frames: the volume fields (OUTPUT_DIR/volume.xmf/h5, unless -output_fields false)
// and each interface's state (interface_<name>.xmf/h5), written together at the first step,
// then every -output_interval and at the last step. These output times are also when the
// stations and energy.csv are flushed. The frame times and the next output time are part of a
// checkpoint, so a restarted run continues the same series.
#pragma once
#include <petscvec.h>

#include <memory>
#include <string>
#include <vector>

#include "slipwave/io/base_displacement.hpp"
#include "slipwave/io/interface_output.hpp"
#include "slipwave/io/volume_output.hpp"
#include "slipwave/problem/elastodynamics.hpp"

namespace slipwave::app {

class OutputFrames {
public:
  // interval: time between frames [s]; volume: write the volume grid. After a restart
  // (checkpoint_dir: the checkpoint's folder, else empty) the frames in times() are kept: the
  // files are copied from checkpoint_dir when dir is another folder, and the series continues.
  PetscErrorCode Open(const problem::Elastodynamics &model, const std::string &dir, PetscReal interval, bool volume, const std::string &checkpoint_dir);
  // Writes a frame at the first step, at the last one and whenever the next output time is
  // reached; due says whether this step was an output time.
  PetscErrorCode WriteIfDue(const problem::Elastodynamics &model, PetscInt step, PetscReal t, bool last, Vec u, Vec v, Vec a, bool *due);
  // Whether this step is an output time (the first, the last, or the next output time reached).
  bool Due(PetscInt step, PetscReal t, bool last) const { return t >= next_output_ * (1 - 1e-12) || last || step == 0; }
  PetscErrorCode Close();

  // What a checkpoint saves and restores (before Open).
  std::vector<PetscReal> *times() { return &times_; }
  PetscReal              *nextOutput() { return &next_output_; }

private:
  PetscReal                                         interval_    = 0;
  PetscReal                                         next_output_ = 0;
  std::vector<PetscReal>                            times_; // times of the frames written
  io::BaseDisplacement                              base_;   // taken off the displacement_relative fields
  std::unique_ptr<io::VolumeOutput>                 volume_; // null with -output_fields false
  std::vector<std::unique_ptr<io::InterfaceOutput>> interfaces_;
};

} // namespace slipwave::app
