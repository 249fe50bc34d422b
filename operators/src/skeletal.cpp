// Skeletal primitives and distance surfaces (skeletal.hpp).
#include "genmod/operators/skeletal.hpp"

#include "genmod/operators/vector.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace genmod {
namespace {

Point3 sub(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot3(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Point3 cross3(const Point3& a, const Point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

void check_point(const Fn& p, const char* who) {
  if (p.dim() != 3) throw std::invalid_argument(std::string(who) + ": the query point must have dimension 3, got " + std::to_string(p.dim()));
}

void check_finite(const Point3& v, const char* who) {
  for (double c : v)
    if (!std::isfinite(c)) throw std::invalid_argument(std::string(who) + ": skeleton coordinates must be finite");
}

double segment_length2(const Point3& a, const Point3& b, const char* who) {
  check_finite(a, who);
  check_finite(b, who);
  const double l2 = dot3(sub(b, a), sub(b, a));
  if (!(l2 > 0)) throw std::invalid_argument(std::string(who) + ": the segment's endpoints coincide");
  return l2;
}

// (p - a).w with each coordinate of p appearing once.
Fn affine_dot(const Fn& p, const Point3& a, const Point3& w) {
  return (p[0] - a[0]) * w[0] + (p[1] - a[1]) * w[1] + (p[2] - a[2]) * w[2];
}

Fn clamp01(const Fn& t) { return min(max(t, 0.0), 1.0); }

}  // namespace

Fn skeleton_query_point() { return cat({x(0), x(1), x(2)}); }

Fn distance2_to_point(const Point3& c, const Fn& p) {
  check_point(p, "distance2_to_point");
  check_finite(c, "distance2_to_point");
  return square(p[0] - c[0]) + square(p[1] - c[1]) + square(p[2] - c[2]);
}

Fn segment_parameter(const Point3& a, const Point3& b, const Fn& p) {
  check_point(p, "segment_parameter");
  const double l2 = segment_length2(a, b, "segment_parameter");
  const Point3 d = sub(b, a);
  return affine_dot(p, a, {d[0] / l2, d[1] / l2, d[2] / l2});
}

Fn distance2_to_segment(const Point3& a, const Point3& b, const Fn& p) {
  check_point(p, "distance2_to_segment");
  segment_length2(a, b, "distance2_to_segment");
  const Fn t = clamp01(segment_parameter(a, b, p));
  const Point3 d = sub(b, a);
  return square(p[0] - a[0] - t * d[0]) + square(p[1] - a[1] - t * d[1]) + square(p[2] - a[2] - t * d[2]);
}

Fn distance2_to_line(const Point3& a, const Point3& b, const Fn& p) {
  check_point(p, "distance2_to_line");
  const double l = std::sqrt(segment_length2(a, b, "distance2_to_line"));
  const Point3 d = sub(b, a);
  const Point3 u = {d[0] / l, d[1] / l, d[2] / l};
  const Fn q0 = p[0] - a[0], q1 = p[1] - a[1], q2 = p[2] - a[2];
  return square(q1 * u[2] - q2 * u[1]) + square(q2 * u[0] - q0 * u[2]) + square(q0 * u[1] - q1 * u[0]);
}

Fn distance2_to_polyline(std::span<const Point3> vertices, const Fn& p) {
  if (vertices.size() < 2)
    throw std::invalid_argument("distance2_to_polyline: a polyline needs at least two vertices, got " + std::to_string(vertices.size()));
  Fn d = distance2_to_segment(vertices[0], vertices[1], p);
  for (std::size_t i = 2; i < vertices.size(); ++i) d = min(d, distance2_to_segment(vertices[i - 1], vertices[i], p));
  return d;
}

Fn distance2_to_triangle(const Point3& a, const Point3& b, const Point3& c, const Fn& p) {
  check_point(p, "distance2_to_triangle");
  for (const Point3* v : {&a, &b, &c}) check_finite(*v, "distance2_to_triangle");
  const Point3 n = cross3(sub(b, a), sub(c, a));
  const double n2 = dot3(n, n);
  if (!(n2 > 0)) throw std::invalid_argument("distance2_to_triangle: the triangle is degenerate (collinear vertices)");
  // p projects inside when it is on the inner side of all three edge planes (the planes
  // through an edge containing the normal); the inward normal of edge e = (u -> v) is n x e.
  auto inner_side = [&](const Point3& u, const Point3& v) { return affine_dot(p, u, cross3(n, sub(v, u))) >= 0.0; };
  const Fn inside = inner_side(a, b) && inner_side(b, c) && inner_side(c, a);
  const Fn plane2 = square(affine_dot(p, a, n)) / n2;
  const Fn edges2 = min(min(distance2_to_segment(a, b, p), distance2_to_segment(b, c, p)), distance2_to_segment(c, a, p));
  return select(inside, plane2, edges2);
}

Fn distance_surface(std::span<const Fn> distances2, std::span<const double> radii) {
  if (distances2.empty()) throw std::invalid_argument("distance_surface: no skeleton elements");
  if (distances2.size() != radii.size())
    throw std::invalid_argument("distance_surface: " + std::to_string(distances2.size()) + " distances but " +
                                std::to_string(radii.size()) + " radii");
  Fn f;
  for (std::size_t i = 0; i < radii.size(); ++i) {
    if (!(radii[i] > 0 && std::isfinite(radii[i])))
      throw std::invalid_argument("distance_surface: radius " + std::to_string(i) + " must be finite and > 0");
    const Fn term = distances2[i] * (1.0 / (radii[i] * radii[i]));
    f = i == 0 ? term : min(f, term);
  }
  return f - 1.0;
}

Fn distance_surface(std::initializer_list<Fn> distances2, std::initializer_list<double> radii) {
  return distance_surface(std::span<const Fn>(distances2.begin(), distances2.size()),
                          std::span<const double>(radii.begin(), radii.size()));
}

Fn tapered_segment_surface(const Point3& a, const Point3& b, double r1, double r2, const Fn& p) {
  if (!(r1 > 0 && r2 > 0 && std::isfinite(r1) && std::isfinite(r2)))
    throw std::invalid_argument("tapered_segment_surface: radii must be finite and > 0");
  const Fn r = r1 + clamp01(segment_parameter(a, b, p)) * (r2 - r1);
  return distance2_to_segment(a, b, p) / square(r) - 1.0;
}

Fn ramiform_density(const SkeletonLimb& parent, std::span<const SkeletonLimb> children, const Fn& p) {
  if (children.empty()) throw std::invalid_argument("ramiform_density: no children");
  auto limb = [&](const SkeletonLimb& l) {
    if (!(l.radius > 0 && std::isfinite(l.radius))) throw std::invalid_argument("ramiform_density: radii must be finite and > 0");
    return (l.radius * l.radius) / distance2_to_segment(l.a, l.b, p);
  };
  Fn sum = limb(children[0]);
  for (std::size_t i = 1; i < children.size(); ++i) sum = sum + limb(children[i]);
  return max(limb(parent), sum);
}

}  // namespace genmod
