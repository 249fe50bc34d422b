// Integer parameter coordinates of the adaptive parametric mesher.
//
// Every kd-tree split halves a leaf, so leaf corners are dyadic: a patch's rectangle is
// addressed by integers 0 .. kGridSize per axis, and a parameter value is computed from its
// integer by one formula (grid_value), so neighbouring leaves share their corners bit for bit
// and seams can be matched exactly in integers.
#pragma once

#include "genmod/kernel/interval.hpp"

#include <cmath>
#include <cstdint>

namespace genmod::parametric {

constexpr int kGridBits = 30;
constexpr std::int64_t kGridSize = std::int64_t{1} << kGridBits;

// The parameter value of grid index k on the range r: lo + (hi - lo) k / 2^30, exactly hi at
// the end. Monotone in k.
inline double grid_value(const Interval& r, std::int64_t k) {
  if (k >= kGridSize) return r.hi();
  return r.lo() + (r.hi() - r.lo()) * std::ldexp(static_cast<double>(k), -kGridBits);
}

// A leaf: grid rectangle [u0, u1] x [v0, v1] of one patch.
struct GridRect {
  std::int64_t u0 = 0, u1 = kGridSize, v0 = 0, v1 = kGridSize;
};

// A parameter point of one patch, in grid units. Ordered (patch, u, v).
struct GridPoint {
  std::uint32_t patch = 0;
  std::int64_t u = 0, v = 0;
  friend bool operator==(const GridPoint&, const GridPoint&) = default;
  friend auto operator<=>(const GridPoint&, const GridPoint&) = default;
};

}  // namespace genmod::parametric
