// The non-manifold polygonizer's post-processes (§5.7.5): small and thin triangles removed,
// and junction vertices duplicated per region pair.
#include "genmod/tessellate/nonmanifold_polygonizer.hpp"
#include "nonmanifold/post_process.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace genmod {

namespace {

using Point = std::array<double, 3>;
using Tri = std::array<std::uint32_t, 3>;

double distance(const Point& a, const Point& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

// Distance from p to the segment a-b and the parameter of the nearest point.
double segment_distance(const Point& p, const Point& a, const Point& b, double& t) {
  Point d{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  t = dd > 0.0 ? ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1] + (p[2] - a[2]) * d[2]) / dd : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return distance(p, {a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]});
}

bool degenerate(const Tri& t) { return t[0] == t[1] || t[1] == t[2] || t[0] == t[2]; }

// Removes degenerate triangles and pairs of triangles on the same three vertices with
// opposite orientations (what a collapse can leave where a thin fold closed up). When the two
// separate different pairs with one region in common, (x, y) and (x, z), that region was a
// sliver thinner than the collapse length, now closed: the two become one triangle between y
// and z (the maple leaf's vein, where it thins out at the blade, between below and above).
std::size_t clean(RegionMesh& m) {
  std::size_t removed = 0;
  std::vector<Tri> tris;
  std::vector<std::pair<int, int>> regions;
  std::map<std::array<std::uint32_t, 3>, std::vector<std::size_t>> by_set;
  for (std::size_t t = 0; t < m.mesh.triangles.size(); ++t) {
    if (degenerate(m.mesh.triangles[t])) {
      ++removed;
      continue;
    }
    std::array<std::uint32_t, 3> s = m.mesh.triangles[t];
    std::sort(s.begin(), s.end());
    by_set[s].push_back(t);
  }
  std::vector<bool> drop(m.mesh.triangles.size(), false);
  for (const auto& [set, list] : by_set) {
    if (list.size() < 2) continue;
    // Orientation parity of each copy relative to the sorted order.
    std::vector<std::size_t> even, odd;
    for (std::size_t t : list) {
      const Tri& x = m.mesh.triangles[t];
      const bool same = (x[0] == set[0] && x[1] == set[1]) || (x[1] == set[0] && x[2] == set[1]) ||
                        (x[2] == set[0] && x[0] == set[1]);
      (same ? even : odd).push_back(t);
    }
    for (std::size_t i = 0; i < std::min(even.size(), odd.size()); ++i) {
      const auto [a, b] = m.regions[even[i]];
      const auto [c, d] = m.regions[odd[i]];
      if (a == c && b == d) {
        drop[even[i]] = drop[odd[i]] = true;
        removed += 2;
        continue;
      }
      const int shared = a == c || a == d ? a : b == c || b == d ? b : -1;
      if (shared < 0) continue;
      const int y = shared == a ? b : a, z = shared == c ? d : c;
      // The even copy's normal points into its greater region, b: y is on that side when
      // y == b, and the merged normal must point into the greater of y and z.
      Tri& kept = m.mesh.triangles[even[i]];
      if ((y == b) != (y > z)) std::swap(kept[1], kept[2]);
      m.regions[even[i]] = {std::min(y, z), std::max(y, z)};
      drop[odd[i]] = true;
      ++removed;
    }
  }
  for (std::size_t t = 0; t < m.mesh.triangles.size(); ++t) {
    if (drop[t] || degenerate(m.mesh.triangles[t])) continue;
    tris.push_back(m.mesh.triangles[t]);
    regions.push_back(m.regions[t]);
  }
  m.mesh.triangles = std::move(tris);
  m.regions = std::move(regions);
  return removed;
}

using nonmanifold::LatticeSimplex;

// The triangles around each vertex; split_thin adds the triangles it changes or makes, so an
// entry may be stale: users check that the triangle still has the vertex.
std::vector<std::vector<std::size_t>> stars(const RegionMesh& m) {
  std::vector<std::vector<std::size_t>> star(m.mesh.vertices.size());
  for (std::size_t t = 0; t < m.mesh.triangles.size(); ++t)
    for (std::uint32_t v : m.mesh.triangles[t]) star[v].push_back(t);
  return star;
}

// Whether putting vertex v of triangle `tri` into simplex `cell` lays the triangle flat into
// a lattice face (or edge) it did not lie in. A tetrahedron's triangles meet its faces along
// the face lines, which the tetrahedron across the face shares; one laid into the face can
// overlap that tetrahedron's triangles (seen on the leaf: the internal vertices of both
// tetrahedra moved onto face lines in the one pass). Collapses are not checked: that would
// refuse the merges onto lattice corners that keep every edge at least the collapse length
// (claim 36), and on the leaf (cubes 0.015-0.04, vein radii 0.01-0.1) none overlapped.
bool flattens(const std::vector<LatticeSimplex>& cells, const Tri& tri, std::uint32_t v, const LatticeSimplex& cell) {
  LatticeSimplex before, after;
  for (std::size_t k = 0; k < 3; ++k) {
    const std::uint32_t x = tri[k];
    if (cells[x].size == 0) return false;  // no lattice
    const LatticeSimplex& c = x == v ? cell : cells[x];
    before = k == 0 ? cells[x] : join(before, cells[x]);
    after = k == 0 ? c : join(after, c);
  }
  return after.size < before.size && after.size < 4;
}

// Where the merged vertex of a short edge u-w goes, and its simplex: it must stay in the
// closure of both simplices, since the triangles of every tetrahedron around either now use
// it. The same simplex: the midpoint, as in the source; one a face of the other: the vertex
// on the face; else the point of the corner or edge they share nearest the midpoint (within
// 1.4 times the edge's length of it: the lattice edges at a corner are 45 degrees or more
// apart). False when they share none (opposite edges of a tetrahedron: at least a cube edge
// over the square root of 2 apart, never that close).
bool merge_target(const Point& pu, const LatticeSimplex& cu, const Point& pw, const LatticeSimplex& cw, Point& p,
                  LatticeSimplex& cell) {
  const Point mid{0.5 * (pu[0] + pw[0]), 0.5 * (pu[1] + pw[1]), 0.5 * (pu[2] + pw[2])};
  if (cu.size == 0 || cw.size == 0) {  // no lattice: remove_small_triangles on its own
    p = mid;
    cell = {};
    return cu.size == cw.size;
  }
  const bool u_in_w = is_face_of(cu, cw), w_in_u = is_face_of(cw, cu);
  if (u_in_w && w_in_u) {
    p = mid;
    cell = cu;
    return true;
  }
  if (w_in_u || u_in_w) {
    p = w_in_u ? pw : pu;
    cell = w_in_u ? cw : cu;
    return true;
  }
  const LatticeSimplex shared = meet(cu, cw);
  if (shared.size < 1 || shared.size > 2) return false;
  p = nonmanifold::nearest_on(shared, mid, cell);
  return true;
}

// Collapses triangle edges shorter than `length` (see merge_target for where to); returns how
// many. A merged vertex put on a lattice corner is welded to the one already there, if any
// (`at_corner`, by corner key, kept across passes): two vertices at one point that share no
// index would make their triangles meet outside their shared vertices and edges.
std::size_t collapse(RegionMesh& m, double length, std::vector<LatticeSimplex>& cells,
                     std::map<std::uint64_t, std::uint32_t>& at_corner) {
  std::vector<std::uint32_t> alias(m.mesh.vertices.size());
  for (std::uint32_t v = 0; v < alias.size(); ++v) alias[v] = v;
  const auto find = [&](std::uint32_t v) {
    while (alias[v] != v) v = alias[v] = alias[alias[v]];
    return v;
  };
  std::size_t n = 0;
  for (const Tri& t : m.mesh.triangles)
    for (int e = 0; e < 3; ++e) {
      std::uint32_t a = find(t[static_cast<std::size_t>(e)]), b = find(t[static_cast<std::size_t>((e + 1) % 3)]);
      if (a == b || !(distance(m.mesh.vertices[a], m.mesh.vertices[b]) < length)) continue;
      if (b < a) std::swap(a, b);
      Point p;
      LatticeSimplex cell;
      if (!merge_target(m.mesh.vertices[a], cells[a], m.mesh.vertices[b], cells[b], p, cell)) continue;
      std::uint32_t keep = a;
      if (cell.size == 1) {
        const auto [it, first] = at_corner.try_emplace(cell.keys[0], a);
        if (!first) keep = find(it->second);  // a vertex of an earlier collapse, on the corner
        it->second = keep;
      }
      m.mesh.vertices[keep] = p;
      cells[keep] = cell;
      // A junction or border vertex keeps its kind: internal, then face, then edge.
      for (const std::uint32_t gone : {a, b}) {
        if (gone == keep) continue;
        if (static_cast<int>(m.vertex_kinds[gone]) > static_cast<int>(m.vertex_kinds[keep]))
          m.vertex_kinds[keep] = m.vertex_kinds[gone];
        alias[gone] = keep;
      }
      ++n;
    }
  for (Tri& t : m.mesh.triangles)
    for (auto& v : t) v = find(v);
  return n;
}

// Moves each vertex closer than `length` to the opposite edge of a triangle onto that edge
// (at its nearest point) and splits the other triangles on the edge there, so the mesh stays
// closed. Triangles changed in this pass are left for the next, and a vertex moves once
// (`moved`), so that the passes end; returns how many moved. A vertex moves only when the
// edge lies in the closure of its simplex (it then lies in the simplex the edge's ends span)
// and no other triangle around it is laid flat into a lattice face (flattens): an edge
// vertex, whose lattice edge holds no other vertex of the triangle, stays, and so does its
// thin triangle.
std::size_t split_thin(RegionMesh& m, double length, std::vector<bool>& moved, std::vector<LatticeSimplex>& cells) {
  auto& tris = m.mesh.triangles;
  // Most meshes have none: look before building the edge map.
  bool any = false;
  for (std::size_t t = 0; t < tris.size() && !any; ++t)
    for (int i = 0; i < 3 && !any; ++i) {
      const std::uint32_t v = tris[t][static_cast<std::size_t>(i)];
      double u;
      any = !moved[v] &&
            segment_distance(m.mesh.vertices[v], m.mesh.vertices[tris[t][static_cast<std::size_t>((i + 1) % 3)]],
                             m.mesh.vertices[tris[t][static_cast<std::size_t>((i + 2) % 3)]], u) < length &&
            u > 0.0 && u < 1.0;
    }
  if (!any) return 0;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> on_edge;
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = tris[t][static_cast<std::size_t>(k)], b = tris[t][static_cast<std::size_t>((k + 1) % 3)];
      if (b < a) std::swap(a, b);
      on_edge[{a, b}].push_back(t);
    }
  std::vector<std::vector<std::size_t>> star = stars(m);
  const auto has = [&](std::size_t s, std::uint32_t v) { return tris[s][0] == v || tris[s][1] == v || tris[s][2] == v; };
  std::vector<bool> touched(tris.size(), false);
  std::size_t count = 0;
  const std::size_t original = tris.size();
  for (std::size_t t = 0; t < original; ++t) {
    if (touched[t]) continue;
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t v = tris[t][static_cast<std::size_t>(i)], a = tris[t][static_cast<std::size_t>((i + 1) % 3)],
                          b = tris[t][static_cast<std::size_t>((i + 2) % 3)];
      if (moved[v]) continue;
      double u;
      if (!(segment_distance(m.mesh.vertices[v], m.mesh.vertices[a], m.mesh.vertices[b], u) < length)) continue;
      if (u <= 0.0 || u >= 1.0) continue;  // nearer an end: the collapse handles it
      const std::vector<std::size_t>& across = on_edge[{std::min(a, b), std::max(a, b)}];
      // Not when another triangle on the edge already has v (two sheets folded onto each
      // other there): it would keep the edge that the split removes from the others.
      bool free = true;
      for (std::size_t s : across) {
        free = free && !touched[s];
        if (s != t) free = free && !has(s, v);
      }
      if (!free) continue;
      const LatticeSimplex cell = join(cells[a], cells[b]);
      const bool lattice = cells[v].size > 0;  // else remove_small_triangles on its own
      if (lattice && (cell.size == 0 || !is_face_of(cell, cells[v]))) continue;
      bool flat = false;
      for (std::size_t s : star[v]) flat = flat || (s != t && has(s, v) && flattens(cells, tris[s], v, cell));
      if (lattice && flat) continue;
      const Point pa = m.mesh.vertices[a], pb = m.mesh.vertices[b];
      const Point p{pa[0] + u * (pb[0] - pa[0]), pa[1] + u * (pb[1] - pa[1]), pa[2] + u * (pb[2] - pa[2])};
      m.mesh.vertices[v] = p;
      if (lattice) cells[v] = cell;
      moved[v] = true;
      for (std::size_t s : across) {
        touched[s] = true;
        if (s == t) continue;
        Tri& x = tris[s];
        for (int k = 0; k < 3; ++k) {
          const std::uint32_t p0 = x[static_cast<std::size_t>(k)], q = x[static_cast<std::size_t>((k + 1) % 3)],
                              r = x[static_cast<std::size_t>((k + 2) % 3)];
          if (!((p0 == a && q == b) || (p0 == b && q == a)) || r == v) continue;
          const std::pair<int, int> region = m.regions[s];
          x = {p0, v, r};
          tris.push_back({v, q, r});
          m.regions.push_back(region);
          star[v].push_back(s);
          for (const std::uint32_t y : {v, q, r}) star[y].push_back(tris.size() - 1);
          ++m.stats.split_edges;
          break;
        }
      }
      tris[t] = {v, v, v};  // now flat: removed by clean()
      ++count;
      break;
    }
  }
  return count;
}

void drop_unused_vertices(RegionMesh& m, std::vector<LatticeSimplex>& cells) {
  std::vector<std::int64_t> map(m.mesh.vertices.size(), -1);
  std::vector<Point> vertices;
  std::vector<RegionVertexKind> kinds;
  std::vector<LatticeSimplex> kept;
  for (Tri& t : m.mesh.triangles)
    for (auto& v : t) {
      if (map[v] < 0) {
        map[v] = static_cast<std::int64_t>(vertices.size());
        vertices.push_back(m.mesh.vertices[v]);
        kinds.push_back(m.vertex_kinds[v]);
        kept.push_back(cells[v]);
      }
      v = static_cast<std::uint32_t>(map[v]);
    }
  m.mesh.vertices = std::move(vertices);
  m.vertex_kinds = std::move(kinds);
  cells = std::move(kept);
}

}  // namespace

namespace nonmanifold {

void remove_small_triangles(RegionMesh& m, double min_length, std::vector<LatticeSimplex>& cells) {
  if (!std::isfinite(min_length) || min_length < 0.0)
    throw std::invalid_argument("genmod: remove_small_triangles: min_length must be finite and >= 0");
  if (m.regions.size() != m.mesh.triangles.size() || m.vertex_kinds.size() != m.mesh.vertices.size() ||
      cells.size() != m.mesh.vertices.size())
    throw std::invalid_argument("genmod: remove_small_triangles: the region and vertex-kind arrays do not match the mesh");
  // Each pass collapses (fewer vertices) or moves a vertex that never moved before, so the
  // loop ends; the bound is a guard.
  std::vector<bool> moved(m.mesh.vertices.size(), false);
  std::map<std::uint64_t, std::uint32_t> at_corner;
  for (std::size_t pass = 0; pass < 4 * m.mesh.vertices.size() + 16; ++pass) {
    const std::size_t collapsed = collapse(m, min_length, cells, at_corner);
    m.stats.collapsed_edges += collapsed;
    if (collapsed > 0 || pass == 0) m.stats.removed_triangles += clean(m);
    if (collapsed > 0) continue;
    const std::size_t split = split_thin(m, min_length, moved, cells);
    if (split == 0) break;
    m.stats.removed_triangles += clean(m);
  }
  drop_unused_vertices(m, cells);
}

}  // namespace nonmanifold

void remove_small_triangles(RegionMesh& m, double min_length) {
  std::vector<nonmanifold::LatticeSimplex> unknown(m.mesh.vertices.size());
  nonmanifold::remove_small_triangles(m, min_length, unknown);
}

Mesh split_by_region_pair(const RegionMesh& m, std::vector<std::pair<int, int>>* vertex_pairs,
                          std::vector<std::uint32_t>* origin) {
  Mesh out;
  std::map<std::pair<std::uint32_t, std::pair<int, int>>, std::uint32_t> copies;
  if (vertex_pairs) vertex_pairs->clear();
  if (origin) origin->clear();
  for (std::size_t t = 0; t < m.mesh.triangles.size(); ++t) {
    Tri tri;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = m.mesh.triangles[t][static_cast<std::size_t>(k)];
      const auto [it, added] = copies.try_emplace({v, m.regions[t]}, static_cast<std::uint32_t>(out.vertices.size()));
      if (added) {
        out.vertices.push_back(m.mesh.vertices[v]);
        if (vertex_pairs) vertex_pairs->push_back(m.regions[t]);
        if (origin) origin->push_back(v);
      }
      tri[static_cast<std::size_t>(k)] = it->second;
    }
    out.triangles.push_back(tri);
  }
  return out;
}

}  // namespace genmod
