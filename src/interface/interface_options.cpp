#include "slipwave/interface/interface_options.hpp"

#include "slipwave/core/option_choice.hpp"
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

  PetscBool length_set = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, pre, "Interface law options", "slipwave");
  PetscCall(readStiffness(PetscOptionsObject, comm, pre, "E", "Normal penalty stiffness [Pa/m], or auto ((lambda+2mu) of the softer side over penalty_length, or over h with penalty_rule mesh)",
                          &o.params.E, &o.E_auto));
  PetscCall(readStiffness(PetscOptionsObject, comm, pre, "G",
                          "Tangential penalty stiffness [Pa/m], or auto (mu of the softer side over penalty_length, or over h with penalty_rule mesh)", &o.params.G, &o.G_auto));
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
    static const char *const kRules[] = {"physical", "mesh"};
    PetscInt                 rule     = (PetscInt)o.penalty_rule;
    PetscCall(core::OptionsChoice(PetscOptionsObject, "-penalty_rule",
                                  "how E, G given as auto are set: physical (default; E = (lambda+2mu)/L, G = mu/L of the softer side, L = penalty_length: "
                                  "the same on any mesh) or mesh (penalty_factor x (lambda+2mu)/h and x mu/h, h the cell size: changes with the mesh)",
                                  kRules, 2, &rule, nullptr));
    o.penalty_rule = (PenaltyRule)rule;
    PetscCall(PetscOptionsReal("-penalty_length",
                               "penalty_rule physical: the interface is as compliant as a layer of the softer side this thick [m], > 0; "
                               "default the interface's width / 200 (2D: its length, 3D: sqrt of its area)",
                               "InterfaceOptionsRead", o.penalty_length, &o.penalty_length, &length_set));
    PetscCall(PetscOptionsReal("-penalty_factor", "penalty_rule mesh: E, G given as auto are factor x (lambda+2mu)/h and factor x mu/h of the softer side (h: the cell size; at -element_degree p, 3 h_e/(p^2+p+1)) [-], > 0", "InterfaceOptionsRead",
                               o.penalty_factor, &o.penalty_factor, nullptr));
    PetscCall(PetscOptionsReal("-contact_damping",
                               "normal dashpot of closed pairs, fraction of the critical damping of the pair's penalty spring between its two nodal masses [-], 0..1",
                               "InterfaceOptionsRead", o.contact_damping, &o.contact_damping, nullptr));
    PetscCall(PetscOptionsReal("-friction_slip_length",
                               "slip over which the friction takes up a change of the effective normal traction (Prakash-Clifton lag, physics/friction_lag.hpp) [m], "
                               "0 <= L <= 1; 0: at once",
                               "InterfaceOptionsRead", o.friction_lag.slip_length, &o.friction_lag.slip_length, nullptr));
    PetscCall(PetscOptionsReal("-friction_reference_velocity",
                               "reference velocity V* of that lag [m/s], 0 <= V* <= 1e3: a sticking pair follows the normal traction over friction_slip_length / V*",
                               "InterfaceOptionsRead", o.friction_lag.reference_velocity, &o.friction_lag.reference_velocity, nullptr));
  }
  PetscOptionsEnd();

  o.params.phi = phi_deg * kRadPerDeg;
  o.params.psi = psi_deg * kRadPerDeg;
  o.params.c = c;
  o.params.e_ini = e_ini;
  o.params.tensile_strength = sigma_t;
  o.sigma_N0 = sigma_N0;
  PetscCall(InterfaceOptionsCheck(comm, pre, o));
  char length_text[32]; // PETSc's %g would print "3."
  std::snprintf(length_text, sizeof length_text, "%g", o.penalty_length);
  PetscCheck(!length_set || (std::isfinite(o.penalty_length) && o.penalty_length > 0), comm, PETSC_ERR_USER_INPUT,
             "-%spenalty_length = %s; allowed: > 0 m (the thickness of softer material the interface is as compliant as)", pre, length_text);
  // A penalty option the rule does not read stops earlier, before the mesh (core/option_rules).
  PetscCheck(o.penalty_factor > 0, comm, PETSC_ERR_USER_INPUT, "-%spenalty_factor = %g; allowed: > 0", pre, o.penalty_factor);
  // The friction lag's ranges are the option rules' (core/option_rules.cpp), checked at start.
  PetscCheck(o.contact_damping >= 0 && o.contact_damping <= 1, comm, PETSC_ERR_USER_INPUT, "-%scontact_damping = %g; allowed: 0 <= ratio <= 1 (fraction of critical)", pre,
             o.contact_damping);
  *options = o;
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAutoPenalty(MPI_Comm comm, const char *prefix, double m_soft, double mu_soft, double h, double width,
                                    InterfaceOptions *options, std::string *note) {
  const char       *pre = prefix ? prefix : kDefaultPrefix;
  InterfaceOptions &o   = *options;
  char              how[256];

  PetscFunctionBeginUser;
  double length = 0; // the layer of softer material the auto penalty stands for [m]
  if (o.penalty_rule == PenaltyRule::Physical) {
    const bool given = o.penalty_length > 0;
    length           = given ? o.penalty_length : width * kDefaultPenaltyLengthFraction;
    PetscCheck(length > 0 && std::isfinite(length), comm, PETSC_ERR_USER_INPUT,
               "-%sE/-%sG = auto: the interface has width %g m, so no default penalty_length; allowed: give -%spenalty_length > 0 [m]", pre, pre, width, pre);
    if (given)
      std::snprintf(how, sizeof how, "penalty rule physical, length %.4g m given (%.3g h)", length, length / h);
    else
      std::snprintf(how, sizeof how, "penalty rule physical, length %.4g m = width %.4g m / %g (%.3g h)", length, width,
                    1.0 / kDefaultPenaltyLengthFraction, length / h);
  } else {
    length = h / o.penalty_factor;
    std::snprintf(how, sizeof how, "penalty rule mesh, factor %g, h = %.3g m", o.penalty_factor, h);
  }
  const double E = o.E_auto ? m_soft / length : o.params.E;
  const double G = o.G_auto ? mu_soft / length : o.params.G;
  char         text[512];
  if (!o.E_auto && !o.G_auto)
    std::snprintf(text, sizeof text, "E = %.4g Pa/m, G = %.4g Pa/m (given; h = %.3g m)", E, G, h);
  else
    std::snprintf(text, sizeof text, "E = %.4g Pa/m%s, G = %.4g Pa/m%s (%s)", E, o.E_auto ? " (auto)" : "", G, o.G_auto ? " (auto)" : "", how);
  *note        = text;
  o.params.E   = E;
  o.params.G   = G;
  o.E_auto     = PETSC_FALSE;
  o.G_auto     = PETSC_FALSE;
  PetscCall(InterfaceOptionsCheck(comm, prefix, o));
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
