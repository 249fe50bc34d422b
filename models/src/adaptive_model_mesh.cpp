// Gallery models meshed by the adaptive parametric mesher: the model's extent (the scale of
// the default tolerance) and its patches handed to mesh_adaptive, which glues shared edges.
#include "genmod/models/gallery.hpp"

#include "genmod/kernel/point_evaluator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace genmod::models {

namespace {
constexpr int kUv[2] = {0, 1};
}  // namespace

double model_extent(const Model& model, const Fn& surface, const ParameterValues& params) {
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  PointEvaluator ev;
  constexpr int n = 17;
  for (const SurfacePatch& p : model_patches(model, surface, params)) {
    const Tape t(p.surface, kUv);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const auto s = ev.eval(t, {p.u.lo() + (p.u.hi() - p.u.lo()) * i / (n - 1),
                                   p.v.lo() + (p.v.hi() - p.v.lo()) * j / (n - 1)});
        for (int k = 0; k < 3; ++k)
          if (std::isfinite(s[k])) lo[k] = std::min(lo[k], s[k]), hi[k] = std::max(hi[k], s[k]);
      }
  }
  const double d = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  if (!(d > 0.0) || !std::isfinite(d))
    throw std::invalid_argument("model '" + model.name + "': its surface has no finite extent at the sampled points");
  return d;
}

AdaptiveMesh mesh_model_adaptive(const Model& model, const Fn& surface, const ParameterValues& p,
                                 const AdaptiveMeshOptions& options) {
  return mesh_adaptive(model_patches(model, surface, p), options);
}

}  // namespace genmod::models
