// The elements a culled field's point evaluation visits (culled_field_point.hpp).
#include "culled_field_point.hpp"

#include "culled_field_bounds.hpp"

namespace genmod::detail {
void near_point(const ElementBvh* bvh, std::span<const BvhItem> linear, int order, std::span<const Interval> point, double t, PointNear& out) {
  out.indices.clear();
  // The skipped bounds are non-negative and summed in double arithmetic: `terms` products and
  // sums, each rounding with relative error <= 2^-53, so the sum grown by terms * 2^-52 bounds
  // the exact total.
  double remainder = 0, terms = 1;
  auto skip_item = [&](const BvhItem& it, double d2) {
    if (!it.remainder) return d2 >= it.cull2;  // compact: exactly 0 beyond its support
    const double b = gaussian_order_above(order, it.weight, it.radius, it.taper, d2);
    if (!(b <= t)) return false;
    remainder += b, terms += 1;
    return true;
  };
  auto near = [&](const BvhItem& it) { out.indices.push_back(it.index); };
  if (bvh) {
    bvh->visit(
        point,
        [&](const BvhNode& n, double d2) {
          if (d2 < n.compact2) return false;
          if (n.remainders == 0) return true;
          const double b = gaussian_order_above(order, n.weight, n.radius, n.taper, d2);
          if (!(b <= t)) return false;
          remainder += static_cast<double>(n.remainders) * b, terms += 2;
          return true;
        },
        skip_item, near);
  } else {
    for (const BvhItem& it : linear)
      if (!skip_item(it, box_distance2_below(it.lo, it.hi, point))) near(it);
  }
  out.remainder = remainder * (1 + terms * 0x1p-52);
}

}  // namespace genmod::detail
