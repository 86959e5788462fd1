#include "slipwave/app/energy_csv.hpp"

#include <array>
#include <cstdio>

#include "slipwave/io/whole_write.hpp"

namespace slipwave::app {
namespace {

// The columns after "step", in the order Append writes them.
constexpr std::array<const char *, 15> kValueColumns = {"time",           "kinetic",          "strain",         "input_work",
                                                        "external_work",  "absorbed",         "damped",         "anelastic",
                                                        "interface_work", "interface_stored", "interface_dissipated", "contact_damped",
                                                        "stored_change",  "balance_error",    "relative_balance_error"};

constexpr std::array<const char *, 4> kFluidColumns = {"fluid_stored", "darcy_dissipated", "fluid_inflow_work", "cavitation_work"};

std::string header(bool fluid, bool hysteretic, bool fourth_order) {
  std::string line = "step";
  for (const char *name : kValueColumns) line += std::string(",") + name;
  if (fluid)
    for (const char *name : kFluidColumns) line += std::string(",") + name;
  if (hysteretic) line += ",hysteretic_dissipated";
  if (fourth_order) line += ",integrator_correction";
  return line + "\n";
}

} // namespace

PetscErrorCode EnergyCsv::Open(const std::string &dir, const std::string &previous, PetscInt restart_step) {
  const std::string path = dir + "/energy.csv";
  PetscFunctionBeginUser;
  std::string kept = header(fluid_, hysteretic_, fourth_order_);
  if (!previous.empty()) {
    if (FILE *in = std::fopen(previous.c_str(), "r")) {
      char line[4096];
      kept.clear();
      while (std::fgets(line, sizeof line, in)) {
        long step = 0;
        if (kept.empty() || (std::sscanf(line, "%ld,", &step) == 1 && step <= restart_step)) kept += line;
      }
      std::fclose(in);
    }
  }
  file_ = std::fopen(path.c_str(), "w");
  PetscCheck(file_, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-output_dir = %s: cannot write energy.csv there", dir.c_str());
  pending_ = kept;
  Flush();
  PetscFunctionReturn(0);
}

void EnergyCsv::Append(PetscInt step, PetscReal t, const problem::EnergyLedger &e, const interface::InterfaceTotals &interfaces) {
  if (!file_) return;
  // One value per entry of kValueColumns, in its order.
  const std::array<double, kValueColumns.size()> values = {(double)t,
                                                           e.kinetic,
                                                           e.strain,
                                                           e.input,
                                                           e.external + e.reactions,
                                                           e.absorbed,
                                                           e.damped,
                                                           e.anelastic,
                                                           e.interface_work,
                                                           interfaces.stored,
                                                           interfaces.dissipated,
                                                           e.contact_damped,
                                                           e.shadow - e.shadow_start,
                                                           e.balance_error,
                                                           e.relativeError()};
  char cell[32];
  std::snprintf(cell, sizeof cell, "%" PetscInt_FMT, step);
  pending_ += cell;
  // The relative error is a ratio read at a glance: 4 digits; the energies keep 10.
  for (size_t k = 0; k + 1 < values.size(); ++k) {
    std::snprintf(cell, sizeof cell, ",%.10g", values[k]);
    pending_ += cell;
  }
  std::snprintf(cell, sizeof cell, ",%.3e", values.back());
  pending_ += cell;
  if (fluid_) {
    const std::array<double, kFluidColumns.size()> fluid = {e.fluid_stored, e.darcy, e.fluid_inflow, e.cavitation};
    for (double x : fluid) {
      std::snprintf(cell, sizeof cell, ",%.10g", x);
      pending_ += cell;
    }
  }
  if (hysteretic_) {
    std::snprintf(cell, sizeof cell, ",%.10g", e.hysteretic_dissipated);
    pending_ += cell;
  }
  if (fourth_order_) {
    std::snprintf(cell, sizeof cell, ",%.10g", e.integrator_correction);
    pending_ += cell;
  }
  pending_ += '\n';
}

void EnergyCsv::Flush() {
  if (!file_) return;
  // The rows since the last flush go out by one write (io/whole_write.hpp): a kill leaves
  // energy.csv ending at a whole row. Nothing else writes through file_'s stdio buffer.
  io::WriteWhole(fileno(file_), pending_);
  pending_.clear();
}

void EnergyCsv::Close() {
  Flush();
  if (file_) std::fclose(file_);
  file_ = nullptr;
}

} // namespace slipwave::app
