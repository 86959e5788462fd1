// Internal force on box meshes, 1 rank: our element loop (BulkOperator::addStiffnessTimes)
// against an assembled PETSc matrix (AIJ and BAIJ, K assembled here from the same element
// kernel), plus the whole RHS (ElastodynamicsRHS) and the whole central-difference step
// (TSStep of type "cd", no monitors) through the model. 2D Q1: 128^2, 256^2, 512^2 cells;
// 3D Q1: 16^3, 32^3, 64^3. Each timing is the best of 3 repeats of a loop of ~0.3 s, so that
// other processes on the machine disturb it less. Rows appended to the CSV:
//   bulk_operator,<2d|3d>_<n>,<metric>,<value>,<unit>
//   build/bench/bench_bulk_operator [--csv FILE] [--quick] [--case 2d_256] [--max-setup SECONDS]
// --quick runs only the two smallest sizes (for a smoke test), --case one size; sizes whose predicted set-up
// (extrapolated from the previous size) exceeds --max-setup (default 60 s) are skipped.
#include <petscdmplex.h>
#include <petscts.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "best_time.hpp"

#include "slipwave/core/log_events.hpp"
#include "slipwave/fem/element_kernels.hpp"
#include "slipwave/problem/elastodynamics.hpp"
#include "slipwave/problem/stable_step.hpp"
#include "slipwave/time/central_difference.hpp"

using namespace slipwave;
using bench::bestTime;
using bench::now;

namespace {

struct Row {
  std::string case_name;
  PetscInt    dim = 0, ndof = 0, ncell = 0, nnz = 0;
  double      setup = 0, loop = 0, loop_comm = 0, mat_aij = 0, mat_baij = 0, rhs = 0, step = 0, diff_aij = 0, diff_baij = 0, asm_time = 0;
};

void setOption(const char *name, const char *value) { PetscOptionsSetValue(nullptr, name, value); }

// K assembled from the element kernel on every cell (the same matrices the BulkOperator stores).
PetscErrorCode assemble(problem::Elastodynamics *m, MatType type, Mat *K) {
  const fem::BulkOperator &b = m->bulk;
  const PetscInt           n = b.nodesPerCell() * b.dimension();
  std::vector<double>      Ke(n * n);
  std::vector<PetscInt>    idx(n);
  PetscFunctionBeginUser;
  PetscCall(DMSetMatType(m->dm, type));
  PetscCall(DMCreateMatrix(m->dm, K));
  PetscCall(MatSetOption(*K, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  for (PetscInt c = 0; c < b.cellCount(); ++c) {
    fem::elementStiffness(b.shape(), b.cellCoordinates(c), m->materials[b.cellRegion(c)].fe.lame, Ke.data());
    for (PetscInt a = 0; a < b.nodesPerCell(); ++a)
      for (PetscInt i = 0; i < b.dimension(); ++i) idx[a * b.dimension() + i] = b.cellNodeOffset(c, a) + i;
    PetscCall(MatSetValuesLocal(*K, n, idx.data(), n, idx.data(), Ke.data(), ADD_VALUES));
  }
  PetscCall(MatAssemblyBegin(*K, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*K, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

PetscErrorCode relativeDifference(Vec a, Vec b, double *d) {
  Vec       w;
  PetscReal nd, na;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(a, &w));
  PetscCall(VecWAXPY(w, -1.0, a, b));
  PetscCall(VecNorm(w, NORM_INFINITY, &nd));
  PetscCall(VecNorm(a, NORM_INFINITY, &na));
  *d = na > 0 ? nd / na : nd;
  PetscCall(VecDestroy(&w));
  PetscFunctionReturn(0);
}

PetscErrorCode runCase(PetscInt dim, PetscInt nc, Row *row) {
  char faces[64];
  PetscFunctionBeginUser;
  if (dim == 2) std::snprintf(faces, sizeof faces, "%d,%d", (int)nc, (int)nc);
  else std::snprintf(faces, sizeof faces, "%d,%d,%d", (int)nc, (int)nc, (int)nc);
  setOption("-mesh_dim", dim == 2 ? "2" : "3");
  setOption("-mesh_box_faces", faces);
  setOption("-mesh_box_upper", dim == 2 ? "100,100" : "100,100,100");
  row->case_name = std::string(dim == 2 ? "2d_" : "3d_") + std::to_string(nc);
  row->dim       = dim;

  problem::Elastodynamics m;
  double                t0 = now();
  PetscCall(problem::ElastodynamicsCreate(PETSC_COMM_WORLD, &m));
  problem::StableStep st;
  PetscCall(problem::StableStepCompute(&m, problem::TimeStepOptions(), &st));
  row->setup = now() - t0;
  row->ncell = m.bulk.cellCount();

  Vec x, f_loop, f_mat, a;
  PetscCall(VecDuplicate(m.mass, &x));
  PetscCall(VecDuplicate(m.mass, &f_loop));
  PetscCall(VecDuplicate(m.mass, &f_mat));
  PetscCall(VecDuplicate(m.mass, &a));
  PetscCall(VecGetSize(x, &row->ndof));
  {
    PetscRandom rnd;
    PetscCall(PetscRandomCreate(PETSC_COMM_WORLD, &rnd));
    PetscCall(PetscRandomSetInterval(rnd, -1.0, 1.0));
    PetscCall(VecSetRandom(x, rnd));
    PetscCall(PetscRandomDestroy(&rnd));
  }

  // 1. The element loop alone, on local arrays.
  PetscCall(DMGlobalToLocal(m.dm, x, INSERT_VALUES, m.u_local));
  {
    const PetscScalar *ul;
    PetscScalar       *fl;
    PetscCall(VecGetArrayRead(m.u_local, &ul));
    PetscCall(VecGetArray(m.f_local, &fl));
    row->loop = bestTime([&] { m.bulk.addStiffnessTimes(ul, fl); });
    PetscCall(VecRestoreArray(m.f_local, &fl));
    PetscCall(VecRestoreArrayRead(m.u_local, &ul));
  }
  // 2. The element loop with the local<->global exchange (what the RHS pays for f = K u).
  PetscErrorCode ierr = 0;
  row->loop_comm      = bestTime([&] { ierr = ierr ? ierr : problem::ElastodynamicsStiffnessTimes(&m, x, f_loop); });
  PetscCall(ierr);
  PetscCall(problem::ElastodynamicsStiffnessTimes(&m, x, f_loop));

  // 3. Assembled matrices, MatMult (AIJ; BAIJ with the dim x dim node blocks).
  for (int pass = 0; pass < 2; ++pass) {
    Mat K;
    t0 = now();
    PetscCall(assemble(&m, pass == 0 ? MATAIJ : MATBAIJ, &K));
    if (pass == 0) {
      row->asm_time = now() - t0;
      MatInfo info;
      PetscCall(MatGetInfo(K, MAT_GLOBAL_SUM, &info));
      row->nnz = (PetscInt)info.nz_used;
    }
    PetscCall(MatMult(K, x, f_mat));
    PetscCall(relativeDifference(f_loop, f_mat, pass == 0 ? &row->diff_aij : &row->diff_baij));
    double &t = pass == 0 ? row->mat_aij : row->mat_baij;
    t         = bestTime([&] { ierr = ierr ? ierr : MatMult(K, x, f_mat); });
    PetscCall(ierr);
    PetscCall(MatDestroy(&K));
  }

  // 4. The whole RHS and the whole step (central difference, nodal damping as the driver sets it).
  row->rhs = bestTime([&] { ierr = ierr ? ierr : problem::ElastodynamicsRHS(nullptr, 0.0, x, a, &m); });
  PetscCall(ierr);
  {
    TS  ts;
    Vec u, v;
    PetscCall(time::CentralDifferenceRegister());
    PetscCall(TSCreate(PETSC_COMM_WORLD, &ts));
    PetscCall(TSSetType(ts, time::kTSCentralDifference));
    PetscCall(TSSetMaxTime(ts, 1e30));
    PetscCall(TSSetMaxSteps(ts, PETSC_MAX_INT));
    PetscCall(TSSetTimeStep(ts, 0.9 * st.dt_limit));
    PetscCall(problem::ElastodynamicsSetUpTS(&m, ts));
    PetscCall(VecDuplicate(x, &u));
    PetscCall(VecDuplicate(x, &v));
    PetscCall(VecZeroEntries(u));
    PetscCall(VecCopy(x, v));
    PetscCall(TS2SetSolution(ts, u, v));
    PetscCall(TSSetUp(ts));
    PetscCall(time::CentralDifferenceComputeInitialAcceleration(ts));
    row->step = bestTime([&] { ierr = ierr ? ierr : TSStep(ts); });
    PetscCall(ierr);
    PetscCall(TSDestroy(&ts));
    PetscCall(VecDestroy(&u));
    PetscCall(VecDestroy(&v));
  }
  for (Vec *w : {&x, &f_loop, &f_mat, &a}) PetscCall(VecDestroy(w));
  PetscCall(problem::ElastodynamicsDestroy(&m));
  PetscFunctionReturn(0);
}

// Correctness of the element loop where consecutive cells do not all share a matrix: two
// regions on an odd-sized box (runs of equal matrices end inside a batch), 2D and 3D, checked
// against the assembled AIJ matrix.
PetscErrorCode validateMixed(PetscInt dim, double *diff) {
  PetscFunctionBeginUser;
  setOption("-mesh_dim", dim == 2 ? "2" : "3");
  setOption("-mesh_box_faces", dim == 2 ? "37,29" : "11,9,7");
  setOption("-mesh_box_upper", dim == 2 ? "100,100" : "100,100,100");
  setOption("-regions", "soil,rock");
  // On grid lines (box regions must fit the mesh): cells 5..22 x 0..13 of 37 x 29 in 2D,
  // 1..6 x 0..3 x 0..4 of 11 x 9 x 7 in 3D.
  setOption("-region_rock_box", dim == 2 ? "13.513513513513514,62.16216216216216,0,48.275862068965516"
                                         : "9.090909090909092,63.63636363636363,0,44.44444444444444,0,71.42857142857143");
  setOption("-material_rock_rho", "2500");
  setOption("-material_rock_vp", "1500");
  setOption("-material_rock_vs", "800");
  problem::Elastodynamics m;
  PetscCall(problem::ElastodynamicsCreate(PETSC_COMM_WORLD, &m));
  Vec         x, f_loop, f_mat;
  Mat         K;
  PetscRandom rnd;
  PetscCall(VecDuplicate(m.mass, &x));
  PetscCall(VecDuplicate(m.mass, &f_loop));
  PetscCall(VecDuplicate(m.mass, &f_mat));
  PetscCall(PetscRandomCreate(PETSC_COMM_WORLD, &rnd));
  PetscCall(VecSetRandom(x, rnd));
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(problem::ElastodynamicsStiffnessTimes(&m, x, f_loop));
  PetscCall(assemble(&m, MATAIJ, &K));
  PetscCall(MatMult(K, x, f_mat));
  PetscCall(relativeDifference(f_loop, f_mat, diff));
  PetscCall(MatDestroy(&K));
  for (Vec *w : {&x, &f_loop, &f_mat}) PetscCall(VecDestroy(w));
  PetscCall(problem::ElastodynamicsDestroy(&m));
  setOption("-regions", "soil");
  for (const char *o : {"-region_rock_box", "-material_rock_rho", "-material_rock_vp", "-material_rock_vs"}) PetscCall(PetscOptionsClearValue(nullptr, o));
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char **argv) {
  const char *csv       = nullptr;
  bool        quick     = false;
  const char *only      = nullptr;
  double      max_setup = 60;
  // Our own arguments are taken out before PETSc sees the command line.
  std::vector<char *> petsc_args{argv[0]};
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--csv") == 0 && i + 1 < argc) csv = argv[++i];
    else if (std::strcmp(argv[i], "--quick") == 0) quick = true;
    else if (std::strcmp(argv[i], "--case") == 0 && i + 1 < argc) only = argv[++i];
    else if (std::strcmp(argv[i], "--max-setup") == 0 && i + 1 < argc) max_setup = std::atof(argv[++i]);
    else petsc_args.push_back(argv[i]);
  }
  int    pargc = (int)petsc_args.size();
  char **pargv = petsc_args.data();
  PetscCall(PetscInitialize(&pargc, &pargv, nullptr, nullptr));
  PetscMPIInt size;
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  PetscCheck(size == 1, PETSC_COMM_WORLD, PETSC_ERR_SUP, "bench_bulk_operator runs on 1 rank");
  PetscCall(core::LogEventsRegister());
  setOption("-regions", "soil");
  setOption("-material_soil_rho", "2000");
  setOption("-material_soil_vp", "400");
  setOption("-material_soil_vs", "200");

  FILE *out = csv ? std::fopen(csv, "a") : nullptr;
  for (PetscInt dim = 2; dim <= 3; ++dim) {
    double diff;
    PetscCall(validateMixed(dim, &diff));
    std::printf("check %dD two regions: element loop vs assembled AIJ, max relative difference %.2e%s\n", (int)dim, diff, diff > 1e-12 ? "  WRONG" : "");
    if (out) std::fprintf(out, "bulk_operator,check_%dd_two_regions,max_rel_diff_vs_assembled,%.3g,1\n", (int)dim, diff);
  }
  std::printf("bulk_operator: internal force f = K u, 1 rank, best of 3 (Mdof/s = million DOF-updates per second)\n");
  std::printf("%-7s %8s %8s %6s | %9s %9s | %9s %9s %9s | %9s %9s | %8s %8s\n", "case", "dofs", "cells", "setup", "loop ms", "+exch ms", "AIJ ms",
              "BAIJ ms", "AIJ/loop", "RHS ms", "step ms", "loop", "step");
  std::printf("%-7s %8s %8s %6s | %9s %9s | %9s %9s %9s | %9s %9s | %8s %8s\n", "", "", "", "s", "", "", "", "", "", "", "", "Mdof/s", "Mdof/s");
  struct Size {
    PetscInt dim, n;
  } sizes[] = {{2, 128}, {2, 256}, {2, 512}, {3, 16}, {3, 32}, {3, 64}};
  double prev_setup_per_cell[4] = {0, 0, 0, 0};
  for (const Size &s : sizes) {
    if (quick && s.n != (s.dim == 2 ? 128 : 16)) continue;
    if (only && std::to_string(s.dim) + "d_" + std::to_string(s.n) != only) continue;
    const double cells     = std::pow((double)s.n, (double)s.dim);
    const double predicted = prev_setup_per_cell[s.dim] * cells;
    if (predicted > max_setup) {
      std::printf("%dd_%d: skipped, predicted set-up %.0f s > %.0f s\n", (int)s.dim, (int)s.n, predicted, max_setup);
      if (out) std::fprintf(out, "bulk_operator,%dd_%d,skipped_predicted_setup,%.1f,s\n", (int)s.dim, (int)s.n, predicted);
      continue;
    }
    Row r;
    PetscCall(runCase(s.dim, s.n, &r));
    prev_setup_per_cell[s.dim] = r.setup / cells;
    const double mdof = 1e-6 * r.ndof;
    std::printf("%-7s %8d %8d %6.1f | %9.3f %9.3f | %9.3f %9.3f %9.2f | %9.3f %9.3f | %8.1f %8.1f\n", r.case_name.c_str(), (int)r.ndof, (int)r.ncell, r.setup,
                1e3 * r.loop, 1e3 * r.loop_comm, 1e3 * r.mat_aij, 1e3 * r.mat_baij, r.mat_aij / r.loop_comm, 1e3 * r.rhs, 1e3 * r.step, mdof / r.loop,
                mdof / r.step);
    if (r.diff_aij > 1e-10 || r.diff_baij > 1e-10)
      std::printf("  WARNING: assembled K u differs from the element loop by %.2e (AIJ) / %.2e (BAIJ)\n", r.diff_aij, r.diff_baij);
    if (out) {
      const char *c = r.case_name.c_str();
      std::fprintf(out, "bulk_operator,%s,dofs,%d,1\n", c, (int)r.ndof);
      std::fprintf(out, "bulk_operator,%s,cells,%d,1\n", c, (int)r.ncell);
      std::fprintf(out, "bulk_operator,%s,setup_time,%.3f,s\n", c, r.setup);
      std::fprintf(out, "bulk_operator,%s,element_loop_time,%.6g,s\n", c, r.loop);
      std::fprintf(out, "bulk_operator,%s,element_loop_with_exchange_time,%.6g,s\n", c, r.loop_comm);
      std::fprintf(out, "bulk_operator,%s,element_loop_dof_rate,%.4g,1/s\n", c, r.ndof / r.loop);
      std::fprintf(out, "bulk_operator,%s,aij_assembly_time,%.3f,s\n", c, r.asm_time);
      std::fprintf(out, "bulk_operator,%s,aij_nonzeros,%d,1\n", c, (int)r.nnz);
      std::fprintf(out, "bulk_operator,%s,aij_matmult_time,%.6g,s\n", c, r.mat_aij);
      std::fprintf(out, "bulk_operator,%s,baij_matmult_time,%.6g,s\n", c, r.mat_baij);
      std::fprintf(out, "bulk_operator,%s,aij_matmult_dof_rate,%.4g,1/s\n", c, r.ndof / r.mat_aij);
      std::fprintf(out, "bulk_operator,%s,aij_over_element_loop_with_exchange,%.3f,1\n", c, r.mat_aij / r.loop_comm);
      std::fprintf(out, "bulk_operator,%s,assembled_vs_loop_max_rel_diff,%.3g,1\n", c, std::max(r.diff_aij, r.diff_baij));
      std::fprintf(out, "bulk_operator,%s,rhs_time,%.6g,s\n", c, r.rhs);
      std::fprintf(out, "bulk_operator,%s,step_time,%.6g,s\n", c, r.step);
      std::fprintf(out, "bulk_operator,%s,step_dof_rate_per_core,%.4g,1/s\n", c, r.ndof / r.step);
    }
  }
  if (out) std::fclose(out);
  PetscCall(PetscFinalize());
  return 0;
}
