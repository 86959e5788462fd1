#include "slipwave/app/output_frames.hpp"

#include <utility>

#include "slipwave/medium/hysteresis.hpp"
#include "slipwave/porous/pore_pressure.hpp"

namespace slipwave::app {

PetscErrorCode OutputFrames::Open(const problem::Elastodynamics &model, const std::string &dir, PetscReal interval, bool volume, const std::string &checkpoint_dir) {
  const bool restarted = !checkpoint_dir.empty();
  bool       kept      = false;
  PetscFunctionBeginUser;
  interval_ = interval;
  PetscCall(base_.Setup(model.dm, model.bulk));
  std::vector<std::pair<PetscInt, PetscReal>> previous;
  for (size_t k = 0; k < times_.size(); ++k) previous.emplace_back((PetscInt)k, times_[k]);
  if (volume) {
    // After a restart the series continues with the frames before the checkpoint, brought
    // over from the checkpoint's folder when DIR is another one.
    if (restarted) PetscCall(io::FieldWriter::CopySeries(model.comm, checkpoint_dir, dir, "volume", (PetscInt)times_.size(), &kept));
    volume_ = std::make_unique<io::VolumeOutput>();
    PetscCall(volume_->Open(model.dm, model.bulk, dir, kept ? &previous : nullptr, model.pore ? model.pore->p : nullptr, model.hysteresis != nullptr,
                            model.pore && model.pore->cavitation));
  }
  for (const auto &iface : model.interfaces) {
    if (restarted) PetscCall(io::FieldWriter::CopySeries(model.comm, checkpoint_dir, dir, "interface_" + iface.spec().name, (PetscInt)times_.size(), &kept));
    interfaces_.push_back(std::make_unique<io::InterfaceOutput>());
    PetscCall(interfaces_.back()->Open(model.comm, model.dim, iface, dir, kept ? &previous : nullptr));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode OutputFrames::WriteIfDue(const problem::Elastodynamics &model, PetscInt step, PetscReal t, bool last, Vec u, Vec v, Vec a, bool *due) {
  PetscFunctionBeginUser;
  *due = Due(step, t, last);
  if (!*due) PetscFunctionReturn(0);
  const PetscInt frame = (PetscInt)times_.size();
  PetscScalar    base[3];
  PetscCall(base_.Mean(u, base));
  if (volume_) {
    if (model.pore) PetscCall(porous::PorePressureTotal(model.pore));
    const bool cavities = model.pore && model.pore->cavitation;
    if (cavities) PetscCall(porous::PorePressureCavityFraction(model.pore));
    io::SoilCellOutput soil{};
    const PetscInt     ncell = model.bulk.cellCount();
    // Hysteretic soil: the elastic cells keep the linear stress, G/Gmax 1 and no strain record.
    std::vector<double> relaxation, max_strain, ratio;
    if (model.hysteresis) {
      relaxation.assign(6 * ncell, 0.0);
      max_strain.assign(ncell, 0.0);
      ratio.assign(ncell, 1.0);
      Vec                u_local;
      const PetscScalar *ul;
      PetscCall(DMGetLocalVector(model.dm, &u_local));
      PetscCall(DMGlobalToLocal(model.dm, u, INSERT_VALUES, u_local));
      PetscCall(VecGetArrayRead(u_local, &ul));
      medium::HysteresisCellFields(model.hysteresis, ul, relaxation.data(), max_strain.data(), ratio.data());
      PetscCall(VecRestoreArrayRead(u_local, &ul));
      PetscCall(DMRestoreLocalVector(model.dm, &u_local));
      soil = {relaxation.data(), max_strain.data(), ratio.data()};
    }
    PetscCall(volume_->Write(model.dm, model.bulk, frame, t, u, base, v, a, model.initial_stress, model.pore ? model.pore->p_total : nullptr, model.pore ? model.pore->p : nullptr,
                             cavities ? model.pore->cavity_fraction : nullptr, model.hysteresis ? &soil : nullptr));
  }
  for (size_t k = 0; k < interfaces_.size(); ++k) PetscCall(interfaces_[k]->Write(model.interfaces[k], frame, t, u, base));
  times_.push_back(t);
  while (next_output_ <= t * (1 + 1e-12)) next_output_ += interval_;
  PetscFunctionReturn(0);
}

PetscErrorCode OutputFrames::Close() {
  PetscFunctionBeginUser;
  if (volume_) PetscCall(volume_->Close());
  PetscCall(base_.Destroy());
  for (auto &out : interfaces_) PetscCall(out->Close());
  PetscFunctionReturn(0);
}

} // namespace slipwave::app
