// Geometric queries with guaranteed answers, built on the constraint solver and the global
// minimizer (snyder.md sections 2.1 and 5):
//
//   curve_intersections(a, b)       where two parametric curves meet
//   curve_self_intersections(c)     where a parametric curve crosses itself
//   ray_hit(surface, origin, dir)   first hit of a ray on a parametric surface
//   ray_hit_implicit(f, origin, dir) first hit of a ray on an implicit surface f = 0
//   surface_intersection(a, b)      the curves where two parametric surfaces meet
//   closest_point(shape, p)         distance from a point to a parametric curve or surface
//   classify_point(surface, p)      inside / outside a closed parametric surface
//
// Shapes are Fn values of their parameters: a curve depends on one coordinate, a surface on
// two (the lower coordinate is u, the higher v), each over a parameter box (default [0,1]).
// Every answer says what is certified: no solution of the underlying equations is lost (the
// solver's promise), and `complete` is false when a search limit stopped a search, in which
// case the answer covers what the search could not rule out.
//
// Example:
//   const double pi = std::numbers::pi;
//   Fn circle = cat({cos(2 * pi * x(0)), sin(2 * pi * x(0))});
//   Fn line = cat({2 * x(0) - 1, Fn(0.5)});
//   CurveIntersections hits = curve_intersections(circle, line);   // 2 hits, certified
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/interval.hpp"
#include "genmod/solvers/box.hpp"
#include "genmod/solvers/implicit_curve.hpp"
#include "genmod/solvers/limits.hpp"

#include <array>
#include <span>
#include <vector>

namespace genmod {

struct QueryOptions {
  double epsilon = 1e-9;  // parameter-space tolerance of the searches
  SearchLimits limits;
};

// One place where two curves meet: parameter intervals on each curve and the point.
struct CurveHit {
  Interval s, t;              // parameters on the first and second curve
  std::vector<double> point;  // the first curve at the midpoint of s
  bool certified = false;     // exactly one intersection in s x t (interval Newton)
};

struct CurveIntersections {
  std::vector<CurveHit> hits;  // sorted by s
  bool complete = true;        // no search limit was hit
};

// Intersections of curves a(s), s in a_domain, and b(t), t in b_domain, of equal dimension.
CurveIntersections curve_intersections(const Fn& a, const Fn& b, Interval a_domain = Interval(0, 1),
                                       Interval b_domain = Interval(0, 1), const QueryOptions& options = {});

// Pairs s < t with c(s) = c(t) and t - s >= min_separation (pairs closer than that are not
// reported: every curve "meets itself" at s = t). A closed curve reports its closing pair
// (domain start, domain end).
CurveIntersections curve_self_intersections(const Fn& c, Interval domain = Interval(0, 1),
                                            double min_separation = 1e-3, const QueryOptions& options = {});

struct RayHit {
  bool hit = false;         // a hit was found (certainly, if `certified`)
  // Ray parameter of the first hit: point = origin + t direction. Empty on a miss ([0, 0]
  // would be a hit at the origin).
  Interval t = Interval::empty();
  Interval u = Interval::empty(), v = Interval::empty();  // surface parameters (parametric surfaces only)
  bool certified = false;   // exactly one hit in the reported box, and no other hit before it
  bool complete = true;     // no search limit was hit
};

// First hit, for t in [0, t_max], of the ray origin + t direction on the parametric surface
// S(u, v) (dimension 3). Degenerate parameterizations (a pole, where many (u, v) map to one
// point) give a hit with a tight t that is not certified.
RayHit ray_hit(const Fn& surface, std::array<double, 3> origin, std::array<double, 3> direction, double t_max,
               Interval u_domain = Interval(0, 1), Interval v_domain = Interval(0, 1),
               const QueryOptions& options = {});

// First hit of the ray on the implicit surface f(x, y, z) = 0 (f over x(0), x(1), x(2)).
RayHit ray_hit_implicit(const Fn& f, std::array<double, 3> origin, std::array<double, 3> direction, double t_max,
                        const QueryOptions& options = {});

struct SurfaceIntersection {
  // The solution curve of a(u, v) = b(s, t) in (u, v, s, t) (Algorithm 5.3 in 4-D).
  ImplicitCurve curve;
  // Each component's points in space (the first surface at its (u, v)), in curve order.
  std::vector<std::vector<std::array<double, 3>>> components;
  bool complete() const noexcept { return curve.complete(); }
};

struct SurfaceIntersectionOptions {
  // Parameters whose two ends are the same point (the angle of a cylinder or a torus): the
  // curve continues across them. u, v are the first surface's, s, t the second's.
  bool periodic_u = false, periodic_v = false, periodic_s = false, periodic_t = false;
  // The curve search in (u, v, s, t); its `periodic` list must stay empty (the flags above set
  // it).
  ImplicitCurveOptions curve{};
};

// Intersection curves of the parametric surfaces a(u, v) and b(s, t) (dimension 3) over
// their parameter boxes (default [0,1]^2 each). Throws std::invalid_argument naming the problem
// (a surface that is not 3-D or has more than two parameters, a bad domain, options.curve.periodic
// not empty).
//
// Example:
//   const double pi = std::numbers::pi;
//   Fn a = cat({cos(2 * pi * x(0)), sin(2 * pi * x(0)), 4 * x(1) - 2});              // about z
//   Fn b = cat({4 * x(0) - 2, 0.6 * cos(2 * pi * x(1)), 0.6 * sin(2 * pi * x(1))});  // about x
//   SurfaceIntersection r = surface_intersection(a, b, {}, {}, {.periodic_u = true, .periodic_t = true});
//   // r.components: 2 closed loops, r.complete()
SurfaceIntersection surface_intersection(const Fn& a, const Fn& b, std::span<const Interval> a_domain = {},
                                         std::span<const Interval> b_domain = {},
                                         const SurfaceIntersectionOptions& options = {});

struct ClosestPoint {
  Interval distance;                 // guaranteed bracket of the distance
  std::vector<double> parameters;    // parameters of a point whose distance is <= distance.hi()
  std::vector<double> point;         // the shape at those parameters
  std::vector<Box> candidates;       // parameter boxes holding every closest point
  bool complete = true;
  // The parameter tolerance used: max(options.epsilon, 1e-7). The squared distance is flat at
  // its minimum (second order), so a finer box tolerance costs boxes without tightening the
  // distance bracket; the value is reported rather than raised silently.
  double epsilon = 0.0;
};

// Distance from p to a parametric curve or surface (dimension = p.size()).
ClosestPoint closest_point(const Fn& shape, std::span<const double> p, std::span<const Interval> domain = {},
                           const QueryOptions& options = {});

enum class PointClass { Inside, Outside, OnSurface, Unknown };

struct Classification {
  PointClass where = PointClass::Unknown;
  Interval distance;  // distance from p to the surface
};

// Inside / outside of a closed parametric surface S(u, v) whose normal S_u x S_v points
// outward (snyder.md section 2.1): the sign of N . (S - p) at the closest points. Certified
// (Inside / Outside) only when that sign is proven on every candidate box of the closest
// point; OnSurface when the distance bracket is within `on_surface` of 0.
Classification classify_point(const Fn& surface, std::array<double, 3> p, Interval u_domain = Interval(0, 1),
                              Interval v_domain = Interval(0, 1), double on_surface = 1e-9,
                              const QueryOptions& options = {});

}  // namespace genmod
