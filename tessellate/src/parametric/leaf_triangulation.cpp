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

// Twice the signed area of the parameter triangle (a, b, c); exact in 64-bit integers.
std::int64_t doubled_area(const GridPoint& a, const GridPoint& b, const GridPoint& c) {
  return (b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u);
}

// Triangulates a leaf's boundary polygon (counter-clockwise from its lower-left corner, more
// than four points) without an extra point: n points give n - 2 triangles, where a fan from
// the centre gives n. The polygon is zipped between its two chains from the lower-left to the
// upper-right corner: A along the bottom and right edges, B up the left edge and along the
// top. A triangle of points on one edge would be degenerate; such a step is never taken, and
// neither chain reaches the upper-right corner before the other is one step from it, so a
// valid step always exists (the corner is on neither of the other chain's edges). Of two
// valid steps, the one with the shorter new diagonal (relative to the leaf's sides) is taken.
template <class Emit>
void zip_polygon(const std::vector<GridPoint>& poly, const GridRect& r, Emit&& emit) {
  const std::size_t n = poly.size();
  std::size_t corner = 0;  // the upper-right corner
  while (!(poly[corner].u == r.u1 && poly[corner].v == r.v1)) ++corner;
  auto a = [&](std::size_t i) { return i; };
  auto b = [&](std::size_t j) { return j == 0 ? std::size_t{0} : n - j; };
  const std::size_t m = corner, last = n - corner;  // A is a(0..m), B is b(0..last)
  const double w = static_cast<double>(r.u1 - r.u0), h = static_cast<double>(r.v1 - r.v0);
  auto diagonal2 = [&](std::size_t p, std::size_t q) {
    const double du = static_cast<double>(poly[p].u - poly[q].u) / w;
    const double dv = static_cast<double>(poly[p].v - poly[q].v) / h;
    return du * du + dv * dv;
  };
  std::size_t i = 1, j = 0;
  while (!(i == m && j == last - 1) && !(i == m - 1 && j == last)) {
    const bool can_a =
        i < m && (i + 1 < m || j == last - 1) && doubled_area(poly[a(i)], poly[a(i + 1)], poly[b(j)]) != 0;
    const bool can_b =
        j < last && (j + 1 < last || i == m - 1) && doubled_area(poly[a(i)], poly[b(j + 1)], poly[b(j)]) != 0;
    if (can_a && (!can_b || diagonal2(a(i + 1), b(j)) <= diagonal2(a(i), b(j + 1)))) {
      emit(a(i), a(i + 1), b(j));
      ++i;
    } else {
      emit(a(i), b(j + 1), b(j));
      ++j;
    }
  }
}

// A leaf with an edge on a collapsed patch edge (a pole): that edge is one surface point, so
// a triangle joining it to two points of one of the leaf's other edges, which zip_polygon may
// make (it is non-degenerate in (u, v)), is degenerate or folded in space wherever that
// edge is a straight segment ending at the pole (a cone's or a disc's ray). Such a leaf is
// triangulated in a plane where the collapsed edge is one point: leaf coordinates (a, b) in
// [0, 1]^2, shrunk toward the middle of each collapsed edge (b = 1 collapsed: a -> 1/2 +
// (a - 1/2)(1 - b)); the leaf's other edges stay straight there, as a ray does in space.
// `poly` has one point left for each collapsed edge. Ear clipping with strictly convex ears
// that hold no other point (closed test): n points give n - 2 triangles, none with three
// points on one straight edge. Returns false (emitting nothing) if no ear is found.
template <class Emit>
bool clip_ears(const std::vector<std::array<double, 2>>& q, Emit&& emit) {
  constexpr double kFlat = 1e-13;  // collinear in the plane (leaf units); true areas are >= 2^-50
  auto area2 = [&](std::size_t a, std::size_t b, std::size_t c) {
    return (q[b][0] - q[a][0]) * (q[c][1] - q[a][1]) - (q[b][1] - q[a][1]) * (q[c][0] - q[a][0]);
  };
  std::vector<std::size_t> left(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) left[i] = i;
  std::vector<std::array<std::size_t, 3>> out;
  while (left.size() > 3) {
    bool clipped = false;
    for (std::size_t k = 0; k < left.size() && !clipped; ++k) {
      const std::size_t a = left[(k + left.size() - 1) % left.size()], b = left[k], c = left[(k + 1) % left.size()];
      if (!(area2(a, b, c) > kFlat)) continue;
      bool empty = true;
      for (std::size_t m : left)
        if (m != a && m != b && m != c && area2(a, b, m) >= -kFlat && area2(b, c, m) >= -kFlat && area2(c, a, m) >= -kFlat)
          empty = false;
      if (!empty) continue;
      out.push_back({a, b, c});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(k));
      clipped = true;
    }
    if (!clipped) return false;
  }
  if (left.size() == 3) {
    if (!(area2(left[0], left[1], left[2]) > kFlat)) return false;
    out.push_back({left[0], left[1], left[2]});
  }
  for (const auto& t : out) emit(t[0], t[1], t[2]);
  return true;
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
  std::vector<GridRect> rects;  // per polygon
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
      rects.push_back(r);
      polygons.push_back(std::move(poly));
    }
  LeafTriangulation out;
  for (const std::vector<GridPoint>& poly : polygons) out.points.insert(out.points.end(), poly.begin(), poly.end());
  std::sort(out.points.begin(), out.points.end());
  out.points.erase(std::unique(out.points.begin(), out.points.end()), out.points.end());
  auto index = [&](const GridPoint& g) {
    return static_cast<std::uint32_t>(std::lower_bound(out.points.begin(), out.points.end(), g) - out.points.begin());
  };
  std::vector<std::array<bool, 4>> collapsed(leaves.size(), {false, false, false, false});
  for (const EdgeRef& e : topology.collapsed) collapsed[e.patch][static_cast<std::size_t>(e.side)] = true;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const std::vector<GridPoint>& poly = polygons[i];
    const auto leaf = static_cast<std::uint32_t>(i);
    if (poly.size() == 4) {
      out.quads.push_back({index(poly[0]), index(poly[1]), index(poly[2]), index(poly[3])});
      out.quad_leaf.push_back(leaf);
      continue;
    }
    const GridRect& r = rects[i];
    const std::array<bool, 4>& c = collapsed[poly[0].patch];
    const std::array<bool, 4> pole{c[0] && r.v0 == 0, c[1] && r.u1 == kGridSize, c[2] && r.v1 == kGridSize,
                                   c[3] && r.u0 == 0};
    if ((pole[0] || pole[1] || pole[2] || pole[3]) && !(pole[0] && pole[2]) && !(pole[1] && pole[3])) {
      // One point per collapsed edge, in the plane described at clip_ears.
      std::vector<std::size_t> kept;
      std::vector<std::array<double, 2>> plane;
      std::array<bool, 4> seen{false, false, false, false};
      for (std::size_t k = 0; k < poly.size(); ++k) {
        const GridPoint& g = poly[k];
        const std::array<bool, 4> on{g.v == r.v0, g.u == r.u1, g.v == r.v1, g.u == r.u0};
        int side = -1;
        for (int s = 0; s < 4; ++s)
          if (pole[static_cast<std::size_t>(s)] && on[static_cast<std::size_t>(s)]) side = s;
        if (side >= 0 && seen[static_cast<std::size_t>(side)]) continue;
        if (side >= 0) seen[static_cast<std::size_t>(side)] = true;
        double a = static_cast<double>(g.u - r.u0) / static_cast<double>(r.u1 - r.u0);
        double b = static_cast<double>(g.v - r.v0) / static_cast<double>(r.v1 - r.v0);
        if (pole[0]) a = 0.5 + (a - 0.5) * b;
        if (pole[2]) a = 0.5 + (a - 0.5) * (1.0 - b);
        if (pole[1]) b = 0.5 + (b - 0.5) * (1.0 - a);
        if (pole[3]) b = 0.5 + (b - 0.5) * a;
        kept.push_back(k);
        plane.push_back({a, b});
      }
      // (The first and last polygon points may both lie on one collapsed edge: the left edge
      // runs into the lower-left corner, where the bottom edge starts.)
      if (kept.size() >= 3 && clip_ears(plane, [&](std::size_t a, std::size_t b, std::size_t d) {
            out.triangles.push_back({index(poly[kept[a]]), index(poly[kept[b]]), index(poly[kept[d]])});
          })) {
        out.triangle_leaf.resize(out.triangles.size(), leaf);
        continue;
      }
    }
    zip_polygon(poly, r, [&](std::size_t a, std::size_t b, std::size_t c2) {
      out.triangles.push_back({index(poly[a]), index(poly[b]), index(poly[c2])});
    });
    out.triangle_leaf.resize(out.triangles.size(), leaf);
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
