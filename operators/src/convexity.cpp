// The convexity measure of the combination surface (blends.hpp: convexity_from_cosine).
//
// 1 - Ease(theta / (pi/2)) with theta = acos(c) is a polynomial in theta^2 (Ease is even), and
// acos(c)^2 is analytic at c = 1, but every opcode formula of it (acos, or atan2 of a norm)
// has 0 * infinity in its derivative where c = 1 (gradient parallel to the normal), which
// leaves the derivative's interval flagged "maybe error" on every box where c can reach 1.
// Two custom operators remove the singular factor:
//   acos_squared(c) = acos(c)^2,           d/dc = -2 acos_ratio(c)
//   acos_ratio(c)   = acos(c) / sqrt(1 - c^2)  (-> 1 at c = 1; decreasing on (-1, 1])
// so the gradient of the convexity is defined and boundable everywhere; acos_ratio's own
// derivative (c acos_ratio(c) - 1) / (1 - c^2) is still 0/0 at c = 1 (second derivatives).
#include "genmod/operators/blends.hpp"

#include "genmod/kernel/custom_op.hpp"
#include "genmod/operators/convolution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

namespace genmod {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
// Below this distance t = 1 - c the ratio uses its series: the truncation error 5 t^3/896 is
// below 6e-15, the direct formula's relative error there would be ~1e-12 (cancellation in
// 1 - c^2 is avoided, but acos loses relative accuracy near 1).
constexpr double kSeriesBelow = 1e-4;
// Relative widening of the ratio's bounds: rounding (a few ulps) plus the series truncation.
constexpr double kRatioSlack = 1e-13;

double acos_ratio_value(double c) {
  if (!(c >= -1 && c <= 1)) return kNaN;
  if (c == -1) return kInf;
  const double t = 1 - c;  // exact for c in [1/2, 1]
  if (t < kSeriesBelow) return (1 + t * (1.0 / 12 + t * (3.0 / 160 + t * (5.0 / 896)))) / std::sqrt(1 - t / 2);
  return std::acos(c) / std::sqrt((1 - c) * (1 + c));
}

// The part of x inside [-1, 1] (empty if none); flags an error if x reaches outside.
Interval in_domain(const Interval& x, std::uint8_t& err) {
  if (x.is_empty()) return x;
  if (x.hi() < -1 || x.lo() > 1) err |= kCertainError;
  else if (x.lo() < -1 || x.hi() > 1) err |= kMaybeError;
  return intersect(x, Interval(-1.0, 1.0));
}

class AcosRatioOp final : public CustomOp {
 public:
  std::string name() const override { return "acos_ratio"; }
  int num_args() const override { return 1; }
  int num_outputs() const override { return 1; }
  void eval(std::span<const double> a, std::span<double> out) const override { out[0] = acos_ratio_value(a[0]); }
  void inclusion(std::span<const Interval> a, std::span<Interval> out, std::span<std::uint8_t> err) const override {
    const Interval c = in_domain(a[0], err[0]);
    if (c.is_empty()) {
      out[0] = Interval::empty();
      return;
    }
    // decreasing: g(hi) <= g <= g(lo); g >= 1 on [-1, 1]
    const double lo = std::max(1.0, acos_ratio_value(c.hi()) * (1 - kRatioSlack));
    const double hi = c.lo() == -1 ? kInf : acos_ratio_value(c.lo()) * (1 + kRatioSlack);
    out[0] = Interval(lo, std::max(lo, hi));
  }
  Fn derivative(std::span<const Fn> a, int) const override;
  bool continuous() const override { return true; }
};

const std::shared_ptr<const CustomOp>& acos_ratio_op() {
  static const std::shared_ptr<const CustomOp> op = std::make_shared<AcosRatioOp>();
  return op;
}

Fn AcosRatioOp::derivative(std::span<const Fn> a, int) const {
  return (a[0] * apply_custom(acos_ratio_op(), {a[0]}) - 1.0) / (1.0 - square(a[0]));
}

class AcosSquaredOp final : public CustomOp {
 public:
  std::string name() const override { return "acos_squared"; }
  int num_args() const override { return 1; }
  int num_outputs() const override { return 1; }
  void eval(std::span<const double> a, std::span<double> out) const override {
    const double c = a[0];
    if (!(c >= -1 && c <= 1)) {
      out[0] = kNaN;
      return;
    }
    const double th = std::acos(c);
    out[0] = th * th;
  }
  void inclusion(std::span<const Interval> a, std::span<Interval> out, std::span<std::uint8_t> err) const override {
    const Interval c = in_domain(a[0], err[0]);
    // acos is the kernel's outward enclosure (a few ulps wider than the true range), so the
    // point value, the square of a rounded acos, stays inside.
    out[0] = c.is_empty() ? Interval::empty() : square(acos(c));
  }
  Fn derivative(std::span<const Fn> a, int) const override { return -2.0 * apply_custom(acos_ratio_op(), {a[0]}); }
  bool continuous() const override { return true; }
};

}  // namespace

Fn acos_squared(const Fn& c) {
  static const std::shared_ptr<const CustomOp> op = std::make_shared<AcosSquaredOp>();
  return apply_custom(op, {c});
}

Fn convexity_from_cosine(const Fn& cosine) {
  // Ease(x) with x^2 = s: s (22 - s (17 - 4 s)) / 9 on [0, 1], 1 beyond (s >= 0 here).
  const Fn s = acos_squared(min(abs(cosine), 1.0)) * (4.0 / (std::numbers::pi * std::numbers::pi));
  return 1.0 - select(s >= 1.0, 1.0, s * (22.0 - s * (17.0 - 4.0 * s)) * (1.0 / 9.0));
}

}  // namespace genmod
