// A DRM free field read from an HDF5 file, so that a wave field computed by another code
// (a regional simulation, a 3D basin model) drives the model. Layout (HDF5 datasets, doubles):
//   /coordinates   (n_points, dim)            point positions [m], in the model's frame
//   /time          (n_samples)                uniform, strictly increasing [s], the model's clock
//   /displacement  (n_points, n_samples, dim) free-field displacement [m]
// The file may hold more points than the DRM layer needs; every DRM node must be one of them
// (within tol). Before the first sample the displacement is that of the first sample, after
// the last one that of the last; in between it is linear in time (the layer's forces need only
// the displacement: the mass is lumped).
#pragma once
#include <petscsys.h>

#include <string>
#include <vector>

namespace slipwave::input {

struct FieldFileHistories {
  double              t0 = 0, dt = 0;
  size_t              samples = 0;
  int                 dim = 0;
  std::vector<double> u; // per requested point: samples x dim
};

// Reads the histories of the points (k x dim, row-major) from path; every rank reads for its
// own points. Stops (on comm) with one line when the file or a dataset is missing or malformed,
// or when a point is not in the file.
PetscErrorCode FieldFileRead(MPI_Comm comm, const std::string &option, const std::string &path, int dim, const std::vector<double> &points, double tol,
                             FieldFileHistories *out);
double FieldFileDisplacement(const FieldFileHistories &h, size_t point, int component, double t);

} // namespace slipwave::input
