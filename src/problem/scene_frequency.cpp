#include "slipwave/problem/scene_frequency.hpp"

#include "slipwave/input/drm.hpp"

namespace slipwave::problem {

SceneFrequency SceneTopFrequency(const Elastodynamics &model) {
  SceneFrequency top;
  const auto     consider = [&top](const input::TimeFunction &history, const std::string &source) {
    if (!history.active()) return;
    const double f = history.topFrequency();
    if (f > top.hz) top = {f, source};
  };
  consider(model.bc.input, "the input wave");
  if (model.drm) {
    const double f = input::DrmTopFrequency(model.drm);
    if (f > top.hz) top = {f, "the DRM incident wave"};
  }
  for (const input::PrescribedVelocity &v : model.bc.prescribed) consider(v.history, "velocity " + v.boundary);
  for (const input::TimedLoad &load : model.bc.timed_loads) consider(load.history, load.name);
  return top;
}

double RegionNodesPerWavelength(const Elastodynamics &model, PetscInt region, double f) {
  return (double)model.bulk.degree() * model.materials[region].elastic.vs / f / model.bulk.regionElementSize(region);
}

} // namespace slipwave::problem
