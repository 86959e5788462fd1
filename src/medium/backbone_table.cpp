#include "slipwave/medium/backbone_table.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace slipwave::medium {
namespace {

std::string trim(const std::string &s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace((unsigned char)s[b])) ++b;
  while (e > b && std::isspace((unsigned char)s[e - 1])) --e;
  return s.substr(b, e - b);
}

// The comma-separated fields of a line, trimmed.
std::vector<std::string> fields(const std::string &line) {
  std::vector<std::string> out;
  std::stringstream        ss(line);
  std::string              f;
  while (std::getline(ss, f, ',')) out.push_back(trim(f));
  return out;
}

// A whole field as a finite number.
bool number(const std::string &s, double *x) {
  if (s.empty()) return false;
  char *end = nullptr;
  errno     = 0;
  *x        = std::strtod(s.c_str(), &end);
  return errno == 0 && end && *end == '\0' && std::isfinite(*x);
}

std::string lower(std::string s) {
  for (char &c : s) c = (char)std::tolower((unsigned char)c);
  return s;
}

} // namespace

std::string ReadBackboneTable(const std::string &path, BackboneTable *table) {
  std::ifstream in(path);
  if (!in) return path + ": cannot open the file";
  *table = BackboneTable();
  std::string line;
  int         number_of_line = 0;
  double      to_ratio       = 0; // 1 (strain) or 0.01 (strain_percent), once the header is read
  while (std::getline(in, line)) {
    ++number_of_line;
    const std::string t = trim(line);
    const std::string where = path + ":" + std::to_string(number_of_line) + ": ";
    if (t.empty()) continue;
    if (t[0] == '#') {
      const std::string body = trim(t.substr(1));
      if (table->source.empty() && lower(body.substr(0, 7)) == "source:") table->source = trim(body.substr(7));
      continue;
    }
    const std::vector<std::string> f = fields(t);
    if (to_ratio == 0) {
      const std::string unit = f.empty() ? "" : lower(f[0]), second = f.size() > 1 ? lower(f[1]) : "";
      if (f.size() != 2 || (unit != "strain" && unit != "strain_percent") || (second != "g/gmax" && second != "modulus_ratio"))
        return where + "header \"" + t + "\" does not name the columns; allowed: strain,G/Gmax (strain a ratio) or strain_percent,G/Gmax";
      to_ratio = unit == "strain" ? 1.0 : 0.01;
      continue;
    }
    double strain, ratio;
    if (f.size() != 2) return where + "\"" + t + "\" has " + std::to_string(f.size()) + " fields; allowed: two, strain,G/Gmax";
    if (!number(f[0], &strain)) return where + "strain \"" + f[0] + "\" is not a finite number";
    if (!number(f[1], &ratio)) return where + "G/Gmax \"" + f[1] + "\" is not a finite number";
    if (!(strain > 0)) return where + "strain " + f[0] + " is not > 0";
    if (!(ratio > 0 && ratio <= 1)) return where + "G/Gmax " + f[1] + " is not in (0, 1]";
    if (!table->strain.empty() && !(strain * to_ratio > table->strain.back()))
      return where + "strain " + f[0] + " does not increase from the row before; allowed: strains in increasing order";
    table->strain.push_back(strain * to_ratio);
    table->ratio.push_back(ratio);
  }
  if (table->source.empty()) return path + ": no \"# source:\" line; allowed: a table that says where its curve comes from (a comment line \"# source: ...\")";
  if (to_ratio == 0) return path + ": no header line; allowed: strain,G/Gmax or strain_percent,G/Gmax before the rows";
  if (table->strain.size() < 2) return path + ": " + std::to_string(table->strain.size()) + " rows; allowed: at least 2 rows of strain,G/Gmax";
  return "";
}

} // namespace slipwave::medium
