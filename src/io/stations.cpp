#include "slipwave/io/stations.hpp"

#include <hdf5.h>

#include <fcntl.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "slipwave/core/log_events.hpp"
#include "slipwave/core/option_choice.hpp"
#include "slipwave/core/option_rules.hpp"
#include "slipwave/core/options_check.hpp"
#include "slipwave/fem/spectral_kernels.hpp"
#include "slipwave/io/volume_output.hpp"
#include "slipwave/io/whole_write.hpp"
#include "slipwave/mesh/spectral_layout.hpp"

namespace slipwave::io {
namespace {

constexpr PetscInt kMaxListedStations = 100; // by -station_coordinates / -station_names

// Rows name,x,y[,z]. dim 0: the mesh is not built yet, so the dimension is the first row's
// (2 or 3 coordinates) and every row must match it.
PetscErrorCode readStationFile(MPI_Comm comm, const char *file, PetscInt dim, std::vector<std::string> *names, std::vector<double> *coords) {
  const auto z         = [&dim]() { return dim == 2 ? "" : dim == 3 ? ",z" : "[,z]"; };
  const bool dim_of_file = dim == 0;
  PetscFunctionBeginUser;
  std::ifstream in(file);
  PetscCheck(in.good(), comm, PETSC_ERR_FILE_OPEN, "-station_file = %s: cannot open the file; allowed: a CSV file with rows name,x,y%s", file, z());
  std::string line;
  int         lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line[0] == '#') continue;
    std::stringstream        ss(line);
    std::string              cell;
    std::vector<std::string> cells;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    if (lineno == 1 && cells.size() > 1 && cells[1].find_first_of("0123456789") == std::string::npos) continue; // header
    if (dim == 0 && (cells.size() == 3 || cells.size() == 4)) dim = (PetscInt)cells.size() - 1;
    PetscCheck((PetscInt)cells.size() == dim + 1, comm, PETSC_ERR_USER_INPUT, "-station_file = %s, line %d: %zu columns; allowed: name,x,y%s%s", file, lineno,
               cells.size(), z(), dim_of_file && !names->empty() ? " as on the rows before" : "");
    // The name becomes a file name (stations/<name>.csv).
    PetscCheck(core::IsSafeFileName(cells[0]), comm, PETSC_ERR_USER_INPUT, "-station_file = %s, line %d: station name '%s'; allowed: %s", file, lineno,
               cells[0].c_str(), core::kSafeFileNameRule);
    PetscCheck(std::find(names->begin(), names->end(), cells[0]) == names->end(), comm, PETSC_ERR_USER_INPUT,
               "-station_file = %s, line %d: station name '%s' is used twice; allowed: distinct names", file, lineno, cells[0].c_str());
    names->push_back(cells[0]);
    for (PetscInt d = 0; d < dim; ++d) {
      char        *end;
      const double x = std::strtod(cells[1 + d].c_str(), &end);
      PetscCheck(end != cells[1 + d].c_str() && *end == '\0' && std::isfinite(x), comm, PETSC_ERR_USER_INPUT,
                 "-station_file = %s, line %d: '%s' is not a finite number; allowed: coordinates x,y%s [m]", file, lineno, cells[1 + d].c_str(), z());
      coords->push_back(x);
    }
  }
  PetscCheck(!names->empty(), comm, PETSC_ERR_USER_INPUT, "-station_file = %s: no station rows; allowed: a CSV file with rows name,x,y%s", file, z());
  PetscFunctionReturn(0);
}

// Degree p > 1: the weights of the station at x on the nodes of the element holding sub-cell
// `cell`, so the record has the element's order, not the sub-cell's linear interpolation.
// The element's reference coordinates come from its Q1 corner map, which is exact: every GLL
// node lies on it (meshing/spectral_subdivision); the weights are the tensor Lagrange basis on
// its (p+1)^dim GLL nodes (at a node: 1 there, 0 elsewhere, to round-off).
PetscErrorCode elementWeights(DM dm, const fem::BulkOperator &bulk, PetscInt cell, const double *x, std::vector<PetscInt> *offsets, std::vector<double> *weights) {
  // The element kernels' corner order (cyclic, fem/element_kernels.hpp) as lexicographic
  // corners (x fastest) of the element frame.
  constexpr PetscInt          kLexCorner[8] = {0, 1, 3, 2, 4, 5, 7, 6};
  const mesh::SpectralLayout *layout;
  mesh::VertexCoordinates     vc;
  PetscFunctionBeginUser;
  PetscCall(mesh::SpectralLayoutOf(dm, &layout));
  const PetscInt dim = bulk.dimension(), p = bulk.degree(), n1 = p + 1, nq = bulk.nodesPerElement(), element = layout->cell_element[cell];
  double         corners[8 * 3], xi[3];
  PetscCall(vc.Open(dm));
  for (PetscInt k = 0; k < (dim == 2 ? 4 : 8); ++k) {
    const PetscInt lex = kLexCorner[k], node = (lex & 1) * p + n1 * (((lex >> 1) & 1) * p + n1 * ((lex >> 2) & 1) * p);
    PetscCall(vc.Get(layout->element_nodes[element * nq + node], &corners[k * dim]));
  }
  PetscCall(vc.Close());
  // The point lies in one of the element's sub-cells, hence in the element.
  PetscCheck(numerics::referenceCoordinates(dim == 2 ? numerics::CellShape::Quad4 : numerics::CellShape::Hex8, corners, x, xi, 1e-8), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "station: no reference coordinates in element %" PetscInt_FMT " although its sub-cell %" PetscInt_FMT " holds the point", element, cell);
  weights->resize(nq);
  fem::spectralBasisValues((int)dim, (int)p, xi, weights->data());
  offsets->resize(nq);
  for (PetscInt a = 0; a < nq; ++a) (*offsets)[a] = bulk.elementNodeOffset(element, a);
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode StationFileCheck(MPI_Comm comm) {
  std::map<std::string, std::string> given;
  std::vector<std::string>           names;
  std::vector<double>                coords;
  PetscFunctionBeginUser;
  PetscCall(core::OptionsNotYetRead(&given));
  const auto file = given.find("station_file");
  if (file == given.end() || file->second.empty()) PetscFunctionReturn(0);
  // The built-in box's dimension is known from the options (range-checked already); a Gmsh
  // file's only once it is read.
  const auto     mesh_dim = given.find("mesh_dim");
  const PetscInt dim      = given.count("mesh_file") ? 0 : mesh_dim != given.end() ? std::atoi(mesh_dim->second.c_str()) : meshing::MeshDescription{}.dim;
  PetscCall(readStationFile(comm, file->second.c_str(), dim, &names, &coords));
  PetscFunctionReturn(0);
}

PetscErrorCode Stations::Setup(DM dm, const fem::BulkOperator &bulk, const meshing::MeshDescription &mesh) {
  MPI_Comm  comm = PetscObjectComm((PetscObject)dm);
  const char *const sides[] = {"structure", "soil"};
  PetscInt          side = 0; // index in sides[]
  char      file[PETSC_MAX_PATH_LEN] = "";
  PetscReal xs[3 * kMaxListedStations] = {}; // -help prints xs[0] as the default
  PetscInt  nx = 3 * kMaxListedStations;
  char     *listed_names[kMaxListedStations];
  PetscInt  nnames = kMaxListedStations;
  PetscBool has_file, has_coords;
  PetscFunctionBeginUser;
  dim_ = bulk.dimension();
  PetscOptionsBegin(comm, "", "Stations (time series at points)", "slipwave");
  PetscCall(PetscOptionsString("-station_file", "CSV file with rows name,x,y[,z] [m]", "Stations::Setup", file, file, sizeof file, &has_file));
  PetscCall(PetscOptionsRealArray("-station_coordinates", "x1,y1[,z1],x2,y2[,z2],... [m]", "Stations::Setup", xs, &nx, &has_coords));
  PetscCall(PetscOptionsStringArray("-station_names", "comma-separated names for -station_coordinates (default S1, S2, ...)", "Stations::Setup", listed_names, &nnames,
                                    nullptr));
  PetscCall(core::OptionsChoice(PetscOptionsObject, "-station_side", "side recorded by a station on an interface (split nodes): structure or soil", sides, 2, &side,
                                nullptr));
  PetscCall(PetscOptionsReal("-station_interval", "time between station samples [s], >= 0 (0: every step); rounded to a whole number of steps, the step's values, unfiltered",
                             "Stations::Setup", interval_, &interval_, nullptr));
  PetscCall(PetscOptionsBool("-station_stress", "also record the stress [Pa] and strain [-] of the cell holding each station", "Stations::Setup", stress_, &stress_, nullptr));
  PetscOptionsEnd();
  PetscCheck(interval_ >= 0 && std::isfinite(interval_), comm, PETSC_ERR_USER_INPUT, "-station_interval = %g; allowed: a time >= 0 s (0: every step)", (double)interval_);
  if (has_file) PetscCall(readStationFile(comm, file, dim_, &names_, &coords_));
  if (has_coords) {
    PetscCheck(nx % dim_ == 0, comm, PETSC_ERR_USER_INPUT, "-station_coordinates has %" PetscInt_FMT " values; allowed: a multiple of %" PetscInt_FMT, nx, dim_);
    for (PetscInt s = 0; s < nx / dim_; ++s) {
      names_.push_back(s < nnames && listed_names[s][0] ? std::string(listed_names[s]) : "S" + std::to_string(names_.size() + 1));
      for (PetscInt d = 0; d < dim_; ++d) coords_.push_back(xs[s * dim_ + d]);
    }
  }
  for (PetscInt k = 0; k < nnames; ++k) PetscCall(PetscFree(listed_names[k]));
  PetscMPIInt rank, size;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  const numerics::CellShape shape = bulk.shape();
  const PetscInt       nen   = bulk.nodesPerCell();
  const size_t nif = mesh.interfaces.size();
  for (size_t s = 0; s < names_.size(); ++s) {
    const double         *x = &coords_[s * dim_];
    std::vector<PetscInt> holding; // this rank's cells that hold the point
    std::vector<double>   xis;
    for (PetscInt c = 0; c < bulk.cellCount(); ++c) {
      const double *xc     = bulk.cellCoordinates(c);
      bool          inside = true;
      for (PetscInt d = 0; d < dim_ && inside; ++d) {
        double lo = 1e300, hi = -1e300;
        for (PetscInt a = 0; a < nen; ++a) {
          lo = std::min(lo, xc[a * dim_ + d]);
          hi = std::max(hi, xc[a * dim_ + d]);
        }
        const double tol = 1e-9 * (hi - lo);
        inside           = x[d] >= lo - tol && x[d] <= hi + tol;
      }
      double xi[3];
      if (inside && numerics::referenceCoordinates(shape, xc, x, xi, 1e-8)) {
        holding.push_back(c);
        xis.insert(xis.end(), xi, xi + 3);
      }
    }
    // Per interface: bit 1 if a soil cell holds the point, bit 2 if a structure cell does.
    std::vector<int> touch(nif, 0);
    for (PetscInt c : holding)
      for (size_t k = 0; k < nif; ++k) {
        const std::string &region = mesh.regions[bulk.cellRegion(c)];
        touch[k] |= (region == mesh.interfaces[k].soil_region ? 1 : 0) | (region == mesh.interfaces[k].structure_region ? 2 : 0);
      }
    if (nif) PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, touch.data(), (int)nif, MPI_INT, MPI_BOR, comm));
    // Priority 0: a cell of the chosen side of an interface the point lies on; 1: any other.
    auto priority = [&](PetscInt c) {
      const std::string &region = mesh.regions[bulk.cellRegion(c)];
      for (size_t k = 0; k < nif; ++k)
        if (touch[k] == 3 && region == (side == 0 ? mesh.interfaces[k].structure_region : mesh.interfaces[k].soil_region)) return 0;
      return 1;
    };
    // Among the cells holding the point, the one of lowest key (priority, then its centroid's
    // x, y, z) owns the station: the same cell on any partition, so that its stress and strain
    // (-station_stress, discontinuous between cells) do not depend on it; ties (a cell on two
    // ranks) go to the lowest rank. Key[0] = 3: no cell on this rank.
    using Key = std::array<double, 4>;
    auto keyOf = [&](PetscInt c) {
      Key k = {(double)priority(c), 0, 0, 0};
      for (PetscInt a = 0; a < nen; ++a)
        for (PetscInt d = 0; d < dim_; ++d) k[1 + d] += bulk.cellCoordinates(c)[a * dim_ + d] / nen;
      return k;
    };
    Key      mine  = {3, 0, 0, 0};
    PetscInt found = -1;
    double   xi[3] = {0, 0, 0};
    for (size_t h = 0; h < holding.size(); ++h)
      if (keyOf(holding[h]) < mine) {
        mine  = keyOf(holding[h]);
        found = holding[h];
        std::copy(&xis[3 * h], &xis[3 * h] + 3, xi);
      }
    std::vector<Key> keys(size);
    PetscCallMPI(MPI_Allgather(mine.data(), 4, MPI_DOUBLE, keys.data(), 4, MPI_DOUBLE, comm));
    const PetscMPIInt owner = (PetscMPIInt)(std::min_element(keys.begin(), keys.end()) - keys.begin());
    char point[96];
    if (dim_ == 3) std::snprintf(point, sizeof point, "(%g, %g, %g)", x[0], x[1], x[2]);
    else std::snprintf(point, sizeof point, "(%g, %g)", x[0], x[1]);
    PetscCheck(keys[owner][0] < 3, comm, PETSC_ERR_USER_INPUT, "station '%s' at %s lies outside the mesh; allowed: points inside the mesh", names_[s].c_str(), point);
    for (size_t k = 0; k < nif; ++k)
      if (touch[k] == 3) {
        const auto &spec = mesh.interfaces[k];
        char        line[512];
        std::snprintf(line, sizeof line, "station %s at %s lies on interface %s (split nodes): records the %s side (%s); -station_side %s records the other",
                      names_[s].c_str(), point, spec.name.c_str(), sides[side], side == 0 ? spec.structure_region.c_str() : spec.soil_region.c_str(),
                      sides[1 - side]);
        ambiguities_.push_back(line);
      }
    if (rank == owner) {
      double N[8];
      Local  l;
      l.station = (PetscInt)s;
      l.cell    = found;
      if (bulk.degree() > 1) PetscCall(elementWeights(dm, bulk, found, x, &l.offsets, &l.shape));
      else {
        numerics::shapeFunctions(shape, xi, N);
        for (PetscInt a = 0; a < nen; ++a) {
          l.offsets.push_back(bulk.cellNodeOffset(found, a));
          l.shape.push_back(N[a]);
        }
      }
      local_.push_back(std::move(l));
    }
  }
  if (!names_.empty())
    for (Vec &w : work_) PetscCall(DMCreateLocalVector(dm, &w));
  PetscFunctionReturn(0);
}

void Stations::setTimeStep(double dt) { every_ = interval_ > 0 ? std::max<long>(1, std::lround(interval_ / dt)) : 1; }

PetscErrorCode Stations::Sample(DM dm, PetscReal t, Vec u, Vec v, Vec a) {
  PetscFunctionBeginUser;
  if (names_.empty()) PetscFunctionReturn(0);
  PetscCall(PetscLogEventBegin(core::event_stations, 0, 0, 0, 0));
  Vec                globals[3] = {u, v, a};
  const PetscScalar *arr[3];
  for (int k = 0; k < 3; ++k) {
    PetscCall(DMGlobalToLocal(dm, globals[k], INSERT_VALUES, work_[k]));
    PetscCall(VecGetArrayRead(work_[k], &arr[k]));
  }
  for (Local &l : local_) {
    l.record.push_back(t);
    for (int k = 0; k < 3; ++k)
      for (PetscInt d = 0; d < dim_; ++d) {
        double s = 0;
        for (size_t n = 0; n < l.offsets.size(); ++n) s += l.shape[n] * PetscRealPart(arr[k][l.offsets[n] + d]);
        l.record.push_back(s);
      }
  }
  for (int k = 0; k < 3; ++k) PetscCall(VecRestoreArrayRead(work_[k], &arr[k]));
  PetscCall(PetscLogEventEnd(core::event_stations, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode Stations::Values(DM dm, Vec u, Vec a, const std::vector<Probe> &wanted, std::vector<double> *values) {
  PetscFunctionBeginUser;
  values->assign(wanted.size(), 0.0);
  if (wanted.empty()) PetscFunctionReturn(0);
  PetscCall(PetscLogEventBegin(core::event_stations, 0, 0, 0, 0));
  const PetscScalar *arr[3] = {nullptr, nullptr, nullptr};
  for (int k : {0, 2}) {
    PetscCall(DMGlobalToLocal(dm, k == 0 ? u : a, INSERT_VALUES, work_[k]));
    PetscCall(VecGetArrayRead(work_[k], &arr[k]));
  }
  for (size_t w = 0; w < wanted.size(); ++w)
    for (const Local &l : local_)
      if (l.station == wanted[w].station) {
        double s = 0;
        for (size_t n = 0; n < l.offsets.size(); ++n) s += l.shape[n] * PetscRealPart(arr[wanted[w].field][l.offsets[n] + wanted[w].component]);
        (*values)[w] = s;
      }
  for (int k : {0, 2}) PetscCall(VecRestoreArrayRead(work_[k], &arr[k]));
  PetscCall(PetscLogEventEnd(core::event_stations, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode Stations::SamplePressure(DM pdm, Vec p_total, Vec p_excess) {
  PetscFunctionBeginUser;
  if (names_.empty()) PetscFunctionReturn(0);
  has_pressure_ = true;
  const PetscScalar *arr[2];
  Vec                globals[2] = {p_total, p_excess};
  for (int k = 0; k < 2; ++k) {
    if (!pressure_local_[k]) PetscCall(DMCreateLocalVector(pdm, &pressure_local_[k]));
    PetscCall(DMGlobalToLocal(pdm, globals[k], INSERT_VALUES, pressure_local_[k]));
    PetscCall(VecGetArrayRead(pressure_local_[k], &arr[k]));
  }
  // The pressure layout has one dof where the displacement has dim_ (fem/node_fields.hpp).
  for (Local &l : local_)
    for (int k = 0; k < 2; ++k) {
      double s = 0;
      for (size_t n = 0; n < l.offsets.size(); ++n) s += l.shape[n] * PetscRealPart(arr[k][l.offsets[n] / dim_]);
      l.record.push_back(s);
    }
  for (int k = 0; k < 2; ++k) PetscCall(VecRestoreArrayRead(pressure_local_[k], &arr[k]));
  PetscFunctionReturn(0);
}

PetscErrorCode Stations::SampleStress(const fem::BulkOperator &bulk, const std::vector<double> &initial_stress, const medium::Hysteresis *hysteresis) {
  PetscFunctionBeginUser;
  if (!stress_ || names_.empty()) PetscFunctionReturn(0);
  PetscCall(PetscLogEventBegin(core::event_stations, 0, 0, 0, 0));
  const PetscScalar *ul;
  PetscCall(VecGetArrayRead(work_[0], &ul)); // Sample's u
  for (Local &l : local_) {
    double relaxation[fem::kStressComponents] = {}, sigma[fem::kStressComponents], eps[fem::kStressComponents];
    if (hysteresis) medium::HysteresisCellRelaxation(hysteresis, ul, l.cell, relaxation);
    CellStressShown(bulk, l.cell, ul, initial_stress, hysteresis ? relaxation : nullptr, sigma);
    bulk.cellStrain(l.cell, ul, eps);
    for (int k : stressColumns()) l.record.push_back(sigma[k]);
    for (int k : strainColumns()) l.record.push_back(eps[k]);
  }
  PetscCall(VecRestoreArrayRead(work_[0], &ul));
  PetscCall(PetscLogEventEnd(core::event_stations, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

namespace {

// A dataset of a station's group: its columns [first, first + width) of the row; width 0: one
// column as a 1D dataset.
struct Dataset {
  const char *name;
  int         first, width;
};

// Rows per HDF5 chunk: a few KiB, so a short run's file stays small and a long one's appends
// touch few chunks.
constexpr hsize_t kChunkRows = 256;

// stations.h5's copy one flush behind (see Flush); app/output_dir.cpp lists it as a run file.
const char *const kSpareName = ".stations.h5.spare";

// A new, empty, extendible dataset: [0] or [0, width], growing along the first dimension.
hid_t createExtendible(hid_t group, const char *name, int width) {
  const int     rank     = width == 0 ? 1 : 2;
  const hsize_t dims[2]  = {0, (hsize_t)width}, maxdims[2] = {H5S_UNLIMITED, (hsize_t)width};
  const hsize_t chunk[2] = {kChunkRows, (hsize_t)std::max(width, 1)};
  hid_t         space    = H5Screate_simple(rank, dims, maxdims);
  hid_t         plist    = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(plist, rank, chunk);
  hid_t dset = H5Dcreate2(group, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, plist, H5P_DEFAULT);
  H5Pclose(plist);
  H5Sclose(space);
  return dset;
}

// Appends rows (row-major, width columns; width 0: a 1D dataset) to an extendible dataset.
herr_t appendRows(hid_t dset, const std::vector<double> &rows, int width) {
  const int cols = std::max(width, 1);
  const int rank = width == 0 ? 1 : 2;
  hsize_t   dims[2], add[2] = {rows.size() / cols, (hsize_t)cols}, start[2] = {0, 0};
  hid_t     space = H5Dget_space(dset);
  H5Sget_simple_extent_dims(space, dims, nullptr);
  H5Sclose(space);
  start[0]           = dims[0];
  const hsize_t grown[2] = {dims[0] + add[0], (hsize_t)cols};
  herr_t        status   = H5Dset_extent(dset, grown);
  space                  = H5Dget_space(dset);
  hid_t memory           = H5Screate_simple(rank, add, nullptr);
  if (status >= 0) status = H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, add, nullptr);
  if (status >= 0) status = H5Dwrite(dset, H5T_NATIVE_DOUBLE, memory, space, H5P_DEFAULT, rows.data());
  H5Sclose(memory);
  H5Sclose(space);
  return status;
}

// Appends rows (per station, row-major, row values each) to the station groups of an HDF5 file,
// created with its groups (each with the attribute "coordinates", the station's point [m],
// dim of coords per station, which plots use to order the stations) and empty extendible
// datasets first if create.
PetscErrorCode appendRowsToFile(const std::string &path, bool create, const std::vector<std::string> &names, const std::vector<double> &coords,
                                const std::vector<std::vector<double>> &rows, int row, const std::vector<Dataset> &datasets) {
  PetscFunctionBeginUser;
  hid_t file = create ? H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT) : H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  PetscCheck(file >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot write %s", path.c_str());
  herr_t status = 0;
  for (size_t s = 0; s < names.size() && status >= 0; ++s) {
    hid_t        group = create ? H5Gcreate2(file, names[s].c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT) : H5Gopen2(file, names[s].c_str(), H5P_DEFAULT);
    if (create) {
      const hsize_t dim   = coords.size() / names.size();
      hid_t         space = H5Screate_simple(1, &dim, nullptr);
      hid_t         attr  = H5Acreate2(group, "coordinates", H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
      status              = attr < 0 ? (herr_t)-1 : H5Awrite(attr, H5T_NATIVE_DOUBLE, &coords[s * dim]);
      if (attr >= 0) H5Aclose(attr);
      H5Sclose(space);
    }
    const size_t nt    = rows[s].size() / row;
    for (size_t q = 0; q < datasets.size() && status >= 0; ++q) {
      const int           width = datasets[q].width, cols = std::max(width, 1);
      std::vector<double> buf(nt * cols);
      for (size_t r = 0; r < nt; ++r)
        for (int k = 0; k < cols; ++k) buf[r * cols + k] = rows[s][r * row + datasets[q].first + k];
      hid_t dset = create ? createExtendible(group, datasets[q].name, width) : H5Dopen2(group, datasets[q].name, H5P_DEFAULT);
      status     = dset < 0 ? (herr_t)-1 : appendRows(dset, buf, width);
      if (dset >= 0) H5Dclose(dset);
    }
    H5Gclose(group);
  }
  const herr_t closed = H5Fclose(file);
  PetscCheck(status >= 0 && closed >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "cannot append to %s", path.c_str());
  PetscFunctionReturn(0);
}

// Swaps the names of two files in one step (Linux renameat2 RENAME_EXCHANGE). Where the file
// system cannot, three renames do it, with an instant in which only the spare names the rows.
PetscErrorCode exchangeFiles(const std::string &a, const std::string &b) {
  PetscFunctionBeginUser;
  if (renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) != 0) {
    const std::string held = a + ".swap";
    const bool        ok   = std::rename(b.c_str(), held.c_str()) == 0 && std::rename(a.c_str(), b.c_str()) == 0 && std::rename(held.c_str(), a.c_str()) == 0;
    PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "cannot replace %s: %s", b.c_str(), std::strerror(errno));
  }
  PetscFunctionReturn(0);
}

} // namespace

// Gathers the rows sampled since the last flush on rank 0, station by station, in station
// order, and appends them to the CSV files and to stations.h5 (created at the first flush);
// last: the run's final flush (the spare copy is removed).
PetscErrorCode Stations::Flush(MPI_Comm comm, const std::string &dir, bool last) {
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  if (names_.empty()) PetscFunctionReturn(0);
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  const int                        row = rowWidth();
  const size_t                     from = flushed_rows_ * row;
  std::vector<std::vector<double>> fresh(names_.size());
  for (size_t s = 0; s < names_.size(); ++s) {
    const Local *l = nullptr;
    for (const Local &x : local_)
      if (x.station == (PetscInt)s) l = &x;
    PetscMPIInt owner_claim = l ? rank : INT32_MAX, owner;
    PetscCallMPI(MPI_Allreduce(&owner_claim, &owner, 1, MPI_INT, MPI_MIN, comm));
    int count = rank == owner ? (int)(l->record.size() - from) : 0;
    PetscCallMPI(MPI_Bcast(&count, 1, MPI_INT, owner, comm));
    fresh[s].resize(count);
    if (rank == owner && owner == 0) fresh[s].assign(l->record.begin() + from, l->record.end());
    else if (rank == owner) PetscCallMPI(MPI_Send(l->record.data() + from, count, MPI_DOUBLE, 0, (int)s, comm));
    else if (rank == 0) PetscCallMPI(MPI_Recv(fresh[s].data(), count, MPI_DOUBLE, owner, (int)s, comm, MPI_STATUS_IGNORE));
  }
  const bool first = flushed_rows_ == 0;
  flushed_rows_ += fresh[0].size() / row; // every station samples at the same steps: the same count
  if (rank != 0) PetscFunctionReturn(0);
  if (first) {
    std::error_code error;
    std::filesystem::create_directories(dir + "/stations", error);
    PetscCheck(!error, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot create %s/stations: %s", dir.c_str(), error.message().c_str());
  }
  const char *axes = "xyz";
  const char *const kComponents[6] = {"xx", "yy", "zz", "xy", "yz", "xz"};
  for (size_t s = 0; s < names_.size(); ++s) {
    const std::string path = dir + "/stations/" + names_[s] + ".csv";
    std::string       text;
    char              cell[32];
    if (first) {
      text = "t";
      for (const char *q : {"u", "v", "a"})
        for (PetscInt d = 0; d < dim_; ++d) text += std::string(",") + q + "_" + axes[d];
      if (has_pressure_) text += ",p,p_excess";
      if (stress_) {
        for (int k : stressColumns()) text += std::string(",s_") + kComponents[k];
        for (int k : strainColumns()) text += std::string(",e_") + kComponents[k];
      }
      text += "\n";
    }
    for (size_t r = 0; r + row <= fresh[s].size(); r += row) {
      for (int k = 0; k < row; ++k) {
        std::snprintf(cell, sizeof cell, k ? ",%.17g" : "%.17g", fresh[s][r + k]);
        text += cell;
      }
      text += '\n';
    }
    // One write for the flush's rows: a kill leaves the CSV ending at an output time.
    PetscCheck(AppendWhole(path, text, first), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "cannot write %s: %s", path.c_str(), std::strerror(errno));
  }
  // stations.h5 is never appended in place: an HDF5 file cut by a kill in the middle of a write
  // can be unreadable as a whole. A spare copy, one flush behind, takes the last two flushes'
  // rows and then trades names with stations.h5 in one atomic rename, so stations.h5 is always
  // a file that was closed whole.
  const std::string h5path = dir + "/stations.h5", spare = dir + "/" + kSpareName;
  const int         dim = (int)dim_, after = 1 + 3 * dim + (has_pressure_ ? 2 : 0), nstress = (int)stressColumns().size();
  // Time and the pore pressures: one column each; the pressures in saturated scenes only.
  std::vector<Dataset> datasets = {{"time", 0, 0}, {"displacement", 1, dim}, {"velocity", 1 + dim, dim}, {"acceleration", 1 + 2 * dim, dim}};
  if (has_pressure_) datasets.insert(datasets.end(), {{"pore_pressure", 1 + 3 * dim, 0}, {"excess_pore_pressure", 2 + 3 * dim, 0}});
  if (stress_) datasets.insert(datasets.end(), {{"stress", after, nstress}, {"strain", after + nstress, (int)strainColumns().size()}});
  if (first) {
    const std::string partial = dir + "/.stations.h5.partial";
    PetscCall(appendRowsToFile(partial, true, names_, coords_, fresh, row, datasets));
    PetscCheck(std::rename(partial.c_str(), h5path.c_str()) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "cannot write %s: %s", h5path.c_str(), std::strerror(errno));
    if (!last) PetscCall(appendRowsToFile(spare, true, names_, coords_, fresh, row, datasets));
    previous_.assign(names_.size(), {});
  } else {
    std::vector<std::vector<double>> rows = previous_;
    for (size_t s = 0; s < names_.size(); ++s) rows[s].insert(rows[s].end(), fresh[s].begin(), fresh[s].end());
    PetscCall(appendRowsToFile(spare, false, names_, coords_, rows, row, datasets));
    PetscCall(exchangeFiles(spare, h5path));
    previous_ = std::move(fresh);
  }
  if (last) std::remove(spare.c_str());
  PetscFunctionReturn(0);
}

void Stations::saveRecords(std::vector<double> *out) const {
  out->clear();
  for (const Local &l : local_) out->insert(out->end(), l.record.begin(), l.record.end());
}

void Stations::loadRecords(const double *in, size_t n) {
  const size_t each = local_.empty() ? 0 : n / local_.size();
  for (size_t k = 0; k < local_.size(); ++k) local_[k].record.assign(in + k * each, in + (k + 1) * each);
  flushed_rows_ = 0; // the next flush writes the files anew with every row so far
}

PetscErrorCode Stations::Destroy() {
  PetscFunctionBeginUser;
  for (Vec &w : work_) PetscCall(VecDestroy(&w));
  for (Vec &w : pressure_local_) PetscCall(VecDestroy(&w));
  PetscFunctionReturn(0);
}

} // namespace slipwave::io
