#include "slipwave/core/option_rules.hpp"

#include <fnmatch.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

namespace slipwave::core {

const char *const kSafeFileNameRule = "names of letters, digits, '_', '.' and '-', not starting with '.' and without '..'";

namespace {

enum class Kind {
  Real,       // every entry a finite number in the range
  RealOrAuto, // like Real, or the word auto
  RealOrNone, // like Real, or the word none
  RealOrGeostatic, // like Real, or the word geostatic
  Int,        // every entry an integer in the range
  Names,      // every entry a safe file name (IsSafeFileName)
  File,       // a readable regular file (a directory, a device or an empty file is refused)
  FileIfThere, // like File, but a missing file is left to the reader, whose message says more
  Choice      // one of the words in `allowed` before its first " ("
};

struct Range {
  double lo, hi;
  bool   lo_open, hi_open;
};
constexpr Range kAny{-HUGE_VAL, HUGE_VAL, false, false};
constexpr Range closed(double lo, double hi) { return {lo, hi, false, false}; }
constexpr Range aboveZero(double hi) { return {0, hi, true, false}; }
constexpr Range magnitude(double m) { return {-m, m, false, false}; }

// One rule per option name (fnmatch pattern; `*` is the region, interface or boundary name).
// Where a module checks the sign or a relation itself (vp >= sqrt(2) vs, f_min < f_max, ...),
// the rule holds only the magnitude beyond which the value is absurd in any scene, and the
// module's message stays the one a user sees for a merely wrong value.
struct Rule {
  const char *pattern;
  Kind        kind;
  int         min_entries, max_entries;
  Range       range;
  const char *allowed;
  int         entries_per_dimension = 0; // > 0: exactly this many per space dimension, checked once it is known
};

// clang-format off
const Rule kRules[] = {
  // run control
  {"-ts_type",                 Kind::Choice, 1, 1, kAny, "cd (central difference, the only time stepper of slipwave)"},
  {"-ts_cd_order",             Kind::Choice, 1, 1, kAny, "2, 4 (central difference; the fourth-order modified-equation scheme)"},
  {"-ts_dt",                   Kind::Real, 1, 1, aboveZero(1e3), "0 < dt <= 1e3 s (and at most the stable limit the setup report prints)"},
  {"-ts_max_time",             Kind::Real, 1, 1, aboveZero(1e12), "0 < t <= 1e12 s (a large value lets -ts_max_steps end the run)"},
  {"-ts_max_steps",            Kind::Int,  1, 1, closed(0, 1e9), "0 to 1e9 steps"},
  {"-time_step_safety",        Kind::Real, 1, 1, aboveZero(1), "0 < s <= 1"},
  {"-output_interval",         Kind::Real, 1, 1, aboveZero(1e7), "0 < interval <= 1e7 s"},
  {"-progress_interval",       Kind::Real, 1, 1, closed(0, 1e7), "0 <= interval <= 1e7 s (0: every step)"},
  {"-energy_growth_limit",     Kind::Real, 1, 1, aboveZero(1e6), "0 < limit <= 1e6 (a multiple of the energy put in)"},
  {"-checkpoint_interval",     Kind::Int,  1, 1, closed(0, 1e9), "0 to 1e9 steps (0: never)"},
  {"-energy_interval",         Kind::Int,  1, 1, closed(1, 1e9), "1 to 1e9 steps"},
  {"-restart",                 Kind::File, 1, 1, kAny, "a checkpoint file written by -checkpoint_interval"},
  {"-initial_velocity",        Kind::Real, 2, 3, magnitude(1e4), "vx,vy[,vz] with |v| <= 1e4 m/s", 1},
  {"-initial_velocity_*",      Kind::Real, 2, 3, magnitude(1e4), "vx,vy[,vz] with |v| <= 1e4 m/s", 1},
  // mesh
  {"-mesh_file",               Kind::File, 1, 1, kAny, "a readable Gmsh .msh file"},
  {"-mesh_build",              Kind::Choice, 1, 1, kAny, "auto, serial, distributed (how a box mesh or a refined -mesh_file is built)"},
  {"-mesh_refine",             Kind::Int,  1, 1, closed(0, 6), "0 to 6 (uniform refinements of the -mesh_file mesh)"},
  {"-mesh_dim",                Kind::Int,  1, 1, closed(2, 3), "2 or 3"},
  {"-element_degree",          Kind::Int,  1, 1, closed(1, 8), "1 to 8 (spectral elements; p > 1 on quadrilaterals and hexahedra only)"},
  {"-mesh_box_faces",          Kind::Int,  2, 3, closed(1, 1e8), "nx,ny[,nz] cells, each 1 to 1e8", 1},
  {"-mesh_box_lower",          Kind::Real, 2, 3, magnitude(1e8), "x,y[,z] with |x| <= 1e8 m", 1},
  {"-mesh_box_upper",          Kind::Real, 2, 3, magnitude(1e8), "x,y[,z] with |x| <= 1e8 m", 1},
  {"-mesh_quality_max_aspect", Kind::Real, 1, 1, closed(1, 1e6), "1 <= aspect <= 1e6"},
  {"-mesh_quality_min_jacobian_ratio", Kind::Real, 1, 1, {0, 1, true, false}, "0 < ratio <= 1"},
  {"-regions",                 Kind::Names, 1, 64, kAny, kSafeFileNameRule},
  {"-void_regions",            Kind::Names, 1, 64, kAny, kSafeFileNameRule},
  {"-interfaces",              Kind::Names, 1, 64, kAny, kSafeFileNameRule},
  {"-interface_*_regions",     Kind::Names, 2, 2, kAny, "two region names soil,structure"},
  {"-region_*_box",            Kind::Real, 1, 6, magnitude(1e8), "xmin,xmax,ymin,ymax[,zmin,zmax] with |x| <= 1e8 m (the mesh dimension sets the count)", 2},
  {"-petscpartitioner_metis_ufactor", Kind::Int, 1, 1, closed(-1, 1e6), "-1 (METIS' default) to 1e6 (1/1000)"},
  {"-petscpartitioner_metis_seed",    Kind::Int, 1, 1, closed(-1, 2147483647), "-1 (METIS' default) or a seed >= 0"},
  // materials and damping
  {"-material_*_rho",          Kind::Real, 1, 1, magnitude(1e5), "0 < rho <= 1e5 kg/m^3"},
  {"-material_*_vp",           Kind::Real, 1, 1, magnitude(1e5), "0 < vp <= 1e5 m/s"},
  {"-material_*_vs",           Kind::Real, 1, 1, magnitude(1e5), "0 < vs <= 1e5 m/s"},
  {"-material_*_E",            Kind::Real, 1, 1, magnitude(1e13), "0 < E <= 1e13 Pa"},
  {"-material_*_nu",           Kind::Real, 1, 1, closed(-1, 0.5), "0 <= nu < 0.5"},
  {"-material_*_damping_ratio", Kind::Real, 1, 1, {0, 0.5, false, true}, "0 <= xi < 0.5 (0: elastic)"},
  {"-material_*_reference_frequency", Kind::Real, 1, 1, magnitude(1e6), "0 < f <= 1e6 Hz"},
  {"-material_*_mean_effective_stress", Kind::RealOrGeostatic, 1, 1, aboveZero(1e12), "sigma'_0 > 0 [Pa] or geostatic"},
  {"-damping_ratio",           Kind::Real, 1, 1, magnitude(1e3), "0 <= xi < 1"},
  {"-damping_frequencies",     Kind::Real, 2, 2, magnitude(1e6), "two frequencies f1,f2 [Hz], 0 < f1 < f2 <= 1e6"},
  {"-attenuation_band",        Kind::Real, 2, 2, magnitude(1e6), "two frequencies f_min,f_max [Hz]"},
  {"-attenuation_mechanisms",  Kind::Int,  1, 1, closed(1, 8), "1 to 8"},
  {"-attenuation_reference_frequency", Kind::Real, 1, 1, magnitude(1e6), "0 < f <= 1e6 Hz"},
  // loads and input motion
  {"-gravity",                 Kind::Real, 1, 1, closed(0, 1e3), "0 <= g <= 1e3 m/s^2"},
  {"-gravity_direction",       Kind::Real, 2, 3, magnitude(1e6), "gx,gy[,gz], not all 0, |g| <= 1e6", 1},
  {"-bc_*_traction",           Kind::Real, 2, 3, magnitude(1e12), "tx,ty[,tz] with |t| <= 1e12 Pa", 1},
  {"-input_amplitude",         Kind::Real, 1, 1, magnitude(1e3), "|v| <= 1e3 m/s"},
  {"-input_record",            Kind::FileIfThere, 1, 1, kAny, "a readable .csv or .at2 file"},
  {"-drm_amplitude",           Kind::Real, 1, 1, magnitude(1e3), "|v| <= 1e3 m/s"},
  // every history (input/time_function: -input_, -drm_, -bc_<b>_, -point_force_<n>_,
  // -body_force_, -structure_load_): only they have options with these endings
  {"-*_amplitude",             Kind::Real, 1, 1, magnitude(1e6), "|amplitude| <= 1e6 (m/s for a boundary velocity, a factor on a load)"},
  {"-*_f0",                    Kind::Real, 1, 1, aboveZero(1e4), "0 < f0 <= 1e4 Hz"},
  {"-*_t0",                    Kind::Real, 1, 1, magnitude(1e7), "|t0| <= 1e7 s"},
  {"-*_gamma",                 Kind::Real, 1, 1, aboveZero(1e3), "0 < gamma <= 1e3 periods"},
  {"-*_phase",                 Kind::Real, 1, 1, magnitude(1e3), "|phase| <= 1e3 rad"},
  {"-*_record",                Kind::FileIfThere, 1, 1, kAny, "a readable .csv (or, for a velocity, .at2) file"},
  {"-*_record_scale",          Kind::Real, 1, 1, magnitude(1e6), "a factor other than 0 with |factor| <= 1e6"},
  {"-*_record_pga",            Kind::Real, 1, 1, magnitude(10), "0 < pga <= 10 g"},
  // DRM (input/drm checks the angle, the offset and the exact count of -drm_box)
  {"-drm_azimuth",             Kind::Real, 1, 1, magnitude(360), "-360 <= azimuth <= 360 deg"},
  {"-drm_box",                 Kind::Real, 1, 5, magnitude(1e8), "xmin,xmax,ymin (2D) or xmin,xmax,ymin,ymax,zmin (3D) with |x| <= 1e8 m"},
  {"-drm_offset",              Kind::Int,  1, 1, magnitude(1e6), "1 to 1e6 cells"},
  {"-drm_regions",             Kind::Names, 1, 64, kAny, kSafeFileNameRule},
  {"-drm_free_field_file",     Kind::FileIfThere, 1, 1, kAny, "a readable HDF5 free-field file (docs/drm.md)"},
  // point forces, body force, structure load (the modules check the count against the dimension)
  {"-point_forces",            Kind::Names, 1, 64, kAny, "at most 64 names of letters, digits, '_', '.' and '-', not starting with '.' and without '..'"},
  {"-point_force_*_location",  Kind::Real, 1, 3, magnitude(1e8), "x,y[,z] with |x| <= 1e8 m"},
  {"-point_force_*_force",     Kind::Real, 1, 3, magnitude(1e15), "fx,fy[,fz] with |f| <= 1e15 N (N/m in 2D)"},
  {"-body_force",              Kind::Real, 1, 3, magnitude(1e4), "bx,by[,bz] with |b| <= 1e4 m/s^2"},
  {"-structure_load_region",   Kind::Names, 1, 1, kAny, "one region name"},
  {"-structure_load_force",    Kind::Real, 1, 3, magnitude(1e15), "fx,fy[,fz] with |f| <= 1e15 N (N/m in 2D)"},
  {"-structure_load_moment",   Kind::Real, 1, 3, magnitude(1e18), "m (2D) or mx,my,mz (3D) with |m| <= 1e18 N m (N m/m in 2D)"},
  {"-bc_*_tie_with",           Kind::Names, 1, 1, kAny, "one boundary name"},
  // interfaces
  {"-interface_*_E",           Kind::RealOrAuto, 1, 1, magnitude(1e16), "auto or 0 < E <= 1e16 Pa/m"},
  {"-interface_*_G",           Kind::RealOrAuto, 1, 1, magnitude(1e16), "auto or 0 < G <= 1e16 Pa/m"},
  {"-interface_*_phi",         Kind::Real, 1, 1, magnitude(360), "0 <= phi < 90 deg"},
  {"-interface_*_psi",         Kind::Real, 1, 1, magnitude(360), "0 <= psi <= phi deg"},
  {"-interface_*_c",           Kind::Real, 1, 1, magnitude(1e12), "0 <= c <= 1e12 Pa"},
  {"-interface_*_e_ini",       Kind::Real, 1, 1, magnitude(1e3), "0 <= e_ini <= 1e3 m"},
  {"-interface_*_tensile_strength", Kind::Real, 1, 1, magnitude(1e12), "0 <= tensile_strength <= c/tan(phi), at most 1e12 Pa"},
  {"-interface_*_sigma_N0",    Kind::Real, 1, 1, magnitude(1e12), "|sigma_N0| <= 1e12 Pa (compression < 0)"},
  {"-interface_*_penalty_rule", Kind::Choice, 1, 1, kAny, "physical, mesh (how E, G = auto are set: from penalty_length [m], or from the cell size)"},
  {"-interface_*_penalty_length", Kind::Real, 1, 1, aboveZero(1e6), "0 < L <= 1e6 m"},
  {"-interface_*_penalty_factor", Kind::Real, 1, 1, aboveZero(1e6), "0 < factor <= 1e6"},
  {"-interface_*_contact_damping", Kind::Real, 1, 1, magnitude(1e3), "0 <= ratio <= 1 (fraction of critical)"},
  {"-interface_*_friction_slip_length", Kind::Real, 1, 1, closed(0, 1), "0 <= L <= 1 m (0: no lag)"},
  {"-interface_*_friction_reference_velocity", Kind::Real, 1, 1, closed(0, 1e3), "0 <= V* <= 1e3 m/s"},
  // saturated regions (physics/biot checks the signs and the relations; these bound the magnitudes)
  {"-material_*_porosity",     Kind::Real, 1, 1, magnitude(10), "0 < n < 1"},
  {"-material_*_hydraulic_conductivity", Kind::Real, 1, 1, magnitude(10), "0 <= k <= 10 m/s"},
  {"-material_*_fluid_bulk_modulus", Kind::Real, 1, 1, magnitude(1e12), "0 < K_f <= 1e12 Pa"},
  {"-material_*_grain_bulk_modulus", Kind::Real, 1, 1, magnitude(1e13), "0 (incompressible grains) or K_drained < K_s <= 1e13 Pa"},
  {"-material_*_fluid_density", Kind::Real, 1, 1, magnitude(1e5), "0 < rho_f <= 1e5 kg/m^3"},
  {"-bc_*_fluid_flux",         Kind::Real, 1, 1, magnitude(10), "|q| <= 10 m/s"},
  {"-water_table",             Kind::Real, 1, 1, magnitude(1e8), "|elevation| <= 1e8 m"},
  {"-fluid_cavitation_pressure", Kind::RealOrNone, 1, 1, closed(-1e9, 0), "-1e9 <= limit <= 0 Pa (gauge) or none"},
  // stations (-station_coordinates fills a fixed array: more values would be cut silently)
  {"-station_file",            Kind::File, 1, 1, kAny, "a readable CSV file with rows name,x,y[,z]"},
  {"-station_coordinates",     Kind::Real, 2, 300, magnitude(1e8), "x1,y1[,z1],... [m], |x| <= 1e8, at most 300 values (150 stations in 2D, 100 in 3D; more with -station_file)"},
  {"-station_names",           Kind::Names, 1, 100, kAny, "at most 100 names of letters, digits, '_', '.' and '-', not starting with '.' and without '..'"},
  // geostatic stage
  {"-geostatic_tolerance",     Kind::Real, 1, 1, {0, 1, true, true}, "0 < tol < 1"},
  {"-geostatic_max_steps",     Kind::Int,  1, 1, closed(1, 1e9), "1 to 1e9 steps"},
};
// clang-format on

const char *kindName(Kind k) {
  switch (k) {
  case Kind::Real: return "number";
  case Kind::RealOrAuto: return "number|auto";
  case Kind::RealOrNone: return "number|none";
  case Kind::RealOrGeostatic: return "number|geostatic";
  case Kind::Int: return "integer";
  case Kind::Names: return "name";
  case Kind::File:
  case Kind::FileIfThere: return "file";
  case Kind::Choice: return "choice";
  }
  return "";
}

const Rule *findRule(const std::string &option) {
  for (const Rule &r : kRules)
    if (fnmatch(r.pattern, option.c_str(), 0) == 0) return &r;
  return nullptr;
}

std::vector<std::string> entries(const std::string &value) {
  std::vector<std::string> out;
  std::istringstream       in(value);
  for (std::string e; std::getline(in, e, ',');) out.push_back(e);
  if (!value.empty() && value.back() == ',') out.push_back("");
  return out;
}

// The whole text is one number (strtod's syntax, which includes inf and nan).
bool fullNumber(const std::string &text, double *x) {
  if (text.empty()) return false;
  char *end = nullptr;
  errno     = 0;
  *x        = std::strtod(text.c_str(), &end);
  if (*end != '\0') return false;
  if (errno == ERANGE && std::fabs(*x) > 1) *x = HUGE_VAL; // 1e400 reads as inf
  return true;
}

bool inRange(double x, const Range &r) {
  if (!std::isfinite(x)) return false;
  return (r.lo_open ? x > r.lo : x >= r.lo) && (r.hi_open ? x < r.hi : x <= r.hi);
}

bool numberAllowed(const Rule &rule, const std::string &entry) {
  if (rule.kind == Kind::RealOrAuto && entry == "auto") return true;
  if (rule.kind == Kind::RealOrNone && entry == "none") return true;
  if (rule.kind == Kind::RealOrGeostatic && entry == "geostatic") return true;
  double x = 0;
  // A word PETSc's parser took (checkOne: its named constants) or a fraction for an integer:
  // its parser's to judge where the option is read. Another word where a keyword may stand:
  // the rule's message, which names the keyword.
  if (!fullNumber(entry, &x)) return rule.kind == Kind::Real || rule.kind == Kind::Int;
  if (rule.kind == Kind::Int && std::isfinite(x) && x != std::floor(x)) return true;
  return inRange(x, rule.range);
}

std::string fileProblem(const std::string &path, bool missing_ok) {
  struct stat st;
  if (stat(path.c_str(), &st) != 0) return errno == ENOENT && missing_ok ? "" : "cannot open the file";
  if (S_ISDIR(st.st_mode)) return "is a directory";
  if (!S_ISREG(st.st_mode)) return "is not a regular file";
  if (access(path.c_str(), R_OK) != 0) return "cannot read the file (permission denied)";
  if (st.st_size == 0) return "is empty";
  return "";
}

bool choiceAllowed(const Rule &rule, const std::string &value) {
  std::string words = rule.allowed;
  words             = words.substr(0, words.find(" ("));
  std::istringstream in(words);
  for (std::string w; std::getline(in, w, ',');) {
    while (!w.empty() && w[0] == ' ') w.erase(0, 1);
    if (w == value) return true;
  }
  return false;
}

PetscErrorCode checkOne(MPI_Comm comm, const std::string &option, const char *value_or_null) {
  PetscFunctionBeginUser;
  const std::string value = value_or_null ? value_or_null : "";
  const Rule       *rule  = findRule(option);
  if (!rule) {
    // Unknown here (PETSc's own options, choices, files): only non-finite numbers are absurd
    // everywhere.
    for (const std::string &e : entries(value)) {
      double x = 0;
      PetscCheck(!fullNumber(e, &x) || std::isfinite(x), comm, PETSC_ERR_USER_INPUT, "%s = %s; allowed: finite numbers", option.c_str(), value.c_str());
    }
    PetscFunctionReturn(0);
  }
  if (!value_or_null) PetscFunctionReturn(0); // a missing value: PETSc's reader reports it
  const std::vector<std::string> parts = entries(value);
  const int                      n     = (int)parts.size();
  switch (rule->kind) {
  case Kind::Real:
  case Kind::RealOrAuto:
  case Kind::RealOrNone:
  case Kind::RealOrGeostatic:
  case Kind::Int:
  case Kind::Names:
    PetscCheck(n >= rule->min_entries && n <= rule->max_entries, comm, PETSC_ERR_USER_INPUT, "%s has %d values; allowed: %s", option.c_str(), n, rule->allowed);
    for (const std::string &e : parts) {
      // A word for a plain number: PETSc's own parser now, before anything is written (it
      // takes its named constants, DEFAULT, DECIDE, ...; its message for any other word gets
      // the option's name). A number-or-keyword rule names its keyword below instead.
      double x = 0;
      if ((rule->kind == Kind::Real || rule->kind == Kind::Int) && !fullNumber(e, &x)) {
        PetscReal real;
        PetscInt  integer;
        if (rule->kind == Kind::Int) PetscCall(PetscOptionsStringToInt(e.c_str(), &integer));
        else PetscCall(PetscOptionsStringToReal(e.c_str(), &real));
      }
      const bool bad = rule->kind == Kind::Names ? !IsSafeFileName(e) : !numberAllowed(*rule, e);
      PetscCheck(!bad, comm, PETSC_ERR_USER_INPUT, "%s = %s; allowed: %s", option.c_str(), value.c_str(), rule->allowed);
    }
    // Names become file and dataset names: two stations called alike would meet in one file.
    for (int a = 0; rule->kind == Kind::Names && a < n; ++a)
      for (int b = a + 1; b < n; ++b)
        PetscCheck(parts[a] != parts[b], comm, PETSC_ERR_USER_INPUT, "%s = %s: '%s' is listed twice; allowed: distinct names", option.c_str(), value.c_str(), parts[a].c_str());
    break;
  case Kind::File:
  case Kind::FileIfThere: {
    const std::string problem = fileProblem(value, rule->kind == Kind::FileIfThere);
    PetscCheck(problem.empty(), comm, PETSC_ERR_FILE_OPEN, "%s = %s: %s; allowed: %s", option.c_str(), value.c_str(), problem.c_str(), rule->allowed);
    break;
  }
  case Kind::Choice:
    PetscCheck(choiceAllowed(*rule, value), comm, PETSC_ERR_USER_INPUT, "%s = %s; allowed: %s", option.c_str(), value.c_str(), rule->allowed);
    break;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode checkCountForDimension(MPI_Comm comm, const std::string &option, const char *value, PetscInt dim) {
  PetscFunctionBeginUser;
  const Rule *rule = findRule(option);
  if (!rule || rule->entries_per_dimension == 0 || !value) PetscFunctionReturn(0);
  const int n = (int)entries(value).size(), want = rule->entries_per_dimension * (int)dim;
  PetscCheck(n == want, comm, PETSC_ERR_USER_INPUT, "%s has %d values; allowed: %d in %" PetscInt_FMT "D (%s)", option.c_str(), n, want, dim, rule->allowed);
  PetscFunctionReturn(0);
}

} // namespace

std::vector<std::string> OptionRulePatterns() {
  std::vector<std::string> out;
  for (const Rule &r : kRules) out.push_back(r.pattern);
  return out;
}

bool IsSafeFileName(const std::string &name) {
  if (name.empty() || name[0] == '.' || name.find("..") != std::string::npos) return false;
  for (char ch : name)
    if (!(std::isalnum((unsigned char)ch) || ch == '_' || ch == '.' || ch == '-')) return false;
  return true;
}

namespace {

bool endsWith(const std::string &s, const char *tail) {
  const std::string t(tail);
  return s.size() >= t.size() && s.compare(s.size() - t.size(), t.size(), t) == 0;
}

// An interface's penalty options that its rule does not read: -interface_<n>_penalty_length
// belongs to the rule physical (the default), _penalty_factor to mesh. Checked here, with the
// values, so the mistake stops before the mesh is built. given: option (with "-") -> value.
PetscErrorCode checkPenaltyRules(MPI_Comm comm, const std::map<std::string, std::string> &given) {
  PetscFunctionBeginUser;
  for (const auto &[option, value] : given) {
    const bool length = endsWith(option, "_penalty_length"), factor = endsWith(option, "_penalty_factor");
    if (option.rfind("-interface_", 0) != 0 || !(length || factor)) continue;
    const std::string pre  = option.substr(1, option.size() - 1 - std::string("penalty_length").size()); // "interface_<n>_" (both tails 14 long)
    const auto        rule = given.find("-" + pre + "penalty_rule");
    PetscBool         mesh = PETSC_FALSE; // matched as the choice itself is (case-insensitive)
    if (rule != given.end()) PetscCall(PetscStrcasecmp(rule->second.c_str(), "mesh", &mesh));
    PetscCheck(!(length && mesh), comm, PETSC_ERR_USER_INPUT,
               "-%spenalty_length = %s with -%spenalty_rule mesh; allowed: penalty_length with penalty_rule physical only (mesh uses penalty_factor)", pre.c_str(),
               value.c_str(), pre.c_str());
    PetscCheck(!(factor && !mesh), comm, PETSC_ERR_USER_INPUT,
               "-%spenalty_factor = %s with -%spenalty_rule physical%s; allowed: penalty_factor with penalty_rule mesh only (physical uses penalty_length [m])",
               pre.c_str(), value.c_str(), pre.c_str(), rule == given.end() ? " (the default)" : "");
  }
  PetscFunctionReturn(0);
}

// -material_<r>_mean_effective_stress geostatic takes each element's sigma'_0 from the
// geostatic stage: the stage must run, under gravity. Checked here, before the mesh is built.
PetscErrorCode checkGeostaticStress(MPI_Comm comm, const std::map<std::string, std::string> &given) {
  PetscFunctionBeginUser;
  for (const auto &[option, value] : given) {
    PetscBool geostatic = PETSC_FALSE;
    if (option.rfind("-material_", 0) != 0 || !endsWith(option, "_mean_effective_stress")) continue;
    PetscCall(PetscStrcasecmp(value.c_str(), "geostatic", &geostatic));
    if (!geostatic) continue;
    // A cap would scale with the point's strains (s tau_max): no strength does that (an undrained
    // strength grows with sigma'_v, not as sigma'_0^0.35; medium/hysteresis.hpp).
    const std::string strength = option.substr(0, option.size() - std::string("mean_effective_stress").size()) + "strength";
    PetscCheck(given.find(strength) == given.end(), comm, PETSC_ERR_USER_INPUT,
               "%s with %s geostatic; allowed: one of them (the strains of a point are scaled by its sigma'_0, which would scale the cap too)", strength.c_str(),
               option.c_str());
    const auto stage = given.find("-geostatic_stage"), gravity = given.find("-gravity");
    PetscBool  on    = PETSC_FALSE;
    if (stage != given.end()) PetscCall(PetscOptionsStringToBool(stage->second.empty() ? "true" : stage->second.c_str(), &on));
    PetscCheck(on, comm, PETSC_ERR_USER_INPUT, "%s = geostatic without the geostatic stage; allowed: with -geostatic_stage true (and -gravity > 0), or sigma'_0 > 0 [Pa]",
               option.c_str());
    PetscCheck(gravity != given.end() && std::strtod(gravity->second.c_str(), nullptr) > 0, comm, PETSC_ERR_USER_INPUT,
               "%s = geostatic without gravity; allowed: with -gravity > 0 [m/s^2] (the stage's stresses come from the weight), or sigma'_0 > 0 [Pa]", option.c_str());
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode OptionsValidate(MPI_Comm comm) {
  PetscInt n = 0;
  char   **names = nullptr, **values = nullptr;
  PetscFunctionBeginUser;
  // Before any module has read its options, every option given is still "left".
  PetscCall(PetscOptionsLeftGet(nullptr, &n, &names, &values));
  PetscErrorCode ierr = 0;
  std::map<std::string, std::string> given;
  for (PetscInt i = 0; i < n && !ierr; ++i) {
    ierr = checkOne(comm, std::string("-") + names[i], values[i]);
    given[std::string("-") + names[i]] = values[i] ? values[i] : "";
  }
  PetscCall(PetscOptionsLeftRestore(nullptr, &n, &names, &values));
  PetscCall(ierr);
  PetscCall(checkPenaltyRules(comm, given));
  PetscCall(checkGeostaticStress(comm, given));
  PetscFunctionReturn(0);
}

PetscErrorCode OptionsValidateForDimension(MPI_Comm comm, PetscInt dim, bool box_mesh) {
  PetscFunctionBeginUser;
  // All options given, read or not: PetscOptionsGetAll has them with their values.
  char *all = nullptr;
  PetscCall(PetscOptionsGetAll(nullptr, &all));
  std::istringstream tokens(all ? all : "");
  std::vector<std::pair<std::string, std::string>> given;
  for (std::string t; tokens >> t;) {
    if (t.size() > 1 && t[0] == '-' && std::isalpha((unsigned char)t[1])) given.push_back({t, ""});
    else if (!given.empty()) given.back().second = t;
  }
  PetscCall(PetscFree(all));
  for (const auto &[option, value] : given) {
    // With a mesh file the box options are not read; the check for unused options names them.
    if (!box_mesh && option.rfind("-mesh_box_", 0) == 0) continue;
    PetscCall(checkCountForDimension(comm, option, value.empty() ? nullptr : value.c_str(), dim));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode OptionsPrintRules(MPI_Comm comm) {
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm, "Allowed values (checked before the run starts; src/core/option_rules.cpp):\n"));
  for (const Rule &r : kRules) {
    const std::string count = r.min_entries == r.max_entries ? std::to_string(r.min_entries) : std::to_string(r.min_entries) + "-" + std::to_string(r.max_entries);
    PetscCall(PetscPrintf(comm, "  %-36s %-12s x%-6s %s\n", r.pattern, kindName(r.kind), count.c_str(), r.allowed));
  }
  PetscFunctionReturn(0);
}

} // namespace slipwave::core
