// A single Bezier segment in 3-D over all its control points (Morkel's BezierSpline of degree
// n - 1 for n points), and the intersection of a line with it as seen along a projection
// direction: the 2-D problem curve shaping solves for every vertex.
#pragma once

#include "genmod/procedural/poly_mesh.hpp"

#include <optional>
#include <vector>

namespace genmod {

class BezierCurve {
 public:
  // Throws std::invalid_argument for fewer than 2 control points or a non-finite coordinate.
  explicit BezierCurve(std::vector<Vec3> control_points);

  int degree() const { return static_cast<int>(points_.size()) - 1; }
  const std::vector<Vec3>& control_points() const { return points_; }
  // The point at parameter t (de Casteljau, stable for t in [0, 1]).
  Vec3 evaluate(double t) const;

 private:
  std::vector<Vec3> points_;
};

// Where the line {origin + s * direction : s real} meets the curve once both are projected
// along `normal` onto a plane perpendicular to it. `direction` and `normal` must be unit
// vectors with direction . normal == 0 (curve shaping prepares them); nothing is checked here.
struct LineCurveHit {
  double s = 0.0;  // line parameter of the hit: the projected displacement is s * direction
  double t = 0.0;  // curve parameter of the hit, in [0, 1]
};
// The hit nearest to the origin along the line (smallest |s|); among equally near hits the
// one with s >= 0, then the one with the smaller t. Empty when the line misses the curve.
//
// Method: the signed distance of the curve from the line, g(t) = (B(t) - origin) . (normal x
// direction), is a polynomial whose Bernstein coefficients are those of the control points, so
// a piece of [0, 1] whose coefficients all have one sign has no root (convex hull property).
// Pieces are halved until they are 2^-30 wide, then a sign change is refined by bisection to
// the last bit, and a piece without one (a tangency, or two roots closer than the width) is
// kept when |g| there is at most 1e-12 of the problem's size. A curve lying along the line
// (every coefficient within that tolerance) gives the vertex itself when the curve passes
// through it, else the curve's nearest point along the line (sampled at 64 * degree + 1
// parameters).
std::optional<LineCurveHit> intersect_line(const BezierCurve& curve, const Vec3& origin, const Vec3& direction,
                                           const Vec3& normal);

}  // namespace genmod
