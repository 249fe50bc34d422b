// Breadth-first propagation of orientation over manifold edges, then signed volumes.
#include "mesh_orientation.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace genmod::parametric {

namespace {

struct EdgeUse {
  std::uint64_t key;     // undirected edge (min << 32 | max)
  std::uint32_t tri;
  bool forward;          // the triangle runs min -> max
};

double signed_volume6(const Mesh& m, const std::array<std::uint32_t, 3>& t) {
  const auto& a = m.vertices[t[0]];
  const auto& b = m.vertices[t[1]];
  const auto& c = m.vertices[t[2]];
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

}  // namespace

OrientationReport orient_outward(Mesh& mesh) {
  OrientationReport report;
  const std::size_t n = mesh.triangles.size();
  std::vector<EdgeUse> uses;
  uses.reserve(3 * n);
  for (std::uint32_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      uses.push_back({(std::uint64_t{std::min(a, b)} << 32) | std::max(a, b), t, a < b});
    }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.key != y.key ? x.key < y.key : x.tri < y.tri;
  });
  // Neighbours across manifold edges: (other triangle, whether both run the edge the same way).
  std::vector<std::vector<std::pair<std::uint32_t, bool>>> across(n);
  std::vector<bool> open(n, false);
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i == 1) {
      ++report.boundary_edges;
      open[uses[i].tri] = true;
    } else if (j - i == 2) {
      const bool same = uses[i].forward == uses[i + 1].forward;
      across[uses[i].tri].push_back({uses[i + 1].tri, same});
      across[uses[i + 1].tri].push_back({uses[i].tri, same});
    } else {
      for (std::size_t k = i; k < j; ++k) open[uses[k].tri] = true;  // non-manifold: leave alone
    }
    i = j;
  }
  std::vector<int> state(n, -1);  // -1 unvisited, 0 keep, 1 flip
  std::vector<std::uint32_t> queue, component;
  for (std::uint32_t seed = 0; seed < n; ++seed) {
    if (state[seed] >= 0) continue;
    component.clear();
    queue.assign(1, seed);
    state[seed] = 0;
    bool closed = true;
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const std::uint32_t t = queue[q];
      component.push_back(t);
      closed = closed && !open[t];
      for (const auto& [other, same] : across[t]) {
        const int want = same ? 1 - state[t] : state[t];
        if (state[other] < 0) {
          state[other] = want;
          queue.push_back(other);
        } else if (state[other] != want) {
          ++report.conflicts;
        }
      }
    }
    for (std::uint32_t t : component)
      if (state[t] == 1) std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
    if (!closed) continue;
    double volume = 0.0;
    for (std::uint32_t t : component) volume += signed_volume6(mesh, mesh.triangles[t]);
    if (volume < 0.0) {
      for (std::uint32_t t : component) std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
      ++report.flipped_components;
    }
  }
  report.conflicts /= 2;  // each inconsistent edge is seen from both sides
  return report;
}

}  // namespace genmod::parametric
