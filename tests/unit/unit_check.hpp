// Minimal checks for the pure-function unit tests: each check prints one TAP-like line
// ("ok - ..." / "not ok - ...") that tests/run_tests.sh counts; main returns failures().
#pragma once
#include <cmath>
#include <cstdio>
#include <string>

namespace unit {

inline int &failureCount() {
  static int n = 0;
  return n;
}

inline void report(bool pass, const std::string &what, const std::string &detail = "") {
  if (pass) {
    std::printf("ok - %s\n", what.c_str());
  } else {
    ++failureCount();
    std::printf("not ok - %s %s\n", what.c_str(), detail.c_str());
  }
}

inline void check(bool cond, const std::string &what) { report(cond, what); }

// |got - want| <= tol_abs + tol_rel*|want|
inline void near(double got, double want, double tol_rel, double tol_abs, const std::string &what) {
  const bool pass = std::isfinite(got) && std::fabs(got - want) <= tol_abs + tol_rel * std::fabs(want);
  char buf[160];
  std::snprintf(buf, sizeof buf, "(got %.15g, want %.15g, tol_rel %.1e, tol_abs %.1e)", got, want, tol_rel, tol_abs);
  report(pass, what, buf);
}

inline int failures() { return failureCount() > 0 ? 1 : 0; }

} // namespace unit
