#include "genmod/procedural/grid_box.hpp"

#include "mesh_rebuild.hpp"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

namespace genmod {

PolyMesh make_grid_box(const Vec3& lo, const Vec3& hi, int n, const std::string& label) {
  if (n < 1) throw std::invalid_argument("make_grid_box: n must be >= 1, got " + std::to_string(n));
  for (int a = 0; a < 3; ++a)
    if (!(std::isfinite(lo[a]) && std::isfinite(hi[a]) && lo[a] < hi[a]))
      throw std::invalid_argument("make_grid_box: the box needs finite lo < hi on every axis (axis " +
                                  std::to_string(a) + ")");
  detail::MeshParts parts;
  // Lattice points are shared by the sides that meet at them: one vertex per lattice index.
  std::unordered_map<std::int64_t, int> index_of;
  const std::int64_t m = n + 1;
  auto vertex = [&](int i, int j, int k) {
    const std::int64_t key = i + m * (j + m * k);
    auto [it, inserted] = index_of.try_emplace(key, static_cast<int>(parts.points.size()));
    if (inserted) {
      const int c[3] = {i, j, k};
      Vec3 p;
      for (int a = 0; a < 3; ++a) p[a] = c[a] == n ? hi[a] : lo[a] + (hi[a] - lo[a]) * c[a] / n;
      parts.points.push_back(p);
    }
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      // (u, w) follow `axis` cyclically, so u x w points along +axis.
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          int ring[4];
          const int du[4] = {0, 1, 1, 0}, dw[4] = {0, 0, 1, 1};
          for (int c = 0; c < 4; ++c) {
            int idx[3];
            idx[axis] = side * n;
            idx[u] = a + du[c];
            idx[w] = b + dw[c];
            ring[c] = vertex(idx[0], idx[1], idx[2]);
          }
          if (side == 1)
            parts.add_face({ring[0], ring[1], ring[2], ring[3]}, label);
          else
            parts.add_face({ring[0], ring[3], ring[2], ring[1]}, label);
        }
    }
  return detail::build_mesh(parts, "make_grid_box");
}

}  // namespace genmod
