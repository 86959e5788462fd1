// Ground-motion readers (CSV and PEER .AT2) on small files written here, their error
// messages with line numbers, the trapezoid integration order and the baseline correction.
#include "slipwave/input/ground_motion_record.hpp"

#include "unit_check.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace slipwave::input;

namespace {

std::vector<std::string> &writtenFiles() {
  static std::vector<std::string> files;
  return files;
}

std::string writeFile(const std::string &name, const std::string &text) {
  const std::string path = "/tmp/slipwave_test_gmr_" + std::to_string(getpid()) + "_" + name;
  std::ofstream(path) << text;
  writtenFiles().push_back(path);
  return path;
}

bool mentions(const ReadStatus &s, const std::string &what) { return !s.ok && s.message.find(what) != std::string::npos; }

// a(t) = A sin(w t) sampled every dt on [0, T]; returns max |v_trapezoid - v_exact| with
// the exact v(t) = A (1 - cos(w t)) / w.
double sineVelocityError(double dt) {
  const double A = 2.0, w = 2 * M_PI * 1.5, T = 4.0;
  std::string csv = "time,acceleration\n";
  const int n = static_cast<int>(std::lround(T / dt));
  char buf[64];
  for (int k = 0; k <= n; ++k) {
    std::snprintf(buf, sizeof buf, "%.17g,%.17g\n", k * dt, A * std::sin(w * k * dt));
    csv += buf;
  }
  GroundMotionRecord r;
  const ReadStatus s = readAccelerationCsv(writeFile("sine.csv", csv), &r);
  if (!s.ok) return HUGE_VAL;
  const auto h = velocityHistory(r);
  double err = 0;
  for (size_t k = 0; k < h.times.size(); ++k)
    err = std::fmax(err, std::fabs(h.values[k] - A * (1 - std::cos(w * h.times[k])) / w));
  return err;
}

} // namespace

int main() {
  // Trapezoid error for a sine: global error ~ T dt^2/12 max|a''| = 4 * dt^2/12 * 2 * w^2
  // (w = 3 pi: 59 dt^2), so halving dt divides the error by 4.
  const double e1 = sineVelocityError(0.01), e2 = sineVelocityError(0.005);
  unit::check(e1 < 59 * 0.01 * 0.01, "sine record: trapezoid velocity within T dt^2/12 max|a''| (" + std::to_string(e1) + ")");
  unit::near(e1 / e2, 4.0, 0.05, 0, "sine record: velocity error is O(dt^2) (ratio 4 when dt halves)");

  GroundMotionRecord r;
  ReadStatus s = readAccelerationCsv(writeFile("nohead.csv", "0,1\n0.1, 2.5\n\n0.35,-1e-2\r\n"), &r);
  unit::check(s.ok && r.time.size() == 3 && r.time[2] == 0.35 && r.acceleration[1] == 2.5 && r.acceleration[2] == -0.01,
              "CSV without header, blank line, CRLF, non-uniform times " + s.message);

  s = readAccelerationCsv("/nonexistent/dir/record.csv", &r);
  unit::check(mentions(s, "/nonexistent/dir/record.csv: cannot open"), "missing CSV file named: " + s.message);
  s = readAccelerationCsv(writeFile("nan.csv", "t,a\n0,1\n0.1,abc\n"), &r);
  unit::check(mentions(s, "nan.csv:3: acceleration \"abc\" is not a number"), "non-numeric value at line 3: " + s.message);
  s = readAccelerationCsv(writeFile("unsorted.csv", "t,a\n0,1\n0.2,1\n0.1,1\n"), &r);
  unit::check(mentions(s, "unsorted.csv:4: time 0.1 is not after the time 0.2 on line 3"), "unsorted time at line 4: " + s.message);
  s = readAccelerationCsv(writeFile("three.csv", "0,1\n0.1,1,7\n"), &r);
  unit::check(mentions(s, "three.csv:2: expected two comma-separated values"), "three fields at line 2: " + s.message);
  s = readAccelerationCsv(writeFile("one.csv", "t,a\n0,1\n"), &r);
  unit::check(mentions(s, "at least 2 samples, found 1"), "single sample rejected: " + s.message);

  // Units of a CSV: from the header's acceleration column, or asked for; g converted with
  // g = 9.80665 m/s^2; a contradiction or a unit word not read is an error.
  s = readAccelerationCsv(writeFile("g.csv", "time_s,acceleration_g\n0,0.5\n0.02,-1\n"), &r);
  unit::check(s.ok && r.file_unit == AccelerationUnit::G, "header acceleration_g: read in g " + s.message);
  unit::near(r.acceleration[1], -9.80665, 1e-15, 0, "header acceleration_g: -1 g = -9.80665 m/s^2");
  for (const char *head : {"t,a (g)", "t, acc [g]", "time,Acceleration G"}) {
    s = readAccelerationCsv(writeFile("g2.csv", std::string(head) + "\n0,1\n1,2\n"), &r);
    unit::check(s.ok && r.file_unit == AccelerationUnit::G && r.acceleration[0] == 9.80665, std::string("header '") + head + "': g " + s.message);
  }
  for (const char *head : {"t,a [m/s^2]", "time,acc_mps2", "t,a (m/s2)", "time,acceleration"}) {
    s = readAccelerationCsv(writeFile("si.csv", std::string(head) + "\n0,1\n1,2\n"), &r);
    unit::check(s.ok && r.file_unit == AccelerationUnit::MetresPerSecondSquared && r.acceleration[0] == 1,
                std::string("header '") + head + "': m/s^2 " + s.message);
  }
  s = readAccelerationCsv(writeFile("asked_g.csv", "0,1\n1,2\n"), &r, AccelerationUnit::G);
  unit::check(s.ok && r.acceleration[1] == 2 * 9.80665, "no header, asked for g: converted " + s.message);
  s = readAccelerationCsv(writeFile("clash.csv", "time_s,acceleration_g\n0,1\n1,2\n"), &r, AccelerationUnit::MetresPerSecondSquared);
  unit::check(mentions(s, "clash.csv:1: the header's acceleration column \"acceleration_g\" is in g, not in m/s^2 as asked"), "g header vs m/s^2 asked: " + s.message);
  // A header naming cm/s^2 (in any of its spellings: the "acceleration_cm_s2" was read
  // as m/s^2, a PGA 100 times too large) is read in cm/s^2: 1 cm/s^2 = 0.01 m/s^2.
  for (const char *head : {"t,acc (cm/s^2)", "time_s,acceleration_cm_s2", "time,acceleration_cm/s^2", "t,acc gal", "t,a [cm/s/s]", "time,ground_acceleration_cmps2"}) {
    s = readAccelerationCsv(writeFile("cm.csv", std::string(head) + "\n0,1\n1,250\n"), &r);
    unit::check(s.ok && r.file_unit == AccelerationUnit::CentimetresPerSecondSquared && r.acceleration[1] == 2.5,
                std::string("header '") + head + "': cm/s^2, 250 cm/s^2 = 2.5 m/s^2 " + s.message);
  }
  for (const char *head : {"time_s,acceleration_m_s2", "t,acceleration m/s/s"}) {
    s = readAccelerationCsv(writeFile("si2.csv", std::string(head) + "\n0,1\n1,2\n"), &r);
    unit::check(s.ok && r.file_unit == AccelerationUnit::MetresPerSecondSquared && r.acceleration[1] == 2, std::string("header '") + head + "': m/s^2 " + s.message);
  }
  s = readAccelerationCsv(writeFile("ft.csv", "time_s,acceleration_ft_s2\n0,1\n1,2\n"), &r);
  unit::check(mentions(s, "ft.csv:1: the header's acceleration column \"acceleration_ft_s2\" names the unit \"ft_s2\", which is not one slipwave reads (g; m/s^2"),
              "unknown unit word named with the allowed ones: " + s.message);
  s = readAccelerationCsv(writeFile("cm_vs_g.csv", "time_s,acceleration_cm_s2\n0,1\n1,2\n"), &r, AccelerationUnit::G);
  unit::check(mentions(s, "the header's acceleration column \"acceleration_cm_s2\" is in cm/s^2, not in g as asked"), "cm/s^2 header vs g asked: " + s.message);
  s = readAccelerationCsv(writeFile("factor.csv", "time,load_factor\n0,1\n1,2\n"), &r, AccelerationUnit::Factor);
  unit::check(s.ok && r.acceleration[1] == 2, "a load factor's header is not read for a unit " + s.message);
  // Absurd values: beyond 1e6 m/s^2 after conversion, refused with their line.
  s = readAccelerationCsv(writeFile("huge.csv", "time,acceleration\n0,1\n0.01,1e200\n"), &r);
  unit::check(mentions(s, "huge.csv:3: acceleration 1e200 m/s^2 is absurd (more than 1e6 m/s^2"), "1e200 m/s^2 refused at line 3: " + s.message);
  s = readAccelerationCsv(writeFile("huge_g.csv", "time,acceleration_g\n0,1\n0.01,2e5\n"), &r);
  unit::check(mentions(s, "huge_g.csv:3: acceleration 2e5 g is absurd"), "2e5 g (1.96e6 m/s^2) refused: " + s.message);
  s = readAccelerationCsv(writeFile("big_ok.csv", "time,acceleration\n0,1\n0.01,9.9e5\n"), &r);
  unit::check(s.ok, "9.9e5 m/s^2 (below the limit) read " + s.message);

  // AT2, keyed header form; values in g, 3 per line, last line short.
  const std::string head = "PEER NGA STRONG MOTION DATABASE RECORD\nTest event, station, 090\n"
                           "ACCELERATION TIME SERIES IN UNITS OF G\n";
  s = readPeerAt2(writeFile("keyed.AT2", head + "NPTS=     5, DT=   .0050 SEC\n  .1000E-01 -.2000E-01  .0\n  1.0 -0.5\n"), &r);
  unit::check(s.ok && r.time.size() == 5, "AT2 keyed header form parsed " + s.message);
  unit::near(r.time[4], 4 * 0.005, 1e-15, 0, "AT2 time of sample 4 = 4 DT");
  unit::near(r.acceleration[1], -0.02 * 9.80665, 1e-15, 0, "AT2 value converted from g with g = 9.80665");
  unit::near(r.acceleration[3], 9.80665, 1e-15, 0, "AT2 value on the second data line");
  s = readPeerAt2(writeFile("positional.AT2", head + "    4    0.0100    NPTS, DT\n0.1 0.2 0.3 0.4\n"), &r);
  unit::check(s.ok && r.time.size() == 4, "AT2 positional header form parsed " + s.message);
  unit::near(r.time[3], 0.03, 1e-15, 0, "AT2 positional DT = 0.01");
  s = readPeerAt2(writeFile("short.AT2", head + "NPTS= 5, DT= .005 SEC\n0.1 0.2\n0.3 0.4\n"), &r);
  unit::check(mentions(s, "short.AT2:6: file ends after 4 values but NPTS = 5"), "NPTS mismatch (too few): " + s.message);
  s = readPeerAt2(writeFile("long.AT2", head + "NPTS= 2, DT= .005 SEC\n0.1 0.2\n0.3\n"), &r);
  unit::check(mentions(s, "long.AT2:6: more values than NPTS = 2"), "NPTS mismatch (too many) at line 6: " + s.message);
  s = readPeerAt2(writeFile("bad.AT2", head + "NPTS= 3, DT= .005 SEC\n0.1 0.2\n0.3x\n"), &r);
  unit::check(mentions(s, "bad.AT2:6: value \"0.3x\" is not a number"), "non-numeric AT2 value at line 6: " + s.message);
  s = readPeerAt2(writeFile("nohdr.AT2", head + "this line has no counts\n0.1\n"), &r);
  unit::check(mentions(s, "nohdr.AT2:4: cannot find NPTS and DT"), "AT2 header without NPTS at line 4: " + s.message);
  s = readPeerAt2(writeFile("trunc.AT2", "only one line\n"), &r);
  unit::check(mentions(s, "trunc.AT2:2: file ends inside the 4 header lines"), "truncated AT2 header: " + s.message);
  // The third line's "UNITS OF": G read as g (above); CM/S/S honoured; an unknown unit refused;
  // a unit other than the one asked for refused.
  const std::string cm_head = "PEER\nevent\nACCELERATION TIME SERIES IN UNITS OF CM/S/S\nNPTS= 2, DT= .01 SEC\n100 -50\n";
  s = readPeerAt2(writeFile("cm.AT2", cm_head), &r);
  unit::check(s.ok && r.file_unit == AccelerationUnit::CentimetresPerSecondSquared && r.acceleration[0] == 1 && r.acceleration[1] == -0.5,
              "AT2 UNITS OF CM/S/S: 100 cm/s^2 = 1 m/s^2 " + s.message);
  s = readPeerAt2(writeFile("cm.AT2", cm_head), &r, AccelerationUnit::G);
  unit::check(mentions(s, "cm.AT2: its header gives the values in cm/s^2, not in g as asked"), "AT2 cm/s^2 header vs g asked: " + s.message);
  s = readPeerAt2(writeFile("in.AT2", "PEER\nevent\nIN UNITS OF INCHES\nNPTS= 2, DT= .01 SEC\n1 2\n"), &r);
  unit::check(mentions(s, "in.AT2:3: the header says \"UNITS OF INCHES\", a unit slipwave does not read"), "AT2 unknown unit: " + s.message);
  s = readPeerAt2(writeFile("huge.AT2", head + "NPTS= 2, DT= .01 SEC\n0.1 1e200\n"), &r);
  unit::check(mentions(s, "huge.AT2:5: acceleration 1e200 g is absurd"), "AT2 1e200 g refused at line 5: " + s.message);

  // Baseline: a0 = any record with its drift removed; adding c0 + c1 t back and correcting
  // again must give a0 (the correction is exact for the discrete integrals), and the
  // corrected record ends at rest: final velocity and displacement zero.
  GroundMotionRecord b;
  for (int k = 0; k <= 400; ++k) {
    const double t = 0.01 * k + 0.002 * std::sin(k);  // non-uniform sampling
    b.time.push_back(t), b.acceleration.push_back(std::sin(7 * t) + 0.3 * std::cos(2 * t) + 0.05);
  }
  removeBaselineDrift(&b);
  const std::vector<double> a0 = b.acceleration;
  const std::vector<double> v = integrateTrapezoid(b.time, b.acceleration);
  unit::near(v.back(), 0, 0, 1e-14, "baseline: final velocity zero");
  unit::near(integrateTrapezoid(b.time, v).back(), 0, 0, 1e-14, "baseline: final displacement zero");
  for (size_t k = 0; k < b.time.size(); ++k) b.acceleration[k] += 0.2 - 0.07 * (b.time[k] - b.time[0]);
  removeBaselineDrift(&b);
  double worst = 0;
  for (size_t k = 0; k < b.time.size(); ++k) worst = std::fmax(worst, std::fabs(b.acceleration[k] - a0[k]));
  unit::near(worst, 0, 0, 1e-13, "baseline: removes exactly an added c0 + c1 t");
  for (const std::string &f : writtenFiles()) std::remove(f.c_str());
  return unit::failures();
}
