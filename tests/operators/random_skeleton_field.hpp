// Shared helpers of the culled field's tests (culled_field_test, culled_hessian_test): boxes,
// the distance to a segment, and a random tree-like skeleton field of n short Gaussian segments in [-1, 1]^3, each grown from a random node
// of the tree so far, radius 0.02-0.04. One element in ten is a point source made by
// `point(b, r, rng)` at the new node; where `tapered(i)`, a segment's end radius is 0.5-1.5
// times its start radius.
#pragma once

#include "genmod/operators/culled_field.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace genmod::testing {

// The cube of half side `half` about c.
inline std::vector<Interval> cube(const Point3& c, double half) {
  return {Interval(c[0] - half, c[0] + half), Interval(c[1] - half, c[1] + half), Interval(c[2] - half, c[2] + half)};
}

// The exact distance from p to the segment a-b.
inline double segment_distance(const Point3& a, const Point3& b, const Point3& p) {
  double ab2 = 0, t = 0;
  for (int i = 0; i < 3; ++i) ab2 += (b[i] - a[i]) * (b[i] - a[i]), t += (p[i] - a[i]) * (b[i] - a[i]);
  t = ab2 > 0 ? std::clamp(t / ab2, 0.0, 1.0) : 0.0;
  double d2 = 0;
  for (int i = 0; i < 3; ++i) d2 += (p[i] - a[i] - t * (b[i] - a[i])) * (p[i] - a[i] - t * (b[i] - a[i]));
  return std::sqrt(d2);
}

template <class PointSource, class Tapered>
std::vector<FieldElement> random_skeleton_field(int n, unsigned seed, PointSource point, Tapered tapered) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1), w(0, 1);
  std::vector<Point3> nodes = {{0, 0, 0}};
  std::vector<FieldElement> es;
  for (int i = 0; i < n; ++i) {
    const Point3 a = nodes[std::uniform_int_distribution<std::size_t>(0, nodes.size() - 1)(rng)];
    const Point3 b = {std::clamp(a[0] + 0.15 * u(rng), -1.0, 1.0), std::clamp(a[1] + 0.15 * u(rng), -1.0, 1.0),
                      std::clamp(a[2] + 0.15 * u(rng), -1.0, 1.0)};
    nodes.push_back(b);
    const double r = 0.02 + 0.02 * w(rng);
    if (i % 10 == 9) es.push_back(point(b, r, rng));
    else es.push_back(gaussian_segment_element(a, b, r, tapered(i) ? r * (0.5 + w(rng)) : r));
  }
  return es;
}

}  // namespace genmod::testing
