#include "slipwave/problem/elastodynamics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "slipwave/core/log_events.hpp"
#include "slipwave/fem/node_fields.hpp"
#include "slipwave/input/body_force.hpp"
#include "slipwave/input/drm.hpp"
#include "slipwave/input/free_field.hpp"
#include "slipwave/input/lateral_tie.hpp"
#include "slipwave/input/point_force.hpp"
#include "slipwave/input/structure_load.hpp"
#include "slipwave/medium/attenuation.hpp"
#include "slipwave/medium/hysteresis.hpp"
#include "slipwave/mesh/cell_quality_check.hpp"
#include "slipwave/numerics/gll_basis.hpp"
#include "slipwave/porous/pore_pressure.hpp"
#include "slipwave/porous/pore_pressure_drm.hpp"
#include "slipwave/problem/nodal_acceleration.hpp"
#include "slipwave/problem/rigid_bodies.hpp"
#include "slipwave/time/central_difference.hpp"

namespace slipwave::problem {
namespace {

input::DrmSetting drmSetting(const Elastodynamics &m, const std::vector<input::DrmPoreFluid> *pore_fluid = nullptr) {
  return {m.comm, m.dm, m.dim, m.mesh.regions, m.materials, m.bulk, m.rayleigh, m.attenuation, m.bc.input_wave, pore_fluid};
}

// What the free-field columns take from the pore pressure (input/free_field.hpp).
input::FreeFieldFluid freeFieldFluid(const porous::PorePressure &pore) {
  input::FreeFieldFluid f;
  for (const porous::SaturatedRegion &r : pore.regions) f.region.push_back({r.saturated, r.alpha, r.M, r.kappa});
  f.pdm           = pore.pdm;
  f.storage       = pore.storage;
  f.free_mask     = pore.free_mask;
  f.p_hydrostatic = pore.p_hydrostatic;
  f.inflow        = pore.inflow;
  for (const std::string &b : pore.drained) f.fluid_boundaries.push_back({b, "drained"});
  for (const std::string &b : pore.flux) f.fluid_boundaries.push_back({b, "flux"});
  f.rules = {pore.dt_diffusion, pore.subcycle, pore.cavitation, pore.cavitation_pressure};
  return f;
}

PetscErrorCode readDamping(Elastodynamics *m) {
  PetscReal freqs[2] = {0.5, 10.0};
  PetscInt  n        = 2;
  PetscBool set;
  PetscFunctionBeginUser;
  PetscOptionsBegin(m->comm, "damping_", "Rayleigh damping", "slipwave");
  PetscCall(PetscOptionsReal("-ratio", "damping ratio xi [-] reached at both frequencies, 0 <= xi < 1 (0: undamped)", "ElastodynamicsCreate", m->damping_ratio, &m->damping_ratio,
                             nullptr));
  PetscCall(PetscOptionsRealArray("-frequencies", "the two frequencies f1,f2 [Hz] where the ratio is exact, 0 < f1 < f2", "ElastodynamicsCreate", freqs, &n, &set));
  PetscOptionsEnd();
  PetscCheck(!set || n == 2, m->comm, PETSC_ERR_USER_INPUT, "-damping_frequencies has %" PetscInt_FMT " values; allowed: two frequencies f1,f2 [Hz]", n);
  m->damping_f1 = freqs[0];
  m->damping_f2 = freqs[1];
  if (m->damping_ratio != 0) {
    const std::string problem = physics::rayleighDampingProblem(m->damping_ratio, freqs[0], freqs[1]);
    PetscCheck(problem.empty(), m->comm, PETSC_ERR_USER_INPUT, "-damping_ratio / -damping_frequencies: %s", problem.c_str());
    m->rayleigh = physics::rayleighFromDampingRatio(m->damping_ratio, freqs[0], freqs[1]);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode assembleMass(Elastodynamics *m) {
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(m->dm, &m->mass));
  PetscCall(VecZeroEntries(m->u_local));
  PetscCall(VecGetArray(m->u_local, &a));
  m->bulk.addLumpedMass(a);
  PetscCall(VecRestoreArray(m->u_local, &a));
  PetscCall(VecZeroEntries(m->mass));
  PetscCall(DMLocalToGlobal(m->dm, m->u_local, ADD_VALUES, m->mass));
  PetscReal min_mass;
  PetscCall(VecMin(m->mass, nullptr, &min_mass));
  PetscCheck(min_mass > 0, m->comm, PETSC_ERR_PLIB, "a node has lumped mass %g; every node must touch a cell", (double)min_mass);
  PetscCall(VecDuplicate(m->mass, &m->inv_mass));
  PetscCall(VecCopy(m->mass, m->inv_mass));
  PetscCall(VecReciprocal(m->inv_mass));
  PetscFunctionReturn(0);
}

// D = (C_abs + alpha M)/m per node; rows and columns of held dofs are zeroed so a dashpot
// cannot drive a dof whose motion is prescribed.
PetscErrorCode assembleDampingBlocks(Elastodynamics *m) {
  const PetscInt bs = m->dim;
  PetscFunctionBeginUser;
  {
    PetscInt           nb;
    const PetscScalar *C;
    PetscCall(VecGetLocalSize(m->bc.absorbing_blocks, &nb));
    PetscCall(VecGetArrayRead(m->bc.absorbing_blocks, &C));
    for (PetscInt node = 0; node < nb / (bs * bs); ++node) {
      bool any = false;
      for (PetscInt k = 0; k < bs * bs; ++k) any = any || C[node * bs * bs + k] != 0.0;
      if (any) m->absorbing_nodes.push_back(node);
    }
    PetscCall(VecRestoreArrayRead(m->bc.absorbing_blocks, &C));
  }
  if (!m->bc.has_absorbing && m->rayleigh.alpha == 0) PetscFunctionReturn(0);
  PetscCall(VecDuplicate(m->bc.absorbing_blocks, &m->damping_blocks));
  PetscInt           n;
  PetscScalar       *D;
  const PetscScalar *C, *mass, *mask;
  PetscCall(VecGetLocalSize(m->mass, &n));
  PetscCall(VecGetArray(m->damping_blocks, &D));
  PetscCall(VecGetArrayRead(m->bc.absorbing_blocks, &C));
  PetscCall(VecGetArrayRead(m->mass, &mass));
  PetscCall(VecGetArrayRead(m->bc.free_mask, &mask));
  for (PetscInt node = 0; node < n / bs; ++node) {
    const PetscReal mi = PetscRealPart(mass[node * bs]);
    for (PetscInt i = 0; i < bs; ++i)
      for (PetscInt j = 0; j < bs; ++j) {
        const PetscInt k     = node * bs * bs + i * bs + j;
        const bool     free  = PetscRealPart(mask[node * bs + i]) > 0 && PetscRealPart(mask[node * bs + j]) > 0;
        const double   alpha = i == j ? m->rayleigh.alpha : 0.0;
        D[k]                 = free ? PetscRealPart(C[k]) / mi + alpha : 0.0;
      }
  }
  PetscCall(VecRestoreArrayRead(m->bc.free_mask, &mask));
  PetscCall(VecRestoreArrayRead(m->mass, &mass));
  PetscCall(VecRestoreArrayRead(m->bc.absorbing_blocks, &C));
  PetscCall(VecRestoreArray(m->damping_blocks, &D));
  PetscFunctionReturn(0);
}

// The penalty `auto` (interface/interface_options.hpp, InterfaceAutoPenalty): physical, from
// a length L, E = (lambda+2mu)/L, G = mu/L of the softer side (default L: the interface's
// width / 200), or mesh, factor x the same over h (h: the smallest cell size; degree p: a face
// node of an element of size h_e sees M (p^2 + p + 1)/(3 h_e) per unit area,
// numerics/gll_basis.hpp gllEndNodeStiffness, so h is h_e 3/(p^2 + p + 1)). The width is the
// interface's total pair area: its length in 2D, the square root of its area in 3D.
PetscErrorCode createInterfaces(Elastodynamics *m) {
  PetscFunctionBeginUser;
  for (const meshing::InterfaceSpec &spec : m->mesh.interfaces) {
    const std::string prefix = "interface_" + spec.name + "_";
    interface::InterfaceOptions opt;
    PetscCall(interface::InterfaceOptionsRead(m->comm, prefix.c_str(), interface::InterfaceUse::Mesh, &opt));
    double m_soft = 1e300, mu_soft = 1e300;
    for (const auto &info : m->materials)
      if (info.region == spec.soil_region || info.region == spec.structure_region) {
        m_soft  = std::min(m_soft, info.fe.lame.lambda + 2 * info.fe.lame.mu);
        mu_soft = std::min(mu_soft, info.fe.lame.mu);
      }
    const double            h = m->bulk.minElementSize() / numerics::gllEndNodeStiffness((int)m->bulk.degree());
    meshing::InterfacePairs pairs;
    PetscCall(meshing::InterfacePairsBuild(m->dm, spec, &pairs));
    double area = 0;
    for (double a : pairs.area) area += a;
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &area, 1, MPI_DOUBLE, MPI_SUM, m->comm));
    const double width = m->dim == 2 ? area : std::sqrt(area);
    std::string  note;
    PetscCall(interface::InterfaceAutoPenalty(m->comm, prefix.c_str(), m_soft, mu_soft, h, width, &opt, &note));
    note = "interface " + spec.name + ": " + note;
    m->interfaces.emplace_back();
    PetscCall(m->interfaces.back().Setup(m->comm, m->dim, spec, pairs, opt.params, opt.sigma_N0, opt.contact_damping, opt.friction_lag, m->mass));
    m->penalty_notes.push_back(note);
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode ElastodynamicsCreate(MPI_Comm comm, Elastodynamics *m) {
  PetscFunctionBeginUser;
  m->comm = comm;
  PetscCall(meshing::MeshCreate(comm, &m->dm, &m->mesh));
  PetscCall(DMGetDimension(m->dm, &m->dim));
  PetscCall(fem::NodeFieldSetSection(m->dm, m->dim));
  PetscCall(medium::MaterialsRead(comm, m->mesh.regions, &m->materials));
  std::vector<porous::SaturatedRegion> saturated;
  bool                         any_saturated = false;
  PetscCall(porous::PorePressureReadMaterials(comm, &m->materials, &saturated, &any_saturated));
  {
    // The pore pressure's coupling and diffusion step by central differences, outside the
    // fourth-order correction (time/central_difference.hpp).
    PetscInt  order = 2;
    PetscBool set;
    PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-ts_cd_order", &order, &set));
    PetscCheck(!any_saturated || !set || order == 2, comm, PETSC_ERR_USER_INPUT,
               "-ts_cd_order %" PetscInt_FMT " with a saturated region (-material_<r>_saturated): not supported; allowed: -ts_cd_order 2", order);
  }
  for (const auto &info : m->materials)
    PetscCheck(info.model != medium::MaterialModel::Rigid || info.vp_undrained == 0, comm, PETSC_ERR_USER_INPUT,
               "-material_%s_saturated with -material_%s_model rigid; allowed: a dry rigid region (the pore fluid needs a deforming skeleton)", info.region.c_str(),
               info.region.c_str());
  {
    // Hysteretic soil: the Iwan stress at the Gauss points of linear cells (medium/hysteresis.hpp).
    std::string hysteretic;
    for (size_t r = 0; r < m->materials.size(); ++r)
      if (m->materials[r].model == medium::MaterialModel::Hysteretic) {
        hysteretic = m->materials[r].region;
        // One point per element from its mean strain is a Q1 device: a spectral element's
        // strain is far from uniform.
        PetscCheck(m->materials[r].hysteretic.points == medium::StressPoints::Gauss || m->mesh.degree == 1, comm, PETSC_ERR_USER_INPUT,
                   "-material_%s_stress_points mean with -element_degree = %" PetscInt_FMT ": not supported; allowed: -material_%s_stress_points gauss (the GLL nodes)",
                   hysteretic.c_str(), m->mesh.degree, hysteretic.c_str());
        PetscCheck(r >= saturated.size() || !saturated[r].saturated, comm, PETSC_ERR_USER_INPUT,
                   "-material_%s_model hysteretic with -material_%s_saturated: not supported yet; allowed: a dry hysteretic region", hysteretic.c_str(), hysteretic.c_str());
      }
  }
  for (size_t r = 0; r < m->materials.size(); ++r) {
    medium::RegionMaterialInfo &info = m->materials[r];
    const bool mean = info.fe.dilatation == fem::Dilatation::Mean, given = info.dilatation_given;
    // A spectral element's GLL quadrature is its own; the mean dilatation is a degree-1 device.
    PetscCheck(!(given && mean) || m->mesh.degree == 1, comm, PETSC_ERR_USER_INPUT,
               "-material_%s_dilatation mean with -element_degree = %" PetscInt_FMT ": not supported; allowed: -material_%s_dilatation gauss (the GLL nodes)",
               info.region.c_str(), m->mesh.degree, info.region.c_str());
    // The u-p coupling takes div u at the Gauss points: the skeleton must take it there too.
    PetscCheck(!mean || r >= saturated.size() || !saturated[r].saturated, comm, PETSC_ERR_USER_INPUT,
               "-material_%s_dilatation mean with -material_%s_saturated: not supported; allowed: -material_%s_dilatation gauss", info.region.c_str(),
               info.region.c_str(), info.region.c_str());
    if (m->mesh.degree > 1) info.fe.dilatation = fem::Dilatation::Gauss;
  }
  PetscCall(readDamping(m));
  PetscCall(medium::AttenuationCreate(comm, &m->materials, &m->attenuation));
  auto setupBulk = [m]() -> PetscErrorCode {
    std::vector<fem::RegionMaterial> fe;
    PetscFunctionBeginUser;
    for (const auto &info : m->materials) fe.push_back(info.fe);
    PetscCall(PetscLogEventBegin(core::event_bulk_setup, 0, 0, 0, 0));
    PetscCall(m->bulk.Setup(m->dm, fe));
    PetscCall(PetscLogEventEnd(core::event_bulk_setup, 0, 0, 0, 0));
    PetscFunctionReturn(0);
  };
  PetscCall(setupBulk());
  // Spectral elements were judged by their corners before subdivision (mesh_builder.cpp).
  if (m->mesh.degree == 1) PetscCall(mesh::CellQualityCheck(m->dm, m->bulk.shape(), m->bulk.cellCount(), [&](PetscInt c) { return m->bulk.cellCoordinates(c); }, m->mesh.serial_cell));
  PetscCall(DMCreateLocalVector(m->dm, &m->u_local));
  PetscCall(VecDuplicate(m->u_local, &m->f_local));
  PetscCall(assembleMass(m));
  PetscCall(PetscLogEventBegin(core::event_boundary_setup, 0, 0, 0, 0));
  PetscCall(input::BoundaryConditionsCreate(m->dm, m->mesh.boundaries, m->materials, m->mass, &m->bc));
  PetscCall(PetscLogEventEnd(core::event_boundary_setup, 0, 0, 0, 0));
  PetscCall(input::PointForcesCreate(m->dm, &m->bc));
  PetscCall(input::BodyForceCreate(m->dm, m->mass, &m->bc));
  PetscCall(input::StructureLoadCreate(m->dm, m->bulk, m->mesh.regions, &m->bc));
  if (m->attenuation && m->attenuation->reference_auto) {
    PetscCall(medium::AttenuationChooseReferences(m->attenuation, m->dm, m->bulk, m->mass, m->bc.free_mask, &m->materials));
    PetscCall(setupBulk());
  }
  if (m->attenuation) PetscCall(medium::AttenuationSetupCells(m->attenuation, m->dm, m->bulk));
  PetscCall(medium::HysteresisCreate(m->bulk, m->materials, &m->hysteresis));
  PetscCall(assembleDampingBlocks(m));
  PetscCall(RigidBodiesCreate(m->dm, m->bulk, m->materials, m->bc, m->mass, &m->rigid));
  PetscCall(input::LateralTieCreate(m->dm, m->bc, m->mass, &m->tie));
  {
    std::vector<input::DrmPoreFluid> fluid;
    for (const porous::SaturatedRegion &r : saturated) fluid.push_back({r.alpha, r.saturated ? r.M : 0.0});
    PetscCall(input::DrmCreate(drmSetting(*m, any_saturated ? &fluid : nullptr), &m->drm));
  }
  PetscCall(VecDuplicate(m->mass, &m->f_internal));
  PetscCall(VecDuplicate(m->mass, &m->f_external));
  PetscCall(VecDuplicate(m->mass, &m->f_input));
  PetscCall(VecDuplicate(m->mass, &m->f_stiffness_damping));
  PetscCall(VecZeroEntries(m->f_stiffness_damping));
  PetscCall(VecDuplicate(m->mass, &m->f_interface));
  PetscCall(VecZeroEntries(m->f_interface));
  PetscCall(VecDuplicate(m->mass, &m->f_anelastic));
  PetscCall(VecZeroEntries(m->f_anelastic));
  PetscCall(VecDuplicate(m->mass, &m->f_contact_damping));
  PetscCall(VecZeroEntries(m->f_contact_damping));
  if (m->hysteresis) {
    PetscCall(VecDuplicate(m->mass, &m->f_hysteretic));
    PetscCall(VecZeroEntries(m->f_hysteretic));
    // Not yet: the DRM's free field is linear, and its layer forces are K u of its cells.
    PetscCheck(!m->drm, comm, PETSC_ERR_USER_INPUT,
               "-input_method drm with a hysteretic region (-material_<r>_model hysteretic): not supported yet; allowed: -input_method base");
  }
  PetscCall(createInterfaces(m));
  if (any_saturated) {
    PetscCall(porous::PorePressureCreate(m->dm, m->bulk, m->mesh.boundaries, std::move(saturated), m->bc.gravity, m->bc.gravity_direction, &m->pore));
    if (m->drm) PetscCall(porous::PorePressureDrmCreate(m->pore, m->drm, m->bulk));
    PetscCall(porous::PorePressureAddHydrostaticForce(m->pore, m->dm, m->bc.constant_force));
    // Interfaces on saturated soil: their fluid condition, and the law in effective stress.
    for (auto &iface : m->interfaces)
      for (size_t r = 0; r < m->materials.size(); ++r)
        if (m->materials[r].region == iface.spec().soil_region && m->pore->regions[r].saturated) {
          PetscCall(porous::PorePressureInterfaceFluid(m->pore, comm, iface.spec().name, iface.pairs().soil_dof));
          PetscCall(iface.SetPorePressure(m->pore->p_total_trial));
        }
    PetscCall(VecDuplicate(m->mass, &m->f_pore));
    PetscCall(VecZeroEntries(m->f_pore));
  }
  // After the pore pressure and its interfaces: the columns take the fluid conditions at the
  // sides' nodes.
  if (m->bc.has_free_field) {
    const input::FreeFieldFluid fluid = m->pore ? freeFieldFluid(*m->pore) : input::FreeFieldFluid();
    PetscCall(input::FreeFieldCreate(m->dm, m->bc, m->materials, m->rayleigh, m->attenuation, m->pore ? &fluid : nullptr, m->bulk.minCellSize(), &m->free_field));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ElastodynamicsAddMass(Elastodynamics *m, Vec added) {
  PetscFunctionBeginUser;
  PetscCall(VecAXPY(m->mass, 1.0, added));
  PetscCall(VecCopy(m->mass, m->inv_mass));
  PetscCall(VecReciprocal(m->inv_mass));
  PetscCall(NodalAccelerationDestroy(&m->nodal));
  if (m->tie) {
    PetscCall(input::LateralTieDestroy(&m->tie));
    PetscCall(input::LateralTieCreate(m->dm, m->bc, m->mass, &m->tie));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ElastodynamicsDestroy(Elastodynamics *m) {
  PetscFunctionBeginUser;
  PetscCall(input::BoundaryConditionsDestroy(&m->bc));
  PetscCall(NodalAccelerationDestroy(&m->nodal));
  PetscCall(input::FreeFieldDestroy(&m->free_field));
  PetscCall(input::DrmDestroy(&m->drm));
  PetscCall(input::LateralTieDestroy(&m->tie));
  PetscCall(medium::AttenuationDestroy(&m->attenuation));
  PetscCall(medium::HysteresisDestroy(&m->hysteresis));
  PetscCall(porous::PorePressureDestroy(&m->pore));
  PetscCall(RigidBodiesDestroy(&m->rigid));
  PetscCall(VecDestroy(&m->f_pore));
  for (auto &iface : m->interfaces) PetscCall(iface.Destroy());
  PetscCall(VecDestroy(&m->f_interface));
  PetscCall(VecDestroy(&m->f_contact_damping));
  for (Vec *v : {&m->mass, &m->inv_mass, &m->damping_blocks, &m->u_local, &m->f_local, &m->f_internal, &m->f_external, &m->f_input, &m->f_stiffness_damping, &m->f_anelastic, &m->f_hysteretic,
                 &m->correction_force, &m->correction_local, &m->correction_f_local})
    PetscCall(VecDestroy(v));
  PetscCall(DMDestroy(&m->dm));
  PetscFunctionReturn(0);
}

PetscErrorCode ElastodynamicsRHS(TS ts, PetscReal t, Vec u, Vec a, void *ctx) {
  auto *m = static_cast<Elastodynamics *>(ctx);
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(core::event_bulk_force, 0, 0, 0, 0));
  PetscCall(ElastodynamicsStiffnessTimes(m, u, m->f_internal));
  // The ghosted u that K u has just gathered into u_local gives the hysteretic regions'
  // strains. Off in the geostatic stage: its static state is the linear one, and the soil
  // starts virgin with the dynamic stage.
  if (m->hysteresis && m->input_enabled) {
    const PetscScalar *ul;
    PetscScalar       *fl;
    PetscCall(VecZeroEntries(m->f_local));
    PetscCall(VecGetArrayRead(m->u_local, &ul));
    PetscCall(VecGetArray(m->f_local, &fl));
    medium::HysteresisForce(m->hysteresis, ul, fl);
    PetscCall(VecRestoreArray(m->f_local, &fl));
    PetscCall(VecRestoreArrayRead(m->u_local, &ul));
    PetscCall(VecZeroEntries(m->f_hysteretic));
    PetscCall(DMLocalToGlobal(m->dm, m->f_local, ADD_VALUES, m->f_hysteretic));
  }
  // The memory forces need K_U u and the ghosted u that K u has just gathered into u_local,
  // and in hysteretic regions the relaxation force of the same u (their drive is the soil's
  // stress). Off in the geostatic stage: the memory starts with the dynamic stage.
  if (m->attenuation && m->input_enabled)
    PetscCall(medium::AttenuationForce(m->attenuation, m->dm, m->bulk, m->u_local, m->f_internal, m->hysteresis, m->f_hysteretic, t, m->f_anelastic));
  // Off in the geostatic stage (input_enabled false): its equilibrium is the drained one, the
  // excess pore pressure stays zero.
  if (m->pore && m->input_enabled) {
    const PetscScalar *ul;
    PetscCall(ElastodynamicsDrmPoreSource(m, ts, t));
    PetscCall(VecGetArrayRead(m->u_local, &ul));
    PetscCall(porous::PorePressureTrial(m->pore, m->dm, ul, t, m->f_pore));
    PetscCall(VecRestoreArrayRead(m->u_local, &ul));
  }
  if (m->rayleigh.beta > 0) {
    Vec v_half;
    PetscCall(time::CentralDifferenceGetHalfStepVelocity(ts, &v_half));
    PetscCall(ElastodynamicsStiffnessTimes(m, v_half, m->f_stiffness_damping));
    PetscCall(VecScale(m->f_stiffness_damping, m->rayleigh.beta));
  }
  PetscCall(PetscLogEventEnd(core::event_bulk_force, 0, 0, 0, 0));
  if (!m->interfaces.empty()) {
    PetscCall(PetscLogEventBegin(core::event_interface, 0, 0, 0, 0));
    PetscCall(VecZeroEntries(m->f_interface));
    // The geostatic stage (no TS) passes no time: a lagged friction is at rest there.
    for (auto &iface : m->interfaces) PetscCall(iface.AddForces(u, m->f_interface, ts ? t : NAN));
    // The contact dashpots use the half-step velocity, like stiffness-proportional damping;
    // the geostatic stage (no TS) relaxes without them.
    if (ts) {
      Vec v_half;
      PetscCall(time::CentralDifferenceGetHalfStepVelocity(ts, &v_half));
      PetscCall(VecZeroEntries(m->f_contact_damping));
      for (auto &iface : m->interfaces) PetscCall(iface.AddDampingForces(v_half, m->f_contact_damping));
    }
    PetscCall(PetscLogEventEnd(core::event_interface, 0, 0, 0, 0));
  }

  PetscCall(PetscLogEventBegin(core::event_boundary, 0, 0, 0, 0));
  const double v_in = m->input_enabled && m->bc.input.active() && m->bc.input_wave != input::InputWave::None ? m->bc.input.velocity(t) : 0.0;
  PetscCall(NodalAccelerationUpdate({m->inv_mass, m->bc.free_mask, m->bc.input_force, m->bc.constant_force, &m->bc.timed_loads, m->free_field || m->drm}, m->f_input,
                                    m->f_external, &m->nodal));
  PetscCall(NodalAccelerationInput(m->nodal, v_in, m->bc.input_force, m->f_input));
  if (m->drm && m->input_enabled) {
    PetscCall(input::DrmAddForce(m->drm, drmSetting(*m), ts, t, m->f_input));
    if (m->pore) PetscCall(porous::PorePressureDrmForce(m->pore, m->drm, m->dm, m->f_input));
  }
  PetscCall(NodalAccelerationExternal(m->nodal, m->bc.constant_force, m->f_input, m->f_external));
  if (m->input_enabled) PetscCall(input::TimedLoadsAdd(m->bc.timed_loads, t, m->f_external));
  if (m->free_field) {
    // The columns' trial reaches t here; their force C v_ff + A t_ff at t is external.
    PetscCall(input::FreeFieldUpdate(m->free_field, m->dm, ts, t, v_in, m->input_enabled));
    PetscCall(VecAXPY(m->f_external, 1.0, m->free_field->force));
  }
  PetscCall(PetscLogEventEnd(core::event_boundary, 0, 0, 0, 0));
  // Every dof, memory-bound like the bulk force (it was inside the boundary event, which then
  // seemed not to halve on 2 ranks: docs/performance.md).
  PetscCall(PetscLogEventBegin(core::event_acceleration, 0, 0, 0, 0));
  const bool interfaces = !m->interfaces.empty();
  PetscCall(NodalAccelerationAssemble(m->nodal,
                                      {m->f_external, m->f_internal, m->rayleigh.beta > 0 ? m->f_stiffness_damping : nullptr, interfaces ? m->f_interface : nullptr,
                                       m->attenuation ? m->f_anelastic : nullptr, interfaces ? m->f_contact_damping : nullptr, m->f_hysteretic},
                                      a));
  if (m->pore) {
    PetscInt           n;
    PetscScalar       *acc;
    const PetscScalar *fp, *mim;
    PetscCall(VecGetLocalSize(a, &n));
    PetscCall(VecGetArray(a, &acc));
    PetscCall(VecGetArrayRead(m->nodal.free_inv_mass, &mim));
    PetscCall(VecGetArrayRead(m->f_pore, &fp));
    for (PetscInt i = 0; i < n; ++i) acc[i] += mim[i] * fp[i];
    PetscCall(VecRestoreArrayRead(m->f_pore, &fp));
    PetscCall(VecRestoreArrayRead(m->nodal.free_inv_mass, &mim));
    PetscCall(VecRestoreArray(a, &acc));
  }
  // The geostatic stage (input_enabled false) holds prescribed dofs at rest: a record's
  // baseline correction leaves a nonzero acceleration at t = 0 that would drag them along.
  if (m->input_enabled)
    for (const input::PrescribedVelocity &p : m->bc.prescribed) PetscCall(VecAXPY(a, p.history.acceleration(t), p.dofs));
  PetscCall(input::LateralTieApply(m->tie, a));
  if (m->rigid) PetscCall(RigidBodiesProject(m->rigid, m->mass, a));
  PetscCall(PetscLogEventEnd(core::event_acceleration, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

} // namespace slipwave::problem

namespace slipwave::problem {

PetscErrorCode ElastodynamicsDrmPoreSource(Elastodynamics *m, TS ts, PetscReal t) {
  PetscFunctionBeginUser;
  if (!m->drm || !m->pore) PetscFunctionReturn(0);
  PetscCall(input::DrmFreeFieldUpdate(m->drm, drmSetting(*m), ts, t));
  PetscCall(porous::PorePressureDrmSource(m->pore, m->drm));
  PetscFunctionReturn(0);
}

PetscErrorCode ElastodynamicsCommit(Elastodynamics *m) {
  PetscFunctionBeginUser;
  for (auto &iface : m->interfaces) iface.Commit();
  input::FreeFieldCommit(m->free_field);
  medium::AttenuationCommit(m->attenuation);
  medium::HysteresisCommit(m->hysteresis);
  PetscCall(porous::PorePressureCommit(m->pore));
  input::DrmCommit(m->drm);
  PetscCall(ElastodynamicsDrainOpenGaps(m));
  PetscFunctionReturn(0);
}

PetscErrorCode ElastodynamicsDrainOpenGaps(Elastodynamics *m) {
  PetscFunctionBeginUser;
  if (!m->pore || m->pore->sealed_interfaces.empty()) PetscFunctionReturn(0);
  const auto &sealed = m->pore->sealed_interfaces;
  Vec         marker;
  PetscCall(VecDuplicate(m->pore->p, &marker));
  PetscCall(VecZeroEntries(marker));
  std::vector<PetscInt> open;
  for (const auto &iface : m->interfaces) {
    if (std::find(sealed.begin(), sealed.end(), iface.spec().name) == sealed.end()) continue;
    iface.openSoilDofs(&open);
    for (PetscInt dof : open) PetscCall(VecSetValue(marker, dof / m->dim, 1.0, INSERT_VALUES));
  }
  PetscCall(VecAssemblyBegin(marker));
  PetscCall(VecAssemblyEnd(marker));
  PetscCall(porous::PorePressureDrainOpenGaps(m->pore, marker));
  PetscCall(VecDestroy(&marker));
  // The next step's law starts from the drained pressure.
  PetscCall(porous::PorePressureTotal(m->pore));
  for (auto &iface : m->interfaces) PetscCall(iface.ReadCommittedPorePressure(m->pore->p_total));
  PetscFunctionReturn(0);
}

namespace {
PetscErrorCode commitHook(void *ctx) { return ElastodynamicsCommit(static_cast<Elastodynamics *>(ctx)); }
PetscErrorCode correctionHook(void *ctx, PetscReal t, PetscReal h, Vec a_star, Vec c) {
  return ElastodynamicsFourthOrderCorrection(static_cast<Elastodynamics *>(ctx), t, h, a_star, c);
}

// Global f = K x through the local vectors x_local, f_local (ghost exchange included).
PetscErrorCode stiffnessTimes(Elastodynamics *m, Vec x, Vec f, Vec x_local, Vec f_local) {
  const PetscScalar *xl;
  PetscScalar       *fl;
  PetscFunctionBeginUser;
  PetscCall(DMGlobalToLocal(m->dm, x, INSERT_VALUES, x_local));
  PetscCall(VecZeroEntries(f_local));
  PetscCall(VecGetArrayRead(x_local, &xl));
  PetscCall(VecGetArray(f_local, &fl));
  m->bulk.addStiffnessTimes(xl, fl);
  PetscCall(VecRestoreArray(f_local, &fl));
  PetscCall(VecRestoreArrayRead(x_local, &xl));
  PetscCall(VecZeroEntries(f));
  PetscCall(DMLocalToGlobal(m->dm, f_local, ADD_VALUES, f));
  PetscFunctionReturn(0);
}

// c = (1/12) (free 1/m) (f(t+h) - 2 f(t) + f(t-h)) added for the loads that are known functions
// of time (the timed loads and the incident wave's force, as the RHS forms them, with the input
// on): on the dofs where they can be nonzero when the model lists them
// (problem/nodal_acceleration.hpp), else on every dof.
PetscErrorCode addLoadSecondDifference(Elastodynamics *m, PetscReal t, PetscReal h, Vec c) {
  PetscFunctionBeginUser;
  if (!m->input_enabled) PetscFunctionReturn(0);
  const auto   second = [t, h](const input::TimeFunction &f) { return f.velocity(t + h) - 2 * f.velocity(t) + f.velocity(t - h); };
  const bool   input  = m->bc.input.active() && m->bc.input_wave != input::InputWave::None;
  PetscScalar *cc;
  const PetscScalar *mim;
  PetscInt     n;
  PetscCall(VecGetLocalSize(c, &n));
  PetscCall(VecGetArray(c, &cc));
  PetscCall(VecGetArrayRead(m->nodal.free_inv_mass, &mim));
  std::vector<std::pair<double, Vec>> loads;
  for (const input::TimedLoad &l : m->bc.timed_loads) loads.emplace_back(second(l.history), l.pattern);
  if (input) loads.emplace_back(second(m->bc.input), m->bc.input_force);
  for (const auto &[weight, pattern] : loads) {
    if (weight == 0) continue;
    const PetscScalar *f;
    PetscCall(VecGetArrayRead(pattern, &f));
    if (m->nodal.listed)
      for (PetscInt k : m->nodal.external_dofs) cc[k] += weight / 12 * mim[k] * f[k];
    else
      for (PetscInt k = 0; k < n; ++k) cc[k] += weight / 12 * mim[k] * f[k];
    PetscCall(VecRestoreArrayRead(pattern, &f));
  }
  PetscCall(VecRestoreArrayRead(m->nodal.free_inv_mass, &mim));
  PetscCall(VecRestoreArray(c, &cc));
  PetscFunctionReturn(0);
}
} // namespace

PetscErrorCode ElastodynamicsFourthOrderCorrection(Elastodynamics *m, PetscReal t, PetscReal h, Vec a_star, Vec c) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(core::event_fourth_order, 0, 0, 0, 0));
  if (!m->correction_force) {
    PetscCall(VecDuplicate(m->mass, &m->correction_force));
    PetscCall(VecDuplicate(m->u_local, &m->correction_local));
    PetscCall(VecDuplicate(m->u_local, &m->correction_f_local));
  }
  PetscCall(stiffnessTimes(m, a_star, m->correction_force, m->correction_local, m->correction_f_local));
  // c = -(h^2/12) (free 1/m) K a*, then the loads' share.
  PetscCall(VecPointwiseMult(c, m->nodal.free_inv_mass, m->correction_force));
  PetscCall(VecScale(c, -h * h / 12));
  PetscCall(addLoadSecondDifference(m, t, h, c));
  PetscCall(input::LateralTieApply(m->tie, c));
  if (m->rigid) PetscCall(RigidBodiesProject(m->rigid, m->mass, c));
  PetscCall(PetscLogEventEnd(core::event_fourth_order, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode ElastodynamicsSetUpTS(Elastodynamics *m, TS ts) {
  PetscFunctionBeginUser;
  PetscCall(TSSetRHSFunction(ts, nullptr, ElastodynamicsRHS, m));
  PetscCall(time::CentralDifferenceSetCommit(ts, commitHook, m));
  PetscCall(time::CentralDifferenceSetCorrection(ts, correctionHook, m));
  PetscCall(time::CentralDifferenceSetNodalDamping(ts, m->dim, m->damping_blocks));
  PetscFunctionReturn(0);
}

PetscErrorCode ElastodynamicsSetInitialStress(Elastodynamics *m, Vec u) {
  const PetscScalar *ul;
  PetscFunctionBeginUser;
  PetscCall(DMGlobalToLocal(m->dm, u, INSERT_VALUES, m->u_local));
  m->initial_stress.assign(6 * m->bulk.cellCount(), 0.0);
  PetscCall(VecGetArrayRead(m->u_local, &ul));
  m->bulk.cellStress(ul, m->initial_stress.data());
  PetscCall(VecRestoreArrayRead(m->u_local, &ul));
  PetscFunctionReturn(0);
}

PetscErrorCode ElastodynamicsStiffnessTimes(Elastodynamics *m, Vec x, Vec f) { return stiffnessTimes(m, x, f, m->u_local, m->f_local); }

} // namespace slipwave::problem
