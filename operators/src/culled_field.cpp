// Superposition with per-box culling (culled_field.hpp).
#include "genmod/operators/culled_field.hpp"

#include "genmod/kernel/custom_op.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/convolution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <array>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

namespace genmod {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
const int kXyz[3] = {0, 1, 2};

// A lower bound of the squared distance between the box and the skeleton's bounding box.
double box_distance2_below(const FieldElement& e, std::span<const Interval> box) {
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

// The same lower bound in plain double arithmetic, for the hot loop: each subtraction, square
// and sum is rounded with relative error <= 2^-52 in any rounding mode (the subtraction of two
// doubles is exact or correctly rounded), so the result shrunk by 1e-12 is below the exact one.
double fast_box_distance2_below(const Point3& s_lo, const Point3& s_hi, std::span<const Interval> box) {
  double sum = 0;
  for (int i = 0; i < 3; ++i) {
    double gap = 0;
    if (box[i].lo() > s_hi[i]) gap = box[i].lo() - s_hi[i];
    else if (box[i].hi() < s_lo[i]) gap = s_lo[i] - box[i].hi();
    sum += gap * gap;
  }
  return sum * (1 - 1e-12);
}

class CulledFieldOp final : public CustomOp {
 public:
  CulledFieldOp(std::vector<FieldElement> elements, CulledFieldOptions options)
      : elements_(std::move(elements)), options_(options) {
    tapes_.reserve(elements_.size());
    for (const FieldElement& e : elements_) {
      tapes_.emplace_back(e.density, std::span<const int>(kXyz, 3));
      Point3 lo, hi;
      for (int i = 0; i < 3; ++i) lo[i] = std::min(e.a[i], e.b[i]), hi[i] = std::max(e.a[i], e.b[i]);
      skeleton_lo_.push_back(lo);
      skeleton_hi_.push_back(hi);
      // The squared distance beyond which the element's bound is at most cull_below:
      // weight exp(-omega d^2 / r^2) <= cull_below  <=>  d^2 >= r^2 ln(weight / cull_below) / omega,
      // made a little larger (1e-9 relative) to absorb the rounding of this formula.
      double d2 = 0;
      if (e.falloff == Falloff::compact) d2 = e.radius * e.radius;
      else if (e.falloff == Falloff::none || options_.cull_below <= 0) d2 = kInf;
      else if (e.weight > options_.cull_below) d2 = e.radius * e.radius * std::log(e.weight / options_.cull_below) / kGaussOmega;
      cull_distance2_.push_back(d2 * (1 + 1e-9));
      remainder_.push_back(e.falloff == Falloff::compact ? 0.0 : options_.cull_below);
    }
  }
  std::string name() const override { return "culled_field"; }
  int num_args() const override { return 3; }
  int num_outputs() const override { return 1; }

  // The full sum; compact elements whose support cannot reach the point are exactly 0 there
  // and are skipped (the same sum, faster).
  void eval(std::span<const double> args, std::span<double> out) const override {
    PointEvaluator pv;
    double sum = 0;
    for (std::size_t k = 0; k < tapes_.size(); ++k) {
      if (elements_[k].falloff == Falloff::compact && point_distance2_below(k, args) >= cull_distance2_[k]) continue;
      sum += pv.eval(tapes_[k], args)[0];
    }
    out[0] = sum;
  }

  void inclusion(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const override {
    for (int i = 0; i < 3; ++i)
      if (args[i].is_empty()) {
        out[0] = Interval::empty();
        return;
      }
    IntervalEvaluator iv;
    Interval sum(0.0);
    double remainder = 0;  // bound of the culled elements: cull_below each (0 for compact support)
    std::size_t culled = 0;
    for (std::size_t k = 0; k < elements_.size(); ++k) {
      if (fast_box_distance2_below(skeleton_lo_[k], skeleton_hi_[k], args) >= cull_distance2_[k]) {
        remainder += remainder_[k];
        ++culled;
        continue;
      }
      const auto y = iv.eval(tapes_[k], args);
      err[0] |= iv.errors()[0];
      sum = sum + y[0];
    }
    // n additions of the same nonnegative value: widen by n ulps' worth (relative 1e-12 covers
    // n < 4e3 ulps of relative error, and culled counts are far below 2^40).
    remainder = remainder * (1 + 1e-12 * static_cast<double>(std::max<std::size_t>(culled, 1))) + std::numeric_limits<double>::denorm_min();
    out[0] = sum + Interval(0.0, remainder);
  }

  // Another culled field, of the elements' partial derivatives: a compact element's derivative
  // vanishes where the element does, so it is culled in the same way (remainder 0); the
  // derivatives of Gaussian elements have no bound here and are never culled.
  Fn derivative(std::span<const Fn> args, int k) const override {
    std::shared_ptr<const CustomOp> d;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      auto& slot = derivatives_[static_cast<std::size_t>(k)];
      if (!slot) {
        std::vector<FieldElement> es = elements_;
        for (FieldElement& e : es) {
          e.density = genmod::derivative(e.density, k);
          if (e.falloff != Falloff::compact) e.falloff = Falloff::none;
        }
        slot = std::make_shared<CulledFieldOp>(std::move(es), options_);
      }
      d = slot;
    }
    return apply_custom(d, args);
  }
  bool continuous() const override { return true; }

 private:
  std::vector<FieldElement> elements_;
  CulledFieldOptions options_;
  std::vector<Tape> tapes_;
  std::vector<Point3> skeleton_lo_, skeleton_hi_;  // the skeletons' bounding boxes
  std::vector<double> cull_distance2_;             // cull when the box is at least this far (squared)
  std::vector<double> remainder_;                  // what a culled element may still contribute
  mutable std::mutex mutex_;
  mutable std::array<std::shared_ptr<const CustomOp>, 3> derivatives_;  // built on first use

  double point_distance2_below(std::size_t k, std::span<const double> p) const {
    const Interval box[3] = {Interval(p[0]), Interval(p[1]), Interval(p[2])};
    return fast_box_distance2_below(skeleton_lo_[k], skeleton_hi_[k], box);
  }
};

void check_element(const FieldElement& e, std::size_t k) {
  const std::string who = "culled_field: element " + std::to_string(k);
  if (e.density.dim() != 1) throw std::invalid_argument(who + ": the density must be scalar");
  if ((e.density.input_mask() & ~std::uint64_t{7}) != 0) throw std::invalid_argument(who + ": the density may depend on x(0), x(1), x(2) only");
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(e.a[i]) || !std::isfinite(e.b[i])) throw std::invalid_argument(who + ": skeleton coordinates must be finite");
  if (!(e.radius > 0 && std::isfinite(e.radius))) throw std::invalid_argument(who + ": radius must be finite and > 0");
  if (!(e.weight >= 0 && std::isfinite(e.weight))) throw std::invalid_argument(who + ": weight must be finite and >= 0");
}

}  // namespace

double culled_element_bound(const FieldElement& e, std::span<const Interval> box) {
  if (e.falloff == Falloff::none) return kInf;
  const double d2 = box_distance2_below(e, box);
  if (e.falloff == Falloff::compact) return d2 >= e.radius * e.radius * (1 + 1e-12) ? 0.0 : kInf;
  // weight * exp(-omega d2 / r^2), rounded upward: the exponent's upper bound.
  const Interval exponent = -Interval(kGaussOmega) * Interval(d2) / square(Interval(e.radius));
  // The relative margin covers the rounding of the element's own point evaluation (its value
  // may exceed the exact bound by a few ulps where the box touches the nearest point).
  return (Interval(e.weight) * exp(exponent) * Interval(1 + 1e-12)).hi() + std::numeric_limits<double>::denorm_min();
}

Fn culled_field(const std::vector<FieldElement>& elements, const CulledFieldOptions& options, const Fn& p) {
  if (elements.empty()) throw std::invalid_argument("culled_field: no elements");
  if (p.dim() != 3) throw std::invalid_argument("culled_field: the query point must have dimension 3");
  if (!(options.cull_below >= 0)) throw std::invalid_argument("culled_field: cull_below must be >= 0");
  for (std::size_t k = 0; k < elements.size(); ++k) check_element(elements[k], k);
  auto op = std::make_shared<CulledFieldOp>(elements, options);
  return apply_custom(std::shared_ptr<const CustomOp>(op), {p[0], p[1], p[2]});
}

Fn culled_field(const std::vector<FieldElement>& elements, const CulledFieldOptions& options) {
  return culled_field(elements, options, skeleton_query_point());
}

}  // namespace genmod
