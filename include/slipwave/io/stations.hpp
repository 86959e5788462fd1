// Stations: points given by coordinates (-station_coordinates x1,y1,x2,y2,... with
// -station_names, or -station_file with rows name,x,y[,z]) where u, v, a are interpolated
// with the cell's shape functions every step (spectral elements of degree p > 1: with the
// basis of the element holding the point, on its (p+1)^dim GLL nodes). At every output time (Flush) rank 0 appends the
// rows sampled since the last flush to DIR/stations/<name>.csv and to DIR/stations.h5
// (extendible datasets, file closed after each append), so a killed run keeps every row up to
// its last output time. The records stay in memory too: a checkpoint holds them all, and the
// first flush after a restart writes the files anew (a restart into a new folder is complete).
// Which cell: any cell holding the point gives the same value (the field is continuous inside
// a body) except on an interface, where the soil and the structure cells hold different
// nodes of each split pair. There the station records the side -station_side chooses
// (structure by default: a point on a foundation's base is usually there to see the
// foundation slide and lift), whatever the partition: among the ranks whose cells hold the
// point, the lowest one with a cell of that side. ambiguities() lists those stations for the
// run report.
#pragma once
#include <petscdm.h>

#include <string>
#include <vector>

#include "slipwave/fem/bulk_operator.hpp"
#include "slipwave/meshing/mesh_builder.hpp"

namespace slipwave::io {

// Before the mesh is built: the file of -station_file parsed in full (names, finite
// coordinates, as many as the built-in box has dimensions, or the same number on every row
// with a Gmsh mesh) by the reader Setup uses, which reads it again on the built mesh.
PetscErrorCode StationFileCheck(MPI_Comm comm);

class Stations {
public:
  PetscErrorCode Setup(DM dm, const fem::BulkOperator &bulk, const meshing::MeshDescription &mesh);
  // One line per station on an interface: where it is and which side it records.
  const std::vector<std::string> &ambiguities() const { return ambiguities_; }
  bool           empty() const { return names_.empty(); }
  // Samples the global u, v, a at time t.
  PetscErrorCode Sample(DM dm, PetscReal t, Vec u, Vec v, Vec a);
  // Saturated scenes, after each Sample: the pore pressure (global vectors, one dof per vertex
  // on a clone of dm) joins the row as columns p (total: hydrostatic + excess) and p_excess
  // [Pa], compression positive.
  PetscErrorCode SamplePressure(DM pdm, Vec p_total, Vec p_excess);
  // Collective: appends the rows sampled since the last flush to the station files; last: the
  // run's final flush.
  PetscErrorCode Flush(MPI_Comm comm, const std::string &dir, bool last);
  PetscErrorCode Destroy();
  const std::vector<std::string> &names() const { return names_; }
  // Checkpoints: this rank's records, station after station (each the same length).
  void saveRecords(std::vector<double> *out) const;
  void loadRecords(const double *in, size_t n);
  // A restart of a saturated scene: the records to load have the pore pressure columns.
  void expectPressure() { has_pressure_ = true; }
  size_t localStations() const { return local_.size(); }
  int    rowWidth() const { return 1 + 3 * (int)dim_ + (has_pressure_ ? 2 : 0); }

private:
  struct Local {
    PetscInt            station;
    std::vector<PetscInt> offsets; // local dof offsets of the cell's (degree > 1: the element's) nodes
    std::vector<double> shape;     // shape function (basis) values at the station
    std::vector<double> record;    // rows of t, u[dim], v[dim], a[dim]
  };
  PetscInt                 dim_ = 0;
  std::vector<std::string> names_;
  std::vector<double>      coords_;
  std::vector<Local>       local_;
  std::vector<std::string> ambiguities_;
  Vec                      work_[3] = {nullptr, nullptr, nullptr};
  size_t                   flushed_rows_ = 0; // rows per station already in the files
  std::vector<std::vector<double>> previous_;  // rank 0: the last flush's rows, not yet in the spare stations.h5
  Vec                      pressure_local_[2] = {nullptr, nullptr};
  bool                     has_pressure_ = false;
};

} // namespace slipwave::io
