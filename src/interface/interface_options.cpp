#include "slipwave/interface/interface_options.hpp"

#include "slipwave/physics/interface_params_check.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace slipwave::interface {
namespace {

constexpr const char *kDefaultPrefix = "interface_";
constexpr double kRadPerDeg = M_PI / 180.0;

// A stiffness option: a number or the word `auto`.
PetscErrorCode readStiffness(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, const char *prefix, const char *name,
                             const char *help, double *value, PetscBool *is_auto) {
  char      text[256] = "auto";
  PetscBool set = PETSC_FALSE;
  char      option[64];

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(option, sizeof option, "-%s", name));
  PetscCall(PetscOptionsString(option, help, "InterfaceOptionsRead", text, text, sizeof text, &set));
  if (std::strcmp(text, "auto") == 0) {
    *is_auto = PETSC_TRUE;
    *value = 0.0;
    PetscFunctionReturn(0);
  }
  char *end = nullptr;
  errno = 0;
  *value = std::strtod(text, &end);
  PetscCheck(end != text && *end == '\0' && errno == 0 && std::isfinite(*value), comm, PETSC_ERR_USER_INPUT,
             "-%s%s = %s is not a number; allowed a stiffness > 0 [Pa/m] or auto", prefix, name, text);
  *is_auto = PETSC_FALSE;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode InterfaceOptionsRead(MPI_Comm comm, const char *prefix, InterfaceUse use, InterfaceOptions *options) {
  const char *pre = prefix ? prefix : kDefaultPrefix;
  InterfaceOptions o;
  PetscReal phi_deg = 30.0, psi_deg = 0.0, c = 0.0, e_ini = 0.0, sigma_t = 0.0, sigma_N0 = 0.0;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, pre, "Interface law options", "slipwave");
  PetscCall(readStiffness(PetscOptionsObject, comm, pre, "E", "Normal penalty stiffness [Pa/m], or auto (derived from the mesh)",
                          &o.params.E, &o.E_auto));
  PetscCall(readStiffness(PetscOptionsObject, comm, pre, "G",
                          "Tangential penalty stiffness [Pa/m], or auto (derived from the mesh)", &o.params.G, &o.G_auto));
  PetscCall(PetscOptionsReal("-phi", "Friction angle [deg], 0 <= phi < 90", "InterfaceOptionsRead", phi_deg, &phi_deg, nullptr));
  PetscCall(PetscOptionsReal("-psi", "Dilatancy angle [deg], 0 <= psi <= phi", "InterfaceOptionsRead", psi_deg, &psi_deg, nullptr));
  PetscCall(PetscOptionsReal("-c", "Cohesion [Pa], >= 0", "InterfaceOptionsRead", c, &c, nullptr));
  PetscCall(PetscOptionsReal("-e_ini", "Interface thickness [m]: opening beyond it loses contact, >= 0", "InterfaceOptionsRead",
                             e_ini, &e_ini, nullptr));
  PetscCall(PetscOptionsReal("-tensile_strength", "Tension cut-off [Pa], 0 <= tensile_strength <= c/tan(phi)",
                             "InterfaceOptionsRead", sigma_t, &sigma_t, nullptr));
  PetscCall(PetscOptionsReal("-sigma_N0", "Initial normal traction [Pa], tension positive (compression < 0)",
                             "InterfaceOptionsRead", sigma_N0, &sigma_N0, nullptr));
  if (use == InterfaceUse::Mesh) {
    PetscCall(PetscOptionsReal("-penalty_factor", "E, G given as auto: factor x (lambda+2mu)/h and factor x mu/h of the softer side (h: the cell size; at -element_degree p, 3 h_e/(p^2+p+1)) [-], > 0", "InterfaceOptionsRead",
                               o.penalty_factor, &o.penalty_factor, nullptr));
    PetscCall(PetscOptionsReal("-contact_damping",
                               "normal dashpot of closed pairs, fraction of the critical damping of the pair's penalty spring between its two nodal masses [-], 0..1",
                               "InterfaceOptionsRead", o.contact_damping, &o.contact_damping, nullptr));
  }
  PetscOptionsEnd();

  o.params.phi = phi_deg * kRadPerDeg;
  o.params.psi = psi_deg * kRadPerDeg;
  o.params.c = c;
  o.params.e_ini = e_ini;
  o.params.tensile_strength = sigma_t;
  o.sigma_N0 = sigma_N0;
  PetscCall(InterfaceOptionsCheck(comm, pre, o));
  PetscCheck(o.penalty_factor > 0, comm, PETSC_ERR_USER_INPUT, "-%spenalty_factor = %g; allowed: > 0", pre, o.penalty_factor);
  PetscCheck(o.contact_damping >= 0 && o.contact_damping <= 1, comm, PETSC_ERR_USER_INPUT, "-%scontact_damping = %g; allowed: 0 <= ratio <= 1 (fraction of critical)", pre,
             o.contact_damping);
  *options = o;
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceOptionsCheck(MPI_Comm comm, const char *prefix, const InterfaceOptions &options) {
  const char *pre = prefix ? prefix : kDefaultPrefix;
  physics::InterfaceParams p = options.params;

  PetscFunctionBeginUser;
  // An `auto` stiffness is not known yet; a placeholder lets the other rules be checked now.
  if (options.E_auto) p.E = 1.0;
  if (options.G_auto) p.G = 1.0;
  auto bad = physics::interfaceParamsCheck(p);
  if (!bad) bad = physics::interfaceInitialStressCheck(p, options.sigma_N0);
  char value[32] = "";
  if (bad) std::snprintf(value, sizeof value, "%g", bad->value); // PETSc's %g would print "40."
  PetscCheck(!bad, comm, PETSC_ERR_USER_INPUT, "-%s%s = %s %s; allowed %s", pre, bad->name, value, bad->unit,
             bad->allowed.c_str());
  PetscFunctionReturn(0);
}

} // namespace slipwave::interface
