// Throughput of the spectral-element internal force (SpectralOperator::addStiffnessTimes, 1
// rank, 1 core) on box-like element blocks of degree p = 1, 2, 4, 6: 2D with about 600 GLL
// nodes per direction, 3D about 60 (so the vectors exceed the caches, as in a real run).
// All elements share one geometry record, so the loop runs batched across elements with the
// factors broadcast (the path of box meshes); "warped" repeats p = 4 with every element its
// own geometry (lane batches with interleaved factors: the path of unstructured meshes). Each timing is the best of 3 loops of ~0.3 s.
// Rows appended to the CSV:
//   spectral_operator,<2d|3d>_p<p>[_warped],mdof_updates_per_s,<value>,M/s
//   build/bench/bench_spectral_operator [--csv FILE] [--quick]
// --quick: blocks 4x smaller per direction in 2D, 2x in 3D (a smoke test).
#include <petscsys.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "best_time.hpp"

#include "../tests/unit/spectral_box_mesh.hpp"
#include "slipwave/fem/spectral_operator.hpp"

using namespace slipwave;
using bench::bestTime;
using bench::now;

namespace {

void warpNodes(double *X) {
  X[0] += 0.02 * std::sin(1.3 * X[1] + 0.4 * X[2]);
  X[1] += 0.02 * std::sin(1.1 * X[0] + 0.2);
  X[2] += 0.02 * std::sin(0.9 * X[0] + 0.7 * X[1]);
}

PetscErrorCode runCase(int dim, int p, bool warped, bool quick, FILE *csv) {
  PetscFunctionBeginUser;
  const int nodes = dim == 2 ? (quick ? 150 : 600) : (quick ? 30 : 60);
  const int n     = std::max(1, (int)std::lround((double)nodes / p));
  const int ne[3] = {n, n, n};
  const auto m    = unit::spectralBoxMesh(dim, p, ne, 1.0, warped ? warpNodes : std::function<void(double *)>());
  const std::vector<fem::RegionMaterial> materials{{2000.0, {1.6e8, 8e7}}};
  fem::SpectralOperator op;
  PetscCall(op.Setup(dim, p, m.nelem, m.coords.data(), m.node_offset.data(), m.region.data(), materials));
  std::vector<PetscScalar> u(m.ndof), f(m.ndof, 0.0);
  for (PetscInt i = 0; i < m.ndof; ++i) u[i] = std::sin(0.001 * i);
  const double t    = bestTime([&] { op.addStiffnessTimes(u.data(), f.data()); });
  const double rate = m.ndof / t / 1e6;
  const std::string name = std::to_string(dim) + "d_p" + std::to_string(p) + (warped ? "_warped" : "");
  std::printf("%-12s %8" PetscInt_FMT " elements %9" PetscInt_FMT " dofs %5" PetscInt_FMT " records  %8.3f ms  %7.1f M DOF-updates/s\n", name.c_str(), m.nelem, m.ndof,
              op.distinctGeometries(), 1e3 * t, rate);
  if (csv) std::fprintf(csv, "spectral_operator,%s,mdof_updates_per_s,%.2f,M/s\n", name.c_str(), rate);
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char **argv) {
  const char         *csv_path = nullptr;
  bool                quick    = false;
  std::vector<char *> petsc_args{argv[0]};
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--csv") == 0 && i + 1 < argc) csv_path = argv[++i];
    else if (std::strcmp(argv[i], "--quick") == 0) quick = true;
    else petsc_args.push_back(argv[i]);
  }
  int    pargc = (int)petsc_args.size();
  char **pargv = petsc_args.data();
  PetscCall(PetscInitialize(&pargc, &pargv, nullptr, nullptr));
  FILE *csv = csv_path ? std::fopen(csv_path, "a") : nullptr;
  for (int dim = 2; dim <= 3; ++dim) {
    for (int p : {1, 2, 4, 6}) PetscCall(runCase(dim, p, false, quick, csv));
    PetscCall(runCase(dim, 4, true, quick, csv));
  }
  if (csv) std::fclose(csv);
  PetscCall(PetscFinalize());
  return 0;
}
