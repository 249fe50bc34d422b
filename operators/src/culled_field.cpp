// Superposition with per-box culling through a hierarchy of the elements (culled_field.hpp).
#include "genmod/operators/culled_field.hpp"

#include "culled_field_bounds.hpp"
#include "culled_field_bvh.hpp"
#include "culled_field_point.hpp"
#include "genmod/kernel/custom_op.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/convolution.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

namespace genmod {
namespace {

using detail::box_distance2_below;

constexpr double kInf = std::numeric_limits<double>::infinity();
// The point value's tolerance, relative to the visited elements' magnitude (header).
constexpr double kPointTolerance = 0x1p-60;
const int kXyz[3] = {0, 1, 2};

// How an element of a field of the given derivative order is culled.
enum class Cull {
  value,     // a Gaussian density: [0, weight Gauss(delta / radius)]
  gradient,  // a first derivative of a Gaussian convolution: [-B, B] (culled_field_bounds)
  hessian,   // a second derivative of a constant-radius one: [-C, C] (culled_field_bounds)
  compact,   // zero beyond its support: [0, 0]
  never,
};

Cull cull_kind(const FieldElement& e, int order) {
  if (e.falloff == Falloff::compact) return Cull::compact;
  if (e.falloff == Falloff::none) return Cull::never;
  if (order == 0) return Cull::value;
  if (order == 1 && e.taper >= 0) return Cull::gradient;
  if (order == 2 && e.taper == 0) return Cull::hessian;
  return Cull::never;
}

// The squared distance beyond which the element is culled (its bound is at most cull_below).
double cull_distance2(const FieldElement& e, Cull kind, double cull_below) {
  switch (kind) {
    case Cull::compact: return e.radius * e.radius * (1 + 1e-9);
    case Cull::never: return kInf;
    case Cull::gradient: return detail::gaussian_gradient_cull_distance2(e.weight, e.radius, e.taper, cull_below);
    case Cull::hessian: return detail::gaussian_hessian_cull_distance2(e.weight, e.radius, cull_below);
    case Cull::value: break;
  }
  if (!(cull_below > 0)) return kInf;
  if (e.weight <= cull_below) return 0;
  // weight exp(-omega d^2 / r^2) <= cull_below  <=>  d^2 >= r^2 ln(weight / cull_below) / omega,
  // made a little larger (1e-9 relative) to absorb the rounding of this formula.
  return e.radius * e.radius * std::log(e.weight / cull_below) / kGaussOmega * (1 + 1e-9);
}

class CulledFieldOp final : public CustomOp {
 public:
  // `order`: the elements' densities are order-th partial derivatives of the user's.
  CulledFieldOp(std::vector<FieldElement> elements, CulledFieldOptions options, int order)
      : elements_(std::move(elements)), options_(options), order_(order) {
    tapes_.reserve(elements_.size());
    std::vector<detail::BvhItem> items;
    for (std::size_t k = 0; k < elements_.size(); ++k) {
      const FieldElement& e = elements_[k];
      tapes_.emplace_back(e.density, std::span<const int>(kXyz, 3));
      Cull kind = cull_kind(e, order_);
      if (kind == Cull::hessian && !options_.cull_second_derivatives) kind = Cull::never;
      const double d2 = cull_distance2(e, kind, options_.cull_below);
      if (!std::isfinite(d2)) {
        always_.push_back(static_cast<std::uint32_t>(k));
        continue;
      }
      detail::BvhItem it{};
      it.index = static_cast<std::uint32_t>(k);
      for (int i = 0; i < 3; ++i) it.lo[i] = std::min(e.a[i], e.b[i]), it.hi[i] = std::max(e.a[i], e.b[i]);
      it.cull2 = d2;
      it.remainder = kind == Cull::value || kind == Cull::gradient || kind == Cull::hessian;
      it.weight = e.weight;
      it.radius = e.radius;
      it.taper = kind == Cull::gradient ? e.taper : 0.0;
      items.push_back(it);
    }
    double top_weight = 0;
    for (const detail::BvhItem& it : items)
      if (it.remainder) ++remainder_items_, top_weight = std::max(top_weight, it.weight);
    // The first pass guesses that the visited elements' magnitude is about the largest weight
    // (the peak of one element): with a bound of at most t per skipped subtree, the bounds
    // beyond the nearest skipped ones decay fast, so the tolerance is usually met at once.
    if (remainder_items_ > 0)
      first_threshold_ = kPointTolerance * std::max(top_weight, options_.cull_below) / (2 * static_cast<double>(remainder_items_));
    if (options_.hierarchy) bvh_ = detail::ElementBvh(std::move(items));
    else linear_ = std::move(items);
  }
  std::string name() const override { return "culled_field"; }
  int num_args() const override { return 3; }
  int num_outputs() const override { return 1; }

  // The point rule of the header: passes at decreasing thresholds until the skipped
  // elements' bound is within the tolerance of the visited ones' magnitude.
  void eval(std::span<const double> args, std::span<double> out) const override {
    if (std::isnan(args[0] + args[1] + args[2])) {
      out[0] = std::numeric_limits<double>::quiet_NaN();
      return;
    }
    const Interval point[3] = {Interval(args[0]), Interval(args[1]), Interval(args[2])};
    detail::PointNear near;
    PointEvaluator pv;
    // cull_below = 0 (no culling): t = 0 skips only compact elements beyond their support.
    double t = options_.cull_below > 0 ? first_threshold_ : 0.0;
    for (;;) {
      detail::near_point(options_.hierarchy ? &bvh_ : nullptr, linear_, order_, point, t, near);
      // always_ is in index order: sort the walk's elements and merge (linear for a field whose
      // elements are all in always_, as with cull_below = 0).
      std::sort(near.indices.begin(), near.indices.end());
      const auto walked = static_cast<std::ptrdiff_t>(near.indices.size());
      near.indices.insert(near.indices.end(), always_.begin(), always_.end());
      std::inplace_merge(near.indices.begin(), near.indices.begin() + walked, near.indices.end());
      // In index order, so that the sum rounds as the plain sum of those elements does.
      double sum = 0, magnitude = 0;
      for (std::uint32_t k : near.indices) {
        const double v = pv.eval(tapes_[k], args)[0];
        sum += v, magnitude += std::abs(v);
      }
      const double tolerance = kPointTolerance * std::max(magnitude, options_.cull_below);
      if (near.remainder <= tolerance || t == 0) {
        out[0] = sum;
        return;
      }
      // Every skipped subtree's bound is <= t, so at most (remainder items) x t is skipped: this
      // threshold meets the tolerance (the magnitude only grows with more elements); t = 0
      // (every element) is the last resort should rounding defeat it.
      const double next = tolerance / (2 * static_cast<double>(remainder_items_));
      t = next < t ? next : 0.0;
    }
  }

  void inclusion(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const override {
    for (int i = 0; i < 3; ++i)
      if (args[i].is_empty()) {
        out[0] = Interval::empty();
        return;
      }
    IntervalEvaluator iv;
    Interval sum(0.0);
    double magnitude = 0;  // >= the sum of |D_e| over the box of the elements evaluated here
    auto add = [&](std::uint32_t k) {
      const auto y = iv.eval(tapes_[k], args);
      err[0] |= iv.errors()[0];
      sum = sum + y[0];
      magnitude += std::max(std::abs(y[0].lo()), std::abs(y[0].hi()));
    };
    for (std::uint32_t k : always_) add(k);
    // An upper bound of the culled elements' total magnitude: a sum of `terms` non-negative
    // products in double arithmetic, each rounding with relative error <= 2^-53, so the sum
    // grown by terms * 2^-52 is an upper bound (no rounding-mode switch per culled subtree).
    double remainder = 0, terms = 0;
    if (options_.hierarchy) {
      bvh_.query(
          args,
          [&](const detail::BvhNode& n, double d2, std::uint32_t count) {
            remainder += static_cast<double>(count) * per_element_bound(n, d2);
            terms += 2;
          },
          [&](const detail::BvhItem& it) { add(it.index); });
    } else {
      // The linear scan: each element tested, each culled one bounded by cull_below.
      double culled = 0;
      for (const detail::BvhItem& it : linear_) {
        if (box_distance2_below(it.lo, it.hi, args) >= it.cull2) culled += it.remainder ? 1 : 0;
        else add(it.index);
      }
      remainder = culled * options_.cull_below;
      terms = 1;
    }
    const double r = remainder * (1 + (terms + 1) * 0x1p-52);
    out[0] = sum + (order_ == 0 ? Interval(0.0, r) : Interval(-r, r));
    // The point value at any p of the box is within kPointTolerance max(M, cull_below) of the
    // exact sum, M the rounded sum of |D_e(p)| over the elements it visits; M <= (magnitude + r)
    // up to rounding, which the factor 2 absorbs. Order 0 skips only elements >= 0: the point
    // value can only be lower.
    if (options_.cull_below > 0) {
      const double w = 2 * kPointTolerance * std::max(magnitude + r, options_.cull_below);
      out[0] = out[0] + (order_ == 0 ? Interval(-w, 0.0) : Interval(-w, w));
    }
  }

  // Another culled field, of the elements' partial derivatives (culled as the header says).
  Fn derivative(std::span<const Fn> args, int k) const override {
    std::shared_ptr<const CustomOp> d;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      auto& slot = derivatives_[static_cast<std::size_t>(k)];
      if (!slot) {
        std::vector<FieldElement> es = elements_;
        for (FieldElement& e : es) e.density = genmod::derivative(e.density, k);
        slot = std::make_shared<CulledFieldOp>(std::move(es), options_, order_ + 1);
      }
      d = slot;
    }
    return apply_custom(d, args);
  }
  bool continuous() const override { return true; }

 private:
  // A bound of each culled element with a remainder in node `n`, at squared distance >= d2:
  // cull_below (each was culled individually or with the subtree, beyond its own cull
  // distance), or the subtree's bound at d2 where that is smaller.
  double per_element_bound(const detail::BvhNode& n, double d2) const {
    return std::min(options_.cull_below, detail::gaussian_order_above(order_, n.weight, n.radius, n.taper, d2));
  }

  std::vector<FieldElement> elements_;
  CulledFieldOptions options_;
  int order_;
  std::vector<Tape> tapes_;
  std::size_t remainder_items_ = 0;       // Gaussian elements in the hierarchy
  double first_threshold_ = 0;            // the first pass's t (point evaluation)
  std::vector<std::uint32_t> always_;     // never culled: evaluated on every box
  detail::ElementBvh bvh_;                // the others, with options_.hierarchy
  std::vector<detail::BvhItem> linear_;   // the others, without
  mutable std::mutex mutex_;
  mutable std::array<std::shared_ptr<const CustomOp>, 3> derivatives_;  // built on first use
};

void check_element(const FieldElement& e, std::size_t k) {
  const std::string who = "culled_field: element " + std::to_string(k);
  if (e.density.dim() != 1) throw std::invalid_argument(who + ": the density must be scalar");
  if ((e.density.input_mask() & ~std::uint64_t{7}) != 0) throw std::invalid_argument(who + ": the density may depend on x(0), x(1), x(2) only");
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(e.a[i]) || !std::isfinite(e.b[i])) throw std::invalid_argument(who + ": skeleton coordinates must be finite");
  if (!(e.radius > 0 && std::isfinite(e.radius))) throw std::invalid_argument(who + ": radius must be finite and > 0");
  if (!(e.weight >= 0 && std::isfinite(e.weight))) throw std::invalid_argument(who + ": weight must be finite and >= 0");
  if (std::isnan(e.taper) || std::isinf(e.taper)) throw std::invalid_argument(who + ": taper must be finite");
}

// Lower bound of the squared distance between the box and the skeleton's bounding box, in
// interval arithmetic (for the exposed bounds; the hot loops use box_distance2_below).
double skeleton_distance2_below(const FieldElement& e, std::span<const Interval> box) {
  Interval sum(0.0);
  for (int i = 0; i < 3; ++i) {
    const double s_lo = std::min(e.a[i], e.b[i]), s_hi = std::max(e.a[i], e.b[i]);
    Interval gap(0.0);
    if (box[i].lo() > s_hi) gap = Interval(box[i].lo()) - Interval(s_hi);
    else if (box[i].hi() < s_lo) gap = Interval(s_lo) - Interval(box[i].hi());
    sum = sum + square(Interval(std::max(gap.lo(), 0.0), std::max(gap.hi(), 0.0)));
  }
  return std::max(sum.lo(), 0.0);
}

}  // namespace

FieldElement gaussian_segment_element(const Point3& a, const Point3& b, double r1, double r2) {
  const Fn d = segment_convolution(a, b, r1, r2);  // checks the radii and the endpoints
  const double length = std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) + (b[2] - a[2]) * (b[2] - a[2]));
  // Rounded up a little: the bound grows with the taper.
  const double taper = r1 == r2 ? 0.0 : std::abs(r2 - r1) / length * (1 + 1e-12);
  return {d, a, b, 1.0, std::max(r1, r2), Falloff::gaussian, taper};
}

FieldElement gaussian_point_element(const Point3& c, double r, double weight) {
  return {point_source(c, r, weight, Kernel::gaussian), c, c, weight, r, Falloff::gaussian, 0.0};
}

double culled_element_bound(const FieldElement& e, std::span<const Interval> box) {
  if (e.falloff == Falloff::none) return kInf;
  const double d2 = skeleton_distance2_below(e, box);
  if (e.falloff == Falloff::compact) return d2 >= e.radius * e.radius * (1 + 1e-12) ? 0.0 : kInf;
  return detail::gaussian_value_above(e.weight, e.radius, d2);
}

double culled_derivative_bound(const FieldElement& e, std::span<const Interval> box, int order) {
  if (order != 1 && order != 2) throw std::invalid_argument("culled_derivative_bound: order must be 1 or 2");
  const Cull kind = cull_kind(e, order);
  if (kind == Cull::never) return kInf;
  const double d2 = skeleton_distance2_below(e, box);
  if (kind == Cull::compact) return d2 >= e.radius * e.radius * (1 + 1e-12) ? 0.0 : kInf;
  return detail::gaussian_order_above(order, e.weight, e.radius, e.taper, d2);
}

Fn culled_field(const std::vector<FieldElement>& elements, const CulledFieldOptions& options, const Fn& p) {
  if (elements.empty()) throw std::invalid_argument("culled_field: no elements");
  if (p.dim() != 3) throw std::invalid_argument("culled_field: the query point must have dimension 3");
  if (!(options.cull_below >= 0)) throw std::invalid_argument("culled_field: cull_below must be >= 0");
  for (std::size_t k = 0; k < elements.size(); ++k) check_element(elements[k], k);
  auto op = std::make_shared<CulledFieldOp>(elements, options, 0);
  return apply_custom(std::shared_ptr<const CustomOp>(op), {p[0], p[1], p[2]});
}

Fn culled_field(const std::vector<FieldElement>& elements, const CulledFieldOptions& options) {
  return culled_field(elements, options, skeleton_query_point());
}

}  // namespace genmod
