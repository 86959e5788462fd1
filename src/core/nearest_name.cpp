#include "slipwave/core/nearest_name.hpp"

#include <algorithm>

namespace slipwave::core {

size_t EditDistance(const std::string &a, const std::string &b) {
  const size_t                     n = a.size(), m = b.size();
  std::vector<std::vector<size_t>> d(n + 1, std::vector<size_t>(m + 1));
  for (size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (size_t i = 1; i <= n; ++i)
    for (size_t j = 1; j <= m; ++j) {
      const size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j]           = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

std::string NearestName(const std::string &name, const std::vector<std::string> &candidates) {
  std::string best;
  size_t      best_distance = std::min<size_t>(2, name.size() / 3) + 1;
  for (const std::string &c : candidates) {
    const size_t d = EditDistance(name, c);
    if (d > 0 && d < best_distance) best = c, best_distance = d;
  }
  return best;
}

} // namespace slipwave::core
