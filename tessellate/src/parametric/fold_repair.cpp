// fold_repair.hpp: the fold test per triangle and the split of folded leaves.
#include "fold_repair.hpp"

#include "genmod/kernel/point_evaluator.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace genmod::parametric {

namespace {
using Vec = std::array<double, 3>;
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
}  // namespace

std::vector<std::uint32_t> folded_leaves(const std::vector<CompiledPatch>& patches, const LeafTriangulation& tri,
                                         const std::vector<Vec>& at, const std::vector<LeafTriangle>& triangles) {
  std::vector<std::uint8_t> folded(triangles.size(), 0);
  tbb::enumerable_thread_specific<PointEvaluator> evaluators;
  tbb::parallel_for(std::size_t{0}, triangles.size(), [&](std::size_t i) {
    const auto& p = triangles[i].points;
    const Vec& a = at[tri.representative[p[0]]];
    const Vec n = cross(sub(at[tri.representative[p[1]]], a), sub(at[tri.representative[p[2]]], a));
    const CompiledPatch& c = patches[tri.points[p[0]].patch];
    double uv[2] = {0.0, 0.0};
    for (std::uint32_t k : p) {
      uv[0] += grid_value(c.u, tri.points[k].u) / 3.0;
      uv[1] += grid_value(c.v, tri.points[k].v) / 3.0;
    }
    const auto j = evaluators.local().eval(c.jacobian, uv);
    const Vec normal = cross({j[0], j[1], j[2]}, {j[3], j[4], j[5]});
    folded[i] = dot(n, normal) < 0.0;  // NaN (undefined Jacobian) decides nothing
  });
  std::vector<std::uint32_t> leaves;
  for (std::size_t i = 0; i < triangles.size(); ++i)
    if (folded[i]) leaves.push_back(triangles[i].leaf);
  std::sort(leaves.begin(), leaves.end());
  leaves.erase(std::unique(leaves.begin(), leaves.end()), leaves.end());
  return leaves;
}

std::size_t split_leaves(const std::vector<CompiledPatch>& patches, std::vector<std::vector<Leaf>>& leaves,
                         const std::vector<std::uint32_t>& which, int max_depth) {
  const std::int64_t finest = kGridSize >> max_depth;
  PointEvaluator ev;
  std::size_t split = 0, flat = 0, next = 0;
  for (std::size_t p = 0; p < leaves.size(); ++p) {
    std::vector<Leaf> out;
    for (const Leaf& l : leaves[p]) {
      const bool chosen = next < which.size() && which[next] == flat;
      next += chosen ? 1 : 0;
      ++flat;
      const GridRect& r = l.rect;
      const bool can_u = r.u1 - r.u0 > finest, can_v = r.v1 - r.v0 > finest;
      if (!chosen || !(can_u || can_v)) {
        out.push_back(l);
        continue;
      }
      const CompiledPatch& c = patches[p];
      const double du = grid_value(c.u, r.u1) - grid_value(c.u, r.u0), dv = grid_value(c.v, r.v1) - grid_value(c.v, r.v0);
      const double mid[2] = {grid_value(c.u, (r.u0 + r.u1) / 2), grid_value(c.v, (r.v0 + r.v1) / 2)};
      const auto j = ev.eval(c.jacobian, mid);
      const double along_u = std::hypot(j[0], j[1], j[2]) * du, along_v = std::hypot(j[3], j[4], j[5]) * dv;
      // Split across the longer side (an undefined Jacobian: the longer parameter side).
      bool split_u = std::isfinite(along_u) && std::isfinite(along_v) ? along_u >= along_v : du >= dv;
      if (!can_u) split_u = false;
      if (!can_v) split_u = true;
      Leaf lo = l, hi = l;
      if (split_u) {
        lo.rect.u1 = hi.rect.u0 = (r.u0 + r.u1) / 2;
      } else {
        lo.rect.v1 = hi.rect.v0 = (r.v0 + r.v1) / 2;
      }
      out.push_back(lo);
      out.push_back(hi);
      ++split;
    }
    leaves[p] = std::move(out);
  }
  return split;
}

}  // namespace genmod::parametric
