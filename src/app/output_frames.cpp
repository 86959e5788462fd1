#include "slipwave/app/output_frames.hpp"

#include <filesystem>
#include <system_error>
#include <utility>

#include "slipwave/model/pore_pressure.hpp"

namespace slipwave::app {
namespace {

// Collective. Whether DIR/<file> holds the frames before the checkpoint, copying it there from
// the checkpoint's folder when DIR is another one. Without it (the run that wrote the
// checkpoint did not write this grid) the series starts anew in DIR: an index must never
// point at frames that are not there.
PetscErrorCode continueSeries(MPI_Comm comm, const std::string &from, const std::string &dir, const std::string &file, bool *kept) {
  namespace fs = std::filesystem;
  PetscMPIInt rank;
  int         status[2] = {0, 0}; // kept, copy failed
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    std::error_code error;
    const fs::path  source = fs::path(from) / file, target = fs::path(dir) / file;
    if (fs::exists(source, error) && !fs::equivalent(fs::path(from), fs::path(dir), error)) {
      fs::copy_file(source, target, fs::copy_options::overwrite_existing, error);
      status[1] = error ? 1 : 0;
    }
    status[0] = fs::exists(target, error) ? 1 : 0;
  }
  PetscCallMPI(MPI_Bcast(status, 2, MPI_INT, 0, comm));
  PetscCheck(!status[1], comm, PETSC_ERR_FILE_WRITE, "cannot copy %s/%s into -output_dir = %s", from.c_str(), file.c_str(), dir.c_str());
  *kept = status[0];
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode OutputFrames::Open(const model::Elastodynamics &model, const std::string &dir, PetscReal interval, bool volume, const std::string &checkpoint_dir) {
  const bool restarted = !checkpoint_dir.empty();
  bool       kept      = false;
  PetscFunctionBeginUser;
  interval_ = interval;
  std::vector<std::pair<PetscInt, PetscReal>> previous;
  for (size_t k = 0; k < times_.size(); ++k) previous.emplace_back((PetscInt)k, times_[k]);
  if (volume) {
    if (restarted) PetscCall(continueSeries(model.comm, checkpoint_dir, dir, "volume.h5", &kept));
    volume_ = std::make_unique<io::VolumeOutput>();
    PetscCall(volume_->Open(model.dm, model.bulk, dir, kept ? &previous : nullptr));
  }
  for (const auto &iface : model.interfaces) {
    if (restarted) PetscCall(continueSeries(model.comm, checkpoint_dir, dir, "interface_" + iface.spec().name + ".h5", &kept));
    interfaces_.push_back(std::make_unique<io::InterfaceOutput>());
    PetscCall(interfaces_.back()->Open(model.comm, model.dim, iface, dir, kept ? &previous : nullptr));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode OutputFrames::WriteIfDue(const model::Elastodynamics &model, PetscInt step, PetscReal t, bool last, Vec u, Vec v, Vec a, bool *due) {
  PetscFunctionBeginUser;
  *due = Due(step, t, last);
  if (!*due) PetscFunctionReturn(0);
  const PetscInt frame = (PetscInt)times_.size();
  if (volume_) {
    if (model.pore) PetscCall(model::PorePressureTotal(model.pore));
    PetscCall(volume_->Write(model.dm, model.bulk, frame, t, u, v, a, model.initial_stress, model.pore ? model.pore->p_total : nullptr, model.pore ? model.pore->p : nullptr));
  }
  for (size_t k = 0; k < interfaces_.size(); ++k) PetscCall(interfaces_[k]->Write(model.interfaces[k], frame, t));
  times_.push_back(t);
  while (next_output_ <= t * (1 + 1e-12)) next_output_ += interval_;
  PetscFunctionReturn(0);
}

PetscErrorCode OutputFrames::Close() {
  PetscFunctionBeginUser;
  if (volume_) PetscCall(volume_->Close());
  for (auto &out : interfaces_) PetscCall(out->Close());
  PetscFunctionReturn(0);
}

} // namespace slipwave::app
