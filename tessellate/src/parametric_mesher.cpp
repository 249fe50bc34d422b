// mesh_adaptive (parametric_mesher.hpp): subdivision, seams, triangulation, vertices,
// orientation.
#include "genmod/tessellate/parametric_mesher.hpp"

#include "parametric/edge_gluing.hpp"
#include "parametric/fold_repair.hpp"
#include "parametric/kd_subdivision.hpp"
#include "parametric/leaf_triangulation.hpp"
#include "parametric/mesh_orientation.hpp"
#include "thread_arena.hpp"

#include "genmod/kernel/point_evaluator.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

namespace genmod {

namespace {

using parametric::CompiledPatch;
using parametric::GridPoint;

void check_input(const std::vector<SurfacePatch>& patches, const AdaptiveMeshOptions& o) {
  const std::string who = "genmod: mesh_adaptive: ";
  if (patches.empty()) throw std::invalid_argument(who + "no patches to mesh");
  if (!(std::isfinite(o.tolerance) && o.tolerance > 0.0))
    throw std::invalid_argument(who + "tolerance must be a positive finite number, got " + std::to_string(o.tolerance));
  if (o.unbounded_depth < 0) throw std::invalid_argument(who + "unbounded_depth must be >= 0");
  if (o.max_depth < 0 || o.max_depth > parametric::kGridBits - 2)
    throw std::invalid_argument(who + "max_depth must be in [0, " + std::to_string(parametric::kGridBits - 2) +
                                "], got " + std::to_string(o.max_depth));
  if (o.max_leaves == 0) throw std::invalid_argument(who + "max_leaves must be at least 1");
  if (!(std::isfinite(o.max_seconds) && o.max_seconds >= 0.0))
    throw std::invalid_argument(who + "max_seconds must be >= 0 (0 = no limit)");
  if (!(std::isfinite(o.glue_tolerance) && o.glue_tolerance >= 0.0))
    throw std::invalid_argument(who + "glue_tolerance must be >= 0");
  for (std::size_t p = 0; p < patches.size(); ++p) {
    const std::string name = who + "patch " + std::to_string(p) + ": ";
    const SurfacePatch& s = patches[p];
    if (s.surface.dim() != 3)
      throw std::invalid_argument(name + "the surface must have 3 components, got " + std::to_string(s.surface.dim()));
    for (int i : s.surface.inputs())
      if (i > 1)
        throw std::invalid_argument(name + "the surface depends on x(" + std::to_string(i) +
                                    "); a surface is a function of u = x(0) and v = x(1)");
    for (const auto& [axis, r] : {std::pair{"u", s.u}, std::pair{"v", s.v}})
      if (r.is_empty() || !r.is_bounded() || !(r.hi() > r.lo()))
        throw std::invalid_argument(name + "the " + axis + " range must be bounded with positive width");
  }
}

// Every sample point, evaluated once; a point where the surface is undefined is an error.
std::vector<std::array<double, 3>> evaluate_points(const std::vector<CompiledPatch>& compiled,
                                                   const parametric::LeafTriangulation& tri) {
  std::vector<std::array<double, 3>> at(tri.points.size());
  tbb::enumerable_thread_specific<PointEvaluator> evaluators;
  tbb::parallel_for(std::size_t{0}, tri.points.size(), [&](std::size_t i) {
    const GridPoint& g = tri.points[i];
    const CompiledPatch& c = compiled[g.patch];
    const double uv[2] = {parametric::grid_value(c.u, g.u), parametric::grid_value(c.v, g.v)};
    const auto s = evaluators.local().eval(c.value, uv);
    at[i] = {s[0], s[1], s[2]};
  });
  for (std::size_t i = 0; i < at.size(); ++i)
    if (!std::isfinite(at[i][0]) || !std::isfinite(at[i][1]) || !std::isfinite(at[i][2])) {
      const GridPoint& g = tri.points[i];
      std::ostringstream msg;
      msg.precision(17);
      msg << "genmod: mesh_adaptive: patch " << g.patch << ": the surface is undefined at (u, v) = ("
          << parametric::grid_value(compiled[g.patch].u, g.u) << ", "
          << parametric::grid_value(compiled[g.patch].v, g.v) << ")";
      throw std::domain_error(msg.str());
    }
  return at;
}

// The mesh's triangles as triangulation points: the leaves' triangles, then each quad split
// along its shorter diagonal in space (a collapsed diagonal keeps the other). Triangles with
// a repeated vertex (at poles) are dropped and counted.
std::vector<parametric::LeafTriangle> mesh_triangles(const parametric::LeafTriangulation& tri,
                                                     const std::vector<std::array<double, 3>>& at,
                                                     std::size_t& dropped) {
  dropped = 0;
  std::vector<parametric::LeafTriangle> out;
  auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t leaf) {
    const std::uint32_t ra = tri.representative[a], rb = tri.representative[b], rc = tri.representative[c];
    if (ra == rb || rb == rc || ra == rc) {
      ++dropped;
      return;
    }
    out.push_back({{a, b, c}, leaf});
  };
  auto distance2 = [&](std::uint32_t a, std::uint32_t b) {
    const auto& p = at[tri.representative[a]];
    const auto& q = at[tri.representative[b]];
    return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
  };
  for (std::size_t i = 0; i < tri.triangles.size(); ++i) {
    const auto& t = tri.triangles[i];
    emit(t[0], t[1], t[2], tri.triangle_leaf[i]);
  }
  for (std::size_t i = 0; i < tri.quads.size(); ++i) {
    const auto& q = tri.quads[i];
    const std::uint32_t leaf = tri.quad_leaf[i];
    const double d02 = distance2(q[0], q[2]), d13 = distance2(q[1], q[3]);
    if (d13 == 0.0 || (d02 > 0.0 && d02 <= d13)) {
      emit(q[0], q[1], q[2], leaf);
      emit(q[0], q[2], q[3], leaf);
    } else {
      emit(q[0], q[1], q[3], leaf);
      emit(q[1], q[2], q[3], leaf);
    }
  }
  return out;
}

}  // namespace

AdaptiveMesh mesh_adaptive(const std::vector<SurfacePatch>& patches, const AdaptiveMeshOptions& options) {
  check_input(patches, options);
  AdaptiveMesh result;
  raster_detail::run_with_threads(options.threads, "mesh_adaptive", [&] {
    std::vector<CompiledPatch> compiled;
    compiled.reserve(patches.size());
    for (const SurfacePatch& p : patches) compiled.push_back(parametric::compile_patch(p));

    const parametric::Subdivision tree = parametric::subdivide(compiled, options);
    result.interval_evaluations = tree.interval_evaluations;
    result.limits_hit = tree.limits_hit;
    const parametric::EdgeTopology topology = parametric::find_edge_topology(patches, compiled, options);
    std::set<std::pair<std::uint32_t, int>> glued;
    for (const auto& g : topology.glues) glued.insert({g.a.patch, g.a.side}), glued.insert({g.b.patch, g.b.side});
    result.glued_edges = glued.size();
    result.collapsed_edges = topology.collapsed.size();

    // Triangulate; split the leaves of folded triangles (fold_repair.hpp) and again, a few
    // rounds at most (each halves the folded leaves; the bear's folds go in one or two).
    constexpr int kFoldRounds = 8;
    std::vector<std::vector<parametric::Leaf>> leaves = tree.leaves;
    parametric::LeafTriangulation tri;
    std::vector<std::array<double, 3>> at;
    std::vector<parametric::LeafTriangle> triangles;
    for (int round = 0;; ++round) {
      tri = parametric::triangulate_leaves(leaves, topology);
      at = evaluate_points(compiled, tri);
      triangles = mesh_triangles(tri, at, result.dropped_triangles);
      if (round == kFoldRounds) break;
      const std::vector<std::uint32_t> folded = parametric::folded_leaves(compiled, tri, at, triangles);
      if (folded.empty() || parametric::split_leaves(compiled, leaves, folded, options.max_depth) == 0) break;
    }
    for (const auto& patch_leaves : leaves) {
      result.leaves += patch_leaves.size();
      for (const parametric::Leaf& l : patch_leaves) {
        result.distance_bound = std::max(result.distance_bound, l.bound);
        if (!std::isfinite(l.bound)) ++result.unbounded_leaves;
      }
    }

    // Vertices: one per representative, numbered in point order.
    std::vector<std::uint32_t> vertex(tri.points.size(), UINT32_MAX);
    for (std::size_t i = 0; i < tri.points.size(); ++i) {
      const std::uint32_t r = tri.representative[i];
      const auto& a = at[i];
      const auto& b = at[r];
      result.seam_deviation = std::max(result.seam_deviation, std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
    }
    auto vertex_of = [&](std::uint32_t point) {
      const std::uint32_t r = tri.representative[point];
      if (vertex[r] == UINT32_MAX) {
        vertex[r] = static_cast<std::uint32_t>(result.mesh.vertices.size());
        result.mesh.vertices.push_back(at[r]);
      }
      return vertex[r];
    };
    for (const parametric::LeafTriangle& t : triangles)
      result.mesh.triangles.push_back({vertex_of(t.points[0]), vertex_of(t.points[1]), vertex_of(t.points[2])});
    if (std::isfinite(result.distance_bound)) result.distance_bound += result.seam_deviation;

    const parametric::OrientationReport orientation = parametric::orient_outward(result.mesh);
    result.boundary_edges = orientation.boundary_edges;
    result.flipped_components = orientation.flipped_components;
  });
  return result;
}

}  // namespace genmod
