#include "slipwave/core/option_files.hpp"

#include <sys/stat.h>
#include <unistd.h>
#include <yaml.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <vector>

#include <petscsys.h>

namespace slipwave::core {
namespace {

// PETSc 3.18 options that start a program (a debugger, a terminal, an editor, an X server)
// or name the display it opens; any option with "debugger" in its name is refused as well.
const char *const kRunsProgram[] = {"start_in_debugger", "on_error_attach_debugger", "stop_for_debugger", "debugger_ranks", "debugger_nodes", "debugger_pause",
                                    "debug_terminal",    "display",                  "on_error_emacs",    "x_virtual",      "popen_machine",  "mpi_debugger"};

constexpr int kMaxDepth = 8; // option files including option files

// Where each option of the option files was given (name without the dash; the last file read
// that gives it), for messages and for paths relative to the file.
struct Origin {
  std::string file, value;
  int         line = 0;
};
std::map<std::string, Origin> g_origins;

// One file's options so far (name -> line): a second occurrence is an error, as the file's
// author cannot mean both values (PETSc would silently take the last).
using SeenOptions = std::map<std::string, int>;

std::string noteOption(const std::string &where, const std::string &file, int line, std::string name, const std::string &value, SeenOptions *seen) {
  while (!name.empty() && name[0] == '-') name.erase(0, 1);
  const auto before = seen->find(name);
  if (before != seen->end())
    return where + ":" + std::to_string(line) + ": " + name + " is given a second time (first at line " + std::to_string(before->second) +
           "); allowed: each option once per file";
  (*seen)[name] = line;
  g_origins[name] = Origin{file, value, line};
  return "";
}


bool runsProgram(std::string name) {
  while (!name.empty() && name[0] == '-') name.erase(0, 1);
  if (name.find("debugger") != std::string::npos) return true;
  for (const char *p : kRunsProgram)
    if (name == p) return true;
  return false;
}

bool endsWith(const std::string &s, const char *tail) {
  const size_t n = std::strlen(tail);
  return s.size() >= n && s.compare(s.size() - n, n, tail) == 0;
}

// Options whose value is an input file: a relative path in an option file is taken from the
// file's folder. Output folders (-output_dir) stay relative to the working folder.
bool namesInputFile(const std::string &name) {
  if (name == "options_file" || name == "options_file_yaml") return false;
  return endsWith(name, "_file") || endsWith(name, "_record") || name == "restart";
}

// PETSc options that write a file named in their value, which may lie outside the output
// folder: viewers ("-x_view ascii:FILE", "-log_view :FILE"), "-info FILE", and those whose
// value is the file itself.
bool writesFile(std::string name, const std::string &value) {
  while (!name.empty() && name[0] == '-') name.erase(0, 1);
  for (const char *p : {"log_trace", "history", "malloc_dump", "malloc_view", "log_all", "log_mpe"})
    if (name == p) return !value.empty();
  if (name == "info") return !value.empty() && value[0] != ':';
  if (endsWith(name, "_view") || endsWith(name, "_monitor") || name.find("_view_") != std::string::npos || name.find("_monitor_") != std::string::npos) {
    const size_t colon = value.find(':');
    return colon != std::string::npos && colon + 1 < value.size() && value[colon + 1] != ':';
  }
  return false;
}

std::string refusedFile(const std::string &where, const std::string &option, const std::string &value) {
  return where + ": " + option + " " + value +
         " writes a file outside the output folder; allowed in an option file: viewers to standard output (give file viewers on the command line)";
}

std::string refusedProgram(const std::string &where, const std::string &option) {
  return where + ": " + option + " runs a program; allowed in an option file: options that run no program (give debugger options on the command line)";
}

// Splits a line as PETSc does: white space between tokens, a double-quoted token may hold spaces.
std::vector<std::string> tokens(const std::string &line) {
  std::vector<std::string> out;
  for (size_t i = 0; i < line.size();) {
    if (std::isspace((unsigned char)line[i])) {
      ++i;
      continue;
    }
    size_t end = line[i] == '"' ? line.find('"', i + 1) : std::string::npos;
    if (line[i] == '"' && end != std::string::npos) {
      out.push_back(line.substr(i + 1, end - i - 1));
      i = end + 1;
      continue;
    }
    end = i;
    while (end < line.size() && !std::isspace((unsigned char)line[end])) ++end;
    out.push_back(line.substr(i, end - i));
    i = end;
  }
  return out;
}

std::string checkFile(const std::string &option, const std::string &path, int depth);

std::string checkText(const std::string &where, const std::string &path, const std::string &text, int depth) {
  std::istringstream in(text);
  int                number = 0;
  SeenOptions        seen;
  for (std::string line; std::getline(in, line);) {
    ++number;
    const size_t comment = line.find('#'); // PETSc 3.18 knows no other comment mark
    if (comment != std::string::npos) line.erase(comment);
    const std::vector<std::string> t = tokens(line);
    if (t.empty()) continue;
    const std::string at = where + ":" + std::to_string(number);
    const char *grammar = "allowed: lines '-option [value]', 'alias -new -old' or '# comment'";
    if (t[0] == "alias") {
      if (t.size() != 3) return at + ": alias needs two names; " + grammar;
      continue;
    }
    if (t[0].size() < 2 || t[0][0] != '-') return at + ": '" + t[0] + "' is not an option name; " + grammar;
    if (t.size() > 2) return at + ": '" + t[2] + "' after the value of " + t[0] + "; " + grammar;
    if (runsProgram(t[0])) return refusedProgram(at, t[0]);
    if (t.size() == 2 && writesFile(t[0], t[1])) return refusedFile(at, t[0], t[1]);
    if (t[0] != "-options_file" && t[0] != "-options_file_yaml") {
      const std::string twice = noteOption(where, path, number, t[0], t.size() == 2 ? t[1] : "", &seen);
      if (!twice.empty()) return twice;
    }
    if (t[0] == "-options_file" || t[0] == "-options_file_yaml") {
      if (t.size() < 2) return at + ": " + t[0] + " needs a file name; allowed: " + t[0] + " <file>";
      const std::string problem = checkFile(at + ": " + t[0], t[1], depth + 1);
      if (!problem.empty()) return problem;
    }
  }
  return "";
}

// Walks a YAML document as PETSc flattens it: nested keys join with '_'.
std::string checkYamlNode(yaml_document_t *doc, yaml_node_t *node, const std::string &prefix, const std::string &where, const std::string &path, SeenOptions *seen) {
  if (!node || node->type != YAML_MAPPING_NODE) return "";
  for (yaml_node_pair_t *p = node->data.mapping.pairs.start; p < node->data.mapping.pairs.top; ++p) {
    yaml_node_t *key = yaml_document_get_node(doc, p->key);
    if (!key || key->type != YAML_SCALAR_NODE) continue;
    const std::string name = (const char *)key->data.scalar.value;
    const std::string full = prefix.empty() ? name : prefix + "_" + name;
    const std::string at = where + ":" + std::to_string(key->start_mark.line + 1);
    if (runsProgram(name) || runsProgram(full)) return refusedProgram(at, "-" + full);
    yaml_node_t *value = yaml_document_get_node(doc, p->value);
    if (value && value->type == YAML_SCALAR_NODE && writesFile(full, (const char *)value->data.scalar.value))
      return refusedFile(at, "-" + full, (const char *)value->data.scalar.value);
    if (value && value->type != YAML_MAPPING_NODE) {
      const std::string twice = noteOption(where, path, key->start_mark.line + 1, full, value->type == YAML_SCALAR_NODE ? (const char *)value->data.scalar.value : "", seen);
      if (!twice.empty()) return twice;
    }
    const std::string inner = checkYamlNode(doc, value, full, where, path, seen);
    if (!inner.empty()) return inner;
  }
  return "";
}

std::string checkYaml(const std::string &where, const std::string &path, const std::string &text) {
  yaml_parser_t   parser;
  yaml_document_t doc;
  if (!yaml_parser_initialize(&parser)) return where + ": cannot start the YAML parser";
  yaml_parser_set_input_string(&parser, (const unsigned char *)text.data(), text.size());
  std::string problem;
  if (!yaml_parser_load(&parser, &doc)) {
    problem = where + ":" + std::to_string(parser.problem_mark.line + 1) + ": not valid YAML (" + (parser.problem ? parser.problem : "parse error") +
              "); allowed: a YAML mapping of option names to values";
  } else {
    SeenOptions seen;
    problem = checkYamlNode(&doc, yaml_document_get_root_node(&doc), "", where, path, &seen);
    yaml_document_delete(&doc);
  }
  yaml_parser_delete(&parser);
  return problem;
}

std::string checkFile(const std::string &option, const std::string &path, int depth) {
  const std::string where   = option + " = " + path;
  const char       *allowed = "; allowed: a readable text file of options ('-option value' lines, or YAML for .yaml/.yml)";
  if (depth > kMaxDepth) return where + ": option files nested more than " + std::to_string(kMaxDepth) + " deep" + allowed;
  struct stat st;
  if (stat(path.c_str(), &st) != 0) return where + ": cannot open the file (no such file)" + allowed;
  if (S_ISDIR(st.st_mode)) return where + ": is a directory" + allowed;
  if (!S_ISREG(st.st_mode) || access(path.c_str(), R_OK) != 0) return where + ": cannot read the file" + allowed;
  std::ifstream     in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (size_t i = 0; i < text.size(); ++i) {
    const unsigned char ch = (unsigned char)text[i];
    if (ch < 0x20 && !std::isspace(ch)) {
      char at[96];
      std::snprintf(at, sizeof at, ": not a text file (byte 0x%02x at offset %zu)", ch, i);
      return where + at + allowed;
    }
  }
  const bool yaml = endsWith(path, ".yaml") || endsWith(path, ".yml") || option.find("_yaml") != std::string::npos;
  return yaml ? checkYaml(where, path, text) : checkText(where, path, text, depth);
}

// The rc files PETSc reads by itself: only the options that run programs matter there.
std::string checkRcFile(const std::string &path) {
  std::ifstream in(path);
  if (!in) return "";
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    const size_t comment = line.find('#'); // PETSc 3.18 knows no other comment mark
    if (comment != std::string::npos) line.erase(comment);
    for (const std::string &t : tokens(line))
      if (t[0] == '-' && runsProgram(t)) return refusedProgram(path + ":" + std::to_string(number), t);
  }
  return "";
}

// Before MPI starts, the launcher's rank variable says which process prints the one line.
bool launcherRankZero() {
  for (const char *name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"})
    if (const char *rank = std::getenv(name)) return std::atoi(rank) == 0;
  return true;
}

} // namespace

std::string OptionFilesCheck(int argc, const char *const *argv) {
  bool skip_rc = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-skip_petscrc") skip_rc = true;
    if (arg != "-options_file" && arg != "-options_file_yaml") continue;
    if (i + 1 >= argc || argv[i + 1][0] == '-') return arg + " needs a file name; allowed: " + arg + " <file>";
    const std::string problem = checkFile(arg, argv[++i], 1);
    if (!problem.empty()) return problem;
  }
  if (skip_rc) return "";
  const char *home = std::getenv("HOME");
  for (const std::string &rc : {std::string(home ? home : "") + "/.petscrc", std::string(".petscrc")}) {
    const std::string problem = checkRcFile(rc);
    if (!problem.empty()) return problem;
  }
  return "";
}

std::string OptionOrigin(const std::string &option) {
  std::string name = option;
  while (!name.empty() && name[0] == '-') name.erase(0, 1);
  const auto origin = g_origins.find(name);
  if (origin == g_origins.end()) return "";
  const char *value = nullptr;
  PetscBool   set   = PETSC_FALSE;
  if (PetscOptionsFindPair(nullptr, nullptr, ("-" + name).c_str(), &value, &set) || !set) return "";
  if (origin->second.value != (value ? value : "")) return ""; // given again later, on the command line or in another file
  return origin->second.file + ":" + std::to_string(origin->second.line);
}

int OptionFilePathsResolve(int argc, const char *const *argv) {
  for (auto &[name, origin] : g_origins) {
    if (!namesInputFile(name) || origin.value.empty() || origin.value[0] == '/') continue;
    const size_t slash = origin.file.find_last_of('/');
    if (slash == std::string::npos) continue; // the file is in the working folder
    bool on_command_line = false;
    for (int i = 1; i < argc; ++i) on_command_line = on_command_line || ("-" + name) == argv[i];
    if (on_command_line || OptionOrigin(name).empty()) continue;
    const std::string resolved = std::filesystem::path(origin.file.substr(0, slash + 1) + origin.value).lexically_normal().string();
    if (PetscOptionsSetValue(nullptr, ("-" + name).c_str(), resolved.c_str())) return 1;
    origin.value = resolved;
  }
  return 0;
}

bool OptionFilesAcceptable(int argc, const char *const *argv, const char *program) {
  const std::string problem = OptionFilesCheck(argc, argv);
  if (problem.empty()) return true;
  if (launcherRankZero()) std::fprintf(stderr, "%s: error: %s\n", program, problem.c_str());
  return false;
}

} // namespace slipwave::core
