#include "slipwave/input/drm_field_file.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace slipwave::input {
namespace {

// Dimensions of a double dataset, or "" and the problem.
std::string datasetShape(hid_t file, const char *name, std::vector<hsize_t> *dims) {
  if (H5Lexists(file, name, H5P_DEFAULT) <= 0) return std::string("has no dataset ") + name;
  const hid_t dset = H5Dopen2(file, name, H5P_DEFAULT), space = H5Dget_space(dset);
  dims->assign((size_t)std::max(H5Sget_simple_extent_ndims(space), 0), 0);
  H5Sget_simple_extent_dims(space, dims->data(), nullptr);
  H5Sclose(space);
  H5Dclose(dset);
  return "";
}

std::vector<double> readAll(hid_t file, const char *name, size_t n) {
  std::vector<double> v(n);
  const hid_t         dset = H5Dopen2(file, name, H5P_DEFAULT);
  H5Dread(dset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Dclose(dset);
  return v;
}

// Everything but the collective error report; returns the problem, "" when read.
std::string readHistories(const std::string &path, int dim, const std::vector<double> &points, double tol, FieldFileHistories *out) {
  char buf[400];
  H5E_auto2_t func;
  void       *data;
  H5Eget_auto2(H5E_DEFAULT, &func, &data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // our one-line message instead of HDF5's stack
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  H5Eset_auto2(H5E_DEFAULT, func, data);
  if (file < 0) return "cannot be opened as an HDF5 file";
  std::vector<hsize_t> dc, dt, du;
  std::string          problem = datasetShape(file, "coordinates", &dc);
  if (problem.empty()) problem = datasetShape(file, "time", &dt);
  if (problem.empty()) problem = datasetShape(file, "displacement", &du);
  if (problem.empty() && (dc.size() != 2 || dc[1] != (hsize_t)dim)) {
    std::snprintf(buf, sizeof buf, "has /coordinates of rank %zu; allowed: (n_points, %d)", dc.size(), dim);
    problem = buf;
  }
  if (problem.empty() && (dt.size() != 1 || dt[0] < 2)) problem = "has /time with fewer than 2 samples or not one-dimensional; allowed: (n_samples >= 2)";
  if (problem.empty() && (du.size() != 3 || du[0] != dc[0] || du[1] != dt[0] || du[2] != (hsize_t)dim)) {
    std::snprintf(buf, sizeof buf, "has /displacement not of shape (n_points %llu, n_samples %llu, %d)", (unsigned long long)dc[0],
                  (unsigned long long)(dt.empty() ? 0 : dt[0]), dim);
    problem = buf;
  }
  if (!problem.empty()) {
    H5Fclose(file);
    return problem;
  }
  const size_t        n = dc[0], m = dt[0];
  const std::vector<double> coords = readAll(file, "coordinates", n * dim), time = readAll(file, "time", m);
  const double        step = (time[m - 1] - time[0]) / (double)(m - 1);
  for (size_t k = 1; k < m && problem.empty(); ++k)
    if (!(step > 0) || std::fabs(time[k] - time[0] - (double)k * step) > 1e-6 * step) {
      std::snprintf(buf, sizeof buf, "has /time not uniform and increasing at sample %zu (%g s); allowed: a uniform time axis", k, time[k]);
      problem = buf;
    }
  // Each point's row in the file: sort the file's points by x, search the window x +- tol.
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return coords[a * dim] < coords[b * dim]; });
  const size_t        k_points = points.size() / dim;
  std::vector<size_t> row(k_points);
  for (size_t k = 0; k < k_points && problem.empty(); ++k) {
    const double *x  = &points[k * dim];
    auto          it = std::lower_bound(order.begin(), order.end(), x[0] - tol, [&](size_t a, double v) { return coords[a * dim] < v; });
    bool          found = false;
    for (; it != order.end() && coords[*it * dim] <= x[0] + tol && !found; ++it) {
      double d2 = 0;
      for (int i = 0; i < dim; ++i) d2 += (coords[*it * dim + i] - x[i]) * (coords[*it * dim + i] - x[i]);
      if (d2 <= tol * tol) row[k] = *it, found = true;
    }
    if (!found) {
      if (dim == 2) std::snprintf(buf, sizeof buf, "has no point at the DRM node (%g, %g) (within %g m)", x[0], x[1], tol);
      else std::snprintf(buf, sizeof buf, "has no point at the DRM node (%g, %g, %g) (within %g m)", x[0], x[1], x[2], tol);
      problem = buf;
    }
  }
  if (problem.empty()) {
    out->t0 = time[0], out->dt = step, out->samples = m, out->dim = dim;
    out->u.resize(k_points * m * dim);
    const hid_t dset = H5Dopen2(file, "displacement", H5P_DEFAULT), fspace = H5Dget_space(dset);
    const hsize_t count[3] = {1, m, (hsize_t)dim};
    const hid_t   mspace   = H5Screate_simple(3, count, nullptr);
    for (size_t k = 0; k < k_points; ++k) {
      const hsize_t start[3] = {row[k], 0, 0};
      H5Sselect_hyperslab(fspace, H5S_SELECT_SET, start, nullptr, count, nullptr);
      H5Dread(dset, H5T_NATIVE_DOUBLE, mspace, fspace, H5P_DEFAULT, &out->u[k * m * dim]);
    }
    H5Sclose(mspace);
    H5Sclose(fspace);
    H5Dclose(dset);
  }
  H5Fclose(file);
  return problem;
}

} // namespace

PetscErrorCode FieldFileRead(MPI_Comm comm, const std::string &option, const std::string &path, int dim, const std::vector<double> &points, double tol,
                             FieldFileHistories *out) {
  PetscMPIInt rank, size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::string problem = readHistories(path, dim, points, tol, out);
  // The first rank with a problem tells everyone, so the run stops with one line.
  PetscMPIInt first = problem.empty() ? size : rank;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, comm));
  if (first < size) {
    int len = (int)problem.size();
    PetscCallMPI(MPI_Bcast(&len, 1, MPI_INT, first, comm));
    problem.resize(len);
    PetscCallMPI(MPI_Bcast(problem.data(), len, MPI_CHAR, first, comm));
    SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s = %s %s", option.c_str(), path.c_str(), problem.c_str());
  }
  PetscFunctionReturn(0);
}

double FieldFileDisplacement(const FieldFileHistories &h, size_t point, int c, double t) {
  const double *u = &h.u[point * h.samples * h.dim];
  const double  s = std::clamp((t - h.t0) / h.dt, 0.0, (double)(h.samples - 1));
  const size_t  k = std::min((size_t)s, h.samples - 2);
  const double  x = s - (double)k;
  return (1 - x) * u[k * h.dim + c] + x * u[(k + 1) * h.dim + c];
}

} // namespace slipwave::input
