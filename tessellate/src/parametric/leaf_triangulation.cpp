// Grid lines of leaf corners per patch, exchanged across glued edges, then one polygon per
// leaf and a union-find over the points for seams and poles.
#include "leaf_triangulation.hpp"

#include "union_find.hpp"

#include <algorithm>
#include <unordered_map>

namespace genmod::parametric {

using tessellate_detail::UnionFind;

namespace {

// The leaf corners of one patch on each grid line: rows[v] = sorted u's, cols[u] = sorted v's.
struct GridLines {
  std::unordered_map<std::int64_t, std::vector<std::int64_t>> rows, cols;

  void add(std::int64_t u, std::int64_t v) {
    rows[v].push_back(u);
    cols[u].push_back(v);
  }
  std::vector<std::int64_t>& edge_line(int side) {
    switch (side) {
      case 0: return rows[0];
      case 1: return cols[kGridSize];
      case 2: return rows[kGridSize];
      default: return cols[0];
    }
  }
  void finish() {
    for (auto* lines : {&rows, &cols})
      for (auto& [key, line] : *lines) {
        std::sort(line.begin(), line.end());
        line.erase(std::unique(line.begin(), line.end()), line.end());
      }
  }
};

// The values of `line` in [lo, hi), ascending, appended to out.
template <class Emit>
void points_between(const std::vector<std::int64_t>& line, std::int64_t lo, std::int64_t hi, Emit&& emit) {
  for (auto it = std::lower_bound(line.begin(), line.end(), lo); it != line.end() && *it < hi; ++it) emit(*it);
}

}  // namespace

LeafTriangulation triangulate_leaves(const std::vector<std::vector<Leaf>>& leaves, const EdgeTopology& topology) {
  std::vector<GridLines> lines(leaves.size());
  for (std::size_t p = 0; p < leaves.size(); ++p)
    for (const Leaf& l : leaves[p]) {
      const GridRect& r = l.rect;
      lines[p].add(r.u0, r.v0), lines[p].add(r.u1, r.v0), lines[p].add(r.u1, r.v1), lines[p].add(r.u0, r.v1);
    }
  for (GridLines& g : lines) g.finish();
  // Exchange the points of glued edges (each edge is glued at most once, so once is enough).
  // Each glue adds b's points to its part of a and that part's points to b.
  auto add_sorted = [](std::vector<std::int64_t>& line, const std::vector<std::int64_t>& more) {
    line.insert(line.end(), more.begin(), more.end());
    std::sort(line.begin(), line.end());
    line.erase(std::unique(line.begin(), line.end()), line.end());
  };
  for (const Glue& g : topology.glues) {
    std::vector<std::int64_t>& a = lines[g.a.patch].edge_line(g.a.side);
    std::vector<std::int64_t>& b = lines[g.b.patch].edge_line(g.b.side);
    std::vector<std::int64_t> to_a, to_b;
    for (auto it = std::lower_bound(b.begin(), b.end(), g.b_lo); it != b.end() && *it <= g.b_hi; ++it)
      to_a.push_back(g.to_a(*it));
    for (auto it = std::lower_bound(a.begin(), a.end(), g.a_lo); it != a.end() && *it <= g.a_hi; ++it)
      to_b.push_back(g.to_b(*it));
    add_sorted(a, to_a);
    add_sorted(b, to_b);
  }

  // One polygon per leaf, as grid points; then index them.
  std::vector<std::vector<GridPoint>> polygons;
  std::vector<GridPoint> centres;  // per polygon; only used for fans
  for (std::uint32_t p = 0; p < leaves.size(); ++p)
    for (const Leaf& l : leaves[p]) {
      const GridRect& r = l.rect;
      std::vector<GridPoint> poly;
      GridLines& g = lines[p];
      points_between(g.rows[r.v0], r.u0, r.u1, [&](std::int64_t u) { poly.push_back({p, u, r.v0}); });
      points_between(g.cols[r.u1], r.v0, r.v1, [&](std::int64_t v) { poly.push_back({p, r.u1, v}); });
      const std::size_t top = poly.size();
      points_between(g.rows[r.v1], r.u0 + 1, r.u1 + 1, [&](std::int64_t u) { poly.push_back({p, u, r.v1}); });
      std::reverse(poly.begin() + static_cast<std::ptrdiff_t>(top), poly.end());
      const std::size_t left = poly.size();
      points_between(g.cols[r.u0], r.v0 + 1, r.v1 + 1, [&](std::int64_t v) { poly.push_back({p, r.u0, v}); });
      std::reverse(poly.begin() + static_cast<std::ptrdiff_t>(left), poly.end());
      centres.push_back({p, (r.u0 + r.u1) / 2, (r.v0 + r.v1) / 2});
      polygons.push_back(std::move(poly));
    }
  LeafTriangulation out;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    out.points.insert(out.points.end(), polygons[i].begin(), polygons[i].end());
    if (polygons[i].size() > 4) out.points.push_back(centres[i]);
  }
  std::sort(out.points.begin(), out.points.end());
  out.points.erase(std::unique(out.points.begin(), out.points.end()), out.points.end());
  auto index = [&](const GridPoint& g) {
    return static_cast<std::uint32_t>(std::lower_bound(out.points.begin(), out.points.end(), g) - out.points.begin());
  };
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const std::vector<GridPoint>& poly = polygons[i];
    if (poly.size() == 4) {
      out.quads.push_back({index(poly[0]), index(poly[1]), index(poly[2]), index(poly[3])});
      continue;
    }
    const std::uint32_t c = index(centres[i]);
    for (std::size_t k = 0; k < poly.size(); ++k)
      out.triangles.push_back({c, index(poly[k]), index(poly[(k + 1) % poly.size()])});
  }

  // Seams and poles: points that are one surface point share the smallest as representative.
  UnionFind sets(out.points.size());
  // Both directions: a mapping rounded to the grid need not be its own inverse.
  auto unite_points = [&](const GridPoint& p, const GridPoint& q) {
    const std::uint32_t i = index(p), j = index(q);
    if (i < out.points.size() && out.points[i] == p && j < out.points.size() && out.points[j] == q) sets.unite(i, j);
  };
  for (const Glue& g : topology.glues) {
    const std::vector<std::int64_t>& b = lines[g.b.patch].edge_line(g.b.side);
    for (auto it = std::lower_bound(b.begin(), b.end(), g.b_lo); it != b.end() && *it <= g.b_hi; ++it)
      unite_points(edge_point(g.b, *it), edge_point(g.a, g.to_a(*it)));
    const std::vector<std::int64_t>& a = lines[g.a.patch].edge_line(g.a.side);
    for (auto it = std::lower_bound(a.begin(), a.end(), g.a_lo); it != a.end() && *it <= g.a_hi; ++it)
      unite_points(edge_point(g.a, *it), edge_point(g.b, g.to_b(*it)));
  }
  for (const EdgeRef& e : topology.collapsed) {
    const std::vector<std::int64_t>& line = lines[e.patch].edge_line(e.side);
    for (std::int64_t t : line) sets.unite(index(edge_point(e, line.front())), index(edge_point(e, t)));
  }
  out.representative.resize(out.points.size());
  for (std::uint32_t i = 0; i < out.points.size(); ++i) out.representative[i] = sets.find(i);
  return out;
}

}  // namespace genmod::parametric
