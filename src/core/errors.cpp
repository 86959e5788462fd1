#include "slipwave/core/errors.hpp"

#include "slipwave/core/option_files.hpp"

#include <cctype>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>

#include <unistd.h>

namespace slipwave::core {
namespace {

const char *g_program = "slipwave";
std::string g_said; // the message ErrorsSayNow printed before its error is raised

bool isUserInputError(PetscErrorCode code, const char *mess) {
  // PETSc raises a bad boolean option value as PETSC_ERR_ARG_WRONG.
  const bool bad_bool = code == PETSC_ERR_ARG_WRONG && mess && std::strncmp(mess, "Unknown logical value: ", 23) == 0;
  return code == PETSC_ERR_USER_INPUT || code == PETSC_ERR_FILE_OPEN || code == PETSC_ERR_ARG_OUTOFRANGE || code == PETSC_ERR_NOT_CONVERGED || bad_bool;
}

// PETSc's option parsers name the value they cannot convert but not the option; find the
// option(s) holding that value so the one line names them.
std::string withOptionName(const char *mess) {
  struct Kind {
    const char *head, *tail, *allowed;
  };
  static const Kind kinds[] = {{"Input string ", " has no numeric value", "a real number"},
                               {"Input string ", " has no integer value", "an integer"},
                               {"Unknown logical value: ", "", "true, false, yes, no, 1 or 0"}};
  const std::string text = mess ? mess : "";
  for (const Kind &k : kinds) {
    if (text.rfind(k.head, 0) != 0) continue;
    const size_t start = std::strlen(k.head);
    const size_t end   = k.tail[0] ? text.find(k.tail, start) : text.find_last_not_of(" ") + 1;
    if (end == std::string::npos || end <= start) continue;
    const std::string value = text.substr(start, end - start);
    char             *all   = nullptr;
    if (PetscOptionsGetAll(nullptr, &all)) return text;
    std::istringstream       tokens(all ? all : "");
    std::string              token, names;
    auto isName = [](const std::string &t) { return t.size() > 1 && t[0] == '-' && std::isalpha((unsigned char)t[1]); };
    while (tokens >> token) {
      if (!isName(token)) continue;
      // The whole value (it may hold blanks: "200 m/s" in a YAML file), or one element of a
      // comma-separated array value.
      const char *held = nullptr;
      PetscBool   set  = PETSC_FALSE;
      if (PetscOptionsFindPair(nullptr, nullptr, token.c_str(), &held, &set) || !set || !held) continue;
      const std::string v = held;
      bool hit = v == value;
      std::istringstream elements(v);
      for (std::string e; !hit && std::getline(elements, e, ',');) hit = e == value;
      if (hit && names.find(token + " ") == std::string::npos) names += (names.empty() ? "" : " or ") + token + " = " + (v.find(' ') != std::string::npos ? "\"" + v + "\"" : v);
    }
    PetscFree(all);
    if (names.empty()) return text;
    return names + ": '" + value + "' is not " + k.allowed + "; allowed: " + k.allowed;
  }
  return text;
}

// The file and line of the first option the message names, when an option file gives it
// ("default.yaml:23: -material_soil_vs = ..."): the user edits that line.
std::string withOrigin(const std::string &text) {
  for (size_t i = 0; i + 1 < text.size(); ++i) {
    if (text[i] != '-' || !std::isalpha((unsigned char)text[i + 1]) || (i > 0 && text[i - 1] != ' ' && text[i - 1] != '(')) continue;
    size_t end = i + 1;
    while (end < text.size() && (std::isalnum((unsigned char)text[end]) || text[end] == '_')) ++end;
    const std::string origin = OptionOrigin(text.substr(i, end - i));
    if (!origin.empty()) return origin + ": " + text;
  }
  return text;
}

// A file not found under a relative path: say which folder it was looked for in (the working
// folder; paths from an option file are already made relative to it, option_files.hpp).
std::string withFolder(const std::string &text) {
  const size_t at = text.find(": cannot open the file");
  if (at == std::string::npos) return text;
  const size_t      start = text.find_last_of(' ', at);
  const std::string path  = text.substr(start == std::string::npos ? 0 : start + 1, at - (start == std::string::npos ? 0 : start + 1));
  char              cwd[PETSC_MAX_PATH_LEN];
  if (path.empty() || path[0] == '/' || !getcwd(cwd, sizeof cwd)) return text;
  return text.substr(0, at) + ": cannot open the file (looked for it in " + cwd + ")" + text.substr(at + std::strlen(": cannot open the file"));
}

PetscErrorCode userInputHandler(MPI_Comm comm, int line, const char *func, const char *file, PetscErrorCode code,
                                PetscErrorType type, const char *mess, void *ctx) {
  static bool reported = false;
  if (!isUserInputError(code, mess) && !reported) return PetscTraceBackErrorHandler(comm, line, func, file, code, type, mess, ctx);
  // The first call carries the message; the calls that follow are the unwinding stack.
  if (type == PETSC_ERROR_INITIAL && !reported) {
    reported = true;
    // ErrorsSayNow printed it already. A prefix match: PETSc formats the raised message into a
    // fixed buffer, so a long line (a long output path) comes back cut short.
    if (mess && mess[0] && g_said.compare(0, std::strlen(mess), mess) == 0) return code;
    PetscMPIInt rank = 0;
    if (comm != PETSC_COMM_SELF) MPI_Comm_rank(comm, &rank);
    if (rank == 0) {
      std::fprintf(stderr, "%s: error: %s\n", g_program, mess ? withOrigin(withFolder(withOptionName(mess))).c_str() : "(no message)");
      std::fflush(stderr);
    }
  }
  return code;
}

} // namespace

PetscErrorCode ErrorsSayNow(MPI_Comm comm, const char *message) {
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  g_said = message;
  if (rank == 0) {
    std::fprintf(stderr, "%s: error: %s\n", g_program, message);
    std::fflush(stderr);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ErrorsPushUserInputHandler(const char *program_name) {
  PetscFunctionBeginUser;
  g_program = program_name;
  PetscCall(PetscPushErrorHandler(userInputHandler, nullptr));
  PetscFunctionReturn(0);
}

} // namespace slipwave::core
