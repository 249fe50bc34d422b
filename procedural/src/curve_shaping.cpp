#include "genmod/procedural/curve_shaping.hpp"

#include "face_checks.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace genmod {

std::size_t shape_to_curve(PolyMesh& mesh, const FaceList& faces, const BezierCurve& curve, const Vec3& direction,
                           const Vec3& normal) {
  if (faces.empty()) return 0;
  const std::string tool = "shape_to_curve";
  require_faces_in_mesh(mesh, faces, tool);
  require_finite_nonzero(direction, tool, "direction");
  require_finite_nonzero(normal, tool, "normal");
  const Vec3 n = normal / normal.norm();
  Vec3 d = direction - n * OpenMesh::dot(direction, n);
  if (!(d.norm() > 1e-12 * direction.norm()))
    throw std::invalid_argument("shape_to_curve: direction is parallel to normal");
  d /= d.norm();

  std::vector<int> vertices;
  for (PolyMesh::FaceHandle f : faces)
    for (auto v : mesh.fv_range(f)) vertices.push_back(v.idx());
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());

  std::size_t met = 0;
  for (int index : vertices) {
    const PolyMesh::VertexHandle v(index);
    const std::optional<LineCurveHit> hit = intersect_line(curve, mesh.point(v), d, n);
    if (!hit) continue;
    ++met;
    Vec3 p = mesh.point(v);
    for (int a = 0; a < 3; ++a)
      if (d[a] != 0.0) p[a] += hit->s * d[a];
    mesh.set_point(v, p);
  }
  return met;
}

}  // namespace genmod
