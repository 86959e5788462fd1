#include "slipwave/app/run_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "slipwave/input/drm.hpp"
#include "slipwave/medium/attenuation.hpp"
#include "slipwave/medium/hysteresis.hpp"
#include "slipwave/porous/pore_pressure.hpp"
#include "slipwave/problem/rigid_bodies.hpp"
#include "slipwave/problem/scene_frequency.hpp"

namespace slipwave::app {
namespace {

// Memory in use after setup (all ranks) and a run-time estimate: the element loop timed here
// times the ratio of a whole step to it (measured: 2.6 on a 512^2 mesh, docs/performance.md;
// 4.3 on the default scene, where the per-step vector work weighs more; 4 is used, so the
// estimate is good to a factor 2), doubled with stiffness-proportional damping (a second loop),
// plus one loop with the fourth-order integrator (its correction's pass).
PetscErrorCode reportCost(const problem::Elastodynamics &model, PetscInt order, double steps) {
  constexpr double kStepOverLoop = 4.0;
  PetscLogDouble   memory, t0, t1;
  PetscFunctionBeginUser;
  PetscCall(PetscMemoryGetCurrentUsage(&memory));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &memory, 1, MPI_DOUBLE, MPI_SUM, model.comm));
  std::vector<PetscScalar> u, f;
  PetscInt                 n;
  PetscCall(VecGetLocalSize(model.u_local, &n));
  // A scrambled field of strains about 1e-3 (a strong shaking's: every surface of a yielding
  // soil works), not a translation (no strain: the soil's update would skip its work).
  u.resize(n);
  for (PetscInt i = 0; i < n; ++i) u[i] = 1e-3 * (double)((i * 7919) % 13) / 13.0;
  f.assign(n, 0.0);
  PetscCall(PetscTime(&t0));
  const int repeats = 5;
  for (int k = 0; k < repeats; ++k) model.bulk.addStiffnessTimes(u.data(), f.data());
  PetscCall(PetscTime(&t1));
  double loop[2] = {(t1 - t0) / repeats, 0.0};
  // A yielding soil's update per step, timed alike (its cost is not in the ratio above: 5-13x
  // the linear loop). Virgin states, the trial dropped: the run's results do not change.
  if (model.hysteresis) {
    PetscCall(PetscTime(&t0));
    for (int k = 0; k < repeats; ++k) medium::HysteresisForce(model.hysteresis, u.data(), f.data());
    PetscCall(PetscTime(&t1));
    medium::HysteresisDiscardTrial(model.hysteresis);
    loop[1] = (t1 - t0) / repeats;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, loop, 2, MPI_DOUBLE, MPI_MAX, model.comm));
  const double per_step = loop[0] * kStepOverLoop * (model.rayleigh.beta > 0 ? 2 : 1) + (order == 4 ? loop[0] : 0.0) + loop[1];
  PetscCall(PetscPrintf(model.comm, "  memory in use after setup: %.1f MB (all ranks); estimated run time %.0f s (%.0f steps x %.3g ms; within a factor 2)\n",
                        memory / 1048576.0, steps * per_step, steps, 1e3 * per_step));
  PetscFunctionReturn(0);
}

// GLL nodes per S wavelength a region needs, counted as p lambda / h (h the element size; at
// p = 1 the usual points per wavelength), by degree, from published practice:
//   p = 1: 10 (Kuhlemeyer & Lysmer 1973: elements of 1/8 to 1/10 of the shortest wavelength);
//   p >= 4: 5 (Komatitsch & Tromp 1999, GJI 139, 806-822, and 2002, GJI 149, 390-412: about
//   5 GLL points per minimum wavelength at degree 4; Seriani & Priolo 1994 find ~4.5 enough
//   at degree 8, so 5 is kept for every degree above 4);
//   p = 2, 3: no published figure; linear between the two (8.3 and 6.7).
double nodesPerWavelengthNeeded(PetscInt degree) { return degree >= 4 ? 5.0 : 10.0 - 5.0 * (double)(degree - 1) / 3.0; }

const char *nodesPerWavelengthSource(PetscInt degree) {
  return degree == 1 ? "Kuhlemeyer & Lysmer 1973" : degree >= 4 ? "Komatitsch & Tromp 1999" : "between Kuhlemeyer & Lysmer 1973 at p = 1 and Komatitsch & Tromp 1999 at p = 4";
}

// The highest frequency the mesh carries: nodesPerWavelengthNeeded GLL nodes per S
// wavelength in the region that carries the least, with its largest element.
struct Resolution {
  double      frequency = 0; // Hz
  std::string region;
  double      size = 0;      // the region's largest element [m]
};

Resolution resolvedFrequency(const problem::Elastodynamics &model) {
  const PetscInt p = model.bulk.degree();
  Resolution     res;
  for (size_t r = 0; r < model.materials.size(); ++r) {
    const auto &m = model.materials[r];
    if (m.model == medium::MaterialModel::Rigid) continue; // carries no waves
    const double h = model.bulk.regionElementSize((PetscInt)r);
    const double f = (double)p * m.elastic.vs / (nodesPerWavelengthNeeded(p) * h);
    if (res.region.empty() || f < res.frequency) res = {f, m.region, h};
  }
  return res;
}

// Of a multi-line report, the lines that stay in the compact report: those indented once
// (a region's or a feature's headline; the deeper ones are its details).
bool isHeadline(const std::string &line) { return line.rfind("  ", 0) == 0 && line.rfind("   ", 0) != 0; }

PetscErrorCode reportInterfaces(const problem::Elastodynamics &model, bool verbose) {
  MPI_Comm comm = model.comm;
  PetscFunctionBeginUser;
  for (size_t k = 0; k < model.interfaces.size(); ++k) {
    const auto &iface = model.interfaces[k];
    const auto &p     = iface.params();
    PetscCall(PetscPrintf(comm, "  interface %s between %s (soil side) and %s: %" PetscInt_FMT " node pairs; phi %.4g deg, psi %.4g deg, c %.4g Pa, e_ini %.4g m\n",
                          iface.spec().name.c_str(), iface.spec().soil_region.c_str(), iface.spec().structure_region.c_str(), iface.pairs().n_global,
                          p.phi * 180 / PETSC_PI, p.psi * 180 / PETSC_PI, p.c, p.e_ini));
    if (!verbose) continue;
    PetscInt cut;
    PetscCall(iface.CountCutPairs(model.mass, &cut));
    PetscCall(PetscPrintf(comm, "    %s; %" PetscInt_FMT " pairs have their two nodes on different ranks\n", model.penalty_notes[k].c_str(), cut));
    double c_min, c_max;
    PetscCall(iface.DashpotRange(&c_min, &c_max));
    PetscCall(PetscPrintf(comm, "    contact damping %.3g of critical on closed pairs (normal dashpots %.4g .. %.4g N s/m)\n", iface.contactDamping(), c_min, c_max));
  }
  PetscFunctionReturn(0);
}

// A string as a JSON string's contents: quotes, backslashes and control characters escaped.
std::string jsonEscaped(const std::string &text) {
  std::string out;
  for (const char c : text) {
    if (c == '"' || c == '\\') out += {'\\', c};
    else if ((unsigned char)c < 0x20) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\u%04x", (unsigned)(unsigned char)c);
      out += hex;
    } else out += c;
  }
  return out;
}

// run_info.json's "hysteretic_regions": per hysteretic region what its backbone was built from
// (the inputs of the published curve, not the fitted surfaces), so that a script can draw the
// curve from its source formulas (scripts/soil_loops.py).
std::string hystereticRegionsJson(const std::vector<medium::RegionMaterialInfo> &materials) {
  std::string json;
  char        buf[512];
  for (const medium::RegionMaterialInfo &m : materials) {
    if (m.model != medium::MaterialModel::Hysteretic) continue;
    const medium::HystereticSpec &s = m.hysteretic;
    std::snprintf(buf, sizeof buf, "%s{\"region\": \"%s\", \"backbone\": \"%s\", \"gmax_pa\": %.17g, \"surfaces\": %d, \"strength_pa\": %.17g", json.empty() ? "" : ", ",
                  m.region.c_str(), medium::kBackboneNames[(int)s.choice], s.model->shearModulus(), s.model->surfaces(), s.strength);
    json += buf;
    switch (s.choice) {
    case medium::BackboneChoice::Mkz:
      std::snprintf(buf, sizeof buf, ", \"reference_strain\": %.17g, \"curvature\": %.17g, \"beta\": %.17g}", s.backbone.reference_strain, s.backbone.curvature, s.backbone.beta);
      break;
    case medium::BackboneChoice::Darendeli:
      std::snprintf(buf, sizeof buf, ", \"plasticity_index\": %.17g, \"ocr\": %.17g, \"mean_effective_stress_pa\": %.17g, \"frequency_hz\": %.17g, \"cycles\": %.17g}",
                    s.darendeli.plasticity_index, s.darendeli.ocr, s.darendeli.mean_effective_stress, s.darendeli.frequency, s.darendeli.cycles);
      break;
    case medium::BackboneChoice::Gqh:
      std::snprintf(buf, sizeof buf, ", \"theta\": [%.17g, %.17g, %.17g, %.17g, %.17g]}", s.backbone.theta[0], s.backbone.theta[1], s.backbone.theta[2], s.backbone.theta[3],
                    s.backbone.theta[4]);
      break;
    case medium::BackboneChoice::Table: {
      // The rows as run (strains as ratios), for the script to draw the user's curve.
      std::string rows;
      for (size_t k = 0; k < s.backbone.table_strain.size(); ++k) {
        std::snprintf(buf, sizeof buf, "%s[%.17g, %.17g]", k ? ", " : "", s.backbone.table_strain[k], s.backbone.table_ratio[k]);
        rows += buf;
      }
      json += ", \"table_file\": \"" + jsonEscaped(s.table_file) + "\", \"table_source\": \"" + jsonEscaped(s.table_source) + "\", \"table\": [" + rows + "]}";
      continue;
    }
    }
    json += buf;
  }
  return json;
}

} // namespace

double LowPassCornerFrequency(const problem::Elastodynamics &model) {
  return resolvedFrequency(model).frequency * nodesPerWavelengthNeeded(model.bulk.degree()) / 8;
}

void WriteRunInfo(const problem::Elastodynamics &model, const problem::StableStep &step, const std::string &output_dir, double dt, const std::string &answers) {
  const Resolution  res  = resolvedFrequency(model);
  const std::string path = output_dir + "/run_info.json";
  if (FILE *f = std::fopen(path.c_str(), "w")) {
    // The resolved frequency in full: scripts take the low-pass corner from it (scene_metrics.py).
    std::fprintf(f, "{\"resolved_frequency_hz\": %.17g, \"points_per_wavelength\": %g, \"slowest_region\": \"%s\", \"resolving_element_size_m\": %.6g, \"h_min_m\": %.6g,\n",
                 res.frequency, nodesPerWavelengthNeeded(model.bulk.degree()), res.region.c_str(), res.size, model.bulk.minCellSize());
    if (model.bulk.degree() > 1) std::fprintf(f, " \"element_degree\": %d, \"element_size_m\": %.6g,\n", (int)model.bulk.degree(), model.bulk.minElementSize());
    if (model.hysteresis) std::fprintf(f, " \"hysteretic_regions\": [%s],\n", hystereticRegionsJson(model.materials).c_str());
    if (!answers.empty()) std::fprintf(f, " \"answers\": %s,\n", answers.c_str());
    if (step.mass_scaling.nodes > 0)
      std::fprintf(f, " \"mass_scaling\": {\"nodes\": %d, \"added_kg\": %.10g, \"lightest_region\": \"%s\", \"lightest_region_mass_kg\": %.10g, \"stable_step_own_mass_s\": %.10g},\n",
                   (int)step.mass_scaling.nodes, step.mass_scaling.added, step.mass_scaling.lightest_region.c_str(), step.mass_scaling.lightest_side, step.dt_own_mass);
    std::fprintf(f, " \"input_top_frequency_hz\": %.6g, \"time_step_s\": %.10g}\n", problem::SceneTopFrequency(model).hz, dt);
    std::fclose(f);
  }
}

PetscErrorCode ReportSetup(const problem::Elastodynamics &model, const problem::StableStep &limit, const problem::IntegratorStep &integrator, const io::Stations &stations, PetscReal dt,
                           PetscReal max_time, const std::string &output_dir, PetscReal output_interval, bool verbose) {
  MPI_Comm    comm = model.comm;
  PetscMPIInt size;
  PetscInt    n_nodes, ncell_local = model.bulk.cellCount(), ncell;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(VecGetSize(model.mass, &n_nodes));
  PetscCallMPI(MPI_Allreduce(&ncell_local, &ncell, 1, MPIU_INT, MPI_SUM, comm));
  PetscCall(PetscPrintf(comm, "slipwave: explicit elastodynamics, %" PetscInt_FMT "D %s, %d rank%s (partitioner %s)%s\n", model.dim, model.dim == 2 ? "plane strain" : "", size,
                        size > 1 ? "s" : "", model.mesh.partitioner.c_str(), verbose ? "" : "; -report_verbose for the details"));
  const PetscInt p = model.bulk.degree();
  if (p == 1)
    PetscCall(PetscPrintf(comm, "  mesh: %s, %" PetscInt_FMT " cells, %" PetscInt_FMT " nodes, %" PetscInt_FMT " distinct element matrices on rank 0\n",
                          model.mesh.source.c_str(), ncell, n_nodes / model.dim, model.bulk.distinctMatrices()));
  else {
    PetscInt nelem_local = model.bulk.elementCount(), nelem;
    PetscCallMPI(MPI_Allreduce(&nelem_local, &nelem, 1, MPIU_INT, MPI_SUM, comm));
    PetscCall(PetscPrintf(comm,
                          "  mesh: %s, spectral elements of degree %" PetscInt_FMT " (GLL): %" PetscInt_FMT " element%s in %" PetscInt_FMT " linear sub-cells, %" PetscInt_FMT
                          " nodes, %" PetscInt_FMT " distinct element geometries on rank 0\n",
                          model.mesh.source.c_str(), p, nelem, nelem == 1 ? "" : "s", ncell, n_nodes / model.dim, model.bulk.distinctMatrices()));
  }
  const problem::SceneFrequency top  = problem::SceneTopFrequency(model);
  const double                  fmax = top.hz;
  for (size_t r = 0; r < model.materials.size(); ++r) {
    const auto    &m = model.materials[r];
    const PetscInt k = (PetscInt)r;
    PetscCall(PetscPrintf(comm, "  region %-10s rho %8.1f kg/m3  vp %8.1f m/s  vs %8.1f m/s", m.region.c_str(), m.elastic.rho, m.elastic.vp, m.elastic.vs));
    if (m.model == medium::MaterialModel::Rigid) PetscCall(PetscPrintf(comm, "  rigid (its vp, vs serve the geostatic stage only)"));
    else if (fmax > 0 && p == 1)
      PetscCall(PetscPrintf(comm, "  %5.1f points per S wavelength at %.2f Hz (cell size %.3g m)", problem::RegionNodesPerWavelength(model, k, fmax), fmax,
                            model.bulk.regionElementSize(k)));
    else if (fmax > 0)
      PetscCall(PetscPrintf(comm, "  %5.1f GLL nodes per S wavelength at %.2f Hz (degree %" PetscInt_FMT ", element size %.3g m)", problem::RegionNodesPerWavelength(model, k, fmax),
                            fmax, p, model.bulk.regionElementSize(k)));
    // The compact report names the region's soil model here; its fitted bodies and curves
    // are details (-report_verbose).
    if (!verbose && m.model == medium::MaterialModel::Hysteretic)
      PetscCall(PetscPrintf(comm, "; hysteretic (%s)", medium::kBackboneNames[(int)m.hysteretic.choice]));
    if (!verbose && m.damping_ratio > 0) PetscCall(PetscPrintf(comm, "; constant-Q %.3g %%", 100 * m.damping_ratio));
    if (m.fe.dilatation == fem::Dilatation::Mean) PetscCall(PetscPrintf(comm, "; mean dilatation"));
    PetscCall(PetscPrintf(comm, "\n"));
  }
  for (size_t r = 0; r < model.materials.size(); ++r) {
    const auto   &m = model.materials[r];
    const double  n = fmax > 0 ? problem::RegionNodesPerWavelength(model, (PetscInt)r, fmax) : 0.0;
    if (m.model != medium::MaterialModel::Rigid && fmax > 0 && n < nodesPerWavelengthNeeded(p))
      PetscCall(PetscPrintf(comm,
                            "  warning: region %s is under-resolved for the top frequency %.2f Hz of %s: %.1f %s per S wavelength, below the %.3g that elements of degree %" PetscInt_FMT " need (%s); refine the mesh or raise -element_degree\n",
                            m.region.c_str(), fmax, top.source.c_str(), n, p == 1 ? "points" : "GLL nodes", nodesPerWavelengthNeeded(p), p, nodesPerWavelengthSource(p)));
  }
  const Resolution res = resolvedFrequency(model);
  if (res.region.empty()) {
    // Every region is rigid: no waves to resolve.
  } else if (p == 1)
    PetscCall(PetscPrintf(comm, "  resolution: S waves up to %.3g Hz (%d points per wavelength in region %s, cell size %.3g m)\n", res.frequency,
                          (int)nodesPerWavelengthNeeded(p), res.region.c_str(), res.size));
  else
    PetscCall(PetscPrintf(comm, "  resolution: S waves up to %.3g Hz (%.3g GLL nodes per wavelength at degree %" PetscInt_FMT " in region %s, element size %.3g m)\n",
                          res.frequency, nodesPerWavelengthNeeded(p), p, res.region.c_str(), res.size));
  std::string bcs;
  for (size_t i = 0; i < model.bc.names.size(); ++i) bcs += " " + model.bc.names[i] + "=" + input::boundaryTypeName(model.bc.types[i]);
  if (verbose) PetscCall(PetscPrintf(comm, "  boundaries:%s\n", bcs.c_str()));
  for (const std::string &w : model.bc.warnings) PetscCall(PetscPrintf(comm, "  warning: %s\n", w.c_str()));
  if (verbose)
    for (const std::string &l : model.bc.load_notes) PetscCall(PetscPrintf(comm, "  load: %s\n", l.c_str()));
  if (model.bc.input_wave != input::InputWave::None)
    PetscCall(PetscPrintf(comm, "  input: %s wave through '%s', %s\n", input::inputWaveName(model.bc.input_wave), model.bc.input_boundary.c_str(), model.bc.input.describe().c_str()));
  for (const std::string &line : input::DrmReport(model.drm))
    if (verbose || isHeadline(line)) PetscCall(PetscPrintf(comm, "%s\n", line.c_str()));
  if (model.damping_ratio > 0)
    PetscCall(PetscPrintf(comm, "  Rayleigh damping %.3g %% at %g and %g Hz: alpha %.4g 1/s, beta %.4g s\n", 100 * model.damping_ratio, model.damping_f1, model.damping_f2,
                          model.rayleigh.alpha, model.rayleigh.beta));
  if (verbose && model.rayleigh.beta > 0)
    PetscCall(PetscPrintf(comm, "    its stiffness-proportional part lowers the stable step from %.4e s (undamped) to %.4e s (-%.1f %%)\n", limit.dt_without_stiffness_damping,
                          limit.dt_bulk, 100 * (1 - limit.dt_bulk / limit.dt_without_stiffness_damping)));
  if (verbose)
    for (const std::string &line : medium::AttenuationReport(model.attenuation, model.materials)) PetscCall(PetscPrintf(comm, "%s\n", line.c_str()));
  if (verbose) PetscCall(PetscPrintf(comm, "%s", problem::RigidBodiesDescribe(model.rigid).c_str()));
  if (verbose)
    for (const std::string &line : medium::HysteresisReport(model.materials)) PetscCall(PetscPrintf(comm, "%s\n", line.c_str()));
  PetscCall(reportInterfaces(model, verbose));
  if (model.pore)
    for (const std::string &line : porous::PorePressureReport(model.pore, model.materials, limit.dt_drained, limit.dt_bulk, limit.coupling_factor, limit.dt_limit, dt))
      if (verbose || isHeadline(line)) PetscCall(PetscPrintf(comm, "%s\n", line.c_str()));
  if (verbose)
    for (const std::string &line : stations.ambiguities()) PetscCall(PetscPrintf(comm, "  %s\n", line.c_str()));
  if (limit.dt_cfl < 1e300)
    PetscCall(PetscPrintf(comm, "  stable step: %.4e s (%s); h_min/vp_max = %.4e s for comparison\n", integrator.dt_limit, integrator.governing.c_str(), limit.dt_cfl));
  else PetscCall(PetscPrintf(comm, "  stable step: %.4e s (%s)\n", integrator.dt_limit, integrator.governing.c_str()));
  if (limit.mass_scaling.nodes > 0) {
    const problem::MassScalingResult &ms = limit.mass_scaling;
    PetscCall(PetscPrintf(comm,
                          "  mass scaling (-time_step_mass_scaling interface): %" PetscInt_FMT " interface nodes carry +%.4g kg%s of inertia without weight, %.3g %% of region %s's mass "
                          "(%.3g %% of the model's), a node up to %.3g x its own; the limit %.4e s instead of %.4e s\n",
                          ms.nodes, ms.added, model.dim == 2 ? "/m" : "", 100 * ms.added / ms.lightest_side, ms.lightest_region.c_str(), 100 * ms.added / ms.model_mass,
                          ms.largest_factor, integrator.dt_limit, limit.dt_own_mass));
  }
  // dt_bulk, not dt_limit: the free-field columns or the pore-pressure diffusion may set the limit lower without any interface.
  if (limit.dt_without_interfaces < 1e300 && limit.dt_bulk < limit.dt_without_interfaces * (1 - 1e-12))
    PetscCall(PetscPrintf(comm, "  warning: the interface penalty lowers the stable step from %.4e s (bulk alone) to %.4e s (-%.1f %%)\n", limit.dt_without_interfaces,
                          limit.dt_bulk, 100 * (1 - limit.dt_bulk / limit.dt_without_interfaces)));
  PetscCall(PetscPrintf(comm, "  time step %.4e s = %.3f of the limit; %.0f steps to t = %g s; %s\n", (double)dt, dt / integrator.dt_limit, std::ceil(max_time / dt), (double)max_time,
                        problem::IntegratorStepSummary(integrator).c_str()));
  if (verbose) PetscCall(PetscPrintf(comm, "    %s\n", problem::IntegratorStepDetail(integrator).c_str()));
  char sampling[160] = "";
  if (!stations.empty())
    std::snprintf(sampling, sizeof sampling, "; %zu stations every %ld step%s (%.4g s, -station_interval)", stations.names().size(), stations.samplingSteps(),
                  stations.samplingSteps() > 1 ? "s" : "", stations.samplingSteps() * (double)dt);
  PetscCall(PetscPrintf(comm, "  output: %s/, frames every %g s%s\n", output_dir.c_str(), (double)output_interval, sampling));
  PetscCall(reportCost(model, integrator.order, std::ceil(max_time / dt)));
  PetscFunctionReturn(0);
}

PetscErrorCode ReportEnd(const problem::Elastodynamics &model, const problem::EnergyLedger &ledger, const problem::StableStep &step, double dt, const std::vector<std::string> &files,
                         PetscInt steps, double wall, const std::string &output_dir) {
  MPI_Comm comm = model.comm;
  PetscFunctionBeginUser;
  for (const auto &iface : model.interfaces) {
    interface::InterfaceTotals t;
    PetscCall(iface.Totals(&t));
    PetscCall(PetscPrintf(comm, "interface %s: %" PetscInt_FMT " stick, %" PetscInt_FMT " slip, %" PetscInt_FMT " open at the end; dissipated %.4g J; largest yield-surface drift corrected %.3g Pa\n",
                          iface.spec().name.c_str(), t.n_stick, t.n_slip, t.n_open, t.dissipated, t.max_drift));
    // Impacts: the open/closed switching the linear bound does not cover.
    if (t.switches > 0 && dt > problem::kSafetyInterfaces * step.dt_limit * (1 + 1e-9))
      PetscCall(PetscPrintf(comm,
                            "  warning: %" PetscInt_FMT " open/closed switches of pairs on interface %s with the step at %.2f of the stable limit (interfaces default to %.2f): impacts may have gained "
                            "energy (two-bar impact: +2.5 %% at 0.9); rerun with -time_step_safety %.2f to check the answers\n",
                            t.switches, iface.spec().name.c_str(), dt / step.dt_limit, (double)problem::kSafetyInterfaces, (double)problem::kSafetyInterfaces));
  }
  if (!model.interfaces.empty()) PetscCall(PetscPrintf(comm, "contact dashpots (all interfaces): took %.4g J\n", ledger.contact_damped));
  if (model.pore) {
    std::string line;
    PetscCall(porous::PorePressureCavitationReport(model.pore, comm, ledger.cavitation, &line));
    PetscCall(PetscPrintf(comm, "%s\n", line.c_str()));
  }
  PetscCall(PetscPrintf(comm, "done: %" PetscInt_FMT " steps in %.2f s wall (%.3g s per step); energy balance error %.2e of the largest energy\n", steps, wall,
                        wall / std::max<PetscInt>(steps, 1), ledger.relativeError()));
  std::string listed;
  // The run's folders (no '.' in their names): stations and the grids' frame files.
  for (const std::string &name : files)
    listed += (listed.empty() ? "" : ", ") + (name == "stations" ? std::string("stations/*.csv") : name.find('.') == std::string::npos ? name + "/*.h5" : name);
  PetscCall(PetscPrintf(comm, "output in %s/: %s%s\n", output_dir.c_str(), listed.empty() ? "nothing" : listed.c_str(),
                        listed.find(".xmf") != std::string::npos ? " (open the .xmf files in ParaView)" : ""));
  PetscFunctionReturn(0);
}

} // namespace slipwave::app
