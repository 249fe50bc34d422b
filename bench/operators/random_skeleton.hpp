// The skeleton of the culled-field benchmarks: a tree-like random walk over [-2, 2]^3 of n
// segments of length 0.05 with direction persistence (reflected at the walls), branching from
// a random earlier node one time in ten; radius 0.02 .. 0.04. Deterministic (seed 7).
#pragma once

#include "genmod/operators/skeletal.hpp"

#include <cmath>
#include <random>
#include <vector>

namespace genmod::bench {

struct SkeletonSegment {
  Point3 a, b;
  double radius;
};

inline std::vector<SkeletonSegment> random_skeleton(int n) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Point3> nodes = {{0, 0, 0}};
  Point3 dir = {1, 0, 0};
  std::size_t from = 0;
  std::vector<SkeletonSegment> out;
  for (int i = 0; i < n; ++i) {
    if (std::uniform_int_distribution<int>(0, 9)(rng) == 0) from = std::uniform_int_distribution<std::size_t>(0, nodes.size() - 1)(rng);
    double len = 0;
    for (int k = 0; k < 3; ++k) dir[k] += 0.5 * u(rng), len += dir[k] * dir[k];
    len = std::sqrt(len);
    const Point3 a = nodes[from];
    Point3 b;
    for (int k = 0; k < 3; ++k) {
      dir[k] /= len;
      b[k] = a[k] + 0.05 * dir[k];
      if (std::abs(b[k]) > 2) dir[k] = -dir[k], b[k] = a[k] + 0.05 * dir[k];
    }
    nodes.push_back(b);
    from = nodes.size() - 1;
    out.push_back({a, b, 0.02 + 0.01 * (1 + u(rng))});
  }
  return out;
}

}  // namespace genmod::bench
