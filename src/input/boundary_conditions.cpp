#include "slipwave/input/boundary_conditions.hpp"

#include <petscsf.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "slipwave/core/option_choice.hpp"
#include "slipwave/input/boundary_faces.hpp"
#include "slipwave/physics/absorbing_boundary.hpp"

namespace slipwave::input {
namespace {

// In the order of BoundaryType and InputWave.
const char *const kTypeNames[] = {"free", "fixed", "absorbing", "traction", "velocity", "freefield", "tied"};
constexpr int     kTypeCount   = 7;
const char *const kWaveNames[] = {"none", "sv", "p"};

// "x,y" -> {0,1}; an empty list means every component.
PetscErrorCode parseComponents(MPI_Comm comm, const char *option, const char *list, PetscInt dim, std::vector<PetscInt> *components) {
  PetscFunctionBeginUser;
  components->clear();
  for (const char *p = list; *p; ++p) {
    if (*p == ',' || *p == ' ') continue;
    const char *axes = "xyz";
    const char *hit  = std::strchr(axes, *p);
    PetscCheck(hit && hit - axes < dim, comm, PETSC_ERR_USER_INPUT, "%s = %s; allowed: a comma-separated subset of %s", option, list, dim == 2 ? "x,y" : "x,y,z");
    components->push_back((PetscInt)(hit - axes));
  }
  if (components->empty())
    for (PetscInt d = 0; d < dim; ++d) components->push_back(d);
  PetscFunctionReturn(0);
}

// Marks the given components of every vertex of `faces` with 1 in a global vector (ADD, so
// a vertex marked on any rank is marked).
PetscErrorCode markFaceDofs(DM dm, const std::vector<BoundaryFace> &faces, const std::vector<PetscInt> &components, Vec marks) {
  PetscSection s;
  Vec          local;
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm, &s));
  PetscCall(DMGetLocalVector(dm, &local));
  PetscCall(VecZeroEntries(local));
  PetscCall(VecGetArray(local, &a));
  for (const BoundaryFace &f : faces)
    for (PetscInt k = 0; k < f.nvert; ++k) {
      PetscInt off;
      PetscCall(PetscSectionGetOffset(s, f.vertices[k], &off));
      for (PetscInt c : components) a[off + c] = 1;
    }
  PetscCall(VecRestoreArray(local, &a));
  PetscCall(DMLocalToGlobal(dm, local, ADD_VALUES, marks));
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscFunctionReturn(0);
}

// Adds w_a * value[d] on component d of every face vertex into a local array.
PetscErrorCode addFaceLoad(PetscSection s, const BoundaryFace &f, PetscInt dim, const double *value, PetscScalar *a) {
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < f.nvert; ++k) {
    PetscInt off;
    PetscCall(PetscSectionGetOffset(s, f.vertices[k], &off));
    for (PetscInt d = 0; d < dim; ++d) a[off + d] += f.weights[k] * value[d];
  }
  PetscFunctionReturn(0);
}

// -gravity, -gravity_direction, -constrain_components and the incident wave (-input_*): the
// "Loads and incident wave" block. Fills the load and input fields of bc; returns the
// components held at every node.
PetscErrorCode readLoadOptions(MPI_Comm comm, PetscInt dim, BoundaryConditions *bc, std::vector<PetscInt> *constrain_all) {
  PetscReal gravity_dir[3] = {0, 0, 0};
  PetscBool gravity_dir_set = PETSC_FALSE;
  gravity_dir[dim - 1]      = -1;
  char      input_boundary[256] = "bottom", component[8] = "", constrain_list[16] = "";
  PetscInt  wave = (PetscInt)InputWave::None;
  PetscBool input_component_set;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "", "Loads and incident wave", "slipwave");
  PetscCall(PetscOptionsReal("-gravity", "gravitational acceleration [m/s^2], >= 0, along -gravity_direction", "BoundaryConditionsCreate", bc->gravity,
                             &bc->gravity, nullptr));
  PetscInt ndir = dim;
  PetscCall(PetscOptionsRealArray("-gravity_direction", "direction of gravity gx,gy[,gz] (normalised; default: down the last axis; tilt it to model a slope)",
                                  "BoundaryConditionsCreate", gravity_dir, &ndir, &gravity_dir_set));
  PetscCall(PetscOptionsString("-constrain_components", "components fixed at every node, e.g. y for a 1D shear column (x,y,z)", "BoundaryConditionsCreate",
                               constrain_list, constrain_list, sizeof constrain_list, nullptr));
  PetscCall(core::OptionsChoice(PetscOptionsObject, "-input_wave", "vertically incident plane wave entering through an absorbing boundary: none, sv, p", kWaveNames, 3,
                                &wave, nullptr));
  PetscCall(PetscOptionsString("-input_boundary", "absorbing boundary the incident wave enters through", "BoundaryConditionsCreate", input_boundary, input_boundary,
                               sizeof input_boundary, nullptr));
  PetscCall(PetscOptionsString("-input_component", "particle-motion component of the incident wave (x, y, z); default x for sv, the vertical for p",
                               "BoundaryConditionsCreate", component, component, sizeof component, &input_component_set));
  PetscCall(bc->input.Read(comm, "input_", HistoryRole::IncidentWave, PetscOptionsObject));
  PetscOptionsEnd();
  bc->input_wave = (InputWave)wave;
  if (bc->input_wave != InputWave::None) {
    PetscCheck(bc->input.active(), comm, PETSC_ERR_USER_INPUT, "-input_wave = %s needs its velocity history; allowed: -input_stf ricker, gabor or record",
               kWaveNames[wave]);
    bc->input_boundary  = input_boundary;
    bc->input_component = bc->input_wave == InputWave::SV ? 0 : dim - 1;
    if (input_component_set) {
      std::vector<PetscInt> c;
      PetscCall(parseComponents(comm, "-input_component", component, dim, &c));
      PetscCheck(c.size() == 1, comm, PETSC_ERR_USER_INPUT, "-input_component = %s; allowed: one of x, y%s", component, dim == 3 ? ", z" : "");
      bc->input_component = c[0];
    }
  }
  PetscCheck(bc->gravity >= 0, comm, PETSC_ERR_USER_INPUT, "-gravity = %g; allowed: >= 0 (its direction is -gravity_direction)", (double)bc->gravity);
  double len = 0;
  for (PetscInt d = 0; d < dim; ++d) len += gravity_dir[d] * gravity_dir[d];
  len = std::sqrt(len);
  PetscCheck(len > 0, comm, PETSC_ERR_USER_INPUT, "-gravity_direction is the zero vector; allowed: %" PetscInt_FMT " components, not all zero", dim);
  for (PetscInt d = 0; d < dim; ++d) bc->gravity_direction[d] = gravity_dir[d] / len;
  constrain_all->clear();
  if (constrain_list[0]) PetscCall(parseComponents(comm, "-constrain_components", constrain_list, dim, constrain_all));
  PetscFunctionReturn(0);
}

// The options of one side, -bc_<name>_*: its block "Boundary <name>".
struct SideOptions {
  BoundaryType          type = BoundaryType::Free;
  std::vector<PetscInt> components; // held components (fixed, velocity)
  std::vector<PetscInt> fixed_components, velocity_components; // with per-component types
  bool                  per_component = false;                 // some -type_<c> given
  PetscReal             traction[3] = {0, 0, 0};
  TimeFunction          history;    // velocity, or the traction's factor
  std::string           tie_with;   // tied
};

// -<prefix>type_x|_y|_z: each component's own type, free, fixed or velocity; the others keep
// the side's -type.
PetscErrorCode readComponentTypes(MPI_Comm comm, PetscInt dim, const std::string &prefix, PetscInt side_type, bool components_given, PetscOptionItems *PetscOptionsObject,
                                  SideOptions *o) {
  const char *const kComponentTypes[] = {"free", "fixed", "velocity"};
  const BoundaryType kComponentType[] = {BoundaryType::Free, BoundaryType::Fixed, BoundaryType::Velocity};
  PetscInt          types[3];
  PetscFunctionBeginUser;
  for (PetscInt c = 0; c < dim; ++c) {
    const std::string name = std::string("-type_") + "xyz"[c];
    PetscInt          choice = 0;
    PetscBool         set;
    PetscCall(core::OptionsChoice(PetscOptionsObject, name.c_str(), "this component's own condition on the boundary: free, fixed, velocity (overrides -type for it)",
                                  kComponentTypes, 3, &choice, &set));
    types[c] = set ? (PetscInt)kComponentType[choice] : side_type;
    o->per_component = o->per_component || set;
  }
  if (!o->per_component) PetscFunctionReturn(0);
  const BoundaryType side = (BoundaryType)side_type;
  PetscCheck(side == BoundaryType::Free || side == BoundaryType::Fixed || side == BoundaryType::Velocity, comm, PETSC_ERR_USER_INPUT,
             "-%stype = %s with -%stype_<component>; allowed: -%stype free, fixed or velocity (the components not named)", prefix.c_str(), kTypeNames[side_type],
             prefix.c_str(), prefix.c_str());
  PetscCheck(!components_given, comm, PETSC_ERR_USER_INPUT, "-%scomponents with -%stype_<component>; allowed: one of them", prefix.c_str(), prefix.c_str());
  for (PetscInt c = 0; c < dim; ++c) {
    if ((BoundaryType)types[c] == BoundaryType::Fixed) o->fixed_components.push_back(c);
    if ((BoundaryType)types[c] == BoundaryType::Velocity) o->velocity_components.push_back(c);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode readSideOptions(MPI_Comm comm, PetscInt dim, const std::string &prefix, const std::string &name, SideOptions *o) {
  const std::string title = "Boundary " + name;
  PetscInt          type  = 0;
  char              comps[16] = "", tie_with[256] = "";
  PetscInt          ntraction = dim;
  PetscBool         traction_set, comps_set;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, prefix.c_str(), title.c_str(), "slipwave");
  PetscCall(core::OptionsChoice(PetscOptionsObject, "-type", "boundary condition", kTypeNames, kTypeCount, &type, nullptr));
  if ((BoundaryType)type == BoundaryType::Tied)
    PetscCall(PetscOptionsString("-tie_with", "the opposite side whose facing nodes move with this one's (type tied)", "BoundaryConditionsCreate", tie_with, tie_with,
                                 sizeof tie_with, nullptr));
  PetscCall(PetscOptionsString("-components", "components held (fixed, velocity): x,y[,z]; default all", "BoundaryConditionsCreate", comps, comps, sizeof comps,
                               &comps_set));
  PetscCall(readComponentTypes(comm, dim, prefix, type, comps_set, PetscOptionsObject, o));
  PetscCall(PetscOptionsRealArray("-traction", "applied traction tx,ty[,tz] [Pa] (type traction; times -stf when given)", "BoundaryConditionsCreate", o->traction, &ntraction,
                                  &traction_set));
  if ((BoundaryType)type == BoundaryType::Velocity || !o->velocity_components.empty())
    PetscCall(o->history.Read(comm, prefix, HistoryRole::BoundaryVelocity, PetscOptionsObject));
  if ((BoundaryType)type == BoundaryType::Traction) PetscCall(o->history.Read(comm, prefix, HistoryRole::Load, PetscOptionsObject));
  PetscOptionsEnd();
  o->type     = (BoundaryType)type;
  o->tie_with = tie_with;
  PetscCall(parseComponents(comm, ("-" + prefix + "components").c_str(), comps, dim, &o->components));
  PetscCheck(!traction_set || o->type == BoundaryType::Traction, comm, PETSC_ERR_USER_INPUT, "-%straction is given but -%stype = %s; allowed: -%stype traction",
             prefix.c_str(), prefix.c_str(), kTypeNames[type], prefix.c_str());
  PetscCheck(!traction_set || ntraction == dim, comm, PETSC_ERR_USER_INPUT, "-%straction has %" PetscInt_FMT " values; allowed: %" PetscInt_FMT, prefix.c_str(), ntraction,
             dim);
  PetscFunctionReturn(0);
}

// What the sides add up while they are read: held dofs (global) and, in local vectors, the
// tractions and the incident-wave force, and the dashpot blocks: dim x dim per node, dim values
// per displacement dof (at dim times its local offset).
struct SideSums {
  PetscSection             s = nullptr; // displacement layout
  Vec                      constrained = nullptr, force_local = nullptr, input_local = nullptr;
  std::vector<PetscScalar> block_local;
  bool                     input_found = false;
};

PetscErrorCode addTiedSide(MPI_Comm comm, const std::vector<std::string> &boundaries, const std::string &name, const std::string &prefix, const SideOptions &o,
                           BoundaryConditions *bc) {
  PetscFunctionBeginUser;
  PetscCheck(std::find(boundaries.begin(), boundaries.end(), o.tie_with) != boundaries.end() && o.tie_with != name, comm, PETSC_ERR_USER_INPUT,
             "-%stie_with = '%s'; allowed: another boundary of the mesh (the opposite side)", prefix.c_str(), o.tie_with.c_str());
  bool seen = false;
  for (const auto &p : bc->tied_pairs) seen = seen || (p.first == o.tie_with && p.second == name);
  if (!seen) bc->tied_pairs.emplace_back(name, o.tie_with);
  PetscFunctionReturn(0);
}

PetscErrorCode addFixedSide(DM dm, const std::vector<BoundaryFace> &faces, const std::vector<PetscInt> &components, const std::string &name, const std::string &prefix,
                            SideSums *sums, BoundaryConditions *bc) {
  PetscFunctionBeginUser;
  PetscCall(markFaceDofs(dm, faces, components, sums->constrained));
  // A vertically incident plane wave moves every point of a horizontally layered site
  // alike; a side held in that component reflects the wave back into the model instead
  // of letting it pass (rollers under SV: the default scene lost 2/3 of its surface
  // velocity that way).
  if (bc->input_wave != InputWave::None && name != bc->input_boundary &&
      std::find(components.begin(), components.end(), bc->input_component) != components.end()) {
    bc->warnings.push_back("boundary '" + name + "' is fixed in " + "xyz"[bc->input_component] + ", the component the incident " +
                           (bc->input_wave == InputWave::SV ? "SV" : "P") + " wave moves: it holds back the free-field motion; use -" + prefix +
                           "type freefield (or tied with the opposite side)");
  }
  PetscFunctionReturn(0);
}

// A constant traction adds to the constant force; one with a history becomes a timed load.
PetscErrorCode addTractionSide(DM dm, PetscInt dim, const std::vector<BoundaryFace> &faces, const std::string &name, SideOptions *o, SideSums *sums,
                               BoundaryConditions *bc) {
  Vec          local = sums->force_local;
  PetscScalar *fa;
  PetscFunctionBeginUser;
  if (o->history.active()) {
    PetscCall(DMGetLocalVector(dm, &local));
    PetscCall(VecZeroEntries(local));
  }
  PetscCall(VecGetArray(local, &fa));
  for (const BoundaryFace &f : faces) PetscCall(addFaceLoad(sums->s, f, dim, o->traction, fa));
  PetscCall(VecRestoreArray(local, &fa));
  if (!o->history.active()) PetscFunctionReturn(0);
  Vec pattern;
  PetscCall(VecDuplicate(bc->constant_force, &pattern));
  PetscCall(VecZeroEntries(pattern));
  PetscCall(DMLocalToGlobal(dm, local, ADD_VALUES, pattern));
  PetscCall(DMRestoreLocalVector(dm, &local));
  bc->load_notes.push_back("traction on '" + name + "': " + o->history.describe());
  PetscCall(TimedLoadAdopt("traction " + name, pattern, std::move(o->history), bc->constant_force, &bc->timed_loads));
  PetscFunctionReturn(0);
}

PetscErrorCode addVelocitySide(DM dm, const std::vector<BoundaryFace> &faces, const std::vector<PetscInt> &components, const std::string &name, const std::string &prefix,
                               SideOptions *o, SideSums *sums, BoundaryConditions *bc) {
  PetscFunctionBeginUser;
  PetscCheck(o->history.active(), PetscObjectComm((PetscObject)dm), PETSC_ERR_USER_INPUT, "-%stype%s velocity needs a history; allowed: -%sstf ricker, gabor, harmonic or record",
             prefix.c_str(), o->per_component ? "_<component>" : "", prefix.c_str());
  PrescribedVelocity pv;
  pv.boundary = name;
  PetscCall(VecDuplicate(sums->constrained, &pv.dofs));
  PetscCall(VecZeroEntries(pv.dofs));
  PetscCall(markFaceDofs(dm, faces, components, pv.dofs));
  PetscCall(VecAXPY(sums->constrained, 1.0, pv.dofs));
  pv.history = std::move(o->history);
  bc->prescribed.push_back(std::move(pv));
  PetscFunctionReturn(0);
}

// A side with per-component types: its fixed and its velocity components, each as a side of
// that type; the side's recorded type is the strongest one it holds (velocity, fixed, free).
PetscErrorCode addComponentSide(DM dm, const std::vector<BoundaryFace> &faces, const std::string &name, const std::string &prefix, SideOptions *o, SideSums *sums,
                                BoundaryConditions *bc) {
  std::string note = "boundary '" + name + "' per component:";
  PetscFunctionBeginUser;
  for (PetscInt c : o->fixed_components) note += std::string(" ") + "xyz"[c] + " fixed";
  for (PetscInt c : o->velocity_components) note += std::string(" ") + "xyz"[c] + " velocity";
  if (!o->fixed_components.empty()) PetscCall(addFixedSide(dm, faces, o->fixed_components, name, prefix, sums, bc));
  if (!o->velocity_components.empty()) {
    note += " (" + o->history.describe() + ")";
    PetscCall(addVelocitySide(dm, faces, o->velocity_components, name, prefix, o, sums, bc));
  }
  bc->types.back() = !o->velocity_components.empty() ? BoundaryType::Velocity : !o->fixed_components.empty() ? BoundaryType::Fixed : BoundaryType::Free;
  bc->load_notes.push_back(note + ", the others free");
  PetscFunctionReturn(0);
}

// Absorbing and free-field sides: a free-field side has the same Lysmer dashpot (on v - v_ff;
// the v_ff part is the external force of input/free_field.cpp), and never the incident wave.
PetscErrorCode addDashpotSide(PetscInt dim, const std::vector<BoundaryFace> &faces, const std::vector<medium::RegionMaterialInfo> &materials, const std::string &name,
                              BoundaryType type, SideSums *sums, BoundaryConditions *bc) {
  PetscScalar *ba = sums->block_local.data(), *ia;
  PetscFunctionBeginUser;
  bc->has_absorbing  = true;
  bc->has_free_field = bc->has_free_field || type == BoundaryType::FreeField;
  const bool is_input = type == BoundaryType::Absorbing && bc->input_wave != InputWave::None && name == bc->input_boundary;
  sums->input_found   = sums->input_found || is_input;
  PetscCall(VecGetArray(sums->input_local, &ia));
  for (const BoundaryFace &f : faces) {
    const physics::ElasticMaterial m = medium::boundaryElastic(materials[f.region]);
    for (PetscInt k = 0; k < f.nvert; ++k) {
      double   C[9];
      PetscInt off;
      physics::lysmerDashpot((int)dim, f.normal, f.weights[k], m, C);
      PetscCall(PetscSectionGetOffset(sums->s, f.vertices[k], &off));
      for (PetscInt j = 0; j < dim * dim; ++j) ba[off * dim + j] += C[j];
      if (is_input) {
        // Force per unit incident velocity: the traction for v_in = 1 along the motion.
        const double c = bc->input_wave == InputWave::SV ? m.vs : m.vp;
        double       direction[3] = {0, 0, 0}, t[3];
        direction[bc->input_component] = 1;
        physics::incidentWaveTraction((int)dim, direction, m.rho, c, 1.0, t);
        for (PetscInt d = 0; d < dim; ++d) ia[off + d] += t[d] * f.weights[k];
      }
    }
  }
  PetscCall(VecRestoreArray(sums->input_local, &ia));
  PetscFunctionReturn(0);
}

// Holds `components` at every node (-constrain_components).
PetscErrorCode constrainEveryNode(PetscInt dim, const std::vector<PetscInt> &components, Vec constrained) {
  PetscInt     n;
  PetscScalar *c;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(constrained, &n));
  PetscCall(VecGetArray(constrained, &c));
  for (PetscInt i = 0; i < n; i += dim)
    for (PetscInt comp : components) c[i + comp] += 1;
  PetscCall(VecRestoreArray(constrained, &c));
  PetscFunctionReturn(0);
}

// constant_force += gravity * direction * M (lumped mass per dof).
PetscErrorCode addGravity(PetscInt dim, Vec mass, BoundaryConditions *bc) {
  PetscInt           n;
  PetscScalar       *f;
  const PetscScalar *m;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(mass, &n));
  PetscCall(VecGetArray(bc->constant_force, &f));
  PetscCall(VecGetArrayRead(mass, &m));
  for (PetscInt i = 0; i < n; ++i) f[i] += bc->gravity * bc->gravity_direction[i % dim] * m[i];
  PetscCall(VecRestoreArrayRead(mass, &m));
  PetscCall(VecRestoreArray(bc->constant_force, &f));
  PetscFunctionReturn(0);
}

// free_mask = 1 where nothing holds the dof.
PetscErrorCode setFreeMask(Vec constrained, Vec free_mask) {
  PetscInt           n;
  PetscScalar       *mask;
  const PetscScalar *c;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(constrained, &n));
  PetscCall(VecGetArray(free_mask, &mask));
  PetscCall(VecGetArrayRead(constrained, &c));
  for (PetscInt i = 0; i < n; ++i) mask[i] = PetscRealPart(c[i]) > 0 ? 0.0 : 1.0;
  PetscCall(VecRestoreArrayRead(constrained, &c));
  PetscCall(VecRestoreArray(free_mask, &mask));
  PetscFunctionReturn(0);
}

// The global vectors as copies of the mass's layout (DMCreateGlobalVector walks the whole chart
// each time). absorbing_blocks: dim x dim per owned node, node by node as the displacement's dofs
// (a layout of its own, a DM clone with a dim^2 section, would cost its global section and its SF).
PetscErrorCode createVectors(Vec mass, PetscInt dim, BoundaryConditions *bc) {
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(mass, &bc->constant_force));
  PetscCall(VecDuplicate(mass, &bc->input_force));
  PetscCall(VecDuplicate(mass, &bc->free_mask));
  PetscInt owned;
  PetscCall(VecGetLocalSize(mass, &owned));
  PetscCall(VecCreate(PetscObjectComm((PetscObject)mass), &bc->absorbing_blocks));
  PetscCall(VecSetSizes(bc->absorbing_blocks, owned * dim, PETSC_DETERMINE));
  PetscCall(VecSetType(bc->absorbing_blocks, VECSTANDARD));
  PetscCall(VecZeroEntries(bc->absorbing_blocks));
  PetscCall(VecZeroEntries(bc->constant_force));
  PetscCall(VecZeroEntries(bc->input_force));
  PetscFunctionReturn(0);
}

// DMLocalToGlobal(ADD_VALUES) of the blocks: the displacement's section SF carries dim values
// per dof instead of one.
PetscErrorCode addBlocksToGlobal(DM dm, PetscInt dim, const std::vector<PetscScalar> &local, Vec global) {
  PetscSF      sf;
  MPI_Datatype unit;
  PetscScalar *g;
  PetscFunctionBeginUser;
  PetscCall(DMGetSectionSF(dm, &sf));
  PetscCallMPI(MPI_Type_contiguous((PetscMPIInt)dim, MPIU_SCALAR, &unit));
  PetscCallMPI(MPI_Type_commit(&unit));
  PetscCall(VecGetArray(global, &g));
  PetscCall(PetscSFReduceBegin(sf, unit, local.data(), g, MPIU_SUM));
  PetscCall(PetscSFReduceEnd(sf, unit, local.data(), g, MPIU_SUM));
  PetscCall(VecRestoreArray(global, &g));
  PetscCallMPI(MPI_Type_free(&unit));
  PetscFunctionReturn(0);
}

} // namespace

const char *boundaryTypeName(BoundaryType t) { return kTypeNames[(int)t]; }
const char *inputWaveName(InputWave w) { return kWaveNames[(int)w]; }

PetscErrorCode BoundaryConditionsCreate(DM dm, const std::vector<std::string> &boundaries, const std::vector<medium::RegionMaterialInfo> &materials, Vec mass,
                                        BoundaryConditions *bc) {
  MPI_Comm              comm = PetscObjectComm((PetscObject)dm);
  PetscInt              dim;
  SideSums              sums;
  std::vector<PetscInt> constrain_all;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(createVectors(mass, dim, bc));
  PetscCall(DMGetLocalSection(dm, &sums.s));
  PetscCall(VecDuplicate(bc->free_mask, &sums.constrained));
  PetscCall(VecZeroEntries(sums.constrained));
  PetscCall(DMGetLocalVector(dm, &sums.force_local));
  PetscCall(DMGetLocalVector(dm, &sums.input_local));
  PetscCall(VecZeroEntries(sums.force_local));
  PetscCall(VecZeroEntries(sums.input_local));
  {
    PetscInt local;
    PetscCall(VecGetLocalSize(sums.force_local, &local));
    sums.block_local.assign((size_t)local * dim, 0.0);
  }

  PetscCall(readLoadOptions(comm, dim, bc, &constrain_all));
  for (const std::string &name : boundaries) {
    const std::string prefix = "bc_" + name + "_";
    SideOptions       o;
    PetscCall(readSideOptions(comm, dim, prefix, name, &o));
    bc->names.push_back(name);
    bc->types.push_back(o.type);
    std::vector<BoundaryFace> faces;
    PetscCall(BoundaryFacesGet(dm, name, &faces));
    if (o.per_component) {
      PetscCall(addComponentSide(dm, faces, name, prefix, &o, &sums, bc));
      continue;
    }
    switch (o.type) {
    case BoundaryType::Free: break;
    case BoundaryType::Tied: PetscCall(addTiedSide(comm, boundaries, name, prefix, o, bc)); break;
    case BoundaryType::Fixed: PetscCall(addFixedSide(dm, faces, o.components, name, prefix, &sums, bc)); break;
    case BoundaryType::Traction: PetscCall(addTractionSide(dm, dim, faces, name, &o, &sums, bc)); break;
    case BoundaryType::Velocity: PetscCall(addVelocitySide(dm, faces, o.components, name, prefix, &o, &sums, bc)); break;
    case BoundaryType::FreeField:
    case BoundaryType::Absorbing: PetscCall(addDashpotSide(dim, faces, materials, name, o.type, &sums, bc)); break;
    }
  }
  PetscCheck(bc->input_wave == InputWave::None || sums.input_found, comm, PETSC_ERR_USER_INPUT,
             "-input_boundary = %s is not an absorbing boundary; allowed: a boundary with -bc_<name>_type absorbing", bc->input_boundary.c_str());
  if (!constrain_all.empty()) PetscCall(constrainEveryNode(dim, constrain_all, sums.constrained));

  PetscCall(DMLocalToGlobal(dm, sums.force_local, ADD_VALUES, bc->constant_force));
  PetscCall(DMLocalToGlobal(dm, sums.input_local, ADD_VALUES, bc->input_force));
  PetscCall(addBlocksToGlobal(dm, dim, sums.block_local, bc->absorbing_blocks));
  PetscCall(DMRestoreLocalVector(dm, &sums.force_local));
  PetscCall(DMRestoreLocalVector(dm, &sums.input_local));
  if (bc->gravity > 0) PetscCall(addGravity(dim, mass, bc));
  PetscCall(setFreeMask(sums.constrained, bc->free_mask));
  PetscCall(VecDestroy(&sums.constrained));
  PetscFunctionReturn(0);
}

PetscErrorCode BoundaryConditionsDestroy(BoundaryConditions *bc) {
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&bc->absorbing_blocks));
  PetscCall(VecDestroy(&bc->constant_force));
  PetscCall(VecDestroy(&bc->input_force));
  PetscCall(VecDestroy(&bc->free_mask));
  for (PrescribedVelocity &p : bc->prescribed) PetscCall(VecDestroy(&p.dofs));
  PetscCall(TimedLoadsDestroy(&bc->timed_loads));
  bc->prescribed.clear();
  PetscFunctionReturn(0);
}

} // namespace slipwave::input
