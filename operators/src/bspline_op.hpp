// Private: the one custom operator behind every curve (polyline, Bezier, B-spline, NURBS,
// Hermite, Catmull-Rom): a (rational) B-spline c(t) of any degree in R^dim.
//
//  * point: de Boor's algorithm in homogeneous coordinates;
//  * inclusion: for each knot span the box overlaps, the Bezier control points of the curve
//    restricted to the overlapped sub-span (blossoms), whose hull contains that piece (convex
//    hull property; for NURBS with positive weights the projected points). The enclosure
//    tightens quadratically as the box shrinks. Full spans are precomputed;
//  * derivative: another B-spline of degree p-1 (exact), or for NURBS the quotient rule on
//    the homogeneous B-spline and its derivative.
//
// Outside its domain [u_p, u_n] a curve is an error (NaN), not an extrapolation.
#pragma once

#include "genmod/kernel/custom_op.hpp"

#include <memory>
#include <mutex>
#include <vector>

namespace genmod::detail {

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

  int dim() const noexcept { return dim_; }
  int degree() const noexcept { return degree_; }
  int num_points() const noexcept { return n_; }
  const std::vector<double>& knots() const noexcept { return knots_; }
  const std::vector<double>& points() const noexcept { return points_; }
  const std::vector<double>& weights() const noexcept { return weights_; }
  double lo() const noexcept { return knots_[static_cast<std::size_t>(degree_)]; }
  double hi() const noexcept { return knots_[static_cast<std::size_t>(n_)]; }
  // The span k (degree <= k < n, nonempty) whose piece evaluates t, for t in the domain.
  int span(double t) const noexcept;

 private:
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
  // Throws std::invalid_argument past kMaxMagnitude (see the definition).
  void check_magnitudes() const;

  int dim_, degree_, n_;
  std::vector<double> knots_, points_, weights_, hpoints_;
  std::string kind_;
  std::vector<double> span_lo_, span_hi_;  // padded enclosures of whole spans, n * dim
  std::vector<double> pad_;                // rounding allowance per span
  bool continuous_ = false;
  mutable std::once_flag derivative_once_, homogeneous_once_;
  mutable std::shared_ptr<const BSplineOp> derivative_, homogeneous_;
};

}  // namespace genmod::detail
