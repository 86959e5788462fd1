#include "slipwave/io/field_writer.hpp"

#include <petscviewerhdf5.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <vector>

namespace slipwave::io {
namespace {

struct CellKind {
  const char *xdmf_type;
  int nodes_per_cell;
};
const CellKind kCellKinds[] = {{"Triangle", 3}, {"Quadrilateral", 4}, {"Tetrahedron", 4}, {"Hexahedron", 8}, {"Polyline", 2}};

// Width of a field as written: scalars, 3-vectors, and symmetric tensors as full 3x3
// (XDMF "Tensor", row-major). Not XDMF "Tensor6": ParaView 5.11's default XDMF3 reader passes
// its xx,xy,xz,yy,yz,zz through unchanged but labels six components XX,YY,ZZ,XY,YZ,XZ (so
// "YY" would show xy), while the legacy reader expands it correctly; nine components read
// the same in both (checked with pvpython).
int WrittenComponents(PetscInt components) { return components == 1 ? 1 : components == 6 ? 9 : 3; }

int WorkSlot(int written) { return written == 1 ? 0 : written == 3 ? 1 : 2; }

const char *AttributeType(int written) { return written == 1 ? "Scalar" : written == 3 ? "Vector" : "Tensor"; }

// Where component k of ours goes in the written row (-1: nowhere). Tensors: ours
// xx,yy,zz,xy,yz,xz fill both symmetric entries of the row-major 3x3. Vectors keep their
// order (a 2-vector leaves z at 0).
void WrittenSlots(PetscInt components, PetscInt k, int slots[2]) {
  static const int kTensor[6][2] = {{0, -1}, {4, -1}, {8, -1}, {1, 3}, {5, 7}, {2, 6}};
  slots[0] = components == 6 ? kTensor[k][0] : static_cast<int>(k);
  slots[1] = components == 6 ? kTensor[k][1] : -1;
}

std::string XmlEscaped(const std::string &text) {
  std::string out;
  for (char c : text) {
    switch (c) {
    case '&': out += "&amp;"; break;
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '"': out += "&quot;"; break;
    case '\'': out += "&apos;"; break;
    default: out += c;
    }
  }
  return out;
}

// Where a file is written before it is complete: a hidden name beside its final one, so a
// kill mid-write leaves the final name absent (or its earlier version) rather than torn.
std::string PartialPath(const std::string &dir, const std::string &file) {
  const std::filesystem::path path = std::filesystem::path(dir) / file;
  return (path.parent_path() / ("." + path.filename().string() + ".partial")).string();
}

std::string Number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// One HDF5 DataItem line; readers resolve the file name relative to the .xmf.
void DataItem(std::ostream &out, const std::string &indent, PetscInt rows, int columns, bool integer, const std::string &h5,
              const std::string &path) {
  out << indent << "<DataItem Dimensions=\"" << rows << ' ' << columns << "\" NumberType=\"" << (integer ? "Int" : "Float")
      << "\" Precision=\"" << (integer ? sizeof(PetscInt) : sizeof(PetscScalar)) << "\" Format=\"HDF\">" << XmlEscaped(h5)
      << ':' << XmlEscaped(path) << "</DataItem>\n";
}

// Runs `action` on rank 0 and makes its outcome (ok, message) known on every rank, so a
// failure stops all ranks instead of leaving them waiting in the next collective call.
template <class Action>
PetscErrorCode OnRootCollective(MPI_Comm comm, Action action, PetscErrorCode code) {
  PetscMPIInt rank = 0;
  char message[512] = "";
  int ok = 1;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) PetscCallCXX(ok = action(message, sizeof message) ? 1 : 0);
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(message, sizeof message, MPI_CHAR, 0, comm));
  PetscCheck(ok, comm, code, "%s", message);
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode FieldWriter::CheckGrid(MPI_Comm comm, const GridLayout &grid, Vec geometry, IS topology) {
  PetscFunctionBeginUser;
  PetscCheck(comm_ == MPI_COMM_NULL, comm, PETSC_ERR_ORDER, "FieldWriter for grid '%s' is already open; Close() it first",
             grid_.name.c_str());
  PetscCheck(grid.dim == 2 || grid.dim == 3, comm, PETSC_ERR_ARG_OUTOFRANGE, "grid '%s': dim = %d; allowed 2 or 3",
             grid.name.c_str(), grid.dim);
  PetscCheck(!grid.name.empty() && grid.name.find('/') == std::string::npos, comm, PETSC_ERR_ARG_WRONG,
             "grid name '%s' must be a non-empty file stem without '/'", grid.name.c_str());
  bool known = false;
  for (const CellKind &kind : kCellKinds) known = known || (grid.cell_type == kind.xdmf_type && grid.nodes_per_cell == kind.nodes_per_cell);
  PetscCheck(known, comm, PETSC_ERR_ARG_WRONG,
             "grid '%s': cell type '%s' with %d nodes per cell is not one of Triangle/3, Quadrilateral/4, Tetrahedron/4, "
             "Hexahedron/8, Polyline/2",
             grid.name.c_str(), grid.cell_type.c_str(), grid.nodes_per_cell);

  PetscInt geometry_size = 0, topology_size = 0;
  PetscCall(VecGetSize(geometry, &geometry_size));
  PetscCall(ISGetSize(topology, &topology_size));
  PetscCheck(geometry_size % grid.dim == 0, comm, PETSC_ERR_ARG_SIZ, "grid '%s': geometry size %" PetscInt_FMT " is not a multiple of dim %d",
             grid.name.c_str(), geometry_size, grid.dim);
  PetscCheck(topology_size % grid.nodes_per_cell == 0, comm, PETSC_ERR_ARG_SIZ,
             "grid '%s': topology size %" PetscInt_FMT " is not a multiple of %d nodes per cell", grid.name.c_str(), topology_size,
             grid.nodes_per_cell);

  comm_ = comm;
  grid_ = grid;
  num_nodes_ = geometry_size / grid.dim;
  num_cells_ = topology_size / grid.nodes_per_cell;
  field_sets_.clear();
  steps_.clear();
  PetscFunctionReturn(0);
}

PetscErrorCode FieldWriter::Open(MPI_Comm comm, const std::string &dir, const GridLayout &grid, Vec geometry, IS topology) {
  PetscFunctionBeginUser;
  PetscCall(OnRootCollective(
      comm,
      [&dir](char *message, size_t size) {
        std::error_code error;
        std::filesystem::create_directories(dir, error);
        if (error) std::snprintf(message, size, "cannot create output directory '%s': %s", dir.c_str(), error.message().c_str());
        return !error;
      },
      PETSC_ERR_FILE_OPEN));

  PetscCall(CheckGrid(comm, grid, geometry, topology));
  dir_ = dir;

  // A fresh series: frames of an earlier run in this folder must not outlive its index.
  PetscCall(OnRootCollective(
      comm,
      [this](char *message, size_t size) {
        std::error_code error;
        const std::string frames = dir_ + "/" + grid_.name;
        std::filesystem::remove_all(frames, error);
        if (!error) std::filesystem::create_directory(frames, error);
        if (error) std::snprintf(message, size, "cannot empty the frame folder '%s': %s", frames.c_str(), error.message().c_str());
        return !error;
      },
      PETSC_ERR_FILE_OPEN));

  const std::string mesh = grid_.name + ".h5";
  PetscCall(PetscViewerHDF5Open(comm_, PartialPath(dir_, mesh).c_str(), FILE_MODE_WRITE, &viewer_));
  PetscCall(WriteRows(geometry, grid_.dim, Centering::Node, "geometry"));
  // A copy carries our dataset name and the row width, leaving the caller's IS untouched.
  IS rows = nullptr;
  PetscCall(ISDuplicate(topology, &rows));
  PetscCall(ISSetBlockSize(rows, grid_.nodes_per_cell));
  PetscCall(PetscObjectSetName(reinterpret_cast<PetscObject>(rows), "topology"));
  PetscCall(ISView(rows, viewer_));
  PetscCall(ISDestroy(&rows));
  PetscCall(CloseAndPublish(mesh));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldWriter::WorkVec(Centering centering, int components, PetscInt local_rows, Vec *work) {
  Vec &slot = work_[centering == Centering::Node ? 0 : 1][WorkSlot(components)];
  PetscInt local_size = -1;

  PetscFunctionBeginUser;
  if (slot) PetscCall(VecGetLocalSize(slot, &local_size));
  if (local_size != local_rows * components) {
    PetscCall(VecDestroy(&slot));
    PetscCall(VecCreate(comm_, &slot));
    PetscCall(VecSetSizes(slot, local_rows * components, PETSC_DECIDE));
    PetscCall(VecSetBlockSize(slot, components));
    PetscCall(VecSetType(slot, VECSTANDARD));
    PetscCall(VecZeroEntries(slot)); // padding entries stay zero: they are never written
  }
  *work = slot;
  PetscFunctionReturn(0);
}

// Copies `source` (rows of source_components) into a work Vec in the written layout and
// writes it as dataset `dataset` of the current group: [rows, written components].
PetscErrorCode FieldWriter::WriteRows(Vec source, int source_components, Centering centering, const char *dataset) {
  const int written = WrittenComponents(source_components);
  PetscInt local_size = 0;
  Vec work = nullptr;
  const PetscScalar *in = nullptr;
  PetscScalar *out = nullptr;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(source, &local_size));
  PetscCheck(local_size % source_components == 0, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ,
             "'%s': local size %" PetscInt_FMT " is not a multiple of %d components", dataset, local_size, source_components);
  const PetscInt local_rows = local_size / source_components;
  PetscCall(WorkVec(centering, written, local_rows, &work));
  PetscCall(VecGetArrayRead(source, &in));
  PetscCall(VecGetArray(work, &out));
  int slots[6][2];
  for (PetscInt k = 0; k < source_components; ++k) WrittenSlots(source_components, k, slots[k]);
  for (PetscInt r = 0; r < local_rows; ++r)
    for (PetscInt k = 0; k < source_components; ++k)
      for (int slot : slots[k])
        if (slot >= 0) out[r * written + slot] = in[r * source_components + k];
  PetscCall(VecRestoreArray(work, &out));
  PetscCall(VecRestoreArrayRead(source, &in));
  PetscCall(PetscObjectSetName(reinterpret_cast<PetscObject>(work), dataset));
  PetscCall(VecView(work, viewer_));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldWriter::FieldInfos(const std::vector<FieldRef> &fields, std::vector<FieldInfo> *out) const {
  PetscFunctionBeginUser;
  std::vector<FieldInfo> &infos = *out;
  infos.clear();
  for (const FieldRef &field : fields) {
    PetscInt components = 0, size = 0;
    PetscCall(VecGetBlockSize(field.values, &components));
    PetscCall(VecGetSize(field.values, &size));
    const PetscInt rows = field.centering == Centering::Node ? num_nodes_ : num_cells_;
    const char *where = field.centering == Centering::Node ? "nodes" : "cells";
    PetscCheck(!field.name.empty() && field.name.find('/') == std::string::npos, comm_, PETSC_ERR_ARG_WRONG,
               "field name '%s' must be non-empty and without '/'", field.name.c_str());
    PetscCheck(components == 1 || components == 2 || components == 3 || components == 6, comm_, PETSC_ERR_ARG_WRONG,
               "field '%s': block size %" PetscInt_FMT "; allowed 1 (scalar), 2 or 3 (vector), 6 (symmetric tensor)",
               field.name.c_str(), components);
    PetscCheck(size == rows * components, comm_, PETSC_ERR_ARG_SIZ,
               "field '%s': size %" PetscInt_FMT " != %" PetscInt_FMT " %s x %" PetscInt_FMT " components", field.name.c_str(), size,
               rows, where, components);
    for (const FieldInfo &seen : infos)
      PetscCheck(seen.name != field.name, comm_, PETSC_ERR_ARG_WRONG, "field '%s' given twice in one step", field.name.c_str());
    PetscCallCXX(infos.push_back(FieldInfo{field.name, field.centering, WrittenComponents(components)}));
  }

  PetscFunctionReturn(0);
}

PetscErrorCode FieldWriter::Resume(MPI_Comm comm, const std::string &dir, const GridLayout &grid, Vec geometry, IS topology,
                                   const std::vector<std::pair<PetscInt, PetscReal>> &previous, const std::vector<FieldRef> &layout) {
  PetscFunctionBeginUser;
  PetscCall(CheckGrid(comm, grid, geometry, topology));
  dir_ = dir;
  std::vector<FieldInfo> infos;
  PetscCall(FieldInfos(layout, &infos));
  PetscCallCXX(field_sets_.push_back(std::move(infos)));
  for (const auto &[step, time] : previous) PetscCallCXX(steps_.push_back(StepRecord{step, time, 0}));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldWriter::WriteStep(PetscInt step, PetscReal time, const std::vector<FieldRef> &fields) {
  PetscFunctionBeginUser;
  PetscCheck(comm_ != MPI_COMM_NULL, PETSC_COMM_SELF, PETSC_ERR_ORDER, "FieldWriter::WriteStep before Open");
  PetscCheck(steps_.empty() || (step > steps_.back().step && time > steps_.back().time), comm_, PETSC_ERR_ARG_WRONG,
             "grid '%s': output step %" PetscInt_FMT " at t = %g does not follow step %" PetscInt_FMT " at t = %g",
             grid_.name.c_str(), step, static_cast<double>(time), steps_.empty() ? 0 : steps_.back().step,
             steps_.empty() ? 0.0 : static_cast<double>(steps_.back().time));
  PetscCheck(step >= 0, comm_, PETSC_ERR_ARG_OUTOFRANGE, "grid '%s': output step %" PetscInt_FMT " < 0", grid_.name.c_str(), step);

  std::vector<FieldInfo> infos;
  PetscCall(FieldInfos(fields, &infos));

  const std::string frame = FrameFile(grid_.name, step);
  PetscCall(PetscViewerHDF5Open(comm_, PartialPath(dir_, frame).c_str(), FILE_MODE_WRITE, &viewer_));
  PetscCall(PetscViewerHDF5SetBaseDimension2(viewer_, PETSC_TRUE)); // scalars as [rows, 1] like the others
  for (const FieldRef &field : fields) {
    PetscInt components = 0;
    PetscCall(VecGetBlockSize(field.values, &components));
    PetscCall(WriteRows(field.values, static_cast<int>(components), field.centering, field.name.c_str()));
  }
  PetscCall(CloseAndPublish(frame));

  size_t set = 0;
  while (set < field_sets_.size() && !(field_sets_[set] == infos)) ++set;
  if (set == field_sets_.size()) PetscCallCXX(field_sets_.push_back(std::move(infos)));
  PetscCallCXX(steps_.push_back(StepRecord{step, time, set}));
  PetscCall(WriteIndex());
  PetscFunctionReturn(0);
}

// Rank 0 writes the XDMF index to a temporary file and renames it over the old one, so a
// reader never sees a half-written index.
PetscErrorCode FieldWriter::WriteIndex() const {
  PetscFunctionBeginUser;
  PetscCall(OnRootCollective(
      comm_,
      [this](char *message, size_t size) {
        const std::string h5 = grid_.name + ".h5";
        const std::string xmf = dir_ + "/" + grid_.name + ".xmf";
        const std::string partial = PartialPath(dir_, grid_.name + ".xmf");
        const std::string name = XmlEscaped(grid_.name);
        const std::string topology_type = grid_.cell_type;
        std::ofstream out(partial, std::ios::trunc);
        out << "<?xml version=\"1.0\" ?>\n"
            << "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
            << "  <Domain>\n"
            << "    <Grid Name=\"" << name << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
        for (const StepRecord &record : steps_) {
          const std::string frame = FrameFile(grid_.name, record.step);
          out << "      <Grid Name=\"" << name << "\" GridType=\"Uniform\">\n"
              << "        <Time Value=\"" << Number(record.time) << "\"/>\n"
              << "        <Topology TopologyType=\"" << topology_type << "\" NumberOfElements=\"" << num_cells_ << '"';
          if (grid_.cell_type == "Polyline") out << " NodesPerElement=\"" << grid_.nodes_per_cell << '"';
          out << ">\n";
          DataItem(out, "          ", num_cells_, grid_.nodes_per_cell, true, h5, "/topology");
          out << "        </Topology>\n"
              << "        <Geometry GeometryType=\"XYZ\">\n";
          DataItem(out, "          ", num_nodes_, 3, false, h5, "/geometry");
          out << "        </Geometry>\n";
          for (const FieldInfo &field : field_sets_[record.field_set]) {
            const bool node = field.centering == Centering::Node;
            out << "        <Attribute Name=\"" << XmlEscaped(field.name) << "\" AttributeType=\"" << AttributeType(field.components)
                << "\" Center=\"" << (node ? "Node" : "Cell") << "\">\n";
            DataItem(out, "          ", node ? num_nodes_ : num_cells_, field.components, false, frame, "/" + field.name);
            out << "        </Attribute>\n";
          }
          out << "      </Grid>\n";
        }
        out << "    </Grid>\n"
            << "  </Domain>\n"
            << "</Xdmf>\n";
        out.close();
        if (!out) {
          std::snprintf(message, size, "cannot write '%s': %s", partial.c_str(), std::strerror(errno));
          return false;
        }
        if (std::rename(partial.c_str(), xmf.c_str()) != 0) {
          std::snprintf(message, size, "cannot rename '%s' to '%s': %s", partial.c_str(), xmf.c_str(), std::strerror(errno));
          return false;
        }
        return true;
      },
      PETSC_ERR_FILE_WRITE));
  PetscFunctionReturn(0);
}

std::string FieldWriter::FrameFile(const std::string &grid, PetscInt step) {
  char name[32];
  std::snprintf(name, sizeof name, "%06" PetscInt_FMT ".h5", step);
  return grid + "/" + name;
}

// Collective. Every rank has closed its part of the file before rank 0 renames it into place.
PetscErrorCode FieldWriter::CloseAndPublish(const std::string &file) {
  PetscFunctionBeginUser;
  PetscCall(PetscViewerDestroy(&viewer_));
  PetscCallMPI(MPI_Barrier(comm_));
  PetscCall(OnRootCollective(
      comm_,
      [this, &file](char *message, size_t size) {
        const std::string partial = PartialPath(dir_, file), target = dir_ + "/" + file;
        if (std::rename(partial.c_str(), target.c_str()) == 0) return true;
        std::snprintf(message, size, "cannot rename '%s' to '%s': %s", partial.c_str(), target.c_str(), std::strerror(errno));
        return false;
      },
      PETSC_ERR_FILE_WRITE));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldWriter::CopySeries(MPI_Comm comm, const std::string &from, const std::string &dir, const std::string &grid, PetscInt steps,
                                       bool *kept) {
  int complete = 0;

  PetscFunctionBeginUser;
  PetscCall(OnRootCollective(
      comm,
      [&](char *message, size_t size) {
        namespace fs = std::filesystem;
        std::error_code error;
        std::vector<std::string> files = {grid + ".h5"};
        for (PetscInt step = 0; step < steps; ++step) files.push_back(FrameFile(grid, step));
        const bool same = fs::equivalent(from, dir, error);
        complete = 1;
        for (const std::string &file : files) complete = complete && fs::is_regular_file(fs::path(from) / file, error);
        if (same || !complete) return true;
        fs::remove_all(fs::path(dir) / grid, error);
        fs::create_directories(fs::path(dir) / grid, error);
        for (const std::string &file : files) {
          // A hard link costs nothing and is safe: frames are never changed in place, only
          // replaced by a rename. Another file system needs a copy. Either goes through a
          // partial name, so a kill during the copy leaves no torn file under a final name.
          const std::string partial = PartialPath(dir, file);
          fs::remove(partial, error);
          error.clear();
          fs::create_hard_link(fs::path(from) / file, partial, error);
          if (error) {
            error.clear();
            fs::copy_file(fs::path(from) / file, partial, fs::copy_options::overwrite_existing, error);
          }
          if (!error) fs::rename(partial, fs::path(dir) / file, error);
          if (error) {
            std::snprintf(message, size, "cannot copy '%s/%s' into '%s': %s", from.c_str(), file.c_str(), dir.c_str(), error.message().c_str());
            return false;
          }
        }
        return true;
      },
      PETSC_ERR_FILE_WRITE));
  PetscCallMPI(MPI_Bcast(&complete, 1, MPI_INT, 0, comm));
  *kept = complete != 0;
  PetscFunctionReturn(0);
}

PetscErrorCode FieldWriter::Close() {
  PetscFunctionBeginUser;
  PetscCall(PetscViewerDestroy(&viewer_));
  for (auto &per_centering : work_)
    for (Vec &work : per_centering) PetscCall(VecDestroy(&work));
  comm_ = MPI_COMM_NULL;
  field_sets_.clear();
  steps_.clear();
  PetscFunctionReturn(0);
}

} // namespace slipwave::io
