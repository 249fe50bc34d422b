// The geometric half of validate(), on CGAL's exact predicates: degenerate triangles,
// self-intersections of the triangle soup as written, outward orientation. The only
// translation unit of genmod that includes CGAL.
#include "validate_internal.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <functional>
#include <utility>

namespace genmod::validation {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;

Point point(const Mesh& mesh, std::uint32_t i) {
  const auto& p = mesh.vertices[i];
  return Point(p[0], p[1], p[2]);
}

// Do triangles s and t (distinct, non-degenerate) meet anywhere except in the vertices and
// the edge they share by index?
bool triangles_intersect(const Mesh& mesh, const std::array<std::uint32_t, 3>& s,
                         const std::array<std::uint32_t, 3>& t) {
  int shared = 0;
  int s_shared[3] = {-1, -1, -1};  // for each corner of s, the matching corner of t
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (s[i] == t[j]) {
        s_shared[i] = j;
        ++shared;
      }
  const K::Triangle_3 ts(point(mesh, s[0]), point(mesh, s[1]), point(mesh, s[2]));
  const K::Triangle_3 tt(point(mesh, t[0]), point(mesh, t[1]), point(mesh, t[2]));
  if (shared == 0) return CGAL::do_intersect(ts, tt);
  if (shared == 3) return true;  // the same triangle twice
  if (shared == 1) {
    // Through the shared vertex v the intersection is a segment starting at v or just v; it
    // is more than v exactly when the edge opposite v of one triangle meets the other.
    int vs = 0;
    while (s_shared[vs] < 0) ++vs;
    const int vt = s_shared[vs];
    const K::Segment_3 opp_s(point(mesh, s[(vs + 1) % 3]), point(mesh, s[(vs + 2) % 3]));
    const K::Segment_3 opp_t(point(mesh, t[(vt + 1) % 3]), point(mesh, t[(vt + 2) % 3]));
    return CGAL::do_intersect(opp_s, tt) || CGAL::do_intersect(opp_t, ts);
  }
  // One shared edge (a, b): they overlap exactly when coplanar with the third corners on the
  // same side of the edge.
  int free_s = 0;
  while (s_shared[free_s] >= 0) ++free_s;
  std::uint32_t a = 0, b = 0;
  bool got_a = false;
  for (int i = 0; i < 3; ++i)
    if (s_shared[i] >= 0) {
      if (!got_a) {
        a = s[i];
        got_a = true;
      } else {
        b = s[i];
      }
    }
  std::uint32_t free_t = t[0];
  for (std::uint32_t x : t)
    if (x != a && x != b) free_t = x;
  const Point pa = point(mesh, a), pb = point(mesh, b), pc = point(mesh, s[free_s]), pd = point(mesh, free_t);
  return CGAL::coplanar(pa, pb, pc, pd) && CGAL::coplanar_orientation(pa, pb, pc, pd) == CGAL::POSITIVE;
}

}  // namespace

std::vector<std::uint32_t> check_degenerate(const Mesh& mesh, const std::vector<std::uint32_t>& proper,
                                            MeshValidity& v) {
  std::vector<std::uint32_t> good;
  good.reserve(proper.size());
  for (std::uint32_t t : proper) {
    const auto& tri = mesh.triangles[t];
    if (CGAL::collinear(point(mesh, tri[0]), point(mesh, tri[1]), point(mesh, tri[2]))) ++v.degenerate_triangles;
    else good.push_back(t);
  }
  return good;
}

std::size_t count_self_intersections(const Mesh& mesh, const std::vector<std::uint32_t>& triangles, int threads) {
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::uint32_t,
                                                        CGAL::Box_intersection_d::ID_EXPLICIT>;
  std::vector<Box> boxes;
  boxes.reserve(triangles.size());
  for (std::uint32_t t : triangles) {
    const auto& tri = mesh.triangles[t];
    double lo[3], hi[3];
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min({mesh.vertices[tri[0]][d], mesh.vertices[tri[1]][d], mesh.vertices[tri[2]][d]});
      hi[d] = std::max({mesh.vertices[tri[0]][d], mesh.vertices[tri[1]][d], mesh.vertices[tri[2]][d]});
    }
    boxes.emplace_back(CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]), t);
  }
  // Candidate pairs (closed boxes that overlap), then exact tests in parallel.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    pairs.emplace_back(std::min(a.info(), b.info()), std::max(a.info(), b.info()));
  });
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  tbb::enumerable_thread_specific<std::size_t> counts(0);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pairs.size(), 1024), [&](const auto& r) {
      std::size_t& n = counts.local();
      for (std::size_t i = r.begin(); i != r.end(); ++i)
        n += triangles_intersect(mesh, mesh.triangles[pairs[i].first], mesh.triangles[pairs[i].second]);
    });
  });
  return counts.combine(std::plus<>());
}

void check_outward(const Mesh& mesh, MeshValidity& v) {
  using SurfaceMesh = CGAL::Surface_mesh<Point>;
  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> index(mesh.vertices.size());
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& tri : mesh.triangles)
    for (std::uint32_t i : tri) used[i] = true;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    if (used[i]) index[i] = sm.add_vertex(point(mesh, static_cast<std::uint32_t>(i)));
  for (const auto& tri : mesh.triangles)
    if (sm.add_face(index[tri[0]], index[tri[1]], index[tri[2]]) == SurfaceMesh::null_face()) return;

  namespace PMP = CGAL::Polygon_mesh_processing;
  auto face_cc = sm.add_property_map<SurfaceMesh::Face_index, std::size_t>("f:cc", 0).first;
  const std::size_t ncc = PMP::connected_components(sm, face_cc);
  auto volume_id = sm.add_property_map<SurfaceMesh::Face_index, std::size_t>("f:vol", 0).first;
  std::vector<std::size_t> nesting;
  std::vector<bool> outward_cc;
  PMP::volume_connected_components(sm, volume_id,
                                   PMP::parameters::do_orientation_tests(true)
                                       .nesting_levels(std::ref(nesting))
                                       .is_cc_outward_oriented(std::ref(outward_cc)));
  if (nesting.size() != ncc || outward_cc.size() != ncc || ncc != v.components) return;
  // Our components are numbered by first triangle; CGAL's by its own traversal. Faces are
  // numbered in insertion order, so ranking CGAL's components by first face gives ours.
  std::vector<std::size_t> rank(ncc, ncc);
  std::size_t next = 0;
  for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f) {
    const std::size_t c = face_cc[SurfaceMesh::Face_index(f)];
    if (rank[c] == ncc) rank[c] = next++;
  }
  bool all_outward = true;
  for (std::size_t c = 0; c < ncc; ++c) {
    ComponentValidity& info = v.component_info[rank[c]];
    info.nesting_level = static_cast<int>(nesting[c]);
    // An outermost shell bounds its solid from outside (normals away from it); a shell
    // nested inside bounds a cavity, so its normals point into the cavity, and so on.
    info.outward = outward_cc[c] == (nesting[c] % 2 == 0);
    all_outward = all_outward && info.outward;
  }
  v.outward = all_outward;
  v.orientation_checked = true;
}

}  // namespace genmod::validation
