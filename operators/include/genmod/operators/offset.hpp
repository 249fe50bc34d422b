// Offsets of planar curves (thesis section 3.1.2.2, research/snyder.md sections 7.13-7.15):
// the normal of a planar curve, offset curves, the offset product (extrusions with rounded
// edges), closed offsets with round end caps (the spoon's thickened cross section) and the
// circular arc through two points with a given sagitta. Like every operator of this layer they
// are compositions of kernel Fns, so points, inclusions and derivatives come from the kernel.
//
// Normal convention (erratum E5 of the thesis): n = normalize(-c1', c0') is the LEFT normal of
// the direction of travel, the printed formula. A positive offset therefore moves a
// counter-clockwise curve INWARD (the thesis's text says outward; its formula says inward):
//
// Example:
//   const double pi = std::numbers::pi;
//   Fn circle = cat({cos(2 * pi * x(0)), sin(2 * pi * x(0))});
//   Fn inner = offset_curve(circle, 0.25);          // the circle of radius 0.75
//   Fn tube = closed_offset(cat({x(0), Fn(0.0)}), 0.1); // a stadium around [0,1] x {0}
//
// Offsets are errors (NaN) where the curve's speed vanishes, and they self-intersect where
// |r| exceeds the radius of curvature on the side they move to. Wrong dimensions throw
// std::invalid_argument naming the operator.
#pragma once

#include "genmod/kernel/fn.hpp"

namespace genmod {

class Curve;  // genmod/operators/curve.hpp

// GENMOD's m_normal2d: (-c1', c0') with ' = d/dx(parm); unnormalized. `curve` has dimension 2.
Fn normal2d(const Fn& curve, int parm = 0);

// c + r normalize(normal2d(c)). r is scalar and may be a function of any coordinates.
Fn offset_curve(const Fn& curve, const Fn& r, int parm = 0);

// Offset product (section 7.14): S = (c(u) + d1(v) n(u), d2(v)), the closed planar cross
// section c offset by d1 and lifted to height d2 (a 3D surface). n is the normal of the cross
// section with respect to x(cross_parm); the profile has dimension 2.
Fn offset_product(const Fn& cross, const Fn& profile, int cross_parm = 0);

// The same surface for a cross section given as a planar Curve evaluated at the scalar u:
// (c(u) + d1 n, d2) with n the left normal of Curve::unit_tangent(u) (the direction of the
// curve's own parameter; for an increasing u, the n of the form above). The normal's
// enclosure stays tight over boxes that straddle knots where the section is
// tangent-continuous but not C^1 in its parameter (lines and arcs joined by double knots),
// where normalize(normal2d(c)) has wide or unbounded enclosures.
Fn offset_product(const Curve& cross, const Fn& u, const Fn& profile);

// GENMOD's m_closed_offset (section 7.15): the boundary of the points within distance r of the
// open planar curve c (c a function of x(parm) on [0, 1]), as a closed curve of x(parm) in
// [0, 1] traversed counter-clockwise (the region on its left), made of four uniformly
// concatenated quarters:
//   [0, 1/4]   offset(c, -r) forward (the right side of c),
//   [1/4, 1/2] the semicircle of radius r around c(1),
//   [1/2, 3/4] offset(c, +r) backward,
//   [3/4, 1]   the semicircle of radius r around c(0).
// It is continuous at the joints (and tangent-continuous where r is constant along c). It is
// the true boundary where r <= the radius of curvature of c. r is scalar; when it depends on
// x(parm) the caps use r(0) and r(1).
Fn closed_offset(const Fn& curve, const Fn& r, int parm = 0);

// GENMOD's m_arc_2pt_height: the circular arc from p1 (t = 0) to p2 (t = 1), planar points,
// whose midpoint (t = 1/2) lies `height` to the LEFT of the chord p1 -> p2 (the sagitta; a
// negative height bulges to the right), at constant angular speed in the scalar t.
// height = 0 is the straight chord at constant speed (no 0/0 there: the form below only
// divides by sinc of the half turning angle, which is >= 2/pi for |height| <= |p2 - p1| / 2).
// Range: any height is accepted; |height| = |p2 - p1| / 2 is a semicircle, larger heights give
// the major arc (at most a full circle as height -> infinity). p1 = p2 is an error (NaN).
// Example:
//   Fn bowl = arc_2pt_height(cat({-1.0, 0.0}), cat({1.0, 0.0}), -0.3, x(0));  // sags down
Fn arc_2pt_height(const Fn& p1, const Fn& p2, const Fn& height, const Fn& t);

}  // namespace genmod
