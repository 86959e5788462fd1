// Memory variables of constant-Q damping (physics/constant_q.hpp) as element forces. With one
// set of Y_l for P and S (Qp = Qs), the generalized Maxwell body acts on the element force
// vector: the internal force of a damped cell is K_U u_e - sum_l zeta_l, with
//   d zeta_l/dt = w_l (Y_l K_U u_e - zeta_l),
// nen*dim values per mechanism per cell, for the cells of damped regions only.
// The update is the exact one for u_e linear in time between the committed state (time t_c)
// and the trial time t_c + h (memoryUpdate): a trial state is computed from the committed one,
// so evaluating the force again at the same time gives the same answer; commit() makes the
// trial state the committed one, once per step.
#pragma once
#include <petscsys.h>

#include <vector>

#include "slipwave/fem/bulk_operator.hpp"
#include "slipwave/physics/constant_q.hpp"

namespace slipwave::fem {

class AnelasticOperator {
public:
  // region_models[r]: the region's fitted body, no mechanisms for an elastic region. Every
  // damped region shares the relaxation frequencies (one band), not the weights.
  void Setup(const BulkOperator &bulk, const std::vector<physics::ConstantQModel> &region_models);
  bool     empty() const { return cells_.empty(); }
  PetscInt dampedCellCount() const { return (PetscInt)cells_.size(); }

  // f_local += sum_l zeta_l(t_c + h) on the damped cells (u_local ghosted), storing the trial state.
  void addMemoryForce(const BulkOperator &bulk, const PetscScalar *u_local, double h, PetscScalar *f_local);
  void commit() { committed_.swap(trial_); }

  // Committed and trial state of this rank, for checkpoints.
  std::vector<double> state() const;
  bool                setState(const std::vector<double> &s);

private:
  std::vector<PetscInt> cells_, cell_model_; // damped cells, and their region's model
  std::vector<double>   omega_, weights_;    // w_l; Y_l of model m at [m * mechanisms + l]
  PetscInt              mechanisms_ = 0, ndof_ = 0;
  // Per damped cell: zeta_1..zeta_L then K_U u_e at the state's time, (L + 1) * ndof values.
  std::vector<double>   committed_, trial_;
};

} // namespace slipwave::fem
