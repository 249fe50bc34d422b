#include "genmod/procedural/grid_box.hpp"

#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

namespace genmod {

PolyMesh make_grid_box(const Vec3& lo, const Vec3& hi, int n, const std::string& label) {
  for (int a = 0; a < 3; ++a)
    if (!(std::isfinite(lo[a]) && std::isfinite(hi[a]) && lo[a] < hi[a]))
      throw std::invalid_argument("make_grid_box: the box needs finite lo < hi on every axis (axis " +
                                  std::to_string(a) + ")");
  if (n < 1 || n > 1024)
    throw std::invalid_argument("make_grid_box: n must be in [1, 1024], got " + std::to_string(n));
  // Grid coordinate i of n on axis a; the ends are lo and hi exactly, so faces lie on the planes.
  auto coordinate = [&](int a, int i) {
    if (i == 0) return lo[a];
    if (i == n) return hi[a];
    return lo[a] + (hi[a] - lo[a]) * (static_cast<double>(i) / n);
  };
  PolyMesh mesh;
  // One vertex per lattice point on the surface, created on first use: the order of creation
  // follows the face order below, so indices are deterministic.
  std::map<std::tuple<int, int, int>, PolyMesh::VertexHandle> vertex_at;
  auto vertex = [&](int i, int j, int k) {
    auto [it, fresh] = vertex_at.try_emplace({i, j, k});
    if (fresh) it->second = mesh.add_vertex(Vec3(coordinate(0, i), coordinate(1, j), coordinate(2, k)));
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      // (u, w) = the next two axes cyclically, so u x w = +axis: a quad counter-clockwise in
      // (u, w) faces +axis; the -axis face reverses it.
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      for (int b = 0; b < n; ++b)
        for (int c = 0; c < n; ++c) {
          auto at = [&](int du, int dw) {
            int idx[3];
            idx[axis] = side ? n : 0;
            idx[u] = c + du;
            idx[w] = b + dw;
            return vertex(idx[0], idx[1], idx[2]);
          };
          PolyMesh::VertexHandle q[4] = {at(0, 0), at(1, 0), at(1, 1), at(0, 1)};
          PolyMesh::FaceHandle f = side ? mesh.add_face(q[0], q[1], q[2], q[3]) : mesh.add_face(q[3], q[2], q[1], q[0]);
          set_face_label(mesh, f, label);
        }
    }
  return mesh;
}

}  // namespace genmod
