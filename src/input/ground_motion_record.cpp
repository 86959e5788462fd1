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

const char *unitName(AccelerationUnit unit) { return unit == AccelerationUnit::G ? "g" : "m/s^2"; }

// What a CSV header's acceleration column name says about the unit of its values.
enum class HeaderUnit { None, MetresPerSecondSquared, G, Other };

HeaderUnit headerUnit(const std::string &column) {
  std::string s; // lower case, without blanks: "m / s^2" reads as "m/s^2"
  for (char c : column)
    if (!std::isspace((unsigned char)c)) s += (char)std::tolower((unsigned char)c);
  std::vector<std::string> words(1); // lower-case alphanumeric words: "acceleration", "g"
  for (char c : column) {
    if (std::isalnum((unsigned char)c)) words.back() += (char)std::tolower((unsigned char)c);
    else if (!words.back().empty()) words.emplace_back();
  }
  for (const std::string &w : words)
    if (w == "gal" || w == "gals") return HeaderUnit::Other;
  if (s.find("cm/s") != std::string::npos || s.find("mm/s") != std::string::npos) return HeaderUnit::Other;
  for (const char *si : {"m/s^2", "m/s2", "m/s/s", "mps2", "m/s\u00b2"})
    if (s.find(si) != std::string::npos) return HeaderUnit::MetresPerSecondSquared;
  for (const std::string &w : words)
    if (w == "g") return HeaderUnit::G;
  return HeaderUnit::None;
}

// The unit the values are in: the one asked for, checked against the header.
ReadStatus resolveUnit(const std::string &path, const std::string &header, AccelerationUnit asked, AccelerationUnit *unit) {
  const size_t     comma  = header.find(',');
  const std::string column = trim(comma == std::string::npos ? std::string() : header.substr(comma + 1));
  const HeaderUnit named  = headerUnit(column);
  if (named == HeaderUnit::Other)
    return failure(path, 1, "the header's acceleration column \"" + column + "\" names a unit that is neither g nor m/s^2 (convert the values)");
  const AccelerationUnit from_header = named == HeaderUnit::G ? AccelerationUnit::G : AccelerationUnit::MetresPerSecondSquared;
  *unit = asked == AccelerationUnit::FromHeader ? from_header : asked;
  if (named != HeaderUnit::None && *unit != from_header)
    return failure(path, 1, std::string("the header's acceleration column \"") + column + "\" is in " + unitName(from_header) + ", not in " + unitName(*unit) +
                                " as asked");
  return {};
}

} // namespace

ReadStatus readAccelerationCsv(const std::string &path, GroundMotionRecord *record, AccelerationUnit unit) {
  std::ifstream in(path);
  if (!in) return failure(path, 0, "cannot open the file");
  record->time.clear(), record->acceleration.clear();
  std::string line, header;
  int line_no = 0, previous_line = 0;
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
    if (!t_ok) return failure(path, line_no, "time \"" + trim(line.substr(0, comma)) + "\" is not a number");
    if (!a_ok) return failure(path, line_no, "acceleration \"" + trim(line.substr(comma + 1)) + "\" is not a number");
    if (!record->time.empty() && !(t > record->time.back())) {
      std::ostringstream msg;
      msg.precision(15);
      msg << "time " << t << " is not after the time " << record->time.back() << " on line " << previous_line
          << "; times must increase strictly";
      return failure(path, line_no, msg.str());
    }
    record->time.push_back(t), record->acceleration.push_back(a);
    previous_line = line_no;
  }
  if (record->time.size() < 2)
    return failure(path, 0, "needs at least 2 samples, found " + std::to_string(record->time.size()));
  const ReadStatus unit_status = resolveUnit(path, header, unit, &record->file_unit);
  if (!unit_status.ok) return unit_status;
  if (record->file_unit == AccelerationUnit::G)
    for (double &a : record->acceleration) a *= kStandardGravity;
  return {};
}

ReadStatus readPeerAt2(const std::string &path, GroundMotionRecord *record) {
  std::ifstream in(path);
  if (!in) return failure(path, 0, "cannot open the file");
  record->time.clear(), record->acceleration.clear();
  std::string line;
  for (int k = 1; k <= 4; ++k)
    if (!std::getline(in, line)) return failure(path, k, "file ends inside the 4 header lines");
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
  record->file_unit = AccelerationUnit::G;

  int line_no = 4;
  while (std::getline(in, line)) {
    ++line_no;
    std::istringstream tokens(line);
    std::string token;
    while (tokens >> token) {
      double g;
      if (!parseNumber(token, &g)) return failure(path, line_no, "value \"" + token + "\" is not a number");
      if (static_cast<long>(record->acceleration.size()) == npts)
        return failure(path, line_no, "more values than NPTS = " + std::to_string(npts) + " (line 4)");
      record->time.push_back(static_cast<double>(record->acceleration.size()) * dt);
      record->acceleration.push_back(g * kStandardGravity);
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
