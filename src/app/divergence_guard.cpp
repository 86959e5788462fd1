#include "slipwave/app/divergence_guard.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "slipwave/core/log_events.hpp"

namespace slipwave::app {
namespace {

// A field the guard searches, in the order a non-finite value spreads back from: the state
// first, then the force parts of the step's right-hand side (which the ledger's sums use).
struct Searched {
  const char *name;
  Vec         values;
};

bool finite(double x) { return std::isfinite(x); }

// The lowest global dof of x that is not finite, or PETSC_MAX_INT (collective).
PetscErrorCode firstNonFinite(MPI_Comm comm, Vec x, PetscInt *first) {
  PetscInt           n, lo, bad = PETSC_MAX_INT;
  const PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(VecGetOwnershipRange(x, &lo, nullptr));
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArrayRead(x, &a));
  for (PetscInt i = 0; i < n && bad == PETSC_MAX_INT; ++i)
    if (!finite(PetscRealPart(a[i]))) bad = lo + i;
  PetscCall(VecRestoreArrayRead(x, &a));
  PetscCallMPI(MPI_Allreduce(&bad, first, 1, MPIU_INT, MPI_MIN, comm));
  PetscFunctionReturn(0);
}

// Coordinates of the node holding global dof `dof` (collective; every rank gets them).
PetscErrorCode nodeCoordinates(const problem::Elastodynamics &model, PetscInt dof, double x[3]) {
  Vec                local, global;
  PetscScalar       *l;
  const PetscScalar *g;
  PetscInt           lo, hi;
  double             mine[3] = {0, 0, 0};
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(model.dm, &local));
  PetscCall(DMGetGlobalVector(model.dm, &global));
  PetscCall(VecGetArray(local, &l));
  model.bulk.nodeCoordinates(l);
  PetscCall(VecRestoreArray(local, &l));
  PetscCall(DMLocalToGlobal(model.dm, local, INSERT_VALUES, global));
  PetscCall(VecGetOwnershipRange(global, &lo, &hi));
  const PetscInt node0 = dof - dof % model.dim;
  if (node0 >= lo && node0 < hi) {
    PetscCall(VecGetArrayRead(global, &g));
    for (PetscInt d = 0; d < model.dim; ++d) mine[d] = PetscRealPart(g[node0 - lo + d]);
    PetscCall(VecRestoreArrayRead(global, &g));
  }
  PetscCallMPI(MPI_Allreduce(mine, x, 3, MPI_DOUBLE, MPI_SUM, model.comm));
  PetscCall(DMRestoreGlobalVector(model.dm, &global));
  PetscCall(DMRestoreLocalVector(model.dm, &local));
  PetscFunctionReturn(0);
}

// "node N (x, y[, z]), component c" for a global dof (collective).
PetscErrorCode dofPlace(const problem::Elastodynamics &model, PetscInt dof, std::string *place) {
  double x[3];
  char   text[160];
  PetscFunctionBeginUser;
  PetscCall(nodeCoordinates(model, dof, x));
  const PetscInt node = dof / model.dim;
  const char     component = "xyz"[dof % model.dim];
  if (model.dim == 3) std::snprintf(text, sizeof text, "node %" PetscInt_FMT " (%g, %g, %g), component %c", node, x[0], x[1], x[2], component);
  else std::snprintf(text, sizeof text, "node %" PetscInt_FMT " (%g, %g), component %c", node, x[0], x[1], component);
  *place = text;
  PetscFunctionReturn(0);
}

// The input that made the value non-finite, if one did: a material, the constant loads
// (gravity, tractions) or the incident wave. "" when every input is finite.
PetscErrorCode inputCause(const problem::Elastodynamics &model, PetscReal t, std::string *cause) {
  char     text[512] = "";
  PetscInt bad;
  PetscFunctionBeginUser;
  for (const auto &m : model.materials) {
    const double values[5] = {m.elastic.rho, m.elastic.vp, m.elastic.vs, m.fe.lame.lambda, m.fe.lame.mu};
    const char  *names[5]  = {"rho", "vp", "vs", "lambda", "mu"};
    for (int k = 0; k < 5 && !text[0]; ++k)
      if (!finite(values[k]))
        std::snprintf(text, sizeof text, "the material of region '%s' (-material_%s_...): %s = %g", m.region.c_str(), m.region.c_str(), names[k], values[k]);
  }
  if (!text[0] && !finite(model.bc.gravity)) std::snprintf(text, sizeof text, "-gravity = %g", model.bc.gravity);
  if (!text[0]) {
    PetscCall(firstNonFinite(model.comm, model.bc.constant_force, &bad));
    std::string place;
    if (bad != PETSC_MAX_INT) PetscCall(dofPlace(model, bad, &place));
    if (bad != PETSC_MAX_INT) std::snprintf(text, sizeof text, "the constant loads (-gravity = %g, -bc_<name>_traction) at %s", model.bc.gravity, place.c_str());
  }
  if (!text[0] && model.bc.input.active()) {
    const double v_in = model.bc.input.velocity(t);
    PetscCall(firstNonFinite(model.comm, model.f_input, &bad));
    // The history's first clause names it (type, file, samples); the rest is its peak values.
    const std::string history = model.bc.input.describe().substr(0, model.bc.input.describe().find(';'));
    if (!finite(v_in) || bad != PETSC_MAX_INT)
      std::snprintf(text, sizeof text, "the incident wave (-input_stf: %s): v_in(t) = %g m/s, input force %s", history.c_str(), v_in,
                    bad == PETSC_MAX_INT ? "finite" : "not finite");
  }
  *cause = text;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode DivergenceGuard(const problem::Elastodynamics &model, const problem::EnergyLedger &e, PetscReal growth_limit, const problem::IntegratorStep &limit, PetscReal h,
                               PetscInt step, PetscReal t, Vec u, Vec v, Vec a) {
  MPI_Comm comm = model.comm;
  PetscFunctionBeginUser;
  // The ledger's global sums run over every dof of u, v and the force parts: a NaN or Inf
  // anywhere makes them non-finite, so no extra pass is needed to detect it, only to locate it.
  if (finite(e.kinetic) && finite(e.strain) && finite(e.shadow)) {
    // Net work the interfaces did on the bulk is energy put in too: an interface started under
    // a normal traction (-interface_<name>_sigma_N0) stores energy and releases it at once.
    // External loads count with their gross work: a Ricker force takes back much of what it
    // put in, and its net work passes near zero while the model still moves.
    const double put_in = std::fabs(e.shadow_start) + std::fabs(e.input) + e.external_gross + std::fabs(e.reactions) + std::fmax(e.interface_work, 0.0);
    const double energy = e.kinetic + std::fabs(e.strain);
    PetscCheck(!(put_in > 0 && energy > growth_limit * put_in), comm, PETSC_ERR_NOT_CONVERGED,
               "diverged at step %" PetscInt_FMT ", t = %g s: kinetic + strain energy %g J exceeds %g x the energy put in (%g J); the time step %g s may be above the stable limit %g s",
               step, (double)t, energy, (double)growth_limit, put_in, (double)h, limit.dt_limit);
    PetscFunctionReturn(0);
  }
  PetscCall(PetscLogEventBegin(core::event_guard, 0, 0, 0, 0));
  const Searched fields[] = {{"displacement", u},
                             {"velocity", v},
                             {"acceleration", a},
                             {"internal force", model.f_internal},
                             {"external force (loads and incident wave)", model.f_external},
                             {"interface force", model.f_interface},
                             {"stiffness-damping force", model.f_stiffness_damping},
                             {"anelastic force", model.f_anelastic},
                             {"contact-damping force", model.f_contact_damping},
                             {"hysteretic relaxation force", model.f_hysteretic}};
  std::string where = "no field holds a non-finite value (the ledger's sums overflowed)";
  for (const Searched &f : fields) {
    PetscInt first = PETSC_MAX_INT;
    if (f.values) PetscCall(firstNonFinite(comm, f.values, &first));
    if (first == PETSC_MAX_INT) continue;
    std::string place;
    PetscCall(dofPlace(model, first, &place));
    where = std::string(f.name) + " is not finite at " + place;
    break;
  }
  std::string cause;
  PetscCall(inputCause(model, t, &cause));
  PetscCall(PetscLogEventEnd(core::event_guard, 0, 0, 0, 0));
  SETERRQ(comm, PETSC_ERR_NOT_CONVERGED, "diverged at step %" PetscInt_FMT ", t = %g s: %s (node numbering of the output); %s; stable step limit %g s (%s)", step, (double)t,
          where.c_str(), cause.empty() ? "every input (materials, loads, incident wave) is finite" : ("caused by " + cause).c_str(), limit.dt_limit, limit.governing.c_str());
}

} // namespace slipwave::app
