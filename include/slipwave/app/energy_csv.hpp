// OUTPUT_DIR/energy.csv: one row per step with the energy ledger and the interfaces' totals.
// Rows are kept in memory and written, whole, by Flush (at every output time, before a
// checkpoint, at the end): a killed run leaves a file of complete rows up to its last output
// time, never a torn row (the stdio buffer alone would write out whatever 4 KiB it held).
// The column names and the values of a row are listed side by side in energy_csv.cpp, so the
// header and the rows cannot drift apart. Written by rank 0 only; on the other ranks the file
// is never opened and Append does nothing.
#pragma once
#include <petscsys.h>

#include <cstdio>
#include <string>

#include "slipwave/interface/interface_assembler.hpp"
#include "slipwave/problem/energy_ledger.hpp"

namespace slipwave::app {

class EnergyCsv {
public:
  // A new file with its header; after a restart, previous names the energy.csv beside the
  // checkpoint: its rows up to restart_step are copied (the new folder is complete on its own)
  // and the run appends to them.
  PetscErrorCode Open(const std::string &dir, const std::string &previous, PetscInt restart_step);
  // Before Open, in saturated scenes: the fluid columns (fluid_stored, darcy_dissipated,
  // fluid_inflow_work) follow the others.
  void SetFluid(bool fluid) { fluid_ = fluid; }
  // Before Open, in scenes with hysteretic regions: hysteretic_dissipated follows, the
  // energy the soil's hysteresis took (problem/energy_ledger.hpp); the balance books it.
  void SetHysteretic(bool hysteretic) { hysteretic_ = hysteretic; }
  // Before Open, with the fourth-order integrator (-ts_cd_order 4): integrator_correction
  // follows, the work of its correction force (problem/energy_ledger.hpp); the balance books it.
  void SetFourthOrder(bool fourth_order) { fourth_order_ = fourth_order; }
  void           Append(PetscInt step, PetscReal t, const problem::EnergyLedger &ledger, const interface::InterfaceTotals &interfaces);
  // Writes the rows kept since the last flush: the file on disk then holds every row so far.
  void Flush();
  void Close();

private:
  FILE       *file_ = nullptr;
  std::string pending_; // rows not yet written
  bool        fluid_ = false, hysteretic_ = false, fourth_order_ = false;
};

} // namespace slipwave::app
