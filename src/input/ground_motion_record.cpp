#include "slipwave/input/ground_motion_record.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

namespace slipwave::input {
namespace {

ReadStatus failure(const std::string &path, int line, const std::string &what) {
  return {false, path + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + what};
}

std::string trim(const std::string &s) {
  const size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

// The whole (trimmed) text must be one finite number.
bool parseNumber(const std::string &text, double *value) {
  const std::string t = trim(text);
  if (t.empty()) return false;
  char *end = nullptr;
  errno = 0;
  *value = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size() && errno == 0 && std::isfinite(*value);
}

double toMetresPerSecondSquared(AccelerationUnit unit) {
  return unit == AccelerationUnit::G ? kStandardGravity : unit == AccelerationUnit::CentimetresPerSecondSquared ? 0.01 : 1.0;
}

// Words that name the quantity, not its unit ("ground_acceleration_g": the unit is "g").
bool quantityWord(const std::string &w) {
  for (const char *q : {"acceleration", "accel", "acc", "a", "ag", "ground", "horizontal", "vertical", "input", "value", "values"})
    if (w == q) return true;
  return false;
}

// A unit text in a canonical spelling: lower case, no blanks or '^', '_' read as '/', "²" as
// "2", "/s/s" as "/s2", "ps2" as "/s2" ("mps2", "cm_s2", "m / s^2" all read as m/s2).
std::string canonicalUnit(std::string text) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = (unsigned char)text[i];
    if (c == 0xc2 && i + 1 < text.size() && (unsigned char)text[i + 1] == 0xb2) { // UTF-8 "²"
      out += '2', ++i;
    } else if (c == '_') out += '/';
    else if (!std::isspace(c) && c != '^') out += (char)std::tolower(c);
  }
  const size_t ss = out.find("/s/s");
  if (ss != std::string::npos && ss + 4 == out.size()) out.replace(ss, 4, "/s2");
  if (out.size() > 3 && out.compare(out.size() - 3, 3, "ps2") == 0 && out.find('/') == std::string::npos) out.replace(out.size() - 3, 3, "/s2");
  return out;
}

bool unitFromText(const std::string &text, AccelerationUnit *unit) {
  const std::string u = canonicalUnit(text);
  if (u == "g") *unit = AccelerationUnit::G;
  else if (u == "m/s2") *unit = AccelerationUnit::MetresPerSecondSquared;
  else if (u == "cm/s2" || u == "gal" || u == "gals") *unit = AccelerationUnit::CentimetresPerSecondSquared;
  else return false;
  return true;
}

// The unit text a column name carries: inside brackets ("acc (g)", "a [m/s^2]"), or what
// follows the quantity words ("acceleration_cm_s2", "ground acceleration g"); "" for none.
std::string unitText(const std::string &column) {
  const size_t open = column.find_first_of("([");
  if (open != std::string::npos) {
    const size_t close = column.find_first_of(")]", open + 1);
    return trim(column.substr(open + 1, close == std::string::npos ? std::string::npos : close - open - 1));
  }
  std::vector<std::string> words(1);
  for (char c : column) {
    if (c == '_' || std::isspace((unsigned char)c)) {
      if (!words.back().empty()) words.emplace_back();
    } else words.back() += c;
  }
  if (words.back().empty()) words.pop_back();
  size_t first = 0; // the first word that is not a quantity word, after the first word
  auto lower = [](std::string w) {
    for (char &c : w) c = (char)std::tolower((unsigned char)c);
    return w;
  };
  AccelerationUnit ignored;
  if (words.size() == 1) return unitFromText(words[0], &ignored) ? words[0] : ""; // "g" alone, or "acceleration"
  for (first = 1; first < words.size() && quantityWord(lower(words[first])); ++first) {}
  std::string unit;
  for (size_t k = first; k < words.size(); ++k) unit += (k > first ? "_" : "") + words[k];
  return unit;
}

const char *kAllowedUnits = "g; m/s^2 (m/s2, m_s2, mps2, m/s/s); cm/s^2 (cm/s2, cm_s2, gal)";

// The unit the values are in: the one the header's acceleration column names, checked
// against the one asked for.
ReadStatus resolveUnit(const std::string &path, const std::string &header, AccelerationUnit asked, AccelerationUnit *unit) {
  const size_t      comma  = header.find(',');
  const std::string column = trim(comma == std::string::npos ? std::string() : header.substr(comma + 1));
  const std::string text   = unitText(column);
  AccelerationUnit  named  = AccelerationUnit::FromHeader; // none named
  if (!text.empty() && !unitFromText(text, &named))
    return failure(path, 1, "the header's acceleration column \"" + column + "\" names the unit \"" + text + "\", which is not one slipwave reads (" + kAllowedUnits +
                                "; or a column named just \"acceleration\")");
  *unit = asked != AccelerationUnit::FromHeader ? asked : named != AccelerationUnit::FromHeader ? named : AccelerationUnit::MetresPerSecondSquared;
  if (named != AccelerationUnit::FromHeader && *unit != named)
    return failure(path, 1, std::string("the header's acceleration column \"") + column + "\" is in " + AccelerationUnitName(named) + ", not in " + AccelerationUnitName(*unit) + " as asked");
  return {};
}

// One value: a finite number within kMaxRecordMagnitude once converted (1e200 would pass
// the parser and overflow the energy sums two steps into the run).
ReadStatus checkMagnitude(const std::string &path, int line, const std::string &text, double value, AccelerationUnit unit) {
  if (std::fabs(value * toMetresPerSecondSquared(unit)) <= kMaxRecordMagnitude) return {};
  std::ostringstream msg;
  if (unit == AccelerationUnit::Factor) msg << "factor " << trim(text) << " is absurd (more than 1e6)";
  else msg << "acceleration " << trim(text) << " " << AccelerationUnitName(unit) << " is absurd (more than 1e6 m/s^2, 1e5 g)";
  return failure(path, line, msg.str());
}

} // namespace

const char *AccelerationUnitName(AccelerationUnit unit) {
  return unit == AccelerationUnit::G ? "g" : unit == AccelerationUnit::CentimetresPerSecondSquared ? "cm/s^2" : unit == AccelerationUnit::Factor ? "-" : "m/s^2";
}

ReadStatus readAccelerationCsv(const std::string &path, GroundMotionRecord *record, AccelerationUnit unit) {
  std::ifstream in(path);
  if (!in) return failure(path, 0, "cannot open the file");
  record->time.clear(), record->acceleration.clear();
  std::string line, header;
  int line_no = 0, previous_line = 0;
  bool unit_known = false; // resolved at the first sample, from the header (line 1) if any
  const bool factor = unit == AccelerationUnit::Factor;
  while (std::getline(in, line)) {
    ++line_no;
    if (trim(line).empty()) continue;
    const size_t comma = line.find(',');
    if (comma == std::string::npos || line.find(',', comma + 1) != std::string::npos) {
      if (line_no == 1) {  // header without the two-field shape
        header = line;
        continue;
      }
      return failure(path, line_no, "expected two comma-separated values \"time,acceleration\", got \"" + trim(line) + "\"");
    }
    double t, a;
    const bool t_ok = parseNumber(line.substr(0, comma), &t), a_ok = parseNumber(line.substr(comma + 1), &a);
    if (line_no == 1 && !t_ok) {  // header
      header = line;
      continue;
    }
    if (!unit_known && !factor) {
      const ReadStatus unit_status = resolveUnit(path, header, unit, &unit);
      if (!unit_status.ok) return unit_status;
    }
    unit_known = true;
    if (!t_ok) return failure(path, line_no, "time \"" + trim(line.substr(0, comma)) + "\" is not a number");
    if (!a_ok) return failure(path, line_no, std::string(factor ? "factor" : "acceleration") + " \"" + trim(line.substr(comma + 1)) + "\" is not a number");
    const ReadStatus magnitude = checkMagnitude(path, line_no, line.substr(comma + 1), a, unit);
    if (!magnitude.ok) return magnitude;
    if (!record->time.empty() && !(t > record->time.back())) {
      std::ostringstream msg;
      msg.precision(15);
      msg << "time " << t << " is not after the time " << record->time.back() << " on line " << previous_line
          << "; times must increase strictly";
      return failure(path, line_no, msg.str());
    }
    record->time.push_back(t), record->acceleration.push_back(factor ? a : a * toMetresPerSecondSquared(unit));
    previous_line = line_no;
  }
  if (record->time.size() < 2)
    return failure(path, 0, "needs at least 2 samples, found " + std::to_string(record->time.size()));
  record->file_unit = factor ? AccelerationUnit::Factor : unit;
  return {};
}

ReadStatus readPeerAt2(const std::string &path, GroundMotionRecord *record, AccelerationUnit asked) {
  std::ifstream in(path);
  if (!in) return failure(path, 0, "cannot open the file");
  record->time.clear(), record->acceleration.clear();
  std::string line;
  // PEER's third line says "... IN UNITS OF G"; another unit there is honoured or refused.
  static const std::regex units_of(R"(UNITS\s+OF\s+(\S+))", std::regex::icase);
  AccelerationUnit        unit = AccelerationUnit::G;
  std::smatch             u;
  for (int k = 1; k <= 4; ++k) {
    if (!std::getline(in, line)) return failure(path, k, "file ends inside the 4 header lines");
    if (k < 4 && std::regex_search(line, u, units_of) && !unitFromText(u[1].str(), &unit))
      return failure(path, k, "the header says \"" + trim(u[0].str()) + "\", a unit slipwave does not read (" + kAllowedUnits + ")");
  }
  if (asked != AccelerationUnit::FromHeader && asked != unit)
    return failure(path, 0, std::string("its header gives the values in ") + AccelerationUnitName(unit) + ", not in " + AccelerationUnitName(asked) + " as asked");
  static const std::regex keyed(R"(NPTS\s*=\s*(\d+)\s*,?\s*DT\s*=\s*([-+0-9.eE]+))", std::regex::icase);
  static const std::regex positional(R"(^\s*(\d+)\s+([-+0-9.eE]+)\s+NPTS)", std::regex::icase);
  std::smatch m;
  if (!std::regex_search(line, m, keyed) && !std::regex_search(line, m, positional))
    return failure(path, 4,
                   "cannot find NPTS and DT in \"" + trim(line) +
                       "\" (expected \"NPTS=  5590, DT=   .0050 SEC\" or \"5590 0.0050 NPTS, DT\")");
  const long npts = std::strtol(m[1].str().c_str(), nullptr, 10);
  double dt;
  if (npts < 2) return failure(path, 4, "NPTS = " + m[1].str() + " is not allowed; it must be at least 2");
  if (!parseNumber(m[2].str(), &dt) || !(dt > 0))
    return failure(path, 4, "DT = " + m[2].str() + " is not allowed; it must be a number > 0");
  record->file_unit = unit;

  int line_no = 4;
  while (std::getline(in, line)) {
    ++line_no;
    std::istringstream tokens(line);
    std::string token;
    while (tokens >> token) {
      double g;
      if (!parseNumber(token, &g)) return failure(path, line_no, "value \"" + token + "\" is not a number");
      const ReadStatus magnitude = checkMagnitude(path, line_no, token, g, unit);
      if (!magnitude.ok) return magnitude;
      if (static_cast<long>(record->acceleration.size()) == npts)
        return failure(path, line_no, "more values than NPTS = " + std::to_string(npts) + " (line 4)");
      record->time.push_back(static_cast<double>(record->acceleration.size()) * dt);
      record->acceleration.push_back(g * toMetresPerSecondSquared(unit));
    }
  }
  if (static_cast<long>(record->acceleration.size()) != npts)
    return failure(path, line_no,
                   "file ends after " + std::to_string(record->acceleration.size()) + " values but NPTS = " +
                       std::to_string(npts) + " (line 4)");
  return {};
}

std::vector<double> integrateTrapezoid(const std::vector<double> &time, const std::vector<double> &values) {
  std::vector<double> out(values.size(), 0.0);
  for (size_t k = 1; k < values.size(); ++k)
    out[k] = out[k - 1] + 0.5 * (time[k] - time[k - 1]) * (values[k] + values[k - 1]);
  return out;
}

void removeBaselineDrift(GroundMotionRecord *record) {
  const std::vector<double> &t = record->time;
  if (t.size() < 2) return;
  // Final velocity and displacement are linear in the acceleration, so integrating the two
  // correction shapes with the same rule makes the correction exact for the discrete record.
  auto finalVelocityAndDisplacement = [&t](const std::vector<double> &a, double *v, double *d) {
    const std::vector<double> vel = integrateTrapezoid(t, a);
    *v = vel.back();
    *d = integrateTrapezoid(t, vel).back();
  };
  std::vector<double> one(t.size(), 1.0), ramp(t.size());
  for (size_t k = 0; k < t.size(); ++k) ramp[k] = t[k] - t.front();
  double v0, d0, v1, d1, v, d;
  finalVelocityAndDisplacement(one, &v0, &d0);
  finalVelocityAndDisplacement(ramp, &v1, &d1);
  finalVelocityAndDisplacement(record->acceleration, &v, &d);
  const double det = v0 * d1 - v1 * d0;
  const double c0 = (v * d1 - v1 * d) / det, c1 = (v0 * d - v * d0) / det;
  for (size_t k = 0; k < t.size(); ++k) record->acceleration[k] -= c0 + c1 * ramp[k];
}

physics::TabulatedHistory velocityHistory(const GroundMotionRecord &record) {
  return {record.time, integrateTrapezoid(record.time, record.acceleration)};
}

} // namespace slipwave::input
