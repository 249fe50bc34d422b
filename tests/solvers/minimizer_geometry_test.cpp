// snyder.md claim 24: ray intersection and point classification by minimization on the unit
// sphere with the Fig 2.3 parameterization S(u,v) = (cos 2pi u sin pi v, sin 2pi u sin pi v, -cos pi v).
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/solvers/minimizer.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace genmod {
namespace {

constexpr double kPi = std::numbers::pi;

// The sphere over (u, v) = (x(1), x(2)).
Fn sphere() {
  const Fn u = x(1), v = x(2);
  return cat({cos(2.0 * kPi * u) * sin(kPi * v), sin(2.0 * kPi * u) * sin(kPi * v), -cos(kPi * v)});
}

Fn cross(const Fn& a, const Fn& b) {
  return cat({a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]});
}

TEST(MinimizerGeometry, Claim24RayIntersectionFindsTheFirstHit) {
  // p + t d = S(u, v) with p = (0, 0, -5), d = (0, 0, 1): hits at t = 4 (first) and t = 6.
  const Fn t = x(0);
  const Fn ray = cat({Fn(0.0), Fn(0.0), -5.0 + t});
  const int unknowns[] = {0, 1, 2};
  const Box box = {Interval(0.0, 10.0), Interval(0.0, 1.0), Interval(0.0, 1.0)};
  const double acc = 1e-3;
  MinimizeOptions opt;
  opt.equality_tolerance = 1e-5;  // bracket of min t subject to |p + t d - S| <= 1e-5 per component
  opt.epsilon = acc;
  opt.delta = acc;
  const MinimizeResult r = minimize_value(t, eq(ray, sphere()), unknowns, box, opt);
  ASSERT_TRUE(r.feasible_found);
  EXPECT_EQ(r.report.limit, LimitHit::None);
  EXPECT_TRUE(r.delta_reached);
  // Guaranteed: lo <= the exact first hit 4; hi is t at a point within 1e-5 of the sphere.
  EXPECT_LE(r.minimum.lo(), 4.0);
  EXPECT_NEAR(r.minimum.lo(), 4.0, acc);
  EXPECT_NEAR(r.minimum.hi(), 4.0, acc);
  ASSERT_EQ(r.best_point.size(), 3u);
  EXPECT_NEAR(r.best_point[0], 4.0, acc);
}

struct Classification {
  double sign;  // N_min . (S_min - p)
  Interval distance2;
};

Classification classify(const double p[3]) {
  const Fn s = sphere();
  const Fn d2 = square(s[0] - p[0]) + square(s[1] - p[1]) + square(s[2] - p[2]);
  const int unknowns[] = {1, 2};
  const Box box = {Interval(0.0, 1.0), Interval(0.0, 1.0)};
  MinimizeOptions opt;
  opt.epsilon = 1e-5;
  opt.delta = 1e-8;
  const MinimizeResult r = minimize(d2, Fn(1.0), unknowns, box, opt);
  EXPECT_EQ(r.report.limit, LimitHit::None);
  EXPECT_TRUE(r.feasible_found);
  // N = S_u x S_v is the outward normal of this parameterization (checked: N . S > 0).
  const Fn normal = cross(derivative(s, 1), derivative(s, 2));
  const std::vector<double> coords = {0.0, r.best_point[0], r.best_point[1]};
  const std::vector<double> sm = evaluate(s, coords), n = evaluate(normal, coords);
  EXPECT_GT(n[0] * sm[0] + n[1] * sm[1] + n[2] * sm[2], 0.0);
  return {n[0] * (sm[0] - p[0]) + n[1] * (sm[1] - p[1]) + n[2] * (sm[2] - p[2]), r.minimum};
}

TEST(MinimizerGeometry, Claim24PointClassificationByMinimization) {
  const double inside[3] = {0.1, 0.2, 0.3}, outside[3] = {1.5, 0.0, 0.0};
  const Classification a = classify(inside), b = classify(outside);
  EXPECT_GT(a.sign, 0.0);
  EXPECT_LT(b.sign, 0.0);
  // The minimum squared distances are (1 - |p|)^2.
  const double r_in = 1.0 - std::sqrt(0.14);
  EXPECT_TRUE(a.distance2.contains(r_in * r_in)) << a.distance2;
  EXPECT_TRUE(b.distance2.contains(0.25)) << b.distance2;
}

}  // namespace
}  // namespace genmod
