#include "genmod/procedural/poly_mesh.hpp"

#include "face_labels.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace genmod {
namespace {

using detail::kLabelProperty;
using detail::label_property;

}  // namespace

void set_face_label(PolyMesh& mesh, PolyMesh::FaceHandle face, const std::string& label) {
  if (!face.is_valid() || face.idx() >= static_cast<int>(mesh.n_faces()))
    throw std::invalid_argument("set_face_label: face " + std::to_string(face.idx()) + " is not in the mesh");
  mesh.property(label_property(mesh), face) = label;
}

std::string face_label(const PolyMesh& mesh, PolyMesh::FaceHandle face) {
  OpenMesh::FPropHandleT<std::string> handle;
  if (!mesh.get_property_handle(handle, kLabelProperty)) return {};
  return mesh.property(handle, face);
}

FaceList faces_labelled(const PolyMesh& mesh, const std::string& label) {
  FaceList faces;
  OpenMesh::FPropHandleT<std::string> handle;
  if (!mesh.get_property_handle(handle, kLabelProperty)) return faces;
  for (PolyMesh::FaceHandle f : mesh.faces())
    if (mesh.property(handle, f) == label) faces.push_back(f);
  return faces;
}

PolyMesh make_box(const Vec3& lo, const Vec3& hi, const std::string& label) {
  for (int a = 0; a < 3; ++a)
    if (!(std::isfinite(lo[a]) && std::isfinite(hi[a]) && lo[a] < hi[a]))
      throw std::invalid_argument("make_box: the box needs finite lo < hi on every axis (axis " +
                                  std::to_string(a) + ")");
  PolyMesh mesh;
  PolyMesh::VertexHandle v[8];
  for (int i = 0; i < 8; ++i)
    v[i] = mesh.add_vertex(Vec3((i & 1) ? hi[0] : lo[0], (i & 2) ? hi[1] : lo[1], (i & 4) ? hi[2] : lo[2]));
  // Counter-clockwise seen from outside.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    PolyMesh::FaceHandle f = mesh.add_face(v[q[0]], v[q[1]], v[q[2]], v[q[3]]);
    set_face_label(mesh, f, label);
  }
  return mesh;
}

MeshCounts counts(const PolyMesh& mesh) {
  MeshCounts c;
  for ([[maybe_unused]] auto v : mesh.vertices()) ++c.vertices;
  for ([[maybe_unused]] auto e : mesh.edges()) ++c.edges;
  for ([[maybe_unused]] auto f : mesh.faces()) ++c.faces;
  return c;
}

bool is_closed_manifold(const PolyMesh& mesh) {
  if (mesh.faces_empty()) return false;
  for (auto e : mesh.edges())
    if (mesh.is_boundary(e)) return false;
  for (auto v : mesh.vertices())
    if (!mesh.is_manifold(v) || mesh.is_isolated(v)) return false;
  return true;
}

FaceList all_faces(const PolyMesh& mesh) {
  FaceList faces;
  for (PolyMesh::FaceHandle f : mesh.faces()) faces.push_back(f);
  return faces;
}

std::array<Vec3, 2> bounds(const PolyMesh& mesh, const FaceList& faces) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::array<Vec3, 2> b{Vec3(inf, inf, inf), Vec3(-inf, -inf, -inf)};
  for (PolyMesh::FaceHandle f : faces)
    for (auto v : mesh.fv_range(f)) {
      const Vec3& p = mesh.point(v);
      for (int a = 0; a < 3; ++a) {
        b[0][a] = std::min(b[0][a], p[a]);
        b[1][a] = std::max(b[1][a], p[a]);
      }
    }
  return b;
}

Mesh to_triangle_mesh(const PolyMesh& input) {
  PolyMesh mesh = input;
  mesh.garbage_collection();
  Mesh out;
  out.vertices.reserve(mesh.n_vertices());
  for (auto v : mesh.vertices()) {
    const Vec3& p = mesh.point(v);
    out.vertices.push_back({p[0], p[1], p[2]});
  }
  for (auto f : mesh.faces()) {
    std::vector<std::uint32_t> ring;
    for (auto v : mesh.fv_range(f)) ring.push_back(static_cast<std::uint32_t>(v.idx()));
    for (std::size_t i = 1; i + 1 < ring.size(); ++i) out.triangles.push_back({ring[0], ring[i], ring[i + 1]});
  }
  return out;
}

}  // namespace genmod
