#include "slipwave/problem/geostatic.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "slipwave/core/log_events.hpp"
#include "slipwave/core/option_choice.hpp"
#include "slipwave/input/boundary_faces.hpp"
#include "slipwave/problem/static_equilibrium.hpp"

namespace slipwave::problem {
namespace {

// Fraction of the unbalanced force taken out by local damping (the usual value in explicit
// geomechanics codes; the stage's speed is not sensitive to it between 0.5 and 0.9).
constexpr double kLocalDamping = 0.8;

// 1 on dofs free during the geostatic stage: free in the run, and not a component along the
// normal of an absorbing or free-field boundary. Those boundaries carry no support in the
// dynamic stage, so the stage holds them like rollers, normal component only (the usual
// static supports: a base holds the vertical, a free-field side the horizontal, a corner
// both), and their reactions then become constant loads. A free-field side must not be held
// along the tangent: the free field moves freely up and down the side. A component counts as
// normal where the face normal has a non-negligible part along it, so an inclined boundary
// still holds all its in-plane components.
PetscErrorCode geostaticMask(Elastodynamics *m, Vec mask) {
  PetscSection s;
  Vec          marks, local;
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(m->dm, &s));
  PetscCall(DMGetLocalVector(m->dm, &local));
  PetscCall(VecZeroEntries(local));
  PetscCall(VecGetArray(local, &a));
  for (size_t b = 0; b < m->bc.names.size(); ++b) {
    if (m->bc.types[b] != input::BoundaryType::Absorbing && m->bc.types[b] != input::BoundaryType::FreeField) continue;
    std::vector<input::BoundaryFace> faces;
    PetscCall(input::BoundaryFacesGet(m->dm, m->bc.names[b], &faces));
    for (const input::BoundaryFace &f : faces)
      for (PetscInt k = 0; k < f.nvert; ++k) {
        PetscInt off;
        PetscCall(PetscSectionGetOffset(s, f.vertices[k], &off));
        for (PetscInt d = 0; d < m->dim; ++d)
          if (std::fabs(f.normal[d]) > 1e-6) a[off + d] = 1;
      }
  }
  PetscCall(VecRestoreArray(local, &a));
  PetscCall(VecDuplicate(mask, &marks));
  PetscCall(VecZeroEntries(marks));
  PetscCall(DMLocalToGlobal(m->dm, local, ADD_VALUES, marks));
  PetscCall(DMRestoreLocalVector(m->dm, &local));
  PetscInt           n;
  const PetscScalar *mk;
  PetscCall(VecCopy(m->bc.free_mask, mask));
  PetscCall(VecGetLocalSize(mask, &n));
  PetscCall(VecGetArray(mask, &a));
  PetscCall(VecGetArrayRead(marks, &mk));
  for (PetscInt i = 0; i < n; ++i)
    if (PetscRealPart(mk[i]) > 0) a[i] = 0;
  PetscCall(VecRestoreArrayRead(marks, &mk));
  PetscCall(VecRestoreArray(mask, &a));
  PetscCall(VecDestroy(&marks));
  PetscFunctionReturn(0);
}

PetscErrorCode unbalancedRatio(Elastodynamics *m, Vec a, Vec mask, double *ratio) {
  Vec       r;
  PetscReal unbalanced, applied;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(a, &r));
  PetscCall(VecPointwiseMult(r, a, m->mass));
  PetscCall(VecPointwiseMult(r, r, mask));
  PetscCall(VecNorm(r, NORM_INFINITY, &unbalanced));
  PetscCall(VecPointwiseMult(r, m->bc.constant_force, mask));
  PetscCall(VecNorm(r, NORM_INFINITY, &applied));
  PetscCall(VecDestroy(&r));
  *ratio = applied > 0 ? unbalanced / applied : 0.0;
  PetscFunctionReturn(0);
}

// The stage's own steps are accepted as soon as taken: the RHS's trial states (interface
// pairs) are committed at once.
PetscErrorCode relaxationForces(Elastodynamics *m, Vec u, Vec a) {
  PetscFunctionBeginUser;
  PetscCall(ElastodynamicsRHS(nullptr, 0.0, u, a, m));
  PetscCall(ElastodynamicsCommit(m));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode GeostaticOptionsRead(MPI_Comm comm, GeostaticOptions *o) {
  const char *const methods[] = {"static", "relaxation"}; // GeostaticMethod order
  PetscInt          method    = (PetscInt)GeostaticMethod::Static;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "geostatic_", "Geostatic stage (gravity equilibrium before shaking)", "slipwave");
  PetscCall(PetscOptionsBool("-stage", "bring the model to rest under gravity and loads first", "GeostaticStage", o->enabled, &o->enabled, nullptr));
  PetscCall(core::OptionsChoice(PetscOptionsObject, "-method",
                                "static: linear solve with the interfaces in stick (KSP options -geostatic_ksp_*, -geostatic_pc_*), relaxation where a pair would "
                                "slip or open; relaxation: dynamic relaxation only",
                                methods, 2, &method, nullptr));
  PetscCall(PetscOptionsReal("-tolerance", "relaxation: unbalanced-force ratio max|M a| / max|f| that ends it [-], 0 < tol < 1", "GeostaticStage", o->tolerance,
                             &o->tolerance, nullptr));
  PetscCall(PetscOptionsInt("-max_steps", "relaxation: steps allowed before the stage is declared not converged, > 0", "GeostaticStage", o->max_steps, &o->max_steps,
                            nullptr));
  PetscOptionsEnd();
  o->method = (GeostaticMethod)method;
  PetscCheck(o->tolerance > 0 && o->tolerance < 1, comm, PETSC_ERR_USER_INPUT, "-geostatic_tolerance = %g; allowed: 0 < tolerance < 1", (double)o->tolerance);
  PetscCheck(o->max_steps > 0, comm, PETSC_ERR_USER_INPUT, "-geostatic_max_steps = %" PetscInt_FMT "; allowed: > 0", o->max_steps);
  if (o->enabled && o->method == GeostaticMethod::Static) PetscCall(StaticSolverCreate(comm, &o->ksp));
  PetscFunctionReturn(0);
}

PetscErrorCode GeostaticOptionsDestroy(GeostaticOptions *o) {
  PetscFunctionBeginUser;
  PetscCall(KSPDestroy(&o->ksp));
  PetscFunctionReturn(0);
}

std::string GeostaticReportLine(const GeostaticOptions &o, const GeostaticReport &g) {
  char        buf[512];
  std::string line;
  if (g.solved_static) {
    std::snprintf(buf, sizeof buf, "static solve (%s, %" PetscInt_FMT " iterations), unbalanced-force ratio %.2e; ", g.solver.c_str(), g.ksp_iterations, g.static_ratio);
    line += buf;
  }
  if (g.solved_static && g.fallback.empty()) {
    line += g.interfaces ? "every interface pair in stick" : "at rest";
  } else {
    if (!g.fallback.empty()) line += g.fallback + ", so relaxation follows: ";
    std::snprintf(buf, sizeof buf, "at rest after %" PetscInt_FMT " relaxation steps (unbalanced-force ratio %.2e < %.1e)", g.steps, g.ratio, (double)o.tolerance);
    line += buf;
  }
  std::snprintf(buf, sizeof buf, " in %.2f s wall", g.wall);
  return "geostatic stage: " + line + buf;
}

PetscErrorCode GeostaticStage(Elastodynamics *m, const GeostaticOptions &o, double dt, GeostaticReport *report, Vec geostatic_u) {
  Vec            u, v, a, mask, run_mask;
  PetscLogDouble t0, t1;
  PetscFunctionBeginUser;
  PetscCall(PetscLogStagePush(core::stage_geostatic));
  PetscCall(PetscTime(&t0));
  PetscCall(DMCreateGlobalVector(m->dm, &u));
  PetscCall(VecDuplicate(u, &v));
  PetscCall(VecDuplicate(u, &a));
  PetscCall(VecDuplicate(u, &mask));
  PetscCall(geostaticMask(m, mask));
  PetscCall(VecZeroEntries(u));
  PetscCall(VecZeroEntries(v));
  // The RHS sees the geostatic supports and no incident wave or stiffness damping.
  run_mask          = m->bc.free_mask;
  m->bc.free_mask   = mask;
  m->input_enabled  = false;
  const double beta = m->rayleigh.beta;
  m->rayleigh.beta  = 0;

  // Where the damping force opposes the velocity it adds up to alpha |f| to the unbalanced
  // force: the effective stiffness grows by 1 + alpha, so the step shrinks by sqrt(1 + alpha)
  // to stay inside the stability limit (the stage is pseudo-time; only the end state counts).
  dt /= std::sqrt(1.0 + kLocalDamping);
  bool relax = true;
  if (o.method == GeostaticMethod::Static && m->tie) {
    report->fallback = "tied lateral sides (a constraint the static solve does not carry)";
  } else if (o.method == GeostaticMethod::Static) {
    StaticSolveReport s;
    PetscCall(StaticEquilibriumSolve(m, o.ksp, mask, u, &s));
    report->solved_static  = true;
    report->interfaces     = !m->interfaces.empty();
    report->solver         = s.method;
    report->ksp_iterations = s.iterations;
    if (s.reason < 0) {
      report->fallback = std::string("the static solve did not converge (") + KSPConvergedReasons[s.reason] + ")";
      PetscCall(VecZeroEntries(u));
    } else {
      // This evaluation advances every pair from its initial state by the whole static jump
      // in one increment of the law: a pair that stays on the linear stick branch ends with
      // exactly the spring's traction; one that would slip or open is flagged.
      PetscCall(relaxationForces(m, u, a));
      PetscCall(unbalancedRatio(m, a, mask, &report->static_ratio));
      for (const auto &iface : m->interfaces) {
        PetscInt off;
        PetscCall(iface.CountOffLinearStick(&off));
        report->pairs_off_stick += off;
      }
      relax = report->pairs_off_stick > 0 || report->static_ratio >= o.tolerance;
      if (report->pairs_off_stick > 0) report->fallback = std::to_string(report->pairs_off_stick) + " interface pairs would slip, open or reach the tension cut-off";
      // A pair that starts on its tension plateau and ends on the stick branch: an interface
      // on saturated soil under a water table starts (sigma_N0 = 0) in effective tension, so
      // its zero-jump force is the plateau's -p, not the stick springs' (which K assumes).
      else if (relax) report->fallback = "the static solution is not in equilibrium (an interface pair starts on its tension plateau)";
    }
  }
  double   ratio = report->static_ratio;
  PetscInt step  = 0;
  if (relax) PetscCall(relaxationForces(m, u, a));
  for (; relax && step < o.max_steps; ++step) {
    // Local damping: each dof's unbalanced force f = M a is opposed by alpha |f| sign(v), so
    // the damping always works against the motion and cannot feed any mode (unlike zeroing
    // the velocities at kinetic-energy peaks, which pumped the modes near the step limit).
    PetscInt           n;
    PetscScalar       *va;
    const PetscScalar *aa;
    PetscCall(VecGetLocalSize(v, &n));
    PetscCall(VecGetArray(v, &va));
    PetscCall(VecGetArrayRead(a, &aa));
    for (PetscInt i = 0; i < n; ++i) {
      const double sv = (va[i] > 0) - (va[i] < 0), sa = (aa[i] > 0) - (aa[i] < 0);
      va[i] += dt * aa[i] * (1.0 - kLocalDamping * sv * sa);
    }
    PetscCall(VecRestoreArrayRead(a, &aa));
    PetscCall(VecRestoreArray(v, &va));
    PetscCall(VecAXPY(u, dt, v));
    PetscCall(relaxationForces(m, u, a));
    if (step % 10 == 0) {
      PetscCall(unbalancedRatio(m, a, mask, &ratio));
      PetscCheck(std::isfinite(ratio), m->comm, PETSC_ERR_NOT_CONVERGED, "geostatic stage diverged at step %" PetscInt_FMT "; the relaxation step %g s may be too large", step,
                 dt);
      if (ratio < o.tolerance) break;
    }
  }
  PetscCheck(!relax || ratio < o.tolerance, m->comm, PETSC_ERR_NOT_CONVERGED,
             "geostatic stage not converged after %" PetscInt_FMT " steps: unbalanced-force ratio %.3e; allowed: below -geostatic_tolerance = %g (raise -geostatic_max_steps)",
             step, ratio, (double)o.tolerance);

  // The new constant load: what the state leaves unbalanced on the geostatic-free dofs, and the
  // support reactions (minus the interface force there) on the held absorbing nodes, so that
  // M a = 0 at the start of the dynamic stage.
  {
    PetscInt           n;
    PetscScalar       *fc;
    const PetscScalar *fi, *fif, *mk;
    PetscCall(VecGetLocalSize(u, &n));
    PetscCall(VecGetArray(m->bc.constant_force, &fc));
    PetscCall(VecGetArrayRead(m->f_internal, &fi));
    PetscCall(VecGetArrayRead(m->f_interface, &fif));
    PetscCall(VecGetArrayRead(mask, &mk));
    for (PetscInt i = 0; i < n; ++i) fc[i] = mk[i] > 0 ? fc[i] - fi[i] : -fif[i];
    PetscCall(VecRestoreArrayRead(mask, &mk));
    PetscCall(VecRestoreArrayRead(m->f_interface, &fif));
    PetscCall(VecRestoreArrayRead(m->f_internal, &fi));
    PetscCall(VecRestoreArray(m->bc.constant_force, &fc));
  }
  PetscCall(ElastodynamicsSetInitialStress(m, u));
  if (geostatic_u) PetscCall(VecCopy(u, geostatic_u));
  for (auto &iface : m->interfaces) iface.ResetJumpReference();

  m->bc.free_mask  = run_mask;
  m->input_enabled = true;
  m->rayleigh.beta = beta;
  PetscCall(VecDestroy(&mask));
  PetscCall(VecDestroy(&a));
  PetscCall(VecDestroy(&v));
  PetscCall(VecDestroy(&u));
  PetscCall(PetscTime(&t1));
  report->steps = step;
  report->ratio = ratio;
  report->wall  = t1 - t0;
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

} // namespace slipwave::problem
