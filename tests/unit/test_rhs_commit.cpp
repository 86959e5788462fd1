// The right-hand side is a function of (t, u, v_{n+1/2}) and the committed history only: the
// interface pairs, the free-field columns and the constant-Q memory advance into trial states
// that the "cd" TS's commit hook accepts after each step (problem/elastodynamics.hpp). Checked
// on two scenes of config/scenes (run from the repository root):
//  - default.yaml (its mesh and record named from the repository root: only slipwave's main
//    reads a scene's paths from the scene's folder) (interface with contact damping, constant-Q soil and block,
//    gravity without the geostatic stage, so the block settles and the pairs' states change),
//  - free_field_site.yaml (free-field columns, Rayleigh damping, incident SV wave),
//  - a saturated box (pore pressure, drained top, P wave): the pressure update is a trial
//    state too, and p at the end must be bit for bit unchanged as well,
//  - a hysteretic box (MKZ, every cell; SV wave of 0.5 m/s, strains to ~2e-3): the Iwan states
//    are kept once and brought to the accepted step's strains by the next force
//    (medium/hysteresis.hpp), so a probe must neither advance them nor leave its strain behind,
// each stepped to t = 0.1 s (0.5 s) twice: plainly, and with two extra RHS evaluations before every
// step at a state the run never takes (t_{n+2}, u_n + 1 mm of noise). A pure RHS leaves the
// second run bit for bit equal to the first (u, v, interface totals); an RHS that committed
// would have moved the pairs' jump reference to the probe, stepped the columns past t_{n+1}
// (then refused to go back) and committed the memory at t_{n+2}. Also: the two probes at the
// same (t, u) give the same acceleration bit for bit.
#include "slipwave/porous/pore_pressure.hpp"
#include "slipwave/problem/elastodynamics.hpp"
#include "slipwave/problem/integrator_step.hpp"
#include "slipwave/problem/stable_step.hpp"
#include "slipwave/time/central_difference.hpp"

#include "petsc_test_main.hpp"

#include <petscts.h>

#include <string>
#include <utility>

namespace {

using namespace slipwave;

struct Final {
  Vec    u = nullptr, v = nullptr, p = nullptr; // p: saturated scenes only
  double stored = 0, dissipated = 0;
  PetscInt steps = 0;
};

PetscErrorCode runScene(const std::string &scene_options, PetscReal t_end, bool probe, Final *out) {
  MPI_Comm              comm = PETSC_COMM_WORLD;
  problem::Elastodynamics m;
  problem::StableStep     step;
  TS                    ts;
  Vec                   u, v, a_probe, a_again, u_probe;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsClear(nullptr));
  PetscCall(PetscOptionsInsertString(nullptr, scene_options.c_str()));
  PetscCall(problem::ElastodynamicsCreate(comm, &m));
  PetscCall(problem::StableStepCompute(&m, problem::TimeStepOptions(), &step));
  PetscCall(TSCreate(comm, &ts));
  PetscCall(TSSetType(ts, time::kTSCentralDifference));
  PetscCall(TSSetMaxTime(ts, t_end));
  PetscCall(TSSetExactFinalTime(ts, TS_EXACTFINALTIME_MATCHSTEP));
  problem::IntegratorStep choice;
  PetscCall(problem::IntegratorStepChoose(m, step, problem::TimeStepOptions{}, ts, &choice));
  PetscCall(problem::TimeStepChoose(ts, choice));
  PetscCall(problem::ElastodynamicsSetUpTS(&m, ts));
  PetscCall(DMCreateGlobalVector(m.dm, &u));
  PetscCall(VecDuplicate(u, &v));
  PetscCall(VecDuplicate(u, &a_probe));
  PetscCall(VecDuplicate(u, &a_again));
  PetscCall(VecDuplicate(u, &u_probe));
  PetscCall(VecZeroEntries(u));
  PetscCall(VecZeroEntries(v));
  PetscCall(TS2SetSolution(ts, u, v));
  PetscCall(time::CentralDifferenceComputeInitialAcceleration(ts));
  PetscRandom rnd;
  PetscCall(PetscRandomCreate(comm, &rnd));
  PetscCall(PetscRandomSetInterval(rnd, -1e-3, 1e-3));
  PetscReal t, dt;
  bool      same_probe = true;
  PetscCall(TSGetTime(ts, &t));
  for (; t < t_end * (1 - 1e-12);) {
    if (probe) {
      PetscCall(TSGetTimeStep(ts, &dt));
      PetscCall(VecSetRandom(u_probe, rnd));
      PetscCall(VecAXPY(u_probe, 1.0, u));
      PetscCall(problem::ElastodynamicsRHS(ts, t + 2 * dt, u_probe, a_probe, &m));
      PetscCall(problem::ElastodynamicsRHS(ts, t + 2 * dt, u_probe, a_again, &m));
      PetscBool equal;
      PetscCall(VecEqual(a_probe, a_again, &equal));
      same_probe = same_probe && equal;
    }
    PetscCall(TSStep(ts));
    PetscCall(TSGetTime(ts, &t));
  }
  if (probe) unit::check(same_probe, scene_options + ": the RHS twice at the same (t, u) gives the same acceleration");
  PetscCall(TSGetStepNumber(ts, &out->steps));
  for (const auto &iface : m.interfaces) {
    interface::InterfaceTotals totals;
    PetscCall(iface.Totals(&totals));
    out->stored += totals.stored;
    out->dissipated += totals.dissipated;
  }
  PetscCall(VecDuplicate(u, &out->u));
  PetscCall(VecDuplicate(v, &out->v));
  PetscCall(VecCopy(u, out->u));
  PetscCall(VecCopy(v, out->v));
  if (m.pore) {
    PetscCall(VecDuplicate(m.pore->p, &out->p));
    PetscCall(VecCopy(m.pore->p, out->p));
  }
  PetscCall(PetscRandomDestroy(&rnd));
  for (Vec *x : {&u, &v, &a_probe, &a_again, &u_probe}) PetscCall(VecDestroy(x));
  PetscCall(TSDestroy(&ts));
  PetscCall(problem::ElastodynamicsDestroy(&m));
  PetscFunctionReturn(0);
}

PetscErrorCode Run(bool) {
  PetscFunctionBeginUser;
  PetscCall(time::CentralDifferenceRegister());
  // The free-field site's wave (Ricker, f0 = 2 Hz) reaches the surface after 0.3 s.
  const std::pair<std::string, PetscReal> scenes[] = {{"-options_file config/scenes/default.yaml -mesh_file config/scenes/default.msh -input_record config/records/el_centro_1940_ns.csv", 0.1},
                                                      {"-options_file config/scenes/free_field_site.yaml", 0.5},
                                                      {"-regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -material_soil_saturated "
                                                       "-material_soil_porosity 0.4 -material_soil_hydraulic_conductivity 0.08 -mesh_box_faces 4,16 -mesh_box_upper 8,32 "
                                                       "-bc_bottom_type absorbing -input_wave p -input_boundary bottom -input_stf ricker -input_f0 10 -input_t0 0.12 "
                                                       "-input_amplitude 0.1 -bc_top_fluid drained",
                                                       0.15},
                                                      {"-regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -material_soil_model hysteretic "
                                                       "-material_soil_backbone mkz -material_soil_reference_strain 1e-3 -mesh_box_faces 8,16 -mesh_box_upper 16,32 "
                                                       "-bc_bottom_type absorbing -input_wave sv -input_boundary bottom -input_stf ricker -input_f0 10 -input_t0 0.12 "
                                                       "-input_amplitude 0.5",
                                                       0.2}};
  for (const auto &[scene, t_end] : scenes) {
    Final plain, probed;
    PetscCall(runScene(scene, t_end, false, &plain));
    PetscCall(runScene(scene, t_end, true, &probed));
    PetscBool u_equal, v_equal;
    PetscReal u_norm;
    PetscCall(VecEqual(plain.u, probed.u, &u_equal));
    PetscCall(VecEqual(plain.v, probed.v, &v_equal));
    PetscCall(VecNorm(plain.u, NORM_INFINITY, &u_norm));
    unit::check(plain.steps > 0 && u_norm > 0, scene + ": the run moves (" + std::to_string(plain.steps) + " steps, max |u| " + std::to_string(u_norm) + " m)");
    unit::check(u_equal && v_equal, scene + ": probe evaluations leave u and v at the end bit for bit unchanged");
    unit::check(plain.stored == probed.stored && plain.dissipated == probed.dissipated, scene + ": and the interface totals (stored " +
                                                                                             std::to_string(plain.stored) + " J)");
    if (plain.p) {
      PetscBool p_equal;
      PetscReal p_norm;
      PetscCall(VecEqual(plain.p, probed.p, &p_equal));
      PetscCall(VecNorm(plain.p, NORM_INFINITY, &p_norm));
      unit::check(p_equal && p_norm > 0, scene + ": and the pore pressure (max |p| " + std::to_string(p_norm) + " Pa)");
    }
    for (Vec *x : {&plain.u, &plain.v, &probed.u, &probed.v, &plain.p, &probed.p}) PetscCall(VecDestroy(x));
  }
  PetscFunctionReturn(0);
}

} // namespace

int main(int argc, char **argv) { return unit::runPetscTest(argc, argv, Run); }
