// Private: the one custom operator behind every curve (polyline, Bezier, B-spline, NURBS,
// Hermite, Catmull-Rom): a (rational) B-spline c(t) of any degree in R^dim.
//
//  * point: de Boor's algorithm in homogeneous coordinates;
//  * inclusion: for each knot span the box overlaps, the Bezier control points of the curve
//    restricted to the overlapped sub-span (blossoms), whose hull contains that piece (convex
//    hull property; for NURBS with positive weights the projected points). The enclosure
//    tightens quadratically as the box shrinks. Full spans are precomputed;
//  * derivative: another B-spline of degree p-1 (exact), or for NURBS a RationalDerivativeOp
//    (below): the quotient rule on the homogeneous B-spline and its derivatives, enclosed
//    span by span.
//
// Outside its domain [u_p, u_n] a curve is an error (NaN), not an extrapolation.
#pragma once

#include "de_boor.hpp"

#include "genmod/kernel/custom_op.hpp"

#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace genmod::detail {

class RationalDerivativeOp;
class UnitTangentOp;

// The interior knots of a degree-p curve where its derivative of the given order may jump:
// those of multiplicity m > p - order (the piece boundary is C^(p - m) there).
std::vector<double> jump_knots(const std::vector<double>& knots, int degree, int num_points, int order);
// True when no jump knot lies in (a, b]: a value at a knot comes from the span that starts
// there, so a box starting on a knot sees one side of it only.
bool jump_free(const std::vector<double>& jumps, double a, double b) noexcept;

class BSplineOp final : public CustomOp, public std::enable_shared_from_this<BSplineOp> {
 public:
  static constexpr int kMaxDegree = 12;
  static constexpr int kMaxDim = 16;
  // The largest knot range and control coordinate (and derivative control coordinate) a
  // curve may have: 2^1000, about 1.07e301, leaving room for sums and rounding pads.
  static constexpr double kMaxMagnitude = 0x1p1000;

  // `points` holds n * dim coordinates (point-major); `weights` is empty (polynomial) or n
  // positive weights; `knots` has n + degree + 1 nondecreasing values. Throws
  // std::invalid_argument naming the problem.
  BSplineOp(int dim, int degree, std::vector<double> knots, std::vector<double> points, std::vector<double> weights,
            std::string kind);

  std::string name() const override { return kind_; }
  int num_args() const override { return 1; }
  int num_outputs() const override { return dim_; }
  void eval(std::span<const double> args, std::span<double> out) const override;
  void inclusion(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const override;
  Fn derivative(std::span<const Fn> args, int k) const override;
  // Continuous inside its domain when no interior knot repeats more than degree times.
  bool continuous() const override { return continuous_; }
  // Continuous on a box that holds no such knot in its interior or at its upper end.
  bool inclusion_continuous(std::span<const Interval> args, std::span<Interval> out,
                            std::span<std::uint8_t> err) const override;

  int dim() const noexcept { return dim_; }
  int degree() const noexcept { return degree_; }
  int num_points() const noexcept { return n_; }
  const std::vector<double>& knots() const noexcept { return knots_; }
  const std::vector<double>& points() const noexcept { return points_; }
  const std::vector<double>& weights() const noexcept { return weights_; }
  // The operator of the unit tangent (degree >= 1), built once.
  std::shared_ptr<const UnitTangentOp> unit_tangent_op() const;
  double lo() const noexcept { return knots_[static_cast<std::size_t>(degree_)]; }
  double hi() const noexcept { return knots_[static_cast<std::size_t>(n_)]; }
  // The span k (degree <= k < n, nonempty) whose piece evaluates t, for t in the domain.
  int span(double t) const noexcept;

 private:
  friend class RationalDerivativeOp;
  friend class UnitTangentOp;
  // Homogeneous coordinates (w x, w) or plain coordinates, one row of hdim() per point.
  int hdim() const noexcept { return rational() ? dim_ + 1 : dim_; }
  bool rational() const noexcept { return !weights_.empty(); }
  // De Boor on span k with parameter params[r-1] at level r (all equal: evaluation;
  // different: a blossom). Writes hdim() values.
  void de_boor(int k, const double* params, double* out) const;
  // Encloses the piece of span k over [s, t] (inside the span) and hulls it into lo / hi.
  void enclose_piece(int k, double s, double t, double* lo, double* hi) const;
  std::shared_ptr<const BSplineOp> derivative_op() const;    // polynomial curves, degree >= 1
  std::shared_ptr<const BSplineOp> homogeneous_op() const;   // rational curves
  std::shared_ptr<const RationalDerivativeOp> rational_derivative_op() const;  // rational curves
  // Throws std::invalid_argument past kMaxMagnitude (see the definition).
  void check_magnitudes() const;

  int dim_, degree_, n_;
  std::vector<double> knots_, points_, weights_, hpoints_;
  std::string kind_;
  std::vector<double> span_lo_, span_hi_;  // padded enclosures of whole spans, n * dim
  std::vector<double> pad_;                // rounding allowance per span
  bool continuous_ = false;
  std::vector<double> jumps_;  // jump_knots(order 0)
  DeBoorKernel fixed_de_boor_ = nullptr;  // unrolled de Boor for this degree and hdim(), if any
  mutable std::once_flag derivative_once_, homogeneous_once_, rational_derivative_once_, unit_tangent_once_;
  mutable std::shared_ptr<const BSplineOp> derivative_, homogeneous_;
  mutable std::shared_ptr<const RationalDerivativeOp> rational_derivative_;
  mutable std::shared_ptr<const UnitTangentOp> unit_tangent_;
};

// The derivative of order k >= 1 of a NURBS c = A / w, (A, w) = H the homogeneous polynomial
// B-spline: c^(j) = (A^(j) - sum_{i=1..j} C(j, i) w^(i) c^(j-i)) / w (Leibniz on A = w c).
// One operator rather than that formula in kernel nodes, for its inclusion: where the curve
// is only C^0 in its parameter (a double knot between a line and an arc, tangent-continuous
// in space), A', w' and c' jump, and the formula's nodes, each enclosed over a box that
// straddles the knot, pair A' of one side with w' of the other; that enclosure does not
// shrink with the box and may contain 0 (a curve normal then has no finite bound). Here every
// knot span the box overlaps is enclosed on its own, all terms from that span (blossom hulls
// of the sub-span, as for the curve), and the spans' enclosures are hulled.
// Owns a copy of the curve (not the curve's operator, which caches this one: no cycle).
class RationalDerivativeOp final : public CustomOp {
 public:
  // `curve` is rational; order >= 1.
  RationalDerivativeOp(std::shared_ptr<const BSplineOp> curve, int order);

  std::string name() const override;
  int num_args() const override { return 1; }
  int num_outputs() const override { return curve_->dim(); }
  void eval(std::span<const double> args, std::span<double> out) const override;
  void inclusion(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const override;
  Fn derivative(std::span<const Fn> args, int k) const override;
  // Continuous where no interior knot repeats more than degree - order times (on a box: where
  // it holds none of those knots in its interior or at its upper end).
  bool continuous() const override { return continuous_; }
  bool inclusion_continuous(std::span<const Interval> args, std::span<Interval> out,
                            std::span<std::uint8_t> err) const override;

  const BSplineOp& curve() const noexcept { return *curve_; }
  // Encloses the derivative on [s, e] inside knot span k of the curve (that span's formula,
  // also at its ends), one interval per output.
  void enclose_span(int k, double s, double e, Interval* out) const;

 private:
  RationalDerivativeOp(std::shared_ptr<const BSplineOp> curve, std::vector<std::shared_ptr<const BSplineOp>> h,
                       int order);
  std::shared_ptr<const RationalDerivativeOp> next() const;
  static std::vector<std::shared_ptr<const BSplineOp>> homogeneous_derivatives(const std::shared_ptr<const BSplineOp>& h,
                                                                              int order);

  std::shared_ptr<const BSplineOp> curve_;               // a copy of the rational curve
  std::vector<std::shared_ptr<const BSplineOp>> h_;      // H, H', ..., H^(min(order, degree))
  int order_;
  bool continuous_ = false;
  std::vector<double> jumps_;
  mutable std::once_flag next_once_;
  mutable std::shared_ptr<const RationalDerivativeOp> next_;
};

}  // namespace genmod::detail
