// Private: the unit tangent T = c' / |c'| of a curve (Curve::unit_tangent), one custom
// operator so that its inclusion can work span by span.
//
// Where a curve is tangent-continuous in space but only C^0 in its parameter (a double knot
// between a line and an arc: the speed jumps, the direction does not), c' over a box that
// straddles the knot is the hull of two different vectors, and normalizing that hull gives a
// wide enclosure that never shrinks with the box. Normalized span by span, each piece is
// tight and the pieces meet where the direction is continuous, so the hull shrinks with the
// box. T is an error (NaN) where c' = 0; its components always lie in [-1, 1].
#pragma once

#include "bspline_op.hpp"

#include <memory>
#include <string>
#include <vector>

namespace genmod::detail {

class UnitTangentOp final : public CustomOp, public std::enable_shared_from_this<UnitTangentOp> {
 public:
  // `curve` has degree >= 1.
  explicit UnitTangentOp(const BSplineOp& curve);

  std::string name() const override { return name_; }
  int num_args() const override { return 1; }
  int num_outputs() const override { return dim_; }
  void eval(std::span<const double> args, std::span<double> out) const override;
  void inclusion(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const override;
  // T' = (c'' - T (T . c'')) / |c'|.
  Fn derivative(std::span<const Fn> args, int k) const override;
  // Continuous on a box where c' is (T may still be an error where c' = 0): a knot where only
  // the speed jumps is not known to be such a place, so a box holding one is not continuous.
  bool continuous() const override { return jumps_.empty(); }
  bool inclusion_continuous(std::span<const Interval> args, std::span<Interval> out,
                            std::span<std::uint8_t> err) const override;

 private:
  // c' at t and its enclosure on [s, e] inside span k of the curve.
  void derivative_at(double t, double* out) const;
  void enclose_derivative(int k, double s, double e, Interval* out) const;
  Fn derivative_fn(std::span<const Fn> args) const;

  int dim_, degree_, n_;
  std::vector<double> knots_, jumps_;
  double lo_, hi_;
  std::string name_;
  std::shared_ptr<const BSplineOp> polynomial_;        // c' of a polynomial curve, or
  std::shared_ptr<const RationalDerivativeOp> rational_;  // c' of a NURBS
};

}  // namespace genmod::detail
