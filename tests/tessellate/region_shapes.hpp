// Multi-region test shapes of the non-manifold polygonizer (its tests and its benchmark): region
// functions of p = (x(0), x(1), x(2)), the region of a point being the largest.
#pragma once

#include "genmod/kernel/fn.hpp"

#include <vector>

namespace genmod::test {

inline Fn radius_of_point() { return sqrt(square(x(0)) + square(x(1)) + square(x(2))); }

// Three regions: the upper (0) and lower (1) halves of a ball of radius r, and outside (2).
inline std::vector<Fn> half_balls(double r) {
  const Fn d = r - radius_of_point(), z = x(2);
  return {min(d, z), min(d, -z), -d};
}

// The sphere-square of Fig. 4.9 with the spec's regions 1..4 as 0..3: the ball (0), outside
// the cube of half side s (1), above (2) and below (3) the plane z = 0.
inline std::vector<Fn> sphere_square(double r, double s) {
  const Fn ball = r - radius_of_point(), z = x(2);
  const Fn outside = max(max(abs(x(0)), abs(x(1))), abs(z)) - s;
  const Fn rest = min(-ball, -outside);
  return {ball, outside, min(rest, z), min(rest, -z)};
}

}  // namespace genmod::test
