// slipwave: explicit finite elements for seismic soil-structure interaction.
#include <petscsys.h>

#include "slipwave/app/simulation.hpp"
#include "slipwave/core/errors.hpp"
#include "slipwave/core/help_order.hpp"
#include "slipwave/core/mpi_singleton.hpp"
#include "slipwave/core/option_files.hpp"
#include "slipwave/core/option_rules.hpp"
#include "slipwave/core/options_check.hpp"

static const char help[] = "slipwave: explicit elastodynamics on PETSc for seismic soil-structure interaction.\n"
                           "Options come from the command line and option files (-options_file scene.yaml); with a scene,\n"
                           "-help lists the options of every module it uses (slipwave -options_file config/scenes/default.yaml -help).\n";

int main(int argc, char **argv) {
  if (!slipwave::core::OptionFilesAcceptable(argc, argv, "slipwave")) return 1;
  slipwave::core::HelpHoldPetscGeneric(argc, argv);
  slipwave::core::MpiSingletonDefaults();
  PetscErrorCode ierr = PetscInitialize(&argc, &argv, nullptr, nullptr);
  if (ierr) return 1;
  slipwave::core::HelpStopHolding();
  PetscBool has_help = PETSC_FALSE;
  ierr = slipwave::core::ErrorsPushUserInputHandler("slipwave");
  if (!ierr) ierr = slipwave::core::OptionFilePathsResolve(argc, argv);
  if (!ierr) ierr = slipwave::core::OptionsApplyRenames(PETSC_COMM_WORLD);
  if (!ierr) ierr = slipwave::core::OptionsValidate(PETSC_COMM_WORLD);
  if (!ierr) ierr = PetscOptionsHasHelp(nullptr, &has_help);
  if (!ierr && has_help) ierr = PetscPrintf(PETSC_COMM_WORLD, "%s\n", help);
  if (!ierr && has_help) ierr = slipwave::core::OptionsPrintRules(PETSC_COMM_WORLD);
  if (!ierr) ierr = slipwave::app::SimulationRun(PETSC_COMM_WORLD);
  if (has_help) slipwave::core::HelpPrintHeld(PETSC_COMM_WORLD);
  const PetscErrorCode fin = PetscFinalize();
  return (ierr || fin) ? 1 : 0;
}
