#include "genmod/procedural/extrusion.hpp"

#include "face_labels.hpp"
#include "mesh_rebuild.hpp"
#include "tool_checks.hpp"

#include <vector>

namespace genmod {

FaceList extrude(PolyMesh& mesh, const FaceList& faces, const Vec3& by) {
  detail::check_faces(mesh, faces, "extrude");
  detail::check_finite(by, "extrude", "the extrusion vector");
  if (faces.empty()) return {};

  std::vector<char> in_set(mesh.n_faces(), 0);
  for (PolyMesh::FaceHandle f : faces) in_set[f.idx()] = 1;

  // A vertex survives if a face outside the set or a side quad (an edge of the set's boundary,
  // which on an open mesh may have no outside face) uses it; every vertex of the set is copied.
  std::vector<char> kept(mesh.n_vertices(), 0);
  for (PolyMesh::FaceHandle f : mesh.faces())
    if (!in_set[f.idx()])
      for (auto v : mesh.fv_range(f)) kept[v.idx()] = 1;
  for (PolyMesh::FaceHandle f : faces)
    for (auto h : mesh.fh_range(f))
      if (!mesh.opposite_face_handle(h).is_valid())
        kept[mesh.from_vertex_handle(h).idx()] = kept[mesh.to_vertex_handle(h).idx()] = 1;

  const auto labels = detail::find_label_property(mesh);
  detail::MeshParts parts;
  std::vector<int> old_index(mesh.n_vertices(), -1), new_index(mesh.n_vertices(), -1);
  for (auto v : mesh.vertices())
    if (kept[v.idx()]) {
      old_index[v.idx()] = static_cast<int>(parts.points.size());
      parts.points.push_back(mesh.point(v));
    }
  // Copies in order of first use by the set's faces, so the result follows the set's order.
  for (PolyMesh::FaceHandle f : faces)
    for (auto v : mesh.fv_range(f))
      if (new_index[v.idx()] < 0) {
        new_index[v.idx()] = static_cast<int>(parts.points.size());
        parts.points.push_back(mesh.point(v) + by);
      }

  for (PolyMesh::FaceHandle f : mesh.faces()) {
    if (in_set[f.idx()]) continue;
    for (auto v : mesh.fv_range(f)) parts.corners.push_back(old_index[v.idx()]);
    parts.face_start.push_back(static_cast<int>(parts.corners.size()));
    parts.labels.push_back(detail::label_of(mesh, labels, f));
  }
  FaceList caps;
  caps.reserve(faces.size());
  for (PolyMesh::FaceHandle f : faces) {
    const std::string& label = detail::label_of(mesh, labels, f);
    // Halfedge a -> b of f lies on the set's boundary when the face across is outside the set.
    for (auto h : mesh.fh_range(f)) {
      const auto across = mesh.opposite_face_handle(h);
      if (across.is_valid() && in_set[across.idx()]) continue;
      const int a = mesh.from_vertex_handle(h).idx(), b = mesh.to_vertex_handle(h).idx();
      parts.add_face({old_index[b], new_index[b], new_index[a], old_index[a]}, label);
    }
    for (auto v : mesh.fv_range(f)) parts.corners.push_back(new_index[v.idx()]);
    parts.face_start.push_back(static_cast<int>(parts.corners.size()));
    parts.labels.push_back(label);
    caps.push_back(PolyMesh::FaceHandle(static_cast<int>(parts.labels.size()) - 1));
  }
  mesh = detail::build_mesh(parts, "extrude");
  return caps;
}

}  // namespace genmod
