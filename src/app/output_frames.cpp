#include "slipwave/app/output_frames.hpp"

#include <utility>

#include "slipwave/model/pore_pressure.hpp"

namespace slipwave::app {

PetscErrorCode OutputFrames::Open(const model::Elastodynamics &model, const std::string &dir, PetscReal interval, bool restarted) {
  PetscFunctionBeginUser;
  interval_ = interval;
  std::vector<std::pair<PetscInt, PetscReal>> previous;
  for (size_t k = 0; k < times_.size(); ++k) previous.emplace_back((PetscInt)k, times_[k]);
  const auto *kept = restarted ? &previous : nullptr;
  PetscCall(volume_.Open(model.dm, model.bulk, dir, kept));
  for (const auto &iface : model.interfaces) {
    interfaces_.push_back(std::make_unique<io::InterfaceOutput>());
    PetscCall(interfaces_.back()->Open(model.comm, model.dim, iface, dir, kept));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode OutputFrames::WriteIfDue(const model::Elastodynamics &model, PetscInt step, PetscReal t, bool last, Vec u, Vec v, Vec a) {
  PetscFunctionBeginUser;
  if (!(t >= next_output_ * (1 - 1e-12) || last || step == 0)) PetscFunctionReturn(0);
  const PetscInt frame = (PetscInt)times_.size();
  if (model.pore) PetscCall(model::PorePressureTotal(model.pore));
  PetscCall(volume_.Write(model.dm, model.bulk, frame, t, u, v, a, model.initial_stress, model.pore ? model.pore->p_total : nullptr, model.pore ? model.pore->p : nullptr));
  for (size_t k = 0; k < interfaces_.size(); ++k) PetscCall(interfaces_[k]->Write(model.interfaces[k], frame, t));
  times_.push_back(t);
  while (next_output_ <= t * (1 + 1e-12)) next_output_ += interval_;
  PetscFunctionReturn(0);
}

PetscErrorCode OutputFrames::Close() {
  PetscFunctionBeginUser;
  PetscCall(volume_.Close());
  for (auto &out : interfaces_) PetscCall(out->Close());
  PetscFunctionReturn(0);
}

} // namespace slipwave::app
