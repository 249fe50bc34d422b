// model_patches: the one list of surfaces a mesher needs for a gallery model.
#include "genmod/models/gallery.hpp"

#include "genmod/kernel/point_evaluator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace genmod::models {

namespace {

constexpr int kUv[2] = {0, 1};

// Face k = end of the solid S(u, v, w): coordinate k fixed at that end, the other two
// (ascending) renamed to x(0), x(1).
SurfacePatch solid_face(const Fn& solid, const Interval domain[3], int k, int end) {
  const int a = k == 0 ? 1 : 0, b = k == 2 ? 1 : 2;
  const Fn fixed = compose(solid, k, Fn(end == 0 ? domain[k].lo() : domain[k].hi()));
  const int from[2] = {a, b};
  return {compose_all(fixed, from, cat({x(0), x(1)})), domain[a], domain[b]};
}

// True when two faces are the same surface at sampled points (a solid swept all the way
// around, whose first and last faces meet inside it).
bool same_face(const SurfacePatch& f, const SurfacePatch& g) {
  const Tape tf(f.surface, kUv), tg(g.surface, kUv);
  PointEvaluator ef, eg;
  constexpr int n = 7;
  double extent = 0.0, gap = 0.0;
  std::array<double, 3> first{};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = f.u.lo() + (f.u.hi() - f.u.lo()) * i / (n - 1), v = f.v.lo() + (f.v.hi() - f.v.lo()) * j / (n - 1);
      const auto p = ef.eval(tf, {u, v});
      const auto q = eg.eval(tg, {u, v});
      if (i == 0 && j == 0) first = {p[0], p[1], p[2]};
      extent = std::max(extent, std::hypot(p[0] - first[0], p[1] - first[1], p[2] - first[2]));
      const double d = std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
      if (std::isnan(d)) return false;  // undefined there: not known to coincide
      gap = std::max(gap, d);
    }
  return gap <= 1e-9 * extent;
}

// The six boundary faces of a solid.
std::vector<ModelPatch> solid_faces(const Model& model, const Fn& surface) {
  if (surface.dim() != 3) throw std::invalid_argument("solid model '" + model.name + "' must have 3 outputs");
  const Interval domain[3] = {model.u, model.v, model.w};
  std::vector<SurfacePatch> faces;
  for (int k = 0; k < 3; ++k) {
    SurfacePatch lo = solid_face(surface, domain, k, 0), hi = solid_face(surface, domain, k, 1);
    if (same_face(lo, hi)) continue;  // closed up: the two faces are inside the solid
    faces.push_back(std::move(lo));
    faces.push_back(std::move(hi));
  }
  return faces;
}

}  // namespace

std::vector<ModelPatch> model_patches(const Model& model, const Fn& surface, const ParameterValues& p) {
  if (model.solid) return solid_faces(model, surface);
  std::vector<ModelPatch> patches;
  if (!model.surface_in_extra_patches) patches.push_back({surface, model.u, model.v, model.periodic_u, model.periodic_v});
  if (model.extra_patches) {
    std::vector<ModelPatch> extra = model.extra_patches(p);
    patches.insert(patches.end(), extra.begin(), extra.end());
  }
  return patches;
}

}  // namespace genmod::models
