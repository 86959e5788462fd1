#include "slipwave/model/boundary_conditions.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "slipwave/model/boundary_faces.hpp"
#include "slipwave/model/node_fields.hpp"
#include "slipwave/physics/absorbing_boundary.hpp"

namespace slipwave::model {
namespace {

const char *const kTypeNames[] = {"free", "fixed", "absorbing", "traction", "velocity", "freefield", "tied", "BoundaryType", "BC_", nullptr};
constexpr int     kTypeCount   = 7;

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

} // namespace

const char *boundaryTypeName(BoundaryType t) { return kTypeNames[(int)t]; }

PetscErrorCode BoundaryConditionsCreate(DM dm, const std::vector<std::string> &boundaries, const std::vector<RegionMaterialInfo> &materials, Vec mass,
                                        BoundaryConditions *bc) {
  MPI_Comm     comm = PetscObjectComm((PetscObject)dm);
  PetscInt     dim;
  PetscSection s, sb;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMGetLocalSection(dm, &s));
  PetscCall(NodeFieldCreateDM(dm, dim * dim, &bc->block_dm));
  PetscCall(DMGetLocalSection(bc->block_dm, &sb));
  PetscCall(DMCreateGlobalVector(bc->block_dm, &bc->absorbing_blocks));
  PetscCall(DMCreateGlobalVector(dm, &bc->constant_force));
  PetscCall(DMCreateGlobalVector(dm, &bc->input_force));
  PetscCall(DMCreateGlobalVector(dm, &bc->free_mask));
  PetscCall(VecZeroEntries(bc->absorbing_blocks));
  PetscCall(VecZeroEntries(bc->constant_force));
  PetscCall(VecZeroEntries(bc->input_force));

  Vec constrained;
  PetscCall(VecDuplicate(bc->free_mask, &constrained));
  PetscCall(VecZeroEntries(constrained));
  Vec          force_local, block_local, input_local;
  PetscScalar *fa, *ba, *ia;
  PetscCall(DMGetLocalVector(dm, &force_local));
  PetscCall(DMGetLocalVector(dm, &input_local));
  PetscCall(DMGetLocalVector(bc->block_dm, &block_local));
  PetscCall(VecZeroEntries(force_local));
  PetscCall(VecZeroEntries(input_local));
  PetscCall(VecZeroEntries(block_local));

  PetscReal gravity_dir[3] = {0, 0, 0};
  PetscBool gravity_dir_set = PETSC_FALSE;
  gravity_dir[dim - 1]      = -1;
  char      wave[16] = "none", input_boundary[256] = "bottom", component[8] = "", constrain_all[16] = "";
  PetscBool input_component_set;
  PetscOptionsBegin(comm, "", "Loads and incident wave", "slipwave");
  PetscCall(PetscOptionsReal("-gravity", "gravitational acceleration [m/s^2], along -gravity_direction", "BoundaryConditionsCreate", bc->gravity,
                             &bc->gravity, nullptr));
  PetscInt ndir = dim;
  PetscCall(PetscOptionsRealArray("-gravity_direction", "direction of gravity gx,gy[,gz] (normalised; default: down the last axis; tilt it to model a slope)",
                                  "BoundaryConditionsCreate", gravity_dir, &ndir, &gravity_dir_set));
  PetscCall(PetscOptionsString("-constrain_components", "components fixed at every node, e.g. y for a 1D shear column (x,y,z)", "BoundaryConditionsCreate",
                               constrain_all, constrain_all, sizeof constrain_all, nullptr));
  PetscCall(PetscOptionsString("-input_wave", "vertically incident plane wave entering through an absorbing boundary: none, sv, p", "BoundaryConditionsCreate", wave,
                               wave, sizeof wave, nullptr));
  PetscCall(PetscOptionsString("-input_boundary", "absorbing boundary the incident wave enters through", "BoundaryConditionsCreate", input_boundary, input_boundary,
                               sizeof input_boundary, nullptr));
  PetscCall(PetscOptionsString("-input_component", "particle-motion component of the incident wave (x, y, z); default x for sv, the vertical for p",
                               "BoundaryConditionsCreate", component, component, sizeof component, &input_component_set));
  PetscCall(bc->input.Read(comm, "input_", HistoryRole::IncidentWave, PetscOptionsObject));
  PetscOptionsEnd();
  bc->input_wave = wave;
  PetscCheck(bc->input_wave == "none" || bc->input_wave == "sv" || bc->input_wave == "p", comm, PETSC_ERR_USER_INPUT, "-input_wave = %s; allowed: none, sv, p",
             wave);
  if (bc->input_wave != "none") {
    PetscCheck(bc->input.active(), comm, PETSC_ERR_USER_INPUT, "-input_wave = %s needs its velocity history; allowed: -input_stf ricker, gabor or record", wave);
    bc->input_boundary = input_boundary;
    bc->input_component = bc->input_wave == "sv" ? 0 : dim - 1;
    if (input_component_set) {
      std::vector<PetscInt> c;
      PetscCall(parseComponents(comm, "-input_component", component, dim, &c));
      PetscCheck(c.size() == 1, comm, PETSC_ERR_USER_INPUT, "-input_component = %s; allowed: one of x, y%s", component, dim == 3 ? ", z" : "");
      bc->input_component = c[0];
    }
  }
  PetscCheck(bc->gravity >= 0, comm, PETSC_ERR_USER_INPUT, "-gravity = %g; allowed: >= 0 (its direction is -gravity_direction)", (double)bc->gravity);
  {
    double len = 0;
    for (PetscInt d = 0; d < dim; ++d) len += gravity_dir[d] * gravity_dir[d];
    len = std::sqrt(len);
    PetscCheck(len > 0, comm, PETSC_ERR_USER_INPUT, "-gravity_direction is the zero vector; allowed: %" PetscInt_FMT " components, not all zero", dim);
    for (PetscInt d = 0; d < dim; ++d) bc->gravity_direction[d] = gravity_dir[d] / len;
  }

  bool input_found = false;
  for (const std::string &name : boundaries) {
    const std::string prefix = "bc_" + name + "_";
    const std::string title  = "Boundary " + name;
    PetscInt          type   = 0;
    char              comps[16] = "";
    PetscReal         traction[3] = {0, 0, 0};
    PetscInt          ntraction = dim;
    PetscBool         traction_set;
    TimeFunction      history;
    char              tie_with[256] = "";
    {
      // PetscOptionsEList stops an unknown value with PETSc's multi-line traceback: check it
      // first so the user gets the one-line error.
      char      value[64] = "";
      PetscBool set, known = PETSC_FALSE;
      PetscCall(PetscOptionsGetString(nullptr, prefix.c_str(), "-type", value, sizeof value, &set));
      for (int i = 0; i < kTypeCount && set && !known; ++i) PetscCall(PetscStrcasecmp(value, kTypeNames[i], &known));
      PetscCheck(!set || known, comm, PETSC_ERR_USER_INPUT, "-%stype = %s; allowed: free, fixed, absorbing, traction, velocity, freefield, tied", prefix.c_str(), value);
    }
    PetscOptionsBegin(comm, prefix.c_str(), title.c_str(), "slipwave");
    PetscCall(PetscOptionsEList("-type", "boundary condition", "BoundaryConditionsCreate", kTypeNames, kTypeCount, kTypeNames[0], &type, nullptr));
    if ((BoundaryType)type == BoundaryType::Tied)
      PetscCall(PetscOptionsString("-tie_with", "the opposite side whose facing nodes move with this one's (type tied)", "BoundaryConditionsCreate", tie_with, tie_with,
                                   sizeof tie_with, nullptr));
    PetscCall(PetscOptionsString("-components", "components held (fixed, velocity): x,y[,z]; default all", "BoundaryConditionsCreate", comps, comps, sizeof comps,
                                 nullptr));
    PetscCall(PetscOptionsRealArray("-traction", "applied traction tx,ty[,tz] [Pa] (type traction)", "BoundaryConditionsCreate", traction, &ntraction, &traction_set));
    if ((BoundaryType)type == BoundaryType::Velocity) PetscCall(history.Read(comm, prefix, HistoryRole::BoundaryVelocity, PetscOptionsObject));
    PetscOptionsEnd();
    const BoundaryType t = (BoundaryType)type;
    bc->names.push_back(name);
    bc->types.push_back(t);
    std::vector<BoundaryFace> faces;
    PetscCall(BoundaryFacesGet(dm, name, &faces));
    std::vector<PetscInt> components;
    PetscCall(parseComponents(comm, ("-" + prefix + "components").c_str(), comps, dim, &components));
    PetscCheck(!traction_set || t == BoundaryType::Traction, comm, PETSC_ERR_USER_INPUT, "-%straction is given but -%stype = %s; allowed: -%stype traction", prefix.c_str(),
               prefix.c_str(), kTypeNames[type], prefix.c_str());
    PetscCheck(!traction_set || ntraction == dim, comm, PETSC_ERR_USER_INPUT, "-%straction has %" PetscInt_FMT " values; allowed: %" PetscInt_FMT, prefix.c_str(),
               ntraction, dim);
    switch (t) {
    case BoundaryType::Free: break;
    case BoundaryType::Tied: {
      const std::string other = tie_with;
      PetscCheck(std::find(boundaries.begin(), boundaries.end(), other) != boundaries.end() && other != name, comm, PETSC_ERR_USER_INPUT,
                 "-%stie_with = '%s'; allowed: another boundary of the mesh (the opposite side)", prefix.c_str(), tie_with);
      bool seen = false;
      for (const auto &p : bc->tied_pairs) seen = seen || (p.first == other && p.second == name);
      if (!seen) bc->tied_pairs.emplace_back(name, other);
      break;
    }
    case BoundaryType::Fixed:
      PetscCall(markFaceDofs(dm, faces, components, constrained));
      // A vertically incident plane wave moves every point of a horizontally layered site
      // alike; a side held in that component reflects the wave back into the model instead
      // of letting it pass (rollers under SV: the default scene lost 2/3 of its surface
      // velocity that way).
      if (bc->input_wave != "none" && name != bc->input_boundary &&
          std::find(components.begin(), components.end(), bc->input_component) != components.end()) {
        bc->warnings.push_back("boundary '" + name + "' is fixed in " + "xyz"[bc->input_component] + ", the component the incident " +
                               (bc->input_wave == "sv" ? "SV" : "P") + " wave moves: it holds back the free-field motion; use -" + prefix +
                               "type freefield (or tied with the opposite side)");
      }
      break;
    case BoundaryType::Traction:
      PetscCall(VecGetArray(force_local, &fa));
      for (const BoundaryFace &f : faces) PetscCall(addFaceLoad(s, f, dim, traction, fa));
      PetscCall(VecRestoreArray(force_local, &fa));
      break;
    case BoundaryType::Velocity: {
      PetscCheck(history.active(), comm, PETSC_ERR_USER_INPUT, "-%stype velocity needs a history; allowed: -%sstf ricker, gabor or record", prefix.c_str(),
                 prefix.c_str());
      PrescribedVelocity pv;
      pv.boundary = name;
      PetscCall(VecDuplicate(constrained, &pv.dofs));
      PetscCall(VecZeroEntries(pv.dofs));
      PetscCall(markFaceDofs(dm, faces, components, pv.dofs));
      PetscCall(VecAXPY(constrained, 1.0, pv.dofs));
      pv.history = std::move(history);
      bc->prescribed.push_back(std::move(pv));
      break;
    }
    case BoundaryType::FreeField:
    case BoundaryType::Absorbing: {
      // A free-field side has the same Lysmer dashpot (on v - v_ff; the v_ff part is the
      // external force of model/free_field.cpp), and never the incident wave.
      bc->has_absorbing  = true;
      bc->has_free_field = bc->has_free_field || t == BoundaryType::FreeField;
      const bool is_input = t == BoundaryType::Absorbing && bc->input_wave != "none" && name == bc->input_boundary;
      input_found         = input_found || is_input;
      PetscCall(VecGetArray(block_local, &ba));
      PetscCall(VecGetArray(input_local, &ia));
      for (const BoundaryFace &f : faces) {
        const physics::ElasticMaterial &m = materials[f.region].elastic;
        for (PetscInt k = 0; k < f.nvert; ++k) {
          double   C[9];
          PetscInt off;
          physics::lysmerDashpot((int)dim, f.normal, f.weights[k], m, C);
          PetscCall(PetscSectionGetOffset(sb, f.vertices[k], &off));
          for (PetscInt j = 0; j < dim * dim; ++j) ba[off + j] += C[j];
          if (is_input) {
            PetscCall(PetscSectionGetOffset(s, f.vertices[k], &off));
            // Force per unit incident velocity: the traction for v_in = 1 along the motion.
            const double c = bc->input_wave == "sv" ? m.vs : m.vp;
            double       direction[3] = {0, 0, 0}, t[3];
            direction[bc->input_component] = 1;
            physics::incidentWaveTraction((int)dim, direction, m.rho, c, 1.0, t);
            for (PetscInt d = 0; d < dim; ++d) ia[off + d] += t[d] * f.weights[k];
          }
        }
      }
      PetscCall(VecRestoreArray(input_local, &ia));
      PetscCall(VecRestoreArray(block_local, &ba));
      break;
    }
    }
  }
  PetscCheck(bc->input_wave == "none" || input_found, comm, PETSC_ERR_USER_INPUT,
             "-input_boundary = %s is not an absorbing boundary; allowed: a boundary with -bc_<name>_type absorbing", input_boundary);

  if (constrain_all[0]) {
    std::vector<PetscInt> components;
    PetscCall(parseComponents(comm, "-constrain_components", constrain_all, dim, &components));
    PetscInt     n;
    PetscScalar *c;
    PetscCall(VecGetLocalSize(constrained, &n));
    PetscCall(VecGetArray(constrained, &c));
    for (PetscInt i = 0; i < n; i += dim)
      for (PetscInt comp : components) c[i + comp] += 1;
    PetscCall(VecRestoreArray(constrained, &c));
  }

  PetscCall(DMLocalToGlobal(dm, force_local, ADD_VALUES, bc->constant_force));
  PetscCall(DMLocalToGlobal(dm, input_local, ADD_VALUES, bc->input_force));
  PetscCall(DMLocalToGlobal(bc->block_dm, block_local, ADD_VALUES, bc->absorbing_blocks));
  PetscCall(DMRestoreLocalVector(dm, &force_local));
  PetscCall(DMRestoreLocalVector(dm, &input_local));
  PetscCall(DMRestoreLocalVector(bc->block_dm, &block_local));

  if (bc->gravity > 0) {
    PetscInt           n;
    PetscScalar       *f;
    const PetscScalar *m;
    PetscCall(VecGetLocalSize(mass, &n));
    PetscCall(VecGetArray(bc->constant_force, &f));
    PetscCall(VecGetArrayRead(mass, &m));
    for (PetscInt i = 0; i < n; ++i) f[i] += bc->gravity * bc->gravity_direction[i % dim] * m[i];
    PetscCall(VecRestoreArrayRead(mass, &m));
    PetscCall(VecRestoreArray(bc->constant_force, &f));
  }

  // free_mask = 1 where nothing holds the dof.
  {
    PetscInt           n;
    PetscScalar       *mask;
    const PetscScalar *c;
    PetscCall(VecGetLocalSize(constrained, &n));
    PetscCall(VecGetArray(bc->free_mask, &mask));
    PetscCall(VecGetArrayRead(constrained, &c));
    for (PetscInt i = 0; i < n; ++i) mask[i] = PetscRealPart(c[i]) > 0 ? 0.0 : 1.0;
    PetscCall(VecRestoreArrayRead(constrained, &c));
    PetscCall(VecRestoreArray(bc->free_mask, &mask));
  }
  PetscCall(VecDestroy(&constrained));
  PetscFunctionReturn(0);
}

PetscErrorCode BoundaryConditionsDestroy(BoundaryConditions *bc) {
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&bc->absorbing_blocks));
  PetscCall(VecDestroy(&bc->constant_force));
  PetscCall(VecDestroy(&bc->input_force));
  PetscCall(VecDestroy(&bc->free_mask));
  for (PrescribedVelocity &p : bc->prescribed) PetscCall(VecDestroy(&p.dofs));
  bc->prescribed.clear();
  PetscCall(DMDestroy(&bc->block_dm));
  PetscFunctionReturn(0);
}

} // namespace slipwave::model
