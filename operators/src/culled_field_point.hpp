// Which elements a culled field's point evaluation visits (culled_field.hpp, "Point value").
// Internal to operators/.
#pragma once

#include "culled_field_bvh.hpp"
#include "genmod/kernel/interval.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace genmod::detail {

// The result of one pass at a threshold t.
struct PointNear {
  std::vector<std::uint32_t> indices;  // the visited elements (unordered)
  double remainder = 0;  // >= the total |value| of the skipped elements at the point (rounded up)
};

// The items of the hierarchy (or of the linear list) that the point may need at threshold t:
// a Gaussian item (or subtree) is skipped when its bound at the point's distance, with the
// subtree's largest weight, radius and taper (order 0: the value bound, order 1: the gradient
// bound of culled_field_bounds.hpp), is at most t, and its bound is added to the remainder; a
// compact item is skipped only beyond its support (where it is exactly 0). With t = 0 only
// those compact items are skipped (the bounds are positive).
void near_point(const ElementBvh* bvh, std::span<const BvhItem> linear, int order, std::span<const Interval> point, double t, PointNear& out);

}  // namespace genmod::detail
