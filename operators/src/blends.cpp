// Blends of skeletal primitives (blends.hpp).
#include "genmod/operators/blends.hpp"

#include "genmod/kernel/custom_op.hpp"
#include "genmod/operators/convolution.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace genmod {
namespace {

void check_scalar(const Fn& f, const char* who) {
  if (f.dim() != 1) throw std::invalid_argument(std::string(who) + ": fields must be scalar, got dimension " + std::to_string(f.dim()));
}

Fn power(const Fn& base, int n) {
  Fn r = base;
  for (int i = 1; i < n; ++i) r = r * base;
  return n == 2 ? square(base) : r;
}

// B + clamp(c, 0, 1) (U - B).
class ConvexityBlendOp final : public CustomOp {
 public:
  std::string name() const override { return "convexity_blend"; }
  int num_args() const override { return 3; }
  int num_outputs() const override { return 1; }
  void eval(std::span<const double> a, std::span<double> out) const override {
    const double c = std::isnan(a[2]) ? a[2] : std::clamp(a[2], 0.0, 1.0);
    out[0] = a[0] + c * (a[1] - a[0]);
  }
  void inclusion(std::span<const Interval> a, std::span<Interval> out, std::span<std::uint8_t>) const override {
    if (a[0].is_empty() || a[1].is_empty() || a[2].is_empty()) {
      out[0] = Interval::empty();
      return;
    }
    const Interval c = intersect(a[2], Interval(0.0, 1.0));
    // The point value B + c (U - B) rounds; widen the hull by the rounding of those two
    // operations (a few ulps of max(|B|, |U|)) so the computed value stays inside.
    const double lo = std::min(a[0].lo(), a[1].lo()), hi = std::max(a[0].hi(), a[1].hi());
    const double scale = std::max(std::abs(lo), std::abs(hi));
    const double slack = 4 * std::numeric_limits<double>::epsilon() * scale + std::numeric_limits<double>::denorm_min();
    Interval hull_bound(lo - slack, hi + slack);
    if (!c.is_empty()) hull_bound = intersect(hull_bound, a[0] + c * (a[1] - a[0]) + Interval(-slack, slack));
    out[0] = hull_bound;
  }
  Fn derivative(std::span<const Fn> a, int k) const override {
    const Fn c = min(max(a[2], 0.0), 1.0);
    if (k == 0) return 1.0 - c;
    if (k == 1) return c;
    return select(a[2] > 0.0 && a[2] < 1.0, a[1] - a[0], 0.0);
  }
  bool continuous() const override { return true; }
};

}  // namespace

Fn average_blend(std::span<const Fn> fields) {
  if (fields.empty()) throw std::invalid_argument("average_blend: no fields");
  Fn sum;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    check_scalar(fields[i], "average_blend");
    sum = i == 0 ? fields[i] : sum + fields[i];
  }
  return sum * (1.0 / static_cast<double>(fields.size()));
}

Fn average_blend(std::initializer_list<Fn> fields) { return average_blend(std::span<const Fn>(fields.begin(), fields.size())); }

Fn range_blend(std::span<const Fn> primitives, std::span<const double> ranges, int thumbweight) {
  if (primitives.empty()) throw std::invalid_argument("range_blend: no primitives");
  if (primitives.size() != ranges.size())
    throw std::invalid_argument("range_blend: " + std::to_string(primitives.size()) + " primitives but " +
                                std::to_string(ranges.size()) + " ranges");
  if (thumbweight < 2 || thumbweight > 64)
    throw std::invalid_argument("range_blend: thumbweight must be an integer in [2, 64], got " + std::to_string(thumbweight));
  Fn sum;
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    check_scalar(primitives[i], "range_blend");
    if (!(ranges[i] > 0 && std::isfinite(ranges[i]))) throw std::invalid_argument("range_blend: ranges must be finite and > 0");
    const Fn term = power(max(1.0 - primitives[i] * (1.0 / ranges[i]), 0.0), thumbweight);
    sum = i == 0 ? term : sum + term;
  }
  return 1.0 - sum;
}

Fn range_blend(std::initializer_list<Fn> primitives, std::initializer_list<double> ranges, int thumbweight) {
  return range_blend(std::span<const Fn>(primitives.begin(), primitives.size()),
                     std::span<const double>(ranges.begin(), ranges.size()), thumbweight);
}

Fn rolling_ball_blend(const Fn& a, const Fn& b, double rho) {
  check_scalar(a, "rolling_ball_blend");
  check_scalar(b, "rolling_ball_blend");
  if (!(rho > 0 && std::isfinite(rho))) throw std::invalid_argument("rolling_ball_blend: ball radius must be finite and > 0");
  const Fn u = max(rho - a, 0.0), v = max(rho - b, 0.0);
  const Fn s = square(u) + square(v);
  // sqrt only where the ball touches both fields (s > 0), so the derivative is defined
  // where s = 0 (an open region).
  return max(rho, min(a, b)) - select(s > 0.0, sqrt(s), 0.0);
}

Fn grouped_blend(std::span<const Fn> densities, const std::vector<std::vector<int>>& blend_with, double iso) {
  if (densities.empty()) throw std::invalid_argument("grouped_blend: no elements");
  if (densities.size() != blend_with.size())
    throw std::invalid_argument("grouped_blend: " + std::to_string(densities.size()) + " densities but " +
                                std::to_string(blend_with.size()) + " blend sets");
  if (!std::isfinite(iso)) throw std::invalid_argument("grouped_blend: iso-value must be finite");
  Fn f;
  for (std::size_t i = 0; i < densities.size(); ++i) {
    check_scalar(densities[i], "grouped_blend");
    Fn sum = densities[i];
    for (int j : blend_with[i]) {
      if (j < 0 || static_cast<std::size_t>(j) >= densities.size() || static_cast<std::size_t>(j) == i)
        throw std::invalid_argument("grouped_blend: blend set " + std::to_string(i) + " names element " + std::to_string(j));
      sum = sum + densities[static_cast<std::size_t>(j)];
    }
    f = i == 0 ? iso - sum : min(f, iso - sum);
  }
  return f;
}

Fn product_blend(const Fn& p1, const Fn& p2) {
  check_scalar(p1, "product_blend");
  check_scalar(p2, "product_blend");
  return 1.0 - (1.0 - p1) * (1.0 - p2);
}

Fn decay(const Fn& x) { return 1.0 - ease(x); }

Fn convexity_blend(const Fn& blend, const Fn& union_field, const Fn& convexity) {
  check_scalar(blend, "convexity_blend");
  check_scalar(union_field, "convexity_blend");
  check_scalar(convexity, "convexity_blend");
  static const std::shared_ptr<const CustomOp> op = std::make_shared<ConvexityBlendOp>();
  return apply_custom(op, {blend, union_field, convexity});
}

}  // namespace genmod
