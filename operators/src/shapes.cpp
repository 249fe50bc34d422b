#include "genmod/operators/shapes.hpp"

#include "dims.hpp"
#include "genmod/operators/transform.hpp"
#include "genmod/operators/vector.hpp"

#include <array>
#include <numbers>
#include <string>

namespace genmod {

namespace {

constexpr double kPi = std::numbers::pi;

using detail::require_dim;

void require_scalar(const char* op, const char* what, const Fn& f) { require_dim(op, what, f, 1); }

// sign(c) |c|^e, with |c|^e = 0 at c = 0.
Fn spow(const Fn& c, const Fn& e) { return select(c < 0.0, -1.0, 1.0) * pow(abs(c), e); }

Fn vec3_or_scalar(const char* op, const char* what, const Fn& f) {
  if (f.dim() == 3) return f;
  if (f.dim() == 1) return cat({f, f, f});
  detail::dimension_error(op, std::string(what) + " has dimension " + std::to_string(f.dim()) + ", expected 1 or 3");
}

Fn substitute_point(const Fn& f, const Fn& q) {
  static constexpr std::array<int, 3> kInputs = {0, 1, 2};
  return compose_all(f, kInputs, q);
}

}  // namespace

Fn sphere_surface(const Fn& radius) {
  require_scalar("sphere_surface", "the radius", radius);
  const Fn theta = 2.0 * kPi * x(0), phi = kPi * (x(1) - 0.5);
  return radius * cat({cos(theta) * cos(phi), sin(theta) * cos(phi), sin(phi)});
}

Fn torus_surface(const Fn& major_radius, const Fn& minor_radius) {
  require_scalar("torus_surface", "the major radius", major_radius);
  require_scalar("torus_surface", "the minor radius", minor_radius);
  const Fn theta = 2.0 * kPi * x(0), phi = 2.0 * kPi * x(1);
  const Fn rho = major_radius + minor_radius * cos(phi);
  return cat({rho * cos(theta), rho * sin(theta), minor_radius * sin(phi)});
}

Fn cylinder_surface(const Fn& radius, const Fn& height) {
  require_scalar("cylinder_surface", "the radius", radius);
  require_scalar("cylinder_surface", "the height", height);
  const Fn theta = 2.0 * kPi * x(0);
  return cat({radius * cos(theta), radius * sin(theta), height * x(1)});
}

Fn cone_surface(const Fn& radius, const Fn& height) {
  require_scalar("cone_surface", "the radius", radius);
  require_scalar("cone_surface", "the height", height);
  const Fn theta = 2.0 * kPi * x(0);
  const Fn rho = radius * (1.0 - x(1));
  return cat({rho * cos(theta), rho * sin(theta), height * x(1)});
}

Fn disk_surface(const Fn& radius) {
  require_scalar("disk_surface", "the radius", radius);
  const Fn theta = 2.0 * kPi * x(1);
  const Fn rho = radius * x(0);
  return cat({rho * cos(theta), rho * sin(theta), Fn(0.0)});
}

Fn superquadric_surface(const Fn& e1, const Fn& e2, const Fn& radii) {
  require_scalar("superquadric_surface", "e1", e1);
  require_scalar("superquadric_surface", "e2", e2);
  const Fn a = vec3_or_scalar("superquadric_surface", "the radii", radii);
  const Fn theta = 2.0 * kPi * x(0), phi = kPi * (x(1) - 0.5);
  const Fn cp = spow(cos(phi), e1);
  return cat({a[0] * cp * spow(cos(theta), e2), a[1] * cp * spow(sin(theta), e2), a[2] * spow(sin(phi), e1)});
}

Fn point3() { return cat({x(0), x(1), x(2)}); }

Fn implicit_sphere(const Fn& radius, const Fn& center) {
  require_scalar("implicit_sphere", "the radius", radius);
  double c0 = 0.0;
  if (center.dim() == 1 && center.is_constant(&c0) && c0 == 0.0) return length(point3()) - radius;
  require_dim("implicit_sphere", "the center", center, 3);
  return length(point3() - center) - radius;
}

Fn implicit_box(const Fn& half_extents) {
  require_dim("implicit_box", "the half extents", half_extents, 3);
  const Fn p = point3();
  const Fn q = abs(p) - half_extents;
  const Fn outside = length(max(q, 0.0));
  const Fn inside = min(max(q[0], max(q[1], q[2])), 0.0);
  return outside + inside;
}

Fn implicit_cylinder(const Fn& radius, const Fn& half_height) {
  require_scalar("implicit_cylinder", "the radius", radius);
  require_scalar("implicit_cylinder", "the half height", half_height);
  const Fn d0 = sqrt(square(x(0)) + square(x(1))) - radius;
  const Fn d1 = abs(x(2)) - half_height;
  const Fn outside = length(cat({max(d0, 0.0), max(d1, 0.0)}));
  return outside + min(max(d0, d1), 0.0);
}

Fn implicit_torus(const Fn& major_radius, const Fn& minor_radius) {
  require_scalar("implicit_torus", "the major radius", major_radius);
  require_scalar("implicit_torus", "the minor radius", minor_radius);
  const Fn q = sqrt(square(x(0)) + square(x(1))) - major_radius;
  return sqrt(square(q) + square(x(2))) - minor_radius;
}

Fn implicit_gyroid(const Fn& frequency, const Fn& thickness) {
  require_scalar("implicit_gyroid", "the frequency", frequency);
  require_scalar("implicit_gyroid", "the thickness", thickness);
  const Fn a = frequency * x(0), b = frequency * x(1), c = frequency * x(2);
  const Fn g = sin(a) * cos(b) + sin(b) * cos(c) + sin(c) * cos(a);
  double t = 0.0;
  if (thickness.is_constant(&t) && t == 0.0) return g;
  return abs(g) - thickness;
}

Fn csg_union(const Fn& a, const Fn& b) {
  require_scalar("csg_union", "the first shape", a);
  require_scalar("csg_union", "the second shape", b);
  return min(a, b);
}

Fn csg_intersection(const Fn& a, const Fn& b) {
  require_scalar("csg_intersection", "the first shape", a);
  require_scalar("csg_intersection", "the second shape", b);
  return max(a, b);
}

Fn csg_difference(const Fn& a, const Fn& b) {
  require_scalar("csg_difference", "the first shape", a);
  require_scalar("csg_difference", "the second shape", b);
  return max(a, -b);
}

Fn smooth_union(const Fn& a, const Fn& b, const Fn& k) {
  require_scalar("smooth_union", "the first shape", a);
  require_scalar("smooth_union", "the second shape", b);
  require_scalar("smooth_union", "the blend radius", k);
  double kv = 0.0;
  if (k.is_constant(&kv) && !(kv > 0.0))
    detail::dimension_error("smooth_union", "the blend radius is " + std::to_string(kv) + ", expected > 0");
  const Fn h = min(max(0.5 + (b - a) / (2.0 * k), 0.0), 1.0);
  return b + (a - b) * h - k * h * (1.0 - h);
}

Fn transform_implicit(const Fn& f, const Matrix& m) {
  require_scalar("transform_implicit", "the shape", f);
  if (m.rows() != 4 || m.cols() != 4)
    detail::dimension_error("transform_implicit", "the matrix is " + std::to_string(m.rows()) + "x" +
                                                      std::to_string(m.cols()) + ", expected 4x4");
  return substitute_point(f, transform3d(point3(), inverse(m)));
}

Fn translate_implicit(const Fn& f, const Fn& offset) {
  require_scalar("translate_implicit", "the shape", f);
  require_dim("translate_implicit", "the offset", offset, 3);
  return substitute_point(f, point3() - offset);
}

Fn scale_implicit(const Fn& f, const Fn& s) {
  require_scalar("scale_implicit", "the shape", f);
  const Fn sv = vec3_or_scalar("scale_implicit", "the scale", s);
  return substitute_point(f, point3() / sv);
}

}  // namespace genmod
