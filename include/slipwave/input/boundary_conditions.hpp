// Boundary conditions and loads, read from options and assembled once into global vectors
// in the displacement layout (or, for dashpot blocks, the dim x dim node-block layout):
//   -bc_<boundary>_type free|fixed|absorbing|traction|velocity|freefield|tied
//     (tied: with -bc_<boundary>_tie_with <opposite side>, nodes facing each other move together;
//     (freefield: a lateral side coupled to a 1D free-field column, see input/free_field.hpp;
//      its Lysmer dashpot goes into absorbing_blocks here, the column's force is added by the RHS)
//   -bc_<boundary>_components x,y[,z]   (fixed, velocity)
//   -bc_<boundary>_type_x|_y|_z free|fixed|velocity: one component's own condition on the
//     same boundary (overrides -bc_<boundary>_type, which must then be free, fixed or
//     velocity, for that component; not with -bc_<boundary>_components): "x driven, y held"
//   -bc_<boundary>_traction tx,ty[,tz]  (traction) [Pa]
//   -bc_<boundary>_stf ... (velocity: its history; traction: the traction's factor history,
//     none = constant; see TimeFunction)
//   -input_wave none|sv|p -input_boundary <absorbing boundary> -input_stf ...  (incident plane wave)
//   -gravity g [m/s^2] along -gravity_direction (default down the last axis);
//   -constrain_components y (every node)
#pragma once
#include <petscdmplex.h>

#include <string>
#include <vector>

#include "slipwave/input/time_function.hpp"
#include "slipwave/input/timed_load.hpp"
#include "slipwave/medium/materials.hpp"

namespace slipwave::input {

enum class BoundaryType { Free, Fixed, Absorbing, Traction, Velocity, FreeField, Tied };
enum class InputWave { None, SV, P }; // -input_wave none|sv|p

struct PrescribedVelocity {
  std::string  boundary;
  Vec          dofs = nullptr; // 1 on the prescribed dofs, 0 elsewhere
  TimeFunction history;
};

struct BoundaryConditions {
  std::vector<std::string>  names;
  std::vector<BoundaryType> types;
  Vec                       absorbing_blocks = nullptr; // Lysmer-Kuhlemeyer C per node (not divided by mass), dim x dim per owned node in the displacement's node order
  Vec                       constant_force = nullptr;   // gravity + constant tractions and loads [N]
  std::vector<TimedLoad>    timed_loads;                // loads with a history (dynamic stage only)
  std::vector<std::string>  load_notes;                 // for the run report: the loads and per-component sides
  Vec                       input_force = nullptr;      // incident-wave force per unit incident velocity [N s/m]
  Vec                       free_mask = nullptr;        // 1 free dof, 0 prescribed
  std::vector<PrescribedVelocity> prescribed;
  TimeFunction              input;
  InputWave                 input_wave = InputWave::None;
  std::string               input_boundary;
  PetscInt                  input_component = 0;
  PetscReal                 gravity = 0;
  double                    gravity_direction[3] = {0, 0, 0}; // unit vector
  std::vector<std::pair<std::string, std::string>> tied_pairs; // opposite sides moving together
  bool                      has_absorbing = false;    // any dashpot (absorbing or freefield)
  bool                      has_free_field = false;
  std::vector<std::string>  warnings; // for the run report: sides that hold back the incident wave
};

PetscErrorCode BoundaryConditionsCreate(DM dm, const std::vector<std::string> &boundaries, const std::vector<medium::RegionMaterialInfo> &materials, Vec mass,
                                        BoundaryConditions *bc);
PetscErrorCode BoundaryConditionsDestroy(BoundaryConditions *bc);

const char *boundaryTypeName(BoundaryType t);
const char *inputWaveName(InputWave w);

} // namespace slipwave::input
