#include "unit_tangent_op.hpp"

#include "genmod/operators/vector.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace genmod::detail {

UnitTangentOp::UnitTangentOp(const BSplineOp& curve)
    : dim_(curve.dim()), degree_(curve.degree()), n_(curve.num_points()), knots_(curve.knots()),
      jumps_(jump_knots(curve.knots(), curve.degree(), curve.num_points(), 1)), lo_(curve.lo()), hi_(curve.hi()),
      name_(curve.name() + "-unit-tangent") {
  if (curve.rational())
    rational_ = curve.rational_derivative_op();
  else
    polynomial_ = curve.derivative_op();
}

void UnitTangentOp::derivative_at(double t, double* out) const {
  const double args[1] = {t};
  const std::span<double> o(out, static_cast<std::size_t>(dim_));
  if (rational_)
    rational_->eval(args, o);
  else
    polynomial_->eval(args, o);
}

void UnitTangentOp::enclose_derivative(int k, double s, double e, Interval* out) const {
  if (rational_) {
    rational_->enclose_span(k, s, e, out);
    return;
  }
  // The derivative's knot vector drops the first knot: span k is its span k - 1.
  double lo[BSplineOp::kMaxDim], hi[BSplineOp::kMaxDim];
  std::fill_n(lo, dim_, std::numeric_limits<double>::infinity());
  std::fill_n(hi, dim_, -std::numeric_limits<double>::infinity());
  polynomial_->enclose_piece(k - 1, s, e, lo, hi);
  for (int q = 0; q < dim_; ++q) out[q] = Interval(lo[q], hi[q]);
}

void UnitTangentOp::eval(std::span<const double> args, std::span<double> out) const {
  double d[BSplineOp::kMaxDim];
  derivative_at(args[0], d);  // NaN outside the domain
  double len2 = 0.0;
  for (int q = 0; q < dim_; ++q) len2 += d[q] * d[q];
  const double len = std::sqrt(len2);
  for (int q = 0; q < dim_; ++q)
    out[static_cast<std::size_t>(q)] = len > 0.0 ? d[q] / len : std::numeric_limits<double>::quiet_NaN();
}

void UnitTangentOp::inclusion(std::span<const Interval> args, std::span<Interval> out,
                              std::span<std::uint8_t> err) const {
  const Interval t = args[0];
  if (t.is_empty()) {
    std::fill(out.begin(), out.end(), Interval::empty());
    return;
  }
  const double a = std::max(t.lo(), lo_), b = std::min(t.hi(), hi_);
  if (a > b) {
    std::fill(out.begin(), out.end(), Interval::empty());
    for (auto& e : err) e |= kCertainError;
    return;
  }
  std::uint8_t error = (t.lo() < lo_ || t.hi() > hi_) ? kMaybeError : kNoError;
  const Interval unit(-1.0, 1.0);
  // The span of a (a value at a knot comes from the span that starts there), up to b's.
  auto span_of = [&](double u) {
    int k = static_cast<int>(std::upper_bound(knots_.begin() + degree_, knots_.begin() + n_ + 1, u) - knots_.begin()) - 1;
    k = std::clamp(k, degree_, n_ - 1);
    while (k > degree_ && !(knots_[static_cast<std::size_t>(k)] < knots_[static_cast<std::size_t>(k) + 1])) --k;
    return k;
  };
  Interval result[BSplineOp::kMaxDim], d[BSplineOp::kMaxDim];
  bool first = true;
  for (int k = span_of(a); k <= span_of(b); ++k) {
    const std::size_t ku = static_cast<std::size_t>(k);
    if (!(knots_[ku] < knots_[ku + 1])) continue;  // empty span: never evaluated
    enclose_derivative(k, std::max(a, knots_[ku]), std::min(b, knots_[ku + 1]), d);
    Interval len2(0.0);
    for (int q = 0; q < dim_; ++q) len2 += square(d[q]);
    std::uint8_t e = kNoError;
    const Interval len = sqrt(len2, &e);
    for (int q = 0; q < dim_; ++q) {
      Interval tq = unit;  // where c' may vanish, T is undefined there and in [-1, 1] elsewhere
      if (len.lo() > 0.0) {
        tq = intersect(divide(d[q], len), unit);
        if (tq.is_empty()) tq = unit;  // only by rounding at the bound
      } else {
        error |= kMaybeError;
      }
      result[q] = first ? tq : hull(result[q], tq);
    }
    first = false;
  }
  for (int q = 0; q < dim_; ++q) {
    out[static_cast<std::size_t>(q)] = result[q];
    err[static_cast<std::size_t>(q)] |= error;
  }
}

bool UnitTangentOp::inclusion_continuous(std::span<const Interval> args, std::span<Interval> out,
                                         std::span<std::uint8_t> err) const {
  inclusion(args, out, err);
  return args[0].is_empty() || jump_free(jumps_, args[0].lo(), args[0].hi());
}

Fn UnitTangentOp::derivative_fn(std::span<const Fn> args) const {
  if (rational_) return genmod::apply_custom(std::shared_ptr<const CustomOp>(rational_), args);
  return genmod::apply_custom(std::shared_ptr<const CustomOp>(polynomial_), args);
}

Fn UnitTangentOp::derivative(std::span<const Fn> args, int) const {
  const Fn d1 = derivative_fn(args);
  const Fn d2 = rational_ ? rational_->derivative(args, 0) : polynomial_->derivative(args, 0);
  const Fn tangent = genmod::apply_custom(std::shared_ptr<const CustomOp>(shared_from_this()), args);
  return (d2 - tangent * dot(tangent, d2)) / length(d1);
}

}  // namespace genmod::detail
