// Cells (or spectral elements) that share their element matrices: same region and same node
// positions relative to their first node, rounded to a quantum (1e-12 of the mesh's extent),
// so every cell of a box-mesh region falls in one class. The key of that class, for a hash map.
#pragma once
#include <cmath>
#include <string>

namespace slipwave::fem {

inline std::string geometryKey(long long region, const double *coords, int nnode, int dim, double quantum) {
  std::string key(reinterpret_cast<const char *>(&region), sizeof region);
  for (int a = 0; a < nnode; ++a)
    for (int i = 0; i < dim; ++i) {
      const long long q = std::llround((coords[a * dim + i] - coords[i]) / quantum);
      key.append(reinterpret_cast<const char *>(&q), sizeof q);
    }
  return key;
}

} // namespace slipwave::fem
