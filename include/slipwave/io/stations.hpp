// Stations: points given by coordinates (-station_coordinates x1,y1,x2,y2,... with
// -station_names, or -station_file with rows name,x,y[,z]) where u, v, a are interpolated
// with the cell's shape functions every N-th step, N = -station_interval / dt rounded (at least
// 1; default 0.005 s, 200 samples per second; 0: every step): uniform samples, each the
// values of its step, not filtered (spectral elements of degree p > 1: with the
// basis of the element holding the point, on its (p+1)^dim GLL nodes). At every output time (Flush) rank 0 appends the
// rows sampled since the last flush to DIR/stations/<name>.csv and to DIR/stations.h5
// (extendible datasets, file closed after each append), so a killed run keeps every row up to
// its last output time. The records stay in memory too: a checkpoint holds them all, and the
// first flush after a restart writes the files anew (a restart into a new folder is complete).
// Which cell: any cell holding the point gives the same value (the field is continuous inside
// a body) except on an interface, where the soil and the structure cells hold different
// nodes of each split pair. There the station records the side -station_side chooses
// (structure by default: a point on a foundation's base is usually there to see the
// foundation slide and lift). ambiguities() lists those stations for the run report. Of the
// cells holding the point (of that side) the station takes the one with the lowest centroid
// (x, then y, z), whatever the partition.
// -station_stress true adds the stress and strain of that cell (the stress the volume output
// shows for it, io/volume_output.hpp: the cell's centroid, at degree p > 1 the element's basis
// at the sub-cell's centre; the strain at the same point) as the last columns, s_* [Pa] and
// e_* [-] (tensor components). A point on a cell face gets one of the cells' values: the
// stress jumps there.
#pragma once
#include <petscdm.h>

#include <string>
#include <vector>

#include "slipwave/fem/bulk_operator.hpp"
#include "slipwave/medium/hysteresis.hpp"
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
  // The time step dt of the run sets the sampling: every N-th step, N = round(interval / dt).
  void           setTimeStep(double dt);
  bool           due(PetscInt step) const { return step % every_ == 0; }
  long           samplingSteps() const { return every_; }
  // Rows per station from step 0 to step (a checkpoint's records).
  PetscInt       samplesUpTo(PetscInt step) const { return step / (PetscInt)every_ + 1; }
  // Samples the global u, v, a at time t.
  PetscErrorCode Sample(DM dm, PetscReal t, Vec u, Vec v, Vec a);
  // Every step if asked (the run's answers, app/run_answers): for each (station, field,
  // component) of wanted (field 0: u, 2: a), the value on the rank that owns the station and
  // 0 on the others (a sum over the ranks gives it everywhere). Collective.
  struct Probe {
    int station, field, component;
  };
  PetscErrorCode Values(DM dm, Vec u, Vec a, const std::vector<Probe> &wanted, std::vector<double> *values);
  // Station s's coordinates [m] (as many as the mesh has dimensions).
  const double  *coordinates(size_t s) const { return &coords_[s * dim_]; }
  // Saturated scenes, after each Sample: the pore pressure (global vectors, one dof per vertex
  // on a clone of dm) joins the row as columns p (total: hydrostatic + excess) and p_excess
  // [Pa], compression positive.
  PetscErrorCode SamplePressure(DM pdm, Vec p_total, Vec p_excess);
  // With -station_stress, after Sample (and SamplePressure), closing the row: the stress of
  // the station's cell as the volume output shows it (initial_stress: 6 per local cell, or
  // empty; hysteresis: the hysteretic regions, or null), columns s_xx, s_yy, s_zz, s_xy
  // (3D: and s_yz, s_xz) [Pa], and the strain of u there, e_xx, e_yy, e_xy (3D: e_xx, e_yy,
  // e_zz, e_xy, e_yz, e_xz) [-], tensor components (the engineering shear strain is 2 e_xy).
  PetscErrorCode SampleStress(const fem::BulkOperator &bulk, const std::vector<double> &initial_stress, const medium::Hysteresis *hysteresis);
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
  int    rowWidth() const { return 1 + 3 * (int)dim_ + (has_pressure_ ? 2 : 0) + (stress_ ? (int)(stressColumns().size() + strainColumns().size()) : 0); }

private:
  // The components of the 6 (xx, yy, zz, xy, yz, xz) recorded: those not zero in plane strain.
  std::vector<int> stressColumns() const { return dim_ == 2 ? std::vector<int>{0, 1, 2, 3} : std::vector<int>{0, 1, 2, 3, 4, 5}; }
  std::vector<int> strainColumns() const { return dim_ == 2 ? std::vector<int>{0, 1, 3} : std::vector<int>{0, 1, 2, 3, 4, 5}; }

  struct Local {
    PetscInt            station;
    PetscInt            cell;          // the local cell holding the point
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
  PetscBool                stress_       = PETSC_FALSE; // -station_stress
  PetscReal                interval_     = 0.005;       // -station_interval [s]
  long                     every_        = 1;           // steps between samples
};

} // namespace slipwave::io
