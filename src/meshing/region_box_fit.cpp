#include "slipwave/meshing/region_box_fit.hpp"

#include <algorithm>
#include <cmath>

namespace slipwave::meshing {

RegionBoxFit RegionBoxOnMesh(int dim, const BoxSpec &box, const std::vector<double> &region_box) {
  RegionBoxFit fit;
  fit.meshed.resize(2 * dim);
  for (int d = 0; d < dim; ++d) {
    const double lower = box.lower[d], upper = box.upper[d], h = (upper - lower) / box.faces[d];
    const double bmin = region_box[2 * d], bmax = region_box[2 * d + 1], tol = kRegionBoxFitTolerance * h;
    // Cell k (0 .. faces-1) has its centroid at lower + (k + 1/2) h: the first and last inside.
    const double k_first = std::max(0.0, std::ceil((bmin - lower) / h - 0.5));
    const double k_last  = std::min((double)box.faces[d] - 1, std::floor((bmax - lower) / h - 0.5));
    if (k_first > k_last) {
      fit.empty = true;
      fit.meshed[2 * d] = fit.meshed[2 * d + 1] = bmin;
      continue;
    }
    const double meshed_min = lower + k_first * h, meshed_max = lower + (k_last + 1) * h;
    fit.meshed[2 * d]     = meshed_min;
    fit.meshed[2 * d + 1] = meshed_max;
    if (bmin > lower + tol && std::fabs(bmin - meshed_min) > tol) fit.fits = false;
    if (bmax < upper - tol && std::fabs(bmax - meshed_max) > tol) fit.fits = false;
  }
  if (fit.empty) fit.fits = true;
  return fit;
}

} // namespace slipwave::meshing
