// Sweeps (snyder.md sections 7.1-7.11): claim 28 sweep invariants, claim 25 Hermite
// constraints on cross sections, claim 29 cross-section mismatch, claim 32 quasi-linear
// order, the shared properties and dimension errors.
#include "genmod/operators/curve.hpp"
#include "genmod/operators/higher_order.hpp"
#include "genmod/operators/sweep.hpp"
#include "genmod/operators/transform.hpp"
#include "genmod/operators/vector.hpp"
#include "operators/operator_properties.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace genmod {
namespace {

using testing::check_operator_properties;
using testing::unit_domain;

constexpr double kPi = std::numbers::pi;
const Fn u = x(0), v = x(1);

std::vector<double> at(const Fn& f, std::vector<double> p) { return evaluate(f, p); }

Fn circle(const Fn& t, double phase = 0.0) { return cat({cos(2.0 * kPi * t + phase), sin(2.0 * kPi * t + phase)}); }

// A grid of (u, v) sample points in [0,1]^2.
std::vector<std::vector<double>> grid(int n = 7) {
  std::vector<std::vector<double>> g;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) g.push_back({double(i) / n, double(j) / n});
  return g;
}

TEST(Sweep, ProfileProductOfCircleIsSurfaceOfRevolution) {  // claim 28
  const Fn profile = cat({0.5 + 0.3 * sin(3.0 * v), 2.0 * v - v * v});
  const Fn s = profile_product(circle(u), profile);
  ASSERT_EQ(s.dim(), 3U);
  for (const auto& p : grid()) {
    const auto sv = at(s, p);
    const auto d = at(profile, p);
    EXPECT_NEAR(std::hypot(sv[0], sv[1]), d[0], 1e-14);
    EXPECT_NEAR(sv[2], d[1], 1e-15);
  }
  check_operator_properties(s, unit_domain(2), 101);
}

TEST(Sweep, ProfileSurfaceFeedsCurvesTheRightParameters) {
  const Curve prof = Curve::catmull_rom({{0.2, 0.0}, {0.6, 0.3}, {0.4, 0.7}, {0.1, 1.0}});
  const Fn s = profile_surface(circle(x(0)), prof(x(0)));
  EXPECT_EQ(s.inputs(), (std::vector<int>{0, 1}));
  for (const auto& p : grid()) {
    const auto sv = at(s, p);
    const auto d = evaluate(prof(x(0)), std::vector<double>{p[1]});
    EXPECT_NEAR(std::hypot(sv[0], sv[1]), d[0], 1e-14);
    EXPECT_NEAR(sv[2], d[1], 1e-15);
  }
  testing::PropertySpec spec = unit_domain(2);
  spec.breaks = {{}, {1.0 / 3.0, 2.0 / 3.0}};  // the Catmull-Rom joints
  check_operator_properties(s, spec, 107);
}

TEST(Sweep, WireProductCrossSectionIsPerpendicularToWire) {  // claim 28
  const Fn cross = cat({0.1 * cos(2.0 * kPi * u), 0.05 * sin(2.0 * kPi * u)});
  const Fn wire = cat({0.7 * cos(2.0 * kPi * v), 0.9 * sin(2.0 * kPi * v)});  // racket oval
  const Fn s = wire_product(cross, wire);
  const Fn t = normalize(derivative(wire, 1));
  for (const auto& p : grid()) {
    const auto sv = at(s, p), dv = at(wire, p), tv = at(t, p), gv = at(cross, p);
    const double ex = sv[0] - dv[0], ey = sv[1] - dv[1];
    EXPECT_NEAR(ex * tv[0] + ey * tv[1], 0.0, 1e-14);
    EXPECT_NEAR(std::hypot(ex, ey), std::abs(gv[0]), 1e-14);
    EXPECT_NEAR(sv[2], gv[1], 1e-15);
  }
  check_operator_properties(s, unit_domain(2), 102);
  // Curve style: the same surface.
  const Fn s2 = wire_surface(compose(cross, 0, x(0)), compose(wire, 1, x(0)));
  for (const auto& p : grid(3)) {
    const auto a = at(s, p), b = at(s2, p);
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(a[j], b[j], 1e-15);
  }
}

TEST(Sweep, RailProductEndpointsLieOnTheRails) {  // claim 28
  // cross(u): x runs from -1 (u = 0) to +1 (u = 1) over a bump.
  const Fn cross = cat({2.0 * u - 1.0, 0.2 * sin(kPi * u)});
  const Curve r1 = Curve::catmull_rom({{-1.0, 0.0}, {-0.8, 0.8}, {0.0, 1.2}, {0.8, 0.8}, {1.0, 0.0}});
  const Curve r2 = Curve::catmull_rom({{-1.3, 0.0}, {-1.1, 1.0}, {0.0, 1.5}, {1.1, 1.0}, {1.3, 0.0}});
  const Fn s = rail_surface(cross, r1(x(0)), r2(x(0)));
  for (double vv : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    const auto a = at(s, {0.0, vv}), b = at(s, {1.0, vv});
    const auto p1 = evaluate(r1(x(0)), std::vector<double>{vv}), p2 = evaluate(r2(x(0)), std::vector<double>{vv});
    EXPECT_NEAR(a[0], p1[0], 1e-14);
    EXPECT_NEAR(a[1], p1[1], 1e-14);
    EXPECT_NEAR(b[0], p2[0], 1e-14);
    EXPECT_NEAR(b[1], p2[1], 1e-14);
    const auto mid = at(s, {0.5, vv});  // g1 = 0: the midpoint, lifted by g2 = 0.2
    EXPECT_NEAR(mid[0], 0.5 * (p1[0] + p2[0]), 1e-14);
    EXPECT_NEAR(mid[2], 0.2, 1e-15);
  }
  const Fn s3 = rail_product(cross, cat({v - 1.0, v * v}), cat({v + 1.0, 1.0 - v}));
  check_operator_properties(s3, unit_domain(2), 103);
}

TEST(Sweep, CrossSectionMismatch) {  // claim 29
  const Fn c1 = circle(x(0)), c2 = 2.0 * circle(x(0), kPi);
  const Fn s = interp_surface(c1, c2, x(0));
  for (double uu : {0.0, 0.1, 0.37, 0.5, 0.9}) {
    const auto p = at(s, {uu, 1.0 / 3.0});
    EXPECT_NEAR(p[0], 0.0, 1e-15);
    EXPECT_NEAR(p[1], 0.0, 1e-15);
    EXPECT_NEAR(p[2], 1.0 / 3.0, 1e-15);
  }
  const Fn matched = interp_surface(c1, 2.0 * c1, x(0));
  for (const auto& p : grid()) {
    const auto sv = at(matched, p);
    EXPECT_NEAR(std::hypot(sv[0], sv[1]), 1.0 + p[1], 1e-14);
  }
  check_operator_properties(s, unit_domain(2), 104);
}

TEST(Sweep, HermiteCrossSectionsMeetTheirConstraints) {  // claim 25, with surfaces
  const Fn p1 = cat({cos(u), sin(u), 0.0}), p2 = cat({u, u * u, 1.0});
  const Fn t1 = cat({0.0, 0.3, 1.0 + u}), t2 = cat({sin(u), 0.0, 2.0});
  const Fn h = hermite_cross_sections(v, p1, p2, t1, t2);
  const Fn hv = derivative(h, 1);
  for (double uu : {0.0, 0.3, 0.8}) {
    const auto a0 = at(h, {uu, 0.0}), a1 = at(h, {uu, 1.0}), d0 = at(hv, {uu, 0.0}), d1 = at(hv, {uu, 1.0});
    const auto e0 = at(p1, {uu}), e1 = at(p2, {uu}), f0 = at(t1, {uu}), f1 = at(t2, {uu});
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(a0[j], e0[j], 1e-14);
      EXPECT_NEAR(a1[j], e1[j], 1e-14);
      EXPECT_NEAR(d0[j], f0[j], 1e-13);
      EXPECT_NEAR(d1[j], f1[j], 1e-13);
    }
  }
  check_operator_properties(h, unit_domain(2), 105);
}

TEST(Sweep, QuasiLinearMatchesTransform3dAndOrder) {  // claim 32 (order), section 7.7
  const Fn cross = cat({cos(2.0 * kPi * u), sin(2.0 * kPi * u)});
  // M(v) = rotation about y by -0.4 pi v, T(v) = (0, 0, v).
  const Fn c = cos(-0.4 * kPi * v), s = sin(-0.4 * kPi * v);
  const Matrix m = matrix(cat({c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c}), 3, 3);
  const Fn t = cat({0.0, 0.0, v});
  const Fn q = quasi_linear(cross, m, t);
  const Fn h = transform3d(cross, homogeneous(m, t));
  const Fn ordered = transform3d(cross, translate(t) * rotate_y(-0.4 * kPi * v));  // rotate first
  for (const auto& p : grid(4)) {
    const auto a = at(q, p), b = at(h, p), o = at(ordered, p);
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(a[j], b[j], 1e-15);
      EXPECT_NEAR(a[j], o[j], 1e-15);
    }
  }
  // At v = 1 the section point (1, 0, 0) is rotated by -0.4 pi about y, then lifted by 1.
  const auto p = at(q, {0.0, 1.0});
  EXPECT_NEAR(p[0], std::cos(-0.4 * kPi), 1e-15);
  EXPECT_NEAR(p[2], -std::sin(-0.4 * kPi) + 1.0, 1e-15);
  check_operator_properties(q, unit_domain(2), 106);
}

TEST(Sweep, BananaQuasiLinearOrder) {  // claim 32
  const Fn cross = cat({0.5 * cos(2.0 * kPi * u), 0.4 * sin(2.0 * kPi * u)});  // centroid at the origin
  const Fn sc = 0.1 + 0.3 * sin(kPi * v);
  const Fn angle = interp(v, 0.0, -0.4 * kPi), z = interp(v, -1.0, 1.0);
  const Fn banana = transform3d(cat({cross, 0.0}), rotate_y(angle) * translate(0.0, 0.0, z) * scale(sc, sc, 1.0));
  // The same sweep as M(v) g + T(v): M = R_y(angle) diag(s, s, 1), T = R_y(angle) (0, 0, z).
  const Fn c = cos(angle), s = sin(angle);
  const Matrix m = matrix(cat({c * sc, 0.0, s, 0.0, sc, 0.0, -s * sc, 0.0, c}), 3, 3);
  const Fn q = quasi_linear(cross, m, cat({s * z, 0.0, c * z}));
  for (const auto& p : grid(5)) {
    const auto a = at(banana, p), b = at(q, p);
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(a[j], b[j], 1e-15);
  }
  for (double uu : {0.0, 0.2, 0.5, 0.9}) EXPECT_NEAR(at(banana, {uu, 0.0})[2], -1.0, 1e-15);  // plane z = -1
  // At v = 1 the section centroid (the mean over u) is (0, 0, 1) rotated by -0.4 pi about y.
  double cx = 0.0, cy = 0.0, cz = 0.0;
  const int n = 64;
  for (int i = 0; i < n; ++i) {
    const auto a = at(banana, {double(i) / n, 1.0});
    cx += a[0] / n, cy += a[1] / n, cz += a[2] / n;
  }
  EXPECT_NEAR(cx, std::sin(-0.4 * kPi), 1e-14);
  EXPECT_NEAR(cy, 0.0, 1e-14);
  EXPECT_NEAR(cz, std::cos(-0.4 * kPi), 1e-14);
}

TEST(Sweep, DimensionErrors) {
  const Fn c2 = cat({u, v}), c3 = cat({u, v, u});
  auto throws_naming = [](auto&& fn, const std::string& name) {
    try {
      fn();
      ADD_FAILURE() << "no exception for " << name;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  };
  throws_naming([&] { profile_product(c3, c2); }, "profile_product");
  throws_naming([&] { profile_product(c2, u); }, "profile_product");
  throws_naming([&] { wire_product(c2, c3); }, "wire_product");
  throws_naming([&] { wire_product(c2, cat({u, u})); }, "does not depend on x(1)");
  throws_naming([&] { rail_product(c2, c2, c3); }, "rail2");
  throws_naming([&] { quasi_linear(c2, Matrix::identity(4), c3); }, "quasi_linear");
  throws_naming([&] { quasi_linear(u, Matrix::identity(3), c3); }, "quasi_linear");
  throws_naming([&] { homogeneous(Matrix::identity(3), c2); }, "homogeneous");
  throws_naming([&] { interp_cross_sections(c2, c2, c2); }, "interp_cross_sections");
  throws_naming([&] { interp_cross_sections(u, c2, c3); }, "interp_cross_sections");
  throws_naming([&] { hermite_cross_sections(u, c2, c2, c3, c2); }, "hermite_cross_sections");
  throws_naming([&] { curve_in(c2, 1); }, "curve_in");
  throws_naming([&] { interp_surface(cat({x(0), x(0)}), cat({x(0), x(0)}), cat({x(0), x(0)})); }, "interp_surface");
}

}  // namespace
}  // namespace genmod
