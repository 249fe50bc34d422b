// Standard shapes: parametric points satisfy the implicit equation of the same shape, normals
// S_u x S_v point outward, implicit shapes have the right sign at known points, CSG / blend
// values, transforms of implicit shapes, the shared properties and dimension errors.
#include "genmod/operators/shapes.hpp"
#include "genmod/operators/transform.hpp"
#include "genmod/operators/vector.hpp"
#include "operators/operator_properties.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace genmod {
namespace {

using testing::check_operator_properties;
using testing::PropertySpec;
using testing::unit_domain;

constexpr double kPi = std::numbers::pi;

double at(const Fn& f, std::vector<double> p, std::size_t j = 0) { return evaluate(f, p)[j]; }

// Interior sample points of [0,1]^2 (away from poles and seams).
std::vector<std::vector<double>> interior(int n = 6) {
  std::vector<std::vector<double>> g;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) g.push_back({(i + 0.37) / n, (j + 0.61) / n});
  return g;
}

// The implicit f evaluated at the parametric point s(u, v).
Fn on_surface(const Fn& implicit, const Fn& surface) {
  const std::vector<int> in = {0, 1, 2};
  return compose_all(implicit, in, surface);
}

// Checks |f(s(u,v))| small and normal . (s - center) > 0 at interior points (no normal check
// when center is empty).
void check_surface(const Fn& s, const Fn& implicit, const std::vector<double>& center, double tol = 1e-14) {
  const Fn f = on_surface(implicit, s);
  const Fn normal = cross(derivative(s, 0), derivative(s, 1));
  for (const auto& p : interior()) {
    EXPECT_NEAR(at(f, p), 0.0, tol) << "u=" << p[0] << " v=" << p[1];
    if (center.empty()) continue;
    const auto sv = evaluate(s, p), nv = evaluate(normal, p);
    double d = 0.0;
    for (int j = 0; j < 3; ++j) d += nv[j] * (sv[j] - center[j]);
    EXPECT_GT(d, 0.0) << "inward normal at u=" << p[0] << " v=" << p[1];
  }
}

TEST(Shapes, SpherePointsAndNormals) {
  check_surface(sphere_surface(1.5), implicit_sphere(1.5), {0, 0, 0});
  check_operator_properties(sphere_surface(1.5), unit_domain(2), 201);
}

TEST(Shapes, TorusPointsAndNormals) {
  const Fn s = torus_surface(2.0, 0.5);
  check_surface(s, implicit_torus(2.0, 0.5), {}, 1e-14);
  // Outward from the tube's center circle, not just the origin.
  const Fn normal = cross(derivative(s, 0), derivative(s, 1));
  for (const auto& p : interior()) {
    const auto sv = evaluate(s, p), nv = evaluate(normal, p);
    const double rho = std::hypot(sv[0], sv[1]);
    const double cx = 2.0 * sv[0] / rho, cy = 2.0 * sv[1] / rho;
    EXPECT_GT(nv[0] * (sv[0] - cx) + nv[1] * (sv[1] - cy) + nv[2] * sv[2], 0.0);
  }
  check_operator_properties(s, unit_domain(2), 202);
}

TEST(Shapes, CylinderConeDisk) {
  const Fn cyl = cylinder_surface(0.8, 2.0);
  // The open cylinder lies on |p_xy| = 0.8 with z in [0, 2]: the capped implicit cylinder of
  // half height 1, moved up by 1, is zero there (the side wall).
  check_surface(cyl, translate_implicit(implicit_cylinder(0.8, 1.0), cat({0.0, 0.0, 1.0})), {0, 0, 1.0});
  for (const auto& p : interior()) {
    // Outward means radially outward for the side wall.
    const auto sv = evaluate(cyl, p);
    const auto nv = evaluate(cross(derivative(cyl, 0), derivative(cyl, 1)), p);
    EXPECT_GT(nv[0] * sv[0] + nv[1] * sv[1], 0.0);
    EXPECT_NEAR(nv[2], 0.0, 1e-15);
  }
  const Fn cone = cone_surface(1.0, 2.0);
  const Fn cone_eq = sqrt(square(x(0)) + square(x(1))) - (1.0 - x(2) / 2.0);
  check_surface(cone, cone_eq, {0, 0, 0.5});
  const Fn disk = disk_surface(1.2);
  const Fn dn = cross(derivative(disk, 0), derivative(disk, 1));
  for (const auto& p : interior()) {
    EXPECT_GT(at(dn, p, 2), 0.0);
    EXPECT_LE(std::hypot(at(disk, p, 0), at(disk, p, 1)), 1.2 + 1e-15);
    EXPECT_EQ(at(disk, p, 2), 0.0);
  }
  for (const Fn& f : {cyl, cone, disk}) check_operator_properties(f, unit_domain(2), 203);
}

TEST(Shapes, Superquadric) {
  // e1 = e2 = 1 is the ellipsoid of the given radii.
  const Fn ell = superquadric_surface(1.0, 1.0, cat({1.0, 2.0, 0.5}));
  const Fn ell_eq = square(x(0)) + square(x(1) / 2.0) + square(x(2) / 0.5) - 1.0;
  check_surface(ell, ell_eq, {0, 0, 0});
  // General exponents satisfy Barr's implicit equation.
  const double e1 = 0.5, e2 = 1.5;
  const Fn sq = superquadric_surface(e1, e2);
  const Fn sq_eq = pow(pow(abs(x(0)), 2.0 / e2) + pow(abs(x(1)), 2.0 / e2), e2 / e1) + pow(abs(x(2)), 2.0 / e1) - 1.0;
  check_surface(sq, sq_eq, {0, 0, 0}, 1e-12);
  check_operator_properties(ell, unit_domain(2), 204);
}

TEST(Shapes, ImplicitSigns) {
  const Fn sph = implicit_sphere(1.0), sphc = implicit_sphere(0.5, cat({1.0, 0.0, 0.0}));
  EXPECT_NEAR(at(sph, {0, 0, 0}), -1.0, 1e-15);
  EXPECT_NEAR(at(sph, {2, 0, 0}), 1.0, 1e-15);
  EXPECT_LT(at(sphc, {1.2, 0.1, 0}), 0.0);
  EXPECT_GT(at(sphc, {0, 0, 0}), 0.0);
  const Fn box = implicit_box(cat({1.0, 2.0, 3.0}));
  EXPECT_NEAR(at(box, {0, 0, 0}), -1.0, 1e-15);
  EXPECT_NEAR(at(box, {0.5, 1.9, 0}), -0.1, 1e-15);
  EXPECT_NEAR(at(box, {2, 0, 0}), 1.0, 1e-15);
  EXPECT_NEAR(at(box, {4, 6, 3}), 5.0, 1e-14);  // corner distance (3, 4, 0)
  const Fn cyl = implicit_cylinder(1.0, 2.0);
  EXPECT_NEAR(at(cyl, {0, 0, 0}), -1.0, 1e-15);
  EXPECT_NEAR(at(cyl, {0, 0, 1.5}), -0.5, 1e-15);
  EXPECT_NEAR(at(cyl, {0, 0, 3}), 1.0, 1e-15);
  EXPECT_NEAR(at(cyl, {4, 0, 6}), 5.0, 1e-14);
  const Fn tor = implicit_torus(2.0, 0.5);
  EXPECT_NEAR(at(tor, {2, 0, 0}), -0.5, 1e-15);
  EXPECT_NEAR(at(tor, {0, 0, 0}), 1.5, 1e-15);
  EXPECT_GT(at(tor, {3, 0, 0}), 0.0);
  const Fn gy = implicit_gyroid(2.0), sheet = implicit_gyroid(2.0, 0.3);
  EXPECT_NEAR(at(gy, {0.1, 0.2, 0.3}),
              std::sin(0.2) * std::cos(0.4) + std::sin(0.4) * std::cos(0.6) + std::sin(0.6) * std::cos(0.2), 1e-15);
  EXPECT_LT(at(gy, {-kPi / 4, 0, 0}), 0.0);  // sin(-pi/2) cos 0 + 0 + 0 = -1
  EXPECT_NEAR(at(sheet, {0, 0, 0}), -0.3, 1e-15);
  EXPECT_NEAR(at(sheet, {-kPi / 4, 0, 0}), 0.7, 1e-15);
  PropertySpec spec = unit_domain(3);
  for (auto& d : spec.domain) d = Interval(-2.0, 2.0);
  spec.breaks = {{0.0}, {0.0}, {0.0}};
  for (const Fn& f : {sph, tor, gy}) check_operator_properties(f, spec, 205);
  // Box, capped cylinder and the gyroid sheet have kinks (min / max / abs) off the coordinate
  // planes: containment and batch = scalar only.
  spec.check_derivative = false;
  for (const Fn& f : {box, cyl, sheet}) check_operator_properties(f, spec, 205);
}

TEST(Shapes, CsgAndBlend) {
  const Fn a = implicit_sphere(1.0), b = implicit_sphere(1.0, cat({1.5, 0.0, 0.0}));
  const std::vector<double> pa = {-0.5, 0, 0}, pb = {2.0, 0, 0}, pab = {0.75, 0, 0}, out = {0, 3, 0};
  EXPECT_LT(at(csg_union(a, b), pa), 0.0);
  EXPECT_LT(at(csg_union(a, b), pb), 0.0);
  EXPECT_GT(at(csg_union(a, b), out), 0.0);
  EXPECT_LT(at(csg_intersection(a, b), pab), 0.0);
  EXPECT_GT(at(csg_intersection(a, b), pa), 0.0);
  EXPECT_LT(at(csg_difference(a, b), pa), 0.0);
  EXPECT_GT(at(csg_difference(a, b), pab), 0.0);
  EXPECT_NEAR(at(csg_union(a, b), pab), -0.25, 1e-15);
  EXPECT_NEAR(at(csg_intersection(a, b), pa), 1.0, 1e-15);
  EXPECT_NEAR(at(csg_difference(a, b), pa), -0.5, 1e-15);
  // Smooth union: equals min when |a - b| >= k, is min - k/4 where a = b, never above min.
  const Fn s = smooth_union(a, b, 0.4);
  EXPECT_NEAR(at(s, pa), at(csg_union(a, b), pa), 1e-15);  // a = -0.5, b = 1
  EXPECT_NEAR(at(s, pab), -0.25 - 0.1, 1e-15);
  for (double t = -1.0; t <= 3.0; t += 0.125) EXPECT_LE(at(s, {t, 0.3, 0.1}), at(csg_union(a, b), {t, 0.3, 0.1}) + 1e-15);
  // Between the spheres, outside both, the blend fills in: at (0.75, 0.7, 0) a = b.
  const double ab = at(a, {0.75, 0.7, 0});
  EXPECT_GT(ab, 0.0);
  EXPECT_NEAR(at(s, {0.75, 0.7, 0}), ab - 0.1, 1e-15);
  PropertySpec spec = unit_domain(3);
  for (auto& d : spec.domain) d = Interval(-2.0, 2.0);
  for (const Fn& f : {csg_union(a, b), csg_difference(a, b), s}) check_operator_properties(f, spec, 206);
}

TEST(Shapes, ImplicitTransforms) {
  const Fn sph = implicit_sphere(1.0);
  const Fn moved = translate_implicit(sph, cat({3.0, 0.0, 0.0}));
  EXPECT_NEAR(at(moved, {3, 0, 0}), -1.0, 1e-15);
  EXPECT_NEAR(at(moved, {0, 0, 0}), 2.0, 1e-15);
  // A box elongated along x, rotated 90 degrees about z, is elongated along y.
  const Fn box = implicit_box(cat({2.0, 0.5, 0.5}));
  const Fn rotated = transform_implicit(box, rotate_z(kPi / 2));
  EXPECT_LT(at(rotated, {0, 1.8, 0}), 0.0);
  EXPECT_GT(at(rotated, {1.8, 0, 0}), 0.0);
  EXPECT_NEAR(at(rotated, {0, 0, 0}), -0.5, 1e-15);
  // Order: translate then rotate (premultiplying): the center goes to rotate_z(pi/2) (1,0,0) = (0,1,0).
  const Fn tr = transform_implicit(sph, rotate_z(kPi / 2) * translate(1.0, 0.0, 0.0));
  EXPECT_NEAR(at(tr, {0, 1, 0}), -1.0, 1e-14);
  const Fn scaled = scale_implicit(sph, 2.0);
  EXPECT_LT(at(scaled, {1.9, 0, 0}), 0.0);
  EXPECT_NEAR(at(scaled, {2, 0, 0}), 0.0, 1e-15);
  const Fn squashed = scale_implicit(sph, cat({1.0, 1.0, 0.25}));
  EXPECT_GT(at(squashed, {0, 0, 0.3}), 0.0);
  EXPECT_LT(at(squashed, {0, 0.9, 0}), 0.0);
  PropertySpec spec = unit_domain(3);
  for (auto& d : spec.domain) d = Interval(-2.0, 2.0);
  for (const Fn& f : {moved, tr}) check_operator_properties(f, spec, 207);
  spec.check_derivative = false;  // the box has kinks
  check_operator_properties(rotated, spec, 207);
}

TEST(Shapes, DimensionErrors) {
  const Fn v2 = cat({x(0), x(1)});
  EXPECT_THROW(sphere_surface(v2), std::invalid_argument);
  EXPECT_THROW(torus_surface(1.0, v2), std::invalid_argument);
  EXPECT_THROW(superquadric_surface(1.0, 1.0, v2), std::invalid_argument);
  EXPECT_THROW(implicit_sphere(1.0, v2), std::invalid_argument);
  EXPECT_THROW(implicit_box(2.0), std::invalid_argument);
  EXPECT_THROW(csg_union(v2, x(0)), std::invalid_argument);
  EXPECT_THROW(smooth_union(x(0), x(1), 0.0), std::invalid_argument);
  EXPECT_THROW(translate_implicit(x(0), v2), std::invalid_argument);
  EXPECT_THROW(transform_implicit(x(0), Matrix::identity(3)), std::invalid_argument);
  EXPECT_THROW(scale_implicit(x(0), v2), std::invalid_argument);
  try {
    implicit_box(v2);
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("implicit_box"), std::string::npos);
  }
}

}  // namespace
}  // namespace genmod
