// OUTPUT_DIR/energy.csv: one row per step with the energy ledger and the interfaces' totals.
// The column names and the values of a row are listed side by side in energy_csv.cpp, so the
// header and the rows cannot drift apart. Written by rank 0 only; on the other ranks the file
// is never opened and Append does nothing.
#pragma once
#include <petscsys.h>

#include <cstdio>
#include <string>

#include "slipwave/interface/interface_assembler.hpp"
#include "slipwave/model/energy_ledger.hpp"

namespace slipwave::app {

class EnergyCsv {
public:
  // A new file with its header; after a restart (restarted), the header and the rows up to
  // restart_step of the file already there are kept and the run appends to them.
  PetscErrorCode Open(const std::string &dir, bool restarted, PetscInt restart_step);
  // Before Open, in saturated scenes: the fluid columns (fluid_stored, darcy_dissipated,
  // fluid_inflow_work) follow the others.
  void SetFluid(bool fluid) { fluid_ = fluid; }
  void           Append(PetscInt step, PetscReal t, const model::EnergyLedger &ledger, const interface::InterfaceTotals &interfaces);
  // Before a checkpoint: the file on disk holds every row up to the checkpointed step.
  void Flush();
  void Close();

private:
  FILE *file_ = nullptr;
  bool  fluid_ = false;
};

} // namespace slipwave::app
