// CPG (snyder.md 7.17, 7.19): Boolean operations on planar regions by their boundary curves.
#include "genmod/solvers/cpg.hpp"

#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/curve.hpp"
#include "operators/operator_properties.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod {
namespace {

constexpr double kPi = std::numbers::pi;
using P = std::array<double, 2>;

Fn circle(double cx, double cy, double radius, double phase = 0.0) {
  const Fn t = phase + 2.0 * kPi * x(0);
  return cat({cx + radius * cos(t), cy + radius * sin(t)});
}

std::vector<P> samples(const Fn& f, int n) {
  Tape tape(f);
  PointEvaluator ev;
  std::vector<P> out;
  for (int i = 0; i <= n; ++i) {
    const double u = static_cast<double>(i) / n;
    const auto y = ev.eval(tape, {u});
    out.push_back({y[0], y[1]});
  }
  return out;
}

double area(const std::vector<P>& p) {
  double s = 0.0;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) s += p[i][0] * p[i + 1][1] - p[i + 1][0] * p[i][1];
  return s / 2.0;
}

CpgOptions filleted(double r) {
  CpgOptions o;
  o.fillet_radius = r;
  return o;
}

double dist(P p, double cx, double cy) { return std::hypot(p[0] - cx, p[1] - cy); }

// Unit circles at (0, 0) and (1, 0): lens area 2 acos(1/2) - (1/2) sqrt(3).
const double kLens = 2.0 * std::acos(0.5) - 0.5 * std::sqrt(3.0);

void expect_closed_and_continuous(const std::vector<P>& p, double max_step) {
  EXPECT_LT(std::hypot(p.front()[0] - p.back()[0], p.front()[1] - p.back()[1]), 1e-7);
  for (std::size_t i = 0; i + 1 < p.size(); ++i)
    ASSERT_LT(std::hypot(p[i + 1][0] - p[i][0], p[i + 1][1] - p[i][1]), max_step) << i;
}

TEST(Cpg, TwoCirclesUnionIntersectionDifference) {
  const Fn a = circle(0, 0, 1), b = circle(1, 0, 1, 0.3);
  struct Case {
    RegionOp op;
    double area;
  };
  for (const Case& c : {Case{RegionOp::Union, 2 * kPi - kLens}, Case{RegionOp::Intersection, kLens},
                        Case{RegionOp::Difference, kPi - kLens}}) {
    const Fn r = region_boolean(a, b, c.op);
    EXPECT_EQ(r.inputs(), std::vector<int>{0});
    const auto p = samples(r, 20000);
    expect_closed_and_continuous(p, 1e-3);
    EXPECT_NEAR(area(p), c.area, 1e-4) << static_cast<int>(c.op);
    for (const P& q : p) {
      const double da = dist(q, 0, 0) - 1, db = dist(q, 1, 0) - 1;  // signed: > 0 outside
      const bool on_a = std::abs(da) < 1e-7, on_b = std::abs(db) < 1e-7;
      ASSERT_TRUE(on_a || on_b) << q[0] << " " << q[1];
      if (c.op == RegionOp::Union) {
        ASSERT_TRUE((on_a && db > -1e-7) || (on_b && da > -1e-7));
      }
      if (c.op == RegionOp::Intersection) {
        ASSERT_TRUE((on_a && db < 1e-7) || (on_b && da < 1e-7));
      }
      if (c.op == RegionOp::Difference) {
        ASSERT_TRUE((on_a && db > -1e-7) || (on_b && da < 1e-7));
      }
    }
  }
}

TEST(Cpg, FilletedUnionAndIntersectionAreG1ArcsOfRadiusR) {
  const Fn a = circle(0, 0, 1), b = circle(1, 0, 1, 0.3);
  const double r = 0.1;
  for (RegionOp op : {RegionOp::Union, RegionOp::Intersection}) {
    const bool uni = op == RegionOp::Union;
    const Fn sharp = region_boolean(a, b, op);
    const Fn f = region_boolean(a, b, op, filleted(r));
    const auto p = samples(f, 20000);
    expect_closed_and_continuous(p, 1e-3);
    // The fillet centers: at distance 1 + r (union, outside both) or 1 - r (inside both).
    const double h = std::sqrt(std::pow(uni ? 1 + r : 1 - r, 2) - 0.25);
    const auto s = samples(sharp, 4000);
    int on_fillet = 0;
    for (const P& q : p) {
      const bool on_a = std::abs(dist(q, 0, 0) - 1) < 1e-7, on_b = std::abs(dist(q, 1, 0) - 1) < 1e-7;
      const bool arc = std::abs(dist(q, 0.5, h) - r) < 1e-7 || std::abs(dist(q, 0.5, -h) - r) < 1e-7;
      ASSERT_TRUE(on_a || on_b || arc) << q[0] << " " << q[1];
      on_fillet += arc && !on_a && !on_b;
      double near = 1e300;  // within r of the sharp result
      for (const P& t : s) near = std::min(near, std::hypot(q[0] - t[0], q[1] - t[1]));
      ASSERT_LT(near, r);
    }
    EXPECT_GT(on_fillet, 20);
    // An ordinary Fn: inclusions hold its samples, batch = scalar (G1 only: no derivative check).
    testing::PropertySpec spec;
    spec.domain = {Interval(0, 1)};
    spec.boxes = 60;
    spec.check_derivative = false;
    testing::check_operator_properties(f, spec, 401);
    // G1: the unit tangent turns continuously (no jump larger than the curvature allows).
    for (std::size_t i = 1; i + 1 < p.size(); ++i) {
      const double ax = p[i][0] - p[i - 1][0], ay = p[i][1] - p[i - 1][1];
      const double bx = p[i + 1][0] - p[i][0], by = p[i + 1][1] - p[i][1];
      const double turn = std::atan2(ax * by - ay * bx, ax * bx + ay * by);
      ASSERT_LT(std::abs(turn), 0.05) << i << " at " << p[i][0] << " " << p[i][1];
    }
    const double sharp_area = uni ? 2 * kPi - kLens : kLens;
    if (uni) EXPECT_GT(area(p), sharp_area); else EXPECT_LT(area(p), sharp_area);
  }
}

TEST(Cpg, PolygonWithCircle) {
  const Curve square = Curve::polyline({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}});
  const Fn a = square(x(0));
  const Fn b = circle(1, 1, 1, 0.2);  // quarter of the disk inside the square
  EXPECT_NEAR(area(samples(region_boolean(a, b, RegionOp::Intersection), 40000)), kPi / 4, 1e-4);
  EXPECT_NEAR(area(samples(region_boolean(a, b, RegionOp::Union), 40000)), 4 + 3 * kPi / 4, 1e-4);
  EXPECT_NEAR(area(samples(region_boolean(a, b, RegionOp::Difference), 40000)), 4 - kPi / 4, 1e-4);
  EXPECT_NEAR(area(samples(region_boolean(b, a, RegionOp::Difference), 40000)), 3 * kPi / 4, 1e-4);
}

std::string message(const Fn& a, const Fn& b, RegionOp op, CpgOptions o = {}) {
  try {
    region_boolean(a, b, op, o);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no exception";
}

TEST(Cpg, ErrorsAreNamed) {
  const Fn a = circle(0, 0, 1);
  auto has = [](const std::string& m, const char* what) {
    EXPECT_NE(m.find(what), std::string::npos) << m;
  };
  has(message(a, cat({x(0), x(0), x(0)}), RegionOp::Union), "not planar");
  has(message(a, cat({x(0), square(x(0))}), RegionOp::Union), "not closed");
  has(message(a, circle(0.5, 0, 1, 0) * cat({Fn(1.0), Fn(-1.0)}), RegionOp::Union), "not counter-clockwise");
  has(message(a, circle(3, 0, 1), RegionOp::Union), "do not intersect");
  has(message(a, circle(0, 0, 0.5), RegionOp::Union), "do not intersect");
  has(message(a, circle(2, 0, 1, 0.4), RegionOp::Union), "not certified");
  has(message(a, circle(1, 0, 1), RegionOp::Union, filleted(-1)), "fillet radius");
  // Two crossing ellipses: a minus b falls apart into two lobes.
  const Fn e1 = cat({2.0 * cos(2 * kPi * x(0) + 0.1), 0.5 * sin(2 * kPi * x(0) + 0.1)});
  const Fn e2 = cat({0.5 * cos(2 * kPi * x(0) + 0.2), 2.0 * sin(2 * kPi * x(0) + 0.2)});
  has(message(e1, e2, RegionOp::Difference), "2 boundary loops");
  // Each ellipse has area pi: union + intersection = 2 pi.
  EXPECT_NEAR(area(samples(region_boolean(e1, e2, RegionOp::Union), 40000)) +
                  area(samples(region_boolean(e1, e2, RegionOp::Intersection), 40000)),
              2 * kPi, 1e-4);
  has(message(a, circle(1, 0, 1), RegionOp::Union, filleted(5)), "fillet");
}

}  // namespace
}  // namespace genmod
