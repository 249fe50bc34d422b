// Curves (GENMOD's m_crv, thesis App. A.3.7): polyline, Bezier, uniform and non-uniform
// B-splines, NURBS, Hermite and Catmull-Rom splines, in any dimension up to 16 and degree up
// to 12. All of them are one operator underneath: a (rational) B-spline, so they share
//
//  * point evaluation by de Boor's algorithm;
//  * a tight inclusion function: over a parameter box, the hull of the Bezier control
//    points of the curve restricted to each overlapped sub-span (the convex hull property
//    of the exact sub-curve; for NURBS, of the projected points, weights being positive).
//    Its width shrinks quadratically with the box. To cover rounding, each bound is moved
//    outward by 16 (p + 2) eps M (w_max / w_min), M the largest control coordinate of the
//    span: de Boor and the blossoms are convex combinations, each level off by a few ulps;
//  * an exact symbolic derivative: the derivative of a degree-p B-spline is a degree-(p-1)
//    B-spline (a new operator); NURBS use the quotient rule on their homogeneous form.
//
// The domain is [u_p, u_n] of the knot vector; every constructor below except bspline() and
// nurbs() with explicit knots uses [0, 1]. Outside the domain the curve is an error (NaN),
// never an extrapolation or a clamp. Bad input (too few points, a knot vector that is not
// nondecreasing, points of different dimensions, weights <= 0) throws std::invalid_argument
// naming the problem. So does a curve past double's safe range: a knot range, a control
// coordinate (times its weight, for NURBS) or a control coordinate of any derivative curve
// larger than 2^1000 (about 1.07e301) in magnitude, where values and enclosures could
// overflow; every curve that is built has derivatives that can be built too.
//
// Example:
//   Curve c = Curve::catmull_rom({{0, 0}, {1, 1}, {2, 0}});
//   Fn path = c(x(0));                 // a 2D curve in x(0)
//   Fn speed = length(derivative(path, 0));
#pragma once

#include "genmod/kernel/custom_op.hpp"

#include <memory>
#include <utility>
#include <vector>

namespace genmod {

namespace detail {
class BSplineOp;
}

class Curve {
 public:
  using Points = std::vector<std::vector<double>>;

  // Straight segments through the points; vertex i at t = i / (n - 1).
  static Curve polyline(const Points& points);
  // One Bezier piece of degree n - 1.
  static Curve bezier(const Points& points);
  // B-spline of the given degree with an explicit knot vector (n + degree + 1 knots).
  static Curve bspline(const Points& points, int degree, std::vector<double> knots);
  // Uniform B-spline on [0, 1]: clamped (interpolates the end points, end knots repeated
  // degree + 1 times) or unclamped (equally spaced knots, domain scaled to [0, 1]).
  static Curve uniform_bspline(const Points& points, int degree, bool clamped = true);
  // NURBS: weights > 0, one per point; empty knots means clamped uniform.
  static Curve nurbs(const Points& points, std::vector<double> weights, int degree, std::vector<double> knots = {});
  // Piecewise cubic Hermite: point i at t = i / (n - 1) with derivative dc/dt = tangents[i]
  // (with respect to the curve parameter t in [0, 1]). C1.
  static Curve hermite(const Points& points, const Points& tangents);
  // Uniform Catmull-Rom spline through the points: the Hermite curve with tangents
  // (P[i+1] - P[i-1]) / (2 h), h = 1 / (n - 1), and one-sided differences at the ends.
  static Curve catmull_rom(const Points& points);

  int dimension() const noexcept;
  int degree() const noexcept;
  const std::vector<double>& knots() const noexcept;
  Points control_points() const;
  // Empty for polynomial curves.
  const std::vector<double>& weights() const noexcept;
  // [u_p, u_n].
  std::pair<double, double> domain() const noexcept;

  // The curve evaluated at the scalar function t (GENMOD's m_crv(file, t)).
  Fn operator()(const Fn& t) const;
  // The unit tangent c'(t) / |c'(t)| at the scalar function t (c' with respect to the curve's
  // own parameter; an error where c' = 0). Unlike normalize(derivative(c(t))), its enclosure
  // over a box that straddles a knot where the curve is tangent-continuous but its speed
  // jumps (lines and arcs joined by double knots) shrinks with the box: each knot span is
  // normalized on its own. Degree >= 1 (throws std::invalid_argument otherwise).
  Fn unit_tangent(const Fn& t) const;
  // The custom operator (one argument, dimension() outputs).
  std::shared_ptr<const CustomOp> op() const;

 private:
  explicit Curve(std::shared_ptr<const detail::BSplineOp> op) : op_(std::move(op)) {}
  std::shared_ptr<const detail::BSplineOp> op_;
};

}  // namespace genmod
