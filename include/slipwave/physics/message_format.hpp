// printf-style formatting of up to three numbers into a message sentence, for the kernels
// that explain a value they refuse or doubt (elastic_material, plausible_values).
#pragma once
#include <cstdio>
#include <string>

namespace slipwave::physics {

inline std::string formatMessage(const char *fmt, double a, double b = 0, double c = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, a, b, c);
  return buf;
}

} // namespace slipwave::physics
