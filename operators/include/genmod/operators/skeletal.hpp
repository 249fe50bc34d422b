// Skeletal primitives and distance surfaces (Bloomenthal, research/bloomenthal.md §1.2, §2.2).
//
// A skeleton is a set of points, segments, polylines and triangles in R^3. The functions
// below are plain kernel Fns of a point p (by default p = (x(0), x(1), x(2))), so the kernel
// supplies point evaluation, a sound inclusion function (natural interval extension) and the
// symbolic derivative. Distances are squared (eq. 5.7: no square root, smooth where the
// unsquared distance is not).
//
// Distance surfaces follow genmod's implicit convention directly: f = d^2 / r^2 - 1 is
// negative inside, zero on the surface (a sphere or capsule of radius r), positive outside.
//
// Example:
//   Fn arm = distance_surface({distance2_to_segment({0, 0, 0}, {1, 0, 0})}, {0.1});
#pragma once

#include "genmod/kernel/fn.hpp"

#include <array>
#include <span>
#include <vector>

namespace genmod {

using Point3 = std::array<double, 3>;

// The query point (x(0), x(1), x(2)).
Fn skeleton_query_point();

// |p - c|^2.
Fn distance2_to_point(const Point3& c, const Fn& p = skeleton_query_point());
// The unclamped projection parameter alpha = (p - a).(b - a) / |b - a|^2 (eq. 5.11): alpha
// in [0, 1] when p projects into the segment. a != b (std::invalid_argument otherwise).
Fn segment_parameter(const Point3& a, const Point3& b, const Fn& p = skeleton_query_point());
// |p - q|^2 with q = a + clamp(alpha, 0, 1) (b - a), the nearest point of the segment.
Fn distance2_to_segment(const Point3& a, const Point3& b, const Fn& p = skeleton_query_point());
// Squared distance to the line through a and b, |(p - a) x (b - a)|^2 / |b - a|^2 (each
// coordinate enters each cross product component once, so its interval is tight).
Fn distance2_to_line(const Point3& a, const Point3& b, const Fn& p = skeleton_query_point());
// Minimum over the consecutive segments of a polyline (at least two vertices).
Fn distance2_to_polyline(std::span<const Point3> vertices, const Fn& p = skeleton_query_point());
// Squared distance to the filled triangle abc: the distance to its plane where p projects
// inside the triangle, else the nearest of its three edges. Non-degenerate triangles only.
Fn distance2_to_triangle(const Point3& a, const Point3& b, const Point3& c, const Fn& p = skeleton_query_point());

// A cubic curve C(t) = c1 t^3 + c2 t^2 + c3 t + c4, t in [0, 1] (§1.2, eq. 5.8).
struct CubicCurve {
  Point3 c1, c2, c3, c4;
  Point3 at(double t) const;
};
// The coefficients (degree 5 down to 0) of the quintic (1/2) d/dt |C(t) - p|^2 of eq. 5.8.
std::array<double, 6> cubic_distance_quintic(const CubicCurve& c, const Point3& p);
// The parameter of the nearest point of the curve to p: the best of t = 0, t = 1 and the
// quintic's roots in (0, 1) (bracketed on 256 intervals, refined by bisection).
double cubic_nearest_parameter(const CubicCurve& c, const Point3& p);
// min_t |p - C(t)|^2 as a custom operator. Point value: at the nearest parameter. Inclusion
// over a box (sound): above, min over 33 curve points of the largest squared distance to a
// box corner (the squared distance to a point is convex, so its maximum is at a corner);
// below, the smallest squared distance from the box to boxes enclosing 32 pieces of the curve
// (interval Taylor forms). Derivative: 2 (p - C(t*(p))) (the envelope theorem), with t*(p)
// the nearest parameter as a custom operator whose derivative comes from the implicit
// function theorem (and jumps where two nearest points tie, as the nearest point does).
Fn distance2_to_cubic(const CubicCurve& c, const Fn& p = skeleton_query_point());

// Distance surface (eqs. 5.9, 5.10): min_i d2_i / r_i^2 - 1, the union of the elements'
// spheres / capsules / slabs of radius r_i. One radius per squared distance, all > 0.
Fn distance_surface(std::span<const Fn> distances2, std::span<const double> radii);
Fn distance_surface(std::initializer_list<Fn> distances2, std::initializer_list<double> radii);
// A tapered limb (§1.5): d^2 / r(alpha)^2 - 1 with r(alpha) = r1 + clamp(alpha, 0, 1)(r2 - r1),
// the radius at the nearest point of the segment (the source's "Near.radius"). r1, r2 > 0.
Fn tapered_segment_surface(const Point3& a, const Point3& b, double r1, double r2,
                           const Fn& p = skeleton_query_point());

// A limb of a ramiform: the segment a -> b with radius r.
struct SkeletonLimb {
  Point3 a, b;
  double radius;
};
// The ramiform density of eq. 5.36: max(f(parent), sum_i f(child_i)) with the distance
// primitive f(limb) = r^2 / d(p, limb)^2 (a DENSITY: larger inside, the surface at 1; wrap
// with density_to_implicit(D, 1.0)). With r_parent^2 = sum r_child^2 the two sides agree on
// the parent's end plane, so the junction has no gap. Undefined (division by zero, flagged)
// on the skeleton itself.
Fn ramiform_density(const SkeletonLimb& parent, std::span<const SkeletonLimb> children,
                    const Fn& p = skeleton_query_point());

}  // namespace genmod
