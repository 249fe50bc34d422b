// Helpers for the mesh tool and procedural model tests: bitwise mesh equality, selection by face
// centroids, a lone unit quad (an open mesh), and the message of a refused call.
#pragma once

#include "genmod/procedural/poly_mesh.hpp"
#include "genmod/tessellate/validate.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod::test {

// The message of the std::invalid_argument `f` throws ("" when it does not throw).
template <class F>
std::string refusal(F f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// Empty when a and b are bitwise the same mesh (points, face vertex lists, labels, deletions),
// else what differs first.
inline std::string mesh_difference(const PolyMesh& a, const PolyMesh& b) {
  if (a.n_vertices() != b.n_vertices() || a.n_faces() != b.n_faces() || a.n_edges() != b.n_edges())
    return "element counts differ";
  for (std::size_t i = 0; i < a.n_vertices(); ++i) {
    const PolyMesh::VertexHandle v(static_cast<int>(i));
    if (std::memcmp(a.point(v).data(), b.point(v).data(), sizeof(double) * 3) != 0)
      return "vertex " + std::to_string(i) + " moved";
  }
  for (std::size_t i = 0; i < a.n_faces(); ++i) {
    const PolyMesh::FaceHandle f(static_cast<int>(i));
    const bool da = a.has_face_status() && a.status(f).deleted(), db = b.has_face_status() && b.status(f).deleted();
    if (da != db) return "face " + std::to_string(i) + " deletion differs";
    if (da) continue;  // a deleted face's half-edge may belong to a newer face now
    std::vector<int> ra, rb;
    for (auto v : a.fv_range(f)) ra.push_back(v.idx());
    for (auto v : b.fv_range(f)) rb.push_back(v.idx());
    if (ra != rb) return "face " + std::to_string(i) + " vertices differ";
    if (face_label(a, f) != face_label(b, f)) return "face " + std::to_string(i) + " label differs";
  }
  return {};
}

inline Vec3 centroid(const PolyMesh& mesh, PolyMesh::FaceHandle f) {
  Vec3 sum(0, 0, 0);
  int k = 0;
  for (auto v : mesh.fv_range(f)) {
    sum += mesh.point(v);
    ++k;
  }
  return sum / k;
}

// The faces whose centroid lies in [lo, hi], in index order.
inline FaceList faces_with_centroid_in(const PolyMesh& mesh, const Vec3& lo, const Vec3& hi) {
  FaceList out;
  for (auto f : mesh.faces()) {
    const Vec3 c = centroid(mesh, f);
    bool inside = true;
    for (int a = 0; a < 3; ++a) inside = inside && c[a] >= lo[a] && c[a] <= hi[a];
    if (inside) out.push_back(f);
  }
  return out;
}

// The unit square in z = 0 as one counter-clockwise quad: an open mesh with four boundary edges.
inline PolyMesh unit_quad() {
  PolyMesh quad;
  const PolyMesh::VertexHandle v[4] = {quad.add_vertex(Vec3(0, 0, 0)), quad.add_vertex(Vec3(1, 0, 0)),
                                       quad.add_vertex(Vec3(1, 1, 0)), quad.add_vertex(Vec3(0, 1, 0))};
  quad.add_face(v[0], v[1], v[2], v[3]);
  return quad;
}

// A closed 2-manifold whose triangulation the validator accepts (outward, no self-intersections).
inline void expect_valid_closed(const PolyMesh& mesh) {
  EXPECT_TRUE(is_closed_manifold(mesh));
  const MeshValidity v = validate(to_triangle_mesh(mesh));
  EXPECT_TRUE(v.valid()) << describe(v);
}

}  // namespace genmod::test
