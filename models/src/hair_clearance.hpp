// Clearance between straight tapered hairs: a hair's tube has cross sections of at most
// radius (1 - s^2) r about the point base + s (tip - base) of its axis, s in [0, 1]. The
// union of those balls is convex (a ball radius concave in s about a point affine in s), so
// it holds the tube and any mesh of it (triangles whose corners are on the tube). Two tubes
// cannot meet when, for all s and t, the axis points are farther apart than the two radii:
//   min over (s, t) of |P(s) - Q(t)| - (1 - s^2) r_P - (1 - t^2) r_Q > 0,
// a convex function of (s, t), so its minimum is found by nested one-dimensional searches.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace genmod::models::detail {

struct HairCapsule {
  std::array<double, 3> base, tip;
  double radius = 0.0;  // at the base; (1 - s^2) radius at s
};

// The distance between the segments [p0, p1] and [q0, q1] (either may be a point).
double segment_distance(const std::array<double, 3>& p0, const std::array<double, 3>& p1,
                        const std::array<double, 3>& q0, const std::array<double, 3>& q1);

struct HairOverlap {
  std::size_t a = 0, b = 0;  // indices, a < b
  double distance = 0.0;     // between their axis points where they overlap most
  double radii = 0.0;        // the sum of their tapered radii there (>= distance)
};

// Of the pairs of hairs whose tapered hulls may meet (the minimum above <= 0), the one that
// overlaps most (smallest minimum, then lowest indices); none when all are apart.
std::optional<HairOverlap> deepest_hair_overlap(const std::vector<HairCapsule>& hairs);

}  // namespace genmod::models::detail
