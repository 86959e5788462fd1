// Time series output of one grid as HDF5 data + an XDMF index, written in parallel through
// PetscViewerHDF5 from plain global Vecs (no DM needed). The .xmf opens in ParaView 5.11
// with its default XDMF3 readers and with the legacy "XDMF Reader" (PETSc's
// petsc_gen_xdmf.py output opens only with the latter).
//
// Files (every dataset is [rows, components]), so that a run killed at any moment leaves
// only complete HDF5 files (HDF5 without SWMR is not crash-consistent: a kill inside an
// in-place append can make the whole file unreadable):
//   DIR/<name>.h5                 /geometry float64 [nodes, 3] (2D coordinates padded with z = 0)
//                                 /topology int [cells, nodes_per_cell] global node numbers
//   DIR/<name>/<step>.h5          /<field> float64 [nodes or cells, 1 | 3 | 9]; step zero-padded
//                                 to 6 digits; one file per output step
//   DIR/<name>.xmf                the XDMF index, file names relative to DIR
// Each HDF5 file is written once, under a hidden partial name (".<file>.partial" in the same
// folder), and renamed into place when complete; the index is replaced (same way) after that,
// so it names only complete files. A run in progress can be opened in ParaView.
// Components as written: 1 scalar; 3 vector (2-component vectors padded with z = 0);
// 9 symmetric tensor as full row-major 3x3 (XDMF "Tensor"): XDMF "Tensor6" is mislabelled
// by ParaView 5.11's default reader (see field_writer.cpp).
#pragma once
#include <petscis.h>
#include <petscvec.h>

#include <string>
#include <utility>
#include <vector>

namespace slipwave::io {

enum class Centering { Node, Cell };

struct GridLayout {
  std::string name;      // file stem and XDMF grid name: "volume" -> DIR/volume.h5, DIR/volume.xmf
  int dim = 3;           // 2 or 3: coordinate components in the geometry Vec
  std::string cell_type; // XDMF TopologyType: Triangle, Quadrilateral, Tetrahedron, Hexahedron, Polyline (2-node lines)
  int nodes_per_cell = 0;
};

// values: global Vec with block size = components: 1 scalar, 2 or 3 vector, 6 symmetric
// tensor in our order xx,yy,zz,xy,yz,xz; one block per node or per cell.
struct FieldRef {
  std::string name; // becomes an HDF5 group name: no '/'
  Centering centering;
  Vec values;
};

class FieldWriter {
 public:
  FieldWriter() = default;
  FieldWriter(const FieldWriter &) = delete;
  FieldWriter &operator=(const FieldWriter &) = delete;
  // Close() must be called before PetscFinalize: the destructor cannot report errors.
  ~FieldWriter() = default;

  // Collective. Creates DIR if needed, writes the geometry (global Vec, node i at entries
  // [i*dim, i*dim+dim)) and the topology (IS of global node numbers, nodes_per_cell per
  // cell) once, replacing any earlier DIR/<name>.h5 and emptying DIR/<name>/.
  PetscErrorCode Open(MPI_Comm comm, const std::string &dir, const GridLayout &grid, Vec geometry, IS topology);
  // Collective. Writes the fields of this output step, then rank 0 rewrites DIR/<name>.xmf
  // listing all steps so far. Steps and times must increase from call to call.
  PetscErrorCode WriteStep(PetscInt step, PetscReal time, const std::vector<FieldRef> &fields);
  // Collective. After a restart: continues the series in DIR written by an earlier
  // Open/WriteStep run, keeping its geometry, topology and the output steps listed in `previous` (step, time),
  // all with the fields of `layout` (only their names, centering and block sizes are used).
  PetscErrorCode Resume(MPI_Comm comm, const std::string &dir, const GridLayout &grid, Vec geometry, IS topology,
                        const std::vector<std::pair<PetscInt, PetscReal>> &previous, const std::vector<FieldRef> &layout);
  // Collective. Frees the work vectors; the files stay complete as after the last step.
  PetscErrorCode Close();

  // The frame file of `step` of grid `grid`, relative to DIR: "<grid>/<step, 6 digits>.h5".
  static std::string FrameFile(const std::string &grid, PetscInt step);
  // Collective. Puts the mesh file and frame files 0..steps-1 of grid `grid` from folder
  // `from` into `dir` (hard links, else copies; nothing to do when they are the same folder),
  // for a restart into another folder. kept: whether `from` held all of them (else nothing is
  // copied and the series must start anew: an index must never name a missing file).
  static PetscErrorCode CopySeries(MPI_Comm comm, const std::string &from, const std::string &dir, const std::string &grid, PetscInt steps,
                                   bool *kept);

 private:
  struct FieldInfo {
    std::string name;
    Centering centering;
    int components; // as written: 1, 3 or 9
    bool operator==(const FieldInfo &o) const {
      return name == o.name && centering == o.centering && components == o.components;
    }
  };
  struct StepRecord {
    PetscInt step;
    PetscReal time;
    size_t field_set; // index into field_sets_
  };

  PetscErrorCode CheckGrid(MPI_Comm comm, const GridLayout &grid, Vec geometry, IS topology);
  PetscErrorCode FieldInfos(const std::vector<FieldRef> &fields, std::vector<FieldInfo> *infos) const;
  PetscErrorCode WorkVec(Centering centering, int components, PetscInt local_rows, Vec *work);
  PetscErrorCode WriteRows(Vec source, int source_components, Centering centering, const char *dataset);
  PetscErrorCode WriteIndex() const;
  PetscErrorCode CloseAndPublish(const std::string &file);

  MPI_Comm comm_ = MPI_COMM_NULL;
  std::string dir_;
  GridLayout grid_;
  PetscInt num_nodes_ = 0, num_cells_ = 0;
  PetscViewer viewer_ = nullptr; // open only while a step is written
  // Reused conversion buffers per centering (Node, Cell) and written width (1, 3, 9).
  Vec work_[2][3] = {};
  // Distinct field lists seen so far and one record per step: all the writer keeps.
  std::vector<std::vector<FieldInfo>> field_sets_;
  std::vector<StepRecord> steps_;
};

} // namespace slipwave::io
