// slipwave-law: drives one interface pair of the Mohr-Coulomb law along a jump history, to
// calibrate the interface parameters against a laboratory shear test.
//   slipwave-law -path IN.csv [-output OUT.csv] -interface_E 1e9 -interface_G 1e9 ...
#include "slipwave/core/errors.hpp"
#include "slipwave/core/mpi_singleton.hpp"
#include "slipwave/core/option_files.hpp"
#include "slipwave/core/options_check.hpp"
#include "slipwave/interface/interface_options.hpp"
#include "slipwave/io/jump_history_csv.hpp"
#include "slipwave/physics/mohr_coulomb_interface.hpp"

#include <algorithm>
#include <cstdio>

static const char help[] =
    "Drives one interface pair of the Mohr-Coulomb law along a jump history.\n"
    "  -path IN.csv     jump history: header t,w_T,w_N (2D) or t,w_T1,w_T2,w_N (3D), jumps in m\n"
    "  -output OUT.csv  result (default: standard output)\n"
    "The increment of a row is its difference from the previous row (the first from zero jump).\n";

namespace {

using namespace slipwave;

template <int Dim>
void writeHeader(FILE *out) {
  if (Dim == 2)
    std::fputs("t,w_T,w_N,sigma_T,sigma_N,wp_T,wp_N,status,dissipation\n", out);
  else
    std::fputs("t,w_T1,w_T2,w_N,sigma_T1,sigma_T2,sigma_N,wp_T1,wp_T2,wp_N,status,dissipation\n", out);
}

// Runs the law along the history; returns the largest drift returned to the yield surface.
template <int Dim>
double runHistory(const physics::InterfaceLaw &law, double sigma_N0, const io::JumpHistory &h, FILE *out) {
  constexpr int NT = Dim - 1;
  auto s = physics::interfaceInitialState<Dim>(law, sigma_N0);
  double previous[Dim] = {};
  double max_drift = 0.0;
  writeHeader<Dim>(out);
  for (std::size_t r = 0; r < h.rows(); ++r) {
    const double *w = &h.w[r * Dim];
    double dw[Dim];
    for (int k = 0; k < Dim; ++k) dw[k] = w[k] - previous[k];
    max_drift = std::max(max_drift, physics::interfaceUpdate<Dim>(law, s, dw, dw[NT]));
    std::copy(w, w + Dim, previous);

    std::fprintf(out, "%.12g", h.t[r]);
    for (int k = 0; k < Dim; ++k) std::fprintf(out, ",%.12g", w[k]);
    for (int k = 0; k < NT; ++k) std::fprintf(out, ",%.12g", s.sigma_T[k]);
    std::fprintf(out, ",%.12g", s.sigma_N);
    for (int k = 0; k < NT; ++k) std::fprintf(out, ",%.12g", s.wp_T[k]);
    std::fprintf(out, ",%.12g,%s,%.12g\n", s.wp_N, physics::interfaceStatusName(s.status), s.dissipation);
  }
  return max_drift;
}

PetscErrorCode run(MPI_Comm comm) {
  char        path[PETSC_MAX_PATH_LEN] = "", output[PETSC_MAX_PATH_LEN] = "";
  PetscBool   has_path = PETSC_FALSE, has_output = PETSC_FALSE, help_requested = PETSC_FALSE;
  PetscMPIInt size = 1;
  interface::InterfaceOptions options;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "Interface law driver options", "slipwave");
  PetscCall(PetscOptionsString("-path", "Jump history CSV: t,w_T,w_N (2D) or t,w_T1,w_T2,w_N (3D), jumps [m]", "slipwave-law",
                               path, path, sizeof path, &has_path));
  PetscCall(PetscOptionsString("-output", "Result CSV (default: standard output)", "slipwave-law", output, output,
                               sizeof output, &has_output));
  PetscOptionsEnd();
  PetscCall(interface::InterfaceOptionsRead(comm, "interface_", interface::InterfaceUse::LawAlone, &options));
  PetscCall(core::OptionsErrorIfUnused(comm));
  PetscCall(PetscOptionsHasHelp(nullptr, &help_requested));
  if (help_requested) PetscFunctionReturn(0);

  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCheck(size == 1, comm, PETSC_ERR_USER_INPUT, "slipwave-law drives a single pair; run it on 1 process, not %d", size);
  PetscCheck(has_path && path[0], comm, PETSC_ERR_USER_INPUT, "-path is required: the jump history CSV to drive the law with");
  PetscCheck(!options.E_auto, comm, PETSC_ERR_USER_INPUT,
             "-interface_E = auto needs a mesh to derive the stiffness and slipwave-law has none; allowed a value > 0 [Pa/m]");
  PetscCheck(!options.G_auto, comm, PETSC_ERR_USER_INPUT,
             "-interface_G = auto needs a mesh to derive the stiffness and slipwave-law has none; allowed a value > 0 [Pa/m]");

  io::JumpHistory history;
  PetscCall(io::JumpHistoryCsvRead(comm, path, &history));

  FILE *out = stdout;
  if (has_output && output[0]) {
    out = std::fopen(output, "w");
    PetscCheck(out, comm, PETSC_ERR_FILE_OPEN, "-output %s: cannot open the file for writing", output);
  }
  const physics::InterfaceLaw law(options.params);
  const double max_drift = history.dim == 2 ? runHistory<2>(law, options.sigma_N0, history, out)
                                            : runHistory<3>(law, options.sigma_N0, history, out);
  const bool write_failed = std::ferror(out) != 0;
  if (out != stdout) std::fclose(out);
  else std::fflush(out);
  PetscCheck(!write_failed, comm, PETSC_ERR_FILE_WRITE, "writing the result failed");
  PetscCall(PetscFPrintf(comm, PETSC_STDERR, "slipwave-law: %zu steps (%dD); largest drift returned to the yield surface %g Pa\n",
                         history.rows(), history.dim, max_drift));
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char **argv) {
  if (!slipwave::core::OptionFilesAcceptable(argc, argv, "slipwave-law")) return 1;
  slipwave::core::MpiSingletonDefaults();
  PetscCall(PetscInitialize(&argc, &argv, nullptr, help));
  PetscErrorCode ierr = slipwave::core::ErrorsPushUserInputHandler("slipwave-law");
  if (!ierr) ierr = run(PETSC_COMM_WORLD);
  if (ierr) {
    PetscFinalize();
    return 1;
  }
  PetscCall(PetscFinalize());
  return 0;
}
