// Seams and poles from the declared periodic axes and from samples of every patch edge.
#include "edge_gluing.hpp"

#include "genmod/kernel/point_evaluator.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace genmod::parametric {

GridPoint edge_point(const EdgeRef& e, std::int64_t t) {
  switch (e.side) {
    case 0: return {e.patch, t, 0};
    case 1: return {e.patch, kGridSize, t};
    case 2: return {e.patch, t, kGridSize};
    default: return {e.patch, 0, t};
  }
}

std::int64_t edge_index(int side, const GridPoint& p) { return side == 0 || side == 2 ? p.u : p.v; }

bool on_edge(int side, const GridPoint& p) {
  switch (side) {
    case 0: return p.v == 0;
    case 1: return p.u == kGridSize;
    case 2: return p.v == kGridSize;
    default: return p.u == 0;
  }
}

namespace {

constexpr int kSamples = 33;
using Point3 = std::array<double, 3>;

double distance(const Point3& a, const Point3& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

struct EdgeSamples {
  EdgeRef edge;
  std::array<Point3, kSamples> at;
  bool finite = true;
};

}  // namespace

EdgeTopology find_edge_topology(const std::vector<SurfacePatch>& patches, const std::vector<CompiledPatch>& compiled,
                                const AdaptiveMeshOptions& options) {
  EdgeTopology topology;
  std::vector<std::array<bool, 4>> taken(patches.size(), {false, false, false, false});
  for (std::uint32_t p = 0; p < patches.size(); ++p) {
    if (patches[p].periodic_u) {
      topology.glues.push_back({{p, 3}, {p, 1}, false});
      taken[p][1] = taken[p][3] = true;
    }
    if (patches[p].periodic_v) {
      topology.glues.push_back({{p, 0}, {p, 2}, false});
      taken[p][0] = taken[p][2] = true;
    }
  }
  if (!options.glue_edges) return topology;

  // Samples of every free edge, and the extent of all of them for the tolerance.
  PointEvaluator ev;
  std::vector<EdgeSamples> edges;
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (std::uint32_t p = 0; p < patches.size(); ++p)
    for (int side = 0; side < 4; ++side) {
      if (taken[p][side]) continue;
      EdgeSamples e{{p, side}, {}, true};
      for (int k = 0; k < kSamples; ++k) {
        const GridPoint g = edge_point(e.edge, (kGridSize / (kSamples - 1)) * k);
        const double uv[2] = {grid_value(compiled[p].u, g.u), grid_value(compiled[p].v, g.v)};
        const auto s = ev.eval(compiled[p].value, uv);
        for (int j = 0; j < 3; ++j) {
          e.at[k][j] = s[j];
          e.finite = e.finite && std::isfinite(s[j]);
          if (std::isfinite(s[j])) lo[j] = std::min(lo[j], s[j]), hi[j] = std::max(hi[j], s[j]);
        }
      }
      if (e.finite) edges.push_back(e);
    }
  if (edges.empty()) return topology;
  const double extent = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  const double eps = options.glue_tolerance * std::max(extent, 1e-300);

  auto coincide = [&](const EdgeSamples& a, const EdgeSamples& b, bool reversed) {
    for (int k = 0; k < kSamples; ++k)
      if (!(distance(a.at[k], b.at[reversed ? kSamples - 1 - k : k]) <= eps)) return false;
    return true;
  };
  std::vector<bool> used(edges.size(), false);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    bool point = true;
    for (int k = 1; k < kSamples && point; ++k) point = distance(edges[i].at[0], edges[i].at[k]) <= eps;
    if (point) {
      topology.collapsed.push_back(edges[i].edge);
      used[i] = true;
    }
  }
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (used[i]) continue;
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      if (used[j]) continue;
      for (const bool reversed : {false, true})
        if (coincide(edges[i], edges[j], reversed)) {
          topology.glues.push_back({edges[i].edge, edges[j].edge, reversed});
          used[i] = used[j] = true;
          break;
        }
      if (used[i]) break;
    }
  }
  return topology;
}

}  // namespace genmod::parametric
