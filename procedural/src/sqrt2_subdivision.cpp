#include "genmod/procedural/sqrt2_subdivision.hpp"

#include "face_labels.hpp"
#include "mesh_rebuild.hpp"
#include "tool_checks.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod {
namespace {

// One level on the faces flagged in `separable` (indexed by face); returns the new mesh's count
// of faces kept from outside the set (the new faces follow them).
int sqrt2_level(PolyMesh& mesh, const std::vector<char>& separable, double s) {
  // Vertex indices of the rebuilt mesh: live vertices in index order (a mesh with garbage is
  // compacted), then one face point per separable face in face order.
  const auto labels = detail::find_label_property(mesh);
  detail::MeshParts parts;
  std::vector<int> vertex_index(mesh.n_vertices(), -1);
  for (auto v : mesh.vertices()) {
    vertex_index[v.idx()] = static_cast<int>(parts.points.size());
    parts.points.push_back(mesh.point(v));
  }
  std::vector<int> face_point(mesh.n_faces(), -1);
  for (auto f : mesh.faces()) {
    if (!separable[f.idx()]) continue;
    Vec3 sum(0, 0, 0);
    int n = 0;
    for (auto v : mesh.fv_range(f)) {
      sum += mesh.point(v);
      ++n;
    }
    face_point[f.idx()] = static_cast<int>(parts.points.size());
    parts.points.push_back(sum / static_cast<double>(n));
  }
  // Old vertices inside the region move towards the mean of their faces' points.
  for (auto v : mesh.vertices()) {
    if (mesh.is_boundary(v) || mesh.is_isolated(v)) continue;
    Vec3 sum(0, 0, 0);
    int n = 0;
    bool inside = true;
    for (auto f : mesh.vf_range(v)) {
      if (!separable[f.idx()]) {
        inside = false;
        break;
      }
      sum += parts.points[face_point[f.idx()]];
      ++n;
    }
    if (!inside) continue;
    const Vec3& p = mesh.point(v);
    parts.points[vertex_index[v.idx()]] = p + s * (sum / static_cast<double>(n) - p);
  }

  int kept = 0;
  for (auto f : mesh.faces()) {
    if (separable[f.idx()]) continue;
    for (auto v : mesh.fv_range(f)) parts.corners.push_back(vertex_index[v.idx()]);
    parts.face_start.push_back(static_cast<int>(parts.corners.size()));
    parts.labels.push_back(detail::label_of(mesh, labels, f));
    ++kept;
  }
  auto in_set = [&](PolyMesh::FaceHandle f) { return f.is_valid() && separable[f.idx()]; };
  for (auto e : mesh.edges()) {
    auto h = mesh.halfedge_handle(e, 0);
    if (!in_set(mesh.face_handle(h))) h = mesh.opposite_halfedge_handle(h);
    const auto F = mesh.face_handle(h);
    if (!in_set(F)) continue;
    const auto G = mesh.opposite_face_handle(h);
    const int a = vertex_index[mesh.from_vertex_handle(h).idx()];
    const int b = vertex_index[mesh.to_vertex_handle(h).idx()];
    const std::string& label = detail::label_of(mesh, labels, F);
    if (in_set(G))
      parts.add_face({a, face_point[G.idx()], b, face_point[F.idx()]}, label);
    else
      parts.add_face({a, b, face_point[F.idx()]}, label);
  }
  mesh = detail::build_mesh(parts, "sqrt2_subdivide");
  return kept;
}

}  // namespace

FaceList sqrt2_subdivide(PolyMesh& mesh, const FaceList& faces, int levels, double smoothing) {
  detail::check_faces(mesh, faces, "sqrt2_subdivide");
  if (levels < 0) throw std::invalid_argument("sqrt2_subdivide: levels must be >= 0, got " + std::to_string(levels));
  if (!std::isfinite(smoothing)) throw std::invalid_argument("sqrt2_subdivide: the smoothing factor is not finite");
  if (faces.empty() || levels == 0) return {};
  std::vector<char> separable(mesh.n_faces(), 0);
  for (auto f : faces) separable[f.idx()] = 1;
  int first_new = 0;
  for (int level = 0; level < levels; ++level) {
    if (level > 0) {
      separable.assign(mesh.n_faces(), 0);
      for (std::size_t i = first_new; i < mesh.n_faces(); ++i) separable[i] = 1;
    }
    first_new = sqrt2_level(mesh, separable, smoothing);
  }
  FaceList created;
  for (std::size_t i = first_new; i < mesh.n_faces(); ++i) created.push_back(PolyMesh::FaceHandle(static_cast<int>(i)));
  return created;
}

void sqrt2_subdivide_all(PolyMesh& mesh, int levels, double smoothing) {
  sqrt2_subdivide(mesh, all_faces(mesh), levels, smoothing);
}

}  // namespace genmod
