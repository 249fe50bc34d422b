// The combinatorial half of validate(): edges, manifoldness, orientation consistency,
// components, Euler characteristics, volumes. No CGAL here.
#include "union_find.hpp"
#include "validate_internal.hpp"

#include <algorithm>
#include <array>
#include <numeric>

namespace genmod::validation {
namespace {

using tessellate_detail::UnionFind;

// One directed edge of a triangle, keyed by its undirected vertex pair.
struct HalfEdge {
  std::uint32_t lo, hi;   // vertex pair, lo < hi
  std::uint32_t tri;      // position in `proper`
  std::uint8_t corner;    // the edge runs from corner `corner` to corner `corner + 1`
  bool forward;           // runs lo -> hi
};

double signed_volume(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& c,
                     const std::array<double, 3>& o) {
  const double ax = a[0] - o[0], ay = a[1] - o[1], az = a[2] - o[2];
  const double bx = b[0] - o[0], by = b[1] - o[1], bz = b[2] - o[2];
  const double cx = c[0] - o[0], cy = c[1] - o[1], cz = c[2] - o[2];
  return (ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)) / 6.0;
}

}  // namespace

std::vector<std::uint32_t> proper_triangles(const Mesh& mesh, MeshValidity& v) {
  std::vector<std::uint32_t> proper;
  proper.reserve(mesh.triangles.size());
  const std::size_t n = mesh.vertices.size();
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    bool ok = true;
    for (std::uint32_t i : tri)
      if (i >= n) {
        ++v.invalid_indices;
        ok = false;
      }
    if (!ok) continue;
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
      ++v.degenerate_triangles;
      continue;
    }
    proper.push_back(t);
  }
  return proper;
}

void check_topology(const Mesh& mesh, const std::vector<std::uint32_t>& proper, MeshValidity& v) {
  const std::size_t nt = proper.size();
  std::vector<HalfEdge> half;
  half.reserve(3 * nt);
  for (std::uint32_t k = 0; k < nt; ++k) {
    const auto& tri = mesh.triangles[proper[k]];
    for (std::uint8_t c = 0; c < 3; ++c) {
      const std::uint32_t a = tri[c], b = tri[(c + 1) % 3];
      half.push_back({std::min(a, b), std::max(a, b), k, c, a < b});
    }
  }
  std::sort(half.begin(), half.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.lo != y.lo ? x.lo < y.lo : x.hi != y.hi ? x.hi < y.hi : x.tri < y.tri;
  });

  // Corners (triangle k, corner c) = 3k + c; a vertex is manifold when all its corners are
  // joined through manifold edges into one fan.
  UnionFind corners(3 * nt), components(nt);
  std::vector<bool> boundary_tri(nt, false);
  for (std::size_t i = 0; i < half.size();) {
    std::size_t j = i;
    while (j < half.size() && half[j].lo == half[i].lo && half[j].hi == half[i].hi) ++j;
    const std::size_t count = j - i;
    ++v.edges;
    for (std::size_t k = i + 1; k < j; ++k) components.unite(half[i].tri, half[k].tri);
    if (count == 1) {
      ++v.boundary_edges;
      boundary_tri[half[i].tri] = true;
    } else if (count > 2) {
      ++v.nonmanifold_edges;
    } else {
      const HalfEdge& e = half[i];
      const HalfEdge& f = half[i + 1];
      if (e.forward == f.forward) ++v.misoriented_edges;
      // The edge's two ends: corner e.corner / e.corner + 1 of e.tri, matched by vertex.
      const auto& te = mesh.triangles[proper[e.tri]];
      const auto& tf = mesh.triangles[proper[f.tri]];
      for (std::uint8_t ce : {e.corner, static_cast<std::uint8_t>((e.corner + 1) % 3)})
        for (std::uint8_t cf = 0; cf < 3; ++cf)
          if (te[ce] == tf[cf]) corners.unite(3 * e.tri + ce, 3 * f.tri + cf);
    }
    i = j;
  }

  // Fans per vertex.
  const std::size_t nv = mesh.vertices.size();
  std::vector<std::uint32_t> fan_root(nv, 0xffffffffu);
  std::vector<bool> nonmanifold(nv, false), used(nv, false);
  for (std::uint32_t k = 0; k < nt; ++k)
    for (std::uint8_t c = 0; c < 3; ++c) {
      const std::uint32_t vert = mesh.triangles[proper[k]][c];
      used[vert] = true;
      const std::uint32_t root = corners.find(3 * k + c);
      if (fan_root[vert] == 0xffffffffu) fan_root[vert] = root;
      else if (fan_root[vert] != root) nonmanifold[vert] = true;
    }
  std::size_t used_count = 0;
  for (std::size_t i = 0; i < nv; ++i) {
    used_count += used[i];
    v.nonmanifold_vertices += nonmanifold[i];
  }
  v.unused_vertices = nv - used_count;

  // Coincident vertices: used vertices at the position of another used vertex.
  std::vector<std::uint32_t> order;
  order.reserve(used_count);
  for (std::uint32_t i = 0; i < nv; ++i)
    if (used[i]) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return mesh.vertices[a] != mesh.vertices[b] ? mesh.vertices[a] < mesh.vertices[b] : a < b;
  });
  for (std::size_t i = 1; i < order.size(); ++i)
    if (mesh.vertices[order[i]] == mesh.vertices[order[i - 1]]) ++v.coincident_vertices;

  // Volumes about the bounding-box center (less cancellation than about the origin).
  std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};
  if (!order.empty()) {
    lo = hi = mesh.vertices[order[0]];
    for (std::uint32_t i : order)
      for (int d = 0; d < 3; ++d) {
        lo[d] = std::min(lo[d], mesh.vertices[i][d]);
        hi[d] = std::max(hi[d], mesh.vertices[i][d]);
      }
  }
  const std::array<double, 3> center{0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};

  // Components, numbered by their first triangle.
  std::vector<std::uint32_t> comp_of(nt);
  std::vector<std::uint32_t> comp_index(nt, 0xffffffffu);
  for (std::uint32_t k = 0; k < nt; ++k) {
    const std::uint32_t r = components.find(k);
    if (comp_index[r] == 0xffffffffu) {
      comp_index[r] = static_cast<std::uint32_t>(v.component_info.size());
      v.component_info.push_back({});
      v.component_info.back().closed = true;
    }
    comp_of[k] = comp_index[r];
  }
  v.components = v.component_info.size();
  std::vector<std::size_t> comp_vertices(v.components, 0), comp_edges(v.components, 0);
  for (std::uint32_t k = 0; k < nt; ++k) {
    ComponentValidity& c = v.component_info[comp_of[k]];
    ++c.triangles;
    if (boundary_tri[k]) c.closed = false;
    const auto& tri = mesh.triangles[proper[k]];
    const double vol = signed_volume(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]], center);
    c.volume += vol;
    v.volume += vol;
  }
  for (std::size_t i = 0; i < half.size();) {
    std::size_t j = i;
    while (j < half.size() && half[j].lo == half[i].lo && half[j].hi == half[i].hi) ++j;
    ++comp_edges[comp_of[half[i].tri]];
    i = j;
  }
  std::vector<std::uint32_t> vertex_comp(nv, 0xffffffffu);
  for (std::uint32_t k = 0; k < nt; ++k)
    for (std::uint32_t vert : mesh.triangles[proper[k]])
      if (vertex_comp[vert] == 0xffffffffu) {
        vertex_comp[vert] = comp_of[k];
        ++comp_vertices[comp_of[k]];
      }
  for (std::size_t c = 0; c < v.components; ++c) {
    ComponentValidity& info = v.component_info[c];
    info.euler_characteristic = static_cast<long>(comp_vertices[c]) - static_cast<long>(comp_edges[c]) +
                                static_cast<long>(info.triangles);
    if (!info.closed) info.volume = 0.0;
  }
  v.euler_characteristic = static_cast<long>(used_count) - static_cast<long>(v.edges) + static_cast<long>(nt);
}

}  // namespace genmod::validation
