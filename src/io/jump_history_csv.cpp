#include "slipwave/io/jump_history_csv.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <sstream>

namespace slipwave::io {
namespace {

std::string trim(const std::string &s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> splitFields(const std::string &line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string field;
  while (std::getline(ss, field, ',')) out.push_back(trim(field));
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

std::string where(const std::string &source, int line) { return source + ":" + std::to_string(line) + ": "; }

std::string formatNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  return buf;
}

bool blankOrComment(const std::string &s) { return s.empty() || s[0] == '#'; }

} // namespace

std::string parseJumpHistory(std::istream &in, const std::string &source, JumpHistory &h) {
  const char *expected = "expected the header t,w_T,w_N (2D) or t,w_T1,w_T2,w_N (3D)";
  h = JumpHistory{};
  std::string raw;
  int line_no = 0;
  std::vector<std::string> header;
  while (std::getline(in, raw)) {
    ++line_no;
    if (blankOrComment(trim(raw))) continue;
    header = splitFields(trim(raw));
    break;
  }
  if (header.empty()) return where(source, line_no) + "no header; " + expected;

  auto find = [&](const char *name) {
    for (std::size_t k = 0; k < header.size(); ++k)
      if (header[k] == name) return static_cast<int>(k);
    return -1;
  };
  const bool is3d = find("w_T1") >= 0 || find("w_T2") >= 0;
  const std::vector<const char *> names =
      is3d ? std::vector<const char *>{"t", "w_T1", "w_T2", "w_N"} : std::vector<const char *>{"t", "w_T", "w_N"};
  std::vector<int> column;
  for (const char *name : names) {
    const int k = find(name);
    if (k < 0) return where(source, line_no) + "missing column " + name + "; " + expected;
    column.push_back(k);
  }
  if (header.size() != names.size()) {
    for (const auto &hname : header) {
      bool known = false;
      for (const char *name : names) known = known || hname == name;
      if (!known) return where(source, line_no) + "unknown column '" + hname + "'; " + expected;
    }
    return where(source, line_no) + "repeated column; " + expected;
  }
  h.dim = is3d ? 3 : 2;

  while (std::getline(in, raw)) {
    ++line_no;
    const std::string text = trim(raw);
    if (blankOrComment(text)) continue;
    const auto fields = splitFields(text);
    if (fields.size() != header.size())
      return where(source, line_no) + std::to_string(fields.size()) + " values, expected " +
             std::to_string(header.size()) + " (one per header column)";
    double values[4];
    for (std::size_t k = 0; k < names.size(); ++k) {
      const std::string &f = fields[column[k]];
      char *end = nullptr;
      errno = 0;
      values[k] = std::strtod(f.c_str(), &end);
      if (f.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(values[k]))
        return where(source, line_no) + "column " + names[k] + ": '" + f + "' is not a finite number";
    }
    if (!h.t.empty() && !(values[0] > h.t.back()))
      return where(source, line_no) + "time " + fields[column[0]] + " does not increase (previous row has t = " +
             formatNumber(h.t.back()) + "); rows must be sorted by strictly increasing t";
    h.t.push_back(values[0]);
    for (std::size_t k = 1; k < names.size(); ++k) h.w.push_back(values[k]);
    h.line.push_back(line_no);
  }
  if (h.t.empty()) return where(source, line_no) + "no data rows after the header";
  return "";
}

PetscErrorCode JumpHistoryCsvRead(MPI_Comm comm, const char *path, JumpHistory *history) {
  std::string error;
  bool opened = true;

  PetscFunctionBeginUser;
  // No C++ exception may cross the PETSc frames.
  try {
    std::ifstream in(path);
    if (!in)
      opened = false;
    else
      error = parseJumpHistory(in, path, *history);
  } catch (const std::exception &e) {
    error = std::string(path) + ": cannot be read (" + e.what() + ")";
  }
  PetscCheck(opened, comm, PETSC_ERR_FILE_OPEN, "%s: cannot open the file for reading", path);
  PetscCheck(error.empty(), comm, PETSC_ERR_USER_INPUT, "%s", error.c_str());
  PetscFunctionReturn(0);
}

} // namespace slipwave::io
