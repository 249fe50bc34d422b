// Helpers for the mesh tool tests: bitwise snapshots and per-face position rings.
#pragma once

#include "genmod/procedural/poly_mesh.hpp"

#include <string>
#include <vector>

namespace genmod::test {

// Everything a tool may change: positions, face vertex lists and labels, in index order.
struct Snapshot {
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;
  std::vector<std::string> labels;
  bool operator==(const Snapshot&) const = default;
};

inline Snapshot snapshot(const PolyMesh& mesh) {
  Snapshot s;
  for (auto v : mesh.vertices()) s.points.push_back(mesh.point(v));
  for (auto f : mesh.faces()) {
    std::vector<int> ring;
    for (auto v : mesh.fv_range(f)) ring.push_back(v.idx());
    s.faces.push_back(ring);
    s.labels.push_back(face_label(mesh, f));
  }
  return s;
}

// The positions of a face's vertices in winding order, rotated to start at the smallest
// (lexicographic) point, so faces can be compared regardless of their first half-edge.
inline std::vector<Vec3> position_ring(const PolyMesh& mesh, PolyMesh::FaceHandle f) {
  std::vector<Vec3> ring;
  for (auto v : mesh.fv_range(f)) ring.push_back(mesh.point(v));
  std::size_t first = 0;
  auto less = [](const Vec3& a, const Vec3& b) {
    return a[0] != b[0] ? a[0] < b[0] : a[1] != b[1] ? a[1] < b[1] : a[2] < b[2];
  };
  for (std::size_t i = 1; i < ring.size(); ++i)
    if (less(ring[i], ring[first])) first = i;
  std::vector<Vec3> rotated;
  for (std::size_t i = 0; i < ring.size(); ++i) rotated.push_back(ring[(first + i) % ring.size()]);
  return rotated;
}

inline PolyMesh make_tetrahedron() {
  PolyMesh mesh;
  PolyMesh::VertexHandle v[4] = {mesh.add_vertex(Vec3(1, 1, 1)), mesh.add_vertex(Vec3(1, -1, -1)),
                                 mesh.add_vertex(Vec3(-1, 1, -1)), mesh.add_vertex(Vec3(-1, -1, 1))};
  // Outward: each face seen from outside counter-clockwise.
  mesh.add_face(v[0], v[1], v[2]);
  mesh.add_face(v[0], v[3], v[1]);
  mesh.add_face(v[0], v[2], v[3]);
  mesh.add_face(v[1], v[3], v[2]);
  return mesh;
}

}  // namespace genmod::test
