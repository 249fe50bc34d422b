// Offsets (snyder.md sections 7.13-7.15): claim 30 (the unit circle offset by 0.25 is the
// circle of radius 0.75, erratum E5), offset product distances, closed offsets with end caps,
// the two-point arc with a sagitta (including its straight-chord limit), the shared properties
// and dimension errors.
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/curve.hpp"
#include "genmod/operators/offset.hpp"
#include "genmod/operators/vector.hpp"
#include "operators/operator_properties.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod {
namespace {

using testing::check_operator_properties;
using testing::unit_domain;

constexpr double kPi = std::numbers::pi;
const Fn u = x(0), v = x(1);

Fn circle(const Fn& t, double radius = 1.0) { return cat({radius * cos(2.0 * kPi * t), radius * sin(2.0 * kPi * t)}); }

std::vector<double> at(const Fn& f, std::vector<double> p) { return evaluate(f, p); }

double square_sum(double a, double b) { return a * a + b * b; }

// Shoelace area of the closed curve f(x(0)) (other coordinates fixed by `rest`).
double shoelace(const Fn& f, std::vector<double> rest = {}, int n = 4000) {
  double area = 0.0;
  std::vector<double> p(1 + rest.size());
  std::copy(rest.begin(), rest.end(), p.begin() + 1);
  p[0] = 0.0;
  std::vector<double> prev = evaluate(f, p);
  for (int i = 1; i <= n; ++i) {
    p[0] = double(i) / n;
    const std::vector<double> cur = evaluate(f, p);
    area += prev[0] * cur[1] - cur[0] * prev[1];
    prev = cur;
  }
  return 0.5 * area;
}

TEST(Offset, Normal2dIsTheLeftNormal) {
  const auto n = at(normal2d(cat({3.0 * u, 0.0 * u + 1.0})), {0.4});
  EXPECT_DOUBLE_EQ(n[0], 0.0);
  EXPECT_DOUBLE_EQ(n[1], 3.0);
  const auto m = at(normal2d(cat({v, u * v}), 1), {2.0, 0.5});  // derivative (1, 2)
  EXPECT_DOUBLE_EQ(m[0], -2.0);
  EXPECT_DOUBLE_EQ(m[1], 1.0);
}

TEST(Offset, PositiveRadiusMovesCounterClockwiseCircleInward) {  // claim 30, erratum E5
  const Fn off = offset_curve(circle(u), 0.25);
  for (int i = 0; i <= 16; ++i) {
    const double t = i / 16.0;
    const auto p = at(off, {t});
    EXPECT_NEAR(std::hypot(p[0], p[1]), 0.75, 1e-15);
    EXPECT_NEAR(std::atan2(p[1], p[0]), std::atan2(std::sin(2 * kPi * t), std::cos(2 * kPi * t)), 1e-14);
  }
  // Negative radius: outward.
  EXPECT_NEAR(at(length(offset_curve(circle(u), -0.25)), {0.3})[0], 1.25, 1e-15);
  check_operator_properties(off, unit_domain(1), 301);
}

TEST(Offset, VariableRadiusKeepsDistanceAlongTheNormal) {
  const Fn c = cat({u + 0.3 * sin(3.0 * u), 0.5 * square(u)});
  const Fn r = 0.05 + 0.1 * v;
  const Fn off = offset_curve(c, r);
  const Fn tangent = derivative(c, 0);
  for (double a : {0.0, 0.2, 0.55, 0.9, 1.0})
    for (double b : {0.0, 0.5, 1.0}) {
      const auto p = at(off, {a, b}), q = at(c, {a, b}), t = at(tangent, {a, b});
      const double dx = p[0] - q[0], dy = p[1] - q[1];
      EXPECT_NEAR(std::hypot(dx, dy), 0.05 + 0.1 * b, 1e-15);
      EXPECT_NEAR(dx * t[0] + dy * t[1], 0.0, 1e-15);
      EXPECT_GT(t[0] * dy - t[1] * dx, 0.0);  // on the left
    }
  check_operator_properties(off, unit_domain(2), 302);
}

TEST(Offset, ErrorWhereTheSpeedVanishes) {
  const Fn off = offset_curve(cat({square(u - 0.5), 0.0 * u}), 0.1);
  EXPECT_TRUE(std::isnan(at(off, {0.5})[0]));
  EXPECT_FALSE(std::isnan(at(off, {0.25})[0]));
}

TEST(Offset, ProductOffsetsTheCrossSectionByTheProfile) {  // section 7.14 invariant
  const Fn cross = cat({0.8 * cos(2.0 * kPi * u), 0.5 * sin(2.0 * kPi * u)});  // ellipse, min radius of curvature 0.3125
  const double rho = 0.1;
  const Fn profile = cat({-rho + rho * cos(kPi * v - kPi / 2), rho * sin(kPi * v - kPi / 2)});
  const Fn s = offset_product(cross, profile);
  ASSERT_EQ(s.dim(), 3U);
  // Distance from S_xy to the cross section = |d1(v)|: check against a dense sample.
  std::vector<std::vector<double>> pts;
  for (int i = 0; i < 20000; ++i) pts.push_back(at(cross, {i / 20000.0}));
  for (double a : {0.0, 0.13, 0.4, 0.77})
    for (double b : {0.0, 0.3, 0.5, 0.8}) {
      const auto p = at(s, {a, b}), d = at(profile, {a, b});
      double best = 1e9;
      for (const auto& q : pts) best = std::min(best, std::hypot(p[0] - q[0], p[1] - q[1]));
      EXPECT_NEAR(best, std::abs(d[0]), 2e-5);
      EXPECT_DOUBLE_EQ(p[2], d[1]);
      // d1 <= 0 moves the counter-clockwise ellipse outward (to the right of travel).
      EXPECT_GE(square_sum(p[0] / 0.8, p[1] / 0.5), 1.0 - 1e-15);
    }
  check_operator_properties(s, unit_domain(2), 303);
}

// The Curve form of the offset product is the same surface as the Fn form, and over boxes
// that straddle a double knot of a tangent-continuous section (a rounded rectangle: lines and
// quarter circles) its enclosures shrink with the box, where the Fn form's normal
// normalize(normal2d(c)) stays as wide as the jump of the speed.
TEST(Offset, ProductOfACurveIsBoundedAcrossItsKnots) {
  const double w = std::sqrt(0.5);
  // The quarter of a rounded square from the middle of its bottom side to the middle of its
  // right side: line, corner (radius 0.5), line; double knots at 0.3 and 0.7.
  const Curve corner = Curve::nurbs({{0, -1}, {0.25, -1}, {0.5, -1}, {1, -1}, {1, -0.5}, {1, -0.25}, {1, 0}},
                                    {1, 1, 1, w, 1, 1, 1}, 2, {0, 0, 0, 0.3, 0.3, 0.7, 0.7, 1, 1, 1});
  const Fn profile = cat({0.1 * v, v});
  const Fn by_curve = offset_product(corner, u, profile), by_fn = offset_product(corner(u), profile);
  for (double a : {0.0, 0.1, 0.3, 0.45, 0.7, 0.9, 1.0})
    for (double b : {0.0, 0.5, 1.0}) {
      const auto p = at(by_curve, {a, b}), q = at(by_fn, {a, b});
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[k], q[k], 1e-15) << a << ", " << b;
    }
  // On the top edge (d1 = 0.1) across the first knot: the Curve form's width shrinks with
  // the box; the Fn form's stays about 0.1 times the spread of its normal (the speeds 5/3 on
  // the line and about 1.6 .. 2.3 on the arc make normalize(c') wide even though c' no longer
  // encloses 0).
  IntervalEvaluator iv;
  const Tape curve_tape(by_curve), fn_tape(by_fn);
  for (double h : {1e-3, 1e-6}) {
    const std::vector<Interval> box{Interval(0.3 - h, 0.3 + h), Interval(1.0)};
    const auto s = iv.eval(curve_tape, box);
    for (int k = 0; k < 2; ++k) EXPECT_LT(s[k].width(), 50.0 * h) << h;
  }
  const auto wide = iv.eval(fn_tape, {Interval(0.3 - 1e-6, 0.3 + 1e-6), Interval(1.0)});
  EXPECT_GT(wide[1].width(), 1e-3);
  check_operator_properties(by_curve, unit_domain(2), 304);
  testing::expect_throw_naming([&] { offset_product(Curve::polyline({{0, 0, 0}, {1, 1, 1}}), u, profile); },
                               "offset_product");
}

TEST(Offset, ClosedOffsetOfASegmentIsAStadium) {
  const Fn seg = cat({2.0 * u - 1.0, 0.0 * u});
  const double r = 0.2;
  const Fn c = closed_offset(seg, r);
  for (int i = 0; i <= 400; ++i) {
    const auto p = at(c, {i / 400.0});
    const double dx = std::max(std::abs(p[0]) - 1.0, 0.0);
    EXPECT_NEAR(std::hypot(dx, p[1]), r, 1e-15) << i;
  }
  // Counter-clockwise (positive area) and the stadium's area.
  EXPECT_NEAR(shoelace(c), 2.0 * 2.0 * r + kPi * r * r, 1e-4);
  // The quarters: right side forward, cap at c(1), left side backward, cap at c(0).
  auto near = [](const std::vector<double>& p, double a, double b) { return std::hypot(p[0] - a, p[1] - b) < 1e-14; };
  EXPECT_TRUE(near(at(c, {0.0}), -1.0, -r));
  EXPECT_TRUE(near(at(c, {0.125}), 0.0, -r));
  EXPECT_TRUE(near(at(c, {0.375}), 1.0 + r, 0.0));
  EXPECT_TRUE(near(at(c, {0.625}), 0.0, r));
  EXPECT_TRUE(near(at(c, {0.875}), -1.0 - r, 0.0));
  EXPECT_TRUE(near(at(c, {1.0}), -1.0, -r));
  testing::PropertySpec spec = unit_domain(1);
  spec.breaks = {{0.25, 0.5, 0.75}};
  check_operator_properties(c, spec, 304);
}

TEST(Offset, ClosedOffsetWithSweptRadiusIsContinuous) {
  const Fn arc = cat({cos(kPi * u), 0.5 * sin(kPi * u)});  // half ellipse, curvature radius >= 0.25
  const Fn r = 0.05 + 0.15 * v;                             // the thickness varies along the sweep
  const Fn c = closed_offset(arc, r);
  EXPECT_EQ(c.inputs(), (std::vector<int>{0, 1}));
  for (double b : {0.0, 0.4, 1.0}) {
    for (double joint : {0.25, 0.5, 0.75}) {
      const auto lo = at(c, {joint - 1e-9, b}), hi = at(c, {joint + 1e-9, b});
      EXPECT_NEAR(lo[0], hi[0], 1e-7);  // speed < 10, step 2e-9
      EXPECT_NEAR(lo[1], hi[1], 1e-7);
    }
    const auto first = at(c, {0.0, b}), last = at(c, {1.0, b});
    EXPECT_NEAR(first[0], last[0], 1e-15);
    EXPECT_NEAR(first[1], last[1], 1e-15);
    EXPECT_GT(shoelace(c, {b}), 0.0);
    // Every point is at distance r from the curve (dense sample of the curve).
    std::vector<std::vector<double>> pts;
    for (int i = 0; i <= 8000; ++i) pts.push_back(at(arc, {i / 8000.0}));
    for (int i = 0; i <= 40; ++i) {
      const auto p = at(c, {i / 40.0, b});
      double best = 1e9;
      for (const auto& q : pts) best = std::min(best, std::hypot(p[0] - q[0], p[1] - q[1]));
      EXPECT_NEAR(best, 0.05 + 0.15 * b, 1e-6) << i;
    }
  }
  testing::PropertySpec spec = unit_domain(2);
  spec.breaks = {{0.25, 0.5, 0.75}, {}};
  check_operator_properties(c, spec, 305);
}

TEST(Arc, SemicircleAtConstantAngularSpeed) {
  const Fn a = arc_2pt_height(cat({-1.0, 0.0}), cat({1.0, 0.0}), 1.0, u);
  for (int i = 0; i <= 20; ++i) {
    const double t = i / 20.0;
    const auto p = at(a, {t});
    // The midpoint is to the LEFT of the chord (-1,0) -> (1,0), i.e. y > 0: clockwise from angle pi to 0.
    EXPECT_NEAR(p[0], std::cos(kPi * (1 - t)), 1e-15) << t;
    EXPECT_NEAR(p[1], std::sin(kPi * (1 - t)), 1e-15) << t;
  }
}

TEST(Arc, EndpointsSagittaAndRadius) {
  const Fn p1 = cat({0.3, -0.2}), p2 = cat({1.1, 0.4});  // chord 1.0
  for (double h : {-0.5, -0.3, -1e-3, 1e-7, 0.2, 0.5, 0.9}) {
    const Fn a = arc_2pt_height(p1, p2, h, u);
    const auto s = at(a, {0.0}), e = at(a, {1.0}), m = at(a, {0.5});
    EXPECT_NEAR(s[0], 0.3, 1e-15);
    EXPECT_NEAR(s[1], -0.2, 1e-15);
    EXPECT_NEAR(e[0], 1.1, 1e-15);
    EXPECT_NEAR(e[1], 0.4, 1e-15);
    // Midpoint = chord midpoint + h * left unit normal (-0.6, 0.8).
    EXPECT_NEAR(m[0], 0.7 - 0.6 * h, 1e-15);
    EXPECT_NEAR(m[1], 0.1 + 0.8 * h, 1e-15);
    // All points on the circle through the three; radius (a^2 + h^2) / (2h).
    const double R = (0.25 + h * h) / (2 * h);
    const double cx = 0.7 - 0.6 * (h - R), cy = 0.1 + 0.8 * (h - R);
    double prev_angle = 0.0;
    for (int i = 0; i <= 10; ++i) {
      const auto p = at(a, {i / 10.0});
      EXPECT_NEAR(std::hypot(p[0] - cx, p[1] - cy), std::abs(R), 1e-12 * std::max(1.0, std::abs(R)));
      if (std::abs(h) > 1e-2) {  // constant angular speed: equal angle steps
        const double ang = std::atan2(p[1] - cy, p[0] - cx);
        if (i > 0) {
          const double step = std::remainder(ang - prev_angle, 2 * kPi);
          EXPECT_NEAR(step, -4 * std::atan(h / 0.5) / 10, 1e-13);
        }
        prev_angle = ang;
      }
    }
  }
}

TEST(Arc, ZeroHeightIsTheChordWithSmoothDerivatives) {
  const Fn h = x(1);
  const Fn a = arc_2pt_height(cat({0.0, 0.0}), cat({2.0, 0.0}), h, u);
  const Fn dh = derivative(a, 1), dt = derivative(a, 0);
  for (double t : {0.0, 0.1, 0.5, 0.77, 1.0}) {
    const auto p = at(a, {t, 0.0});
    EXPECT_NEAR(p[0], 2 * t, 1e-15);
    EXPECT_EQ(p[1], 0.0);
    // d/dh at h = 0: the parabola of sagitta h, 4 t (1 - t) along the left normal (0, 1).
    const auto d = at(dh, {t, 0.0});
    EXPECT_NEAR(d[0], 0.0, 1e-15);
    EXPECT_NEAR(d[1], 4 * t * (1 - t), 1e-14);
    const auto s = at(dt, {t, 0.0});
    EXPECT_NEAR(s[0], 2.0, 1e-14);
    EXPECT_NEAR(s[1], 0.0, 1e-14);
    // Both signs of h give mirror images (and small h the chord's limit, smoothly).
    for (double eps : {1e-3, 0.02, 0.0499, 0.0501, 0.2}) {
      const auto lo = at(a, {t, -eps}), hi = at(a, {t, eps});
      EXPECT_NEAR(lo[1], -hi[1], 1e-15);
      EXPECT_NEAR(lo[0], hi[0], 1e-15);
      const auto dlo = at(dh, {t, -eps}), dhi = at(dh, {t, eps});
      EXPECT_NEAR(dlo[1], dhi[1], 1e-13);
    }
  }
  testing::PropertySpec spec;
  spec.domain = {Interval(0.0, 1.0), Interval(-1.0, 1.0)};
  check_operator_properties(a, spec, 306);
  // Moving end points (functions) too.
  const Fn b = arc_2pt_height(cat({-v, 0.2 * v}), cat({v, 0.0}), 0.4 * v - 0.2, u);
  testing::PropertySpec spec2 = unit_domain(2);
  spec2.domain[1] = Interval(0.2, 1.0);
  check_operator_properties(b, spec2, 307);
}

// The arc's enclosures stay tight where its turning angle is small: over every cell of a
// 64 x 64 grid of (t, height) boxes around height 0 the unit normal (the tangent normalized,
// so a tangent enclosure straddling 0 makes it unbounded) has a finite enclosure of width
// below 0.2 (about twice the normal's true turn over a cell). The quotient form of sin(z)/z
// used to give 104 unbounded cells here (its derivative cancels for small z) and widths up
// to 4.5e3.
TEST(Arc, UnitNormalEnclosureIsTightNearZeroHeight) {
  const Fn a = arc_2pt_height(cat({-1.0, 0.0}), cat({1.0, 0.0}), v, u);
  const Tape tape(normalize(normal2d(a, 0)), std::vector<int>{0, 1});
  IntervalEvaluator ev;
  constexpr int kCells = 64;
  double widest = 0.0;
  for (int i = 0; i < kCells; ++i)
    for (int j = 0; j < kCells; ++j) {
      const Interval t(double(i) / kCells, double(i + 1) / kCells);
      const Interval h(-0.5 + double(j) / kCells, -0.5 + double(j + 1) / kCells);
      const auto n = ev.eval(tape, {t, h});
      for (const Interval& c : n) {
        ASSERT_TRUE(c.is_bounded()) << "t " << t << " height " << h;
        widest = std::max(widest, c.width());
      }
    }
  EXPECT_LT(widest, 0.2);
}

// Containment by dense sampling, for the arc and its first and second derivatives in t and
// its derivative in the height, over random boxes: small and large boxes around height 0
// (the straight chord), and boxes around the switch of sin(z)/z from its series to the
// quotient (a half turning angle of 3 radians: height = tan(1.5) for the half chord 1).
TEST(Arc, EnclosuresContainDenseSamplesNearZeroHeightAndTheSwitch) {
  const Fn a = arc_2pt_height(cat({-1.0, 0.0}), cat({1.0, 0.0}), v, u);
  const Fn at1 = derivative(a, 0), at2 = derivative(at1, 0), ah = derivative(a, 1);
  const Fn all = cat({a, at1, at2, ah});
  const std::vector<int> uv{0, 1};
  const Tape tape(all, uv);
  IntervalEvaluator iv;
  PointEvaluator pv;
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double h_switch = std::tan(1.5);
  int boxes = 0;
  for (const double centre : {0.0, 1e-9, -3e-4, 0.05, h_switch, -h_switch})
    for (int k = 0; k < 60; ++k) {
      const double hw = std::pow(10.0, -8.0 + 7.5 * unit(rng)) * std::max(1.0, std::abs(centre));
      const double h0 = centre + hw * (2.0 * unit(rng) - 1.0);
      const double tw = std::pow(10.0, -6.0 + 6.0 * unit(rng));
      const double t0 = unit(rng) * (1.0 - tw);
      const Interval t(t0, t0 + tw), h(h0 - hw, h0 + hw);
      const auto enc = iv.eval(tape, {t, h});
      const std::vector<Interval> box(enc.begin(), enc.end());
      // Bounded near the chord (a wide box near a full circle may enclose sinc(alpha) = 0).
      if (std::abs(centre) < 1.0)
        for (const Interval& b : box) ASSERT_TRUE(b.is_bounded()) << "t " << t << " height " << h;
      for (int i = 0; i <= 12; ++i)
        for (int j = 0; j <= 12; ++j) {
          const double tp = t.lo() + (t.hi() - t.lo()) * i / 12.0, hp = h.lo() + (h.hi() - h.lo()) * j / 12.0;
          const auto y = pv.eval(tape, {tp, hp});
          for (std::size_t c = 0; c < y.size(); ++c)
            ASSERT_TRUE(box[c].contains(y[c]))
                << "output " << c << " = " << y[c] << " outside " << box[c] << " at t " << tp << ", height " << hp;
        }
      ++boxes;
    }
  EXPECT_EQ(boxes, 360);
}

// No jump where sin(z)/z switches from the series to the quotient (half turning angle 3).
TEST(Arc, ContinuousAcrossTheSeriesSwitch) {
  const Fn a = arc_2pt_height(cat({-1.0, 0.0}), cat({1.0, 0.0}), v, u);
  const Fn at1 = derivative(a, 0);
  const double h = std::tan(1.5);
  for (double t : {0.0, 0.3, 0.5, 0.9}) {
    const auto lo = evaluate(a, {t, h * (1 - 1e-12)}), hi = evaluate(a, {t, h * (1 + 1e-12)});
    const auto dlo = evaluate(at1, {t, h * (1 - 1e-12)}), dhi = evaluate(at1, {t, h * (1 + 1e-12)});
    for (int j = 0; j < 2; ++j) {
      EXPECT_NEAR(lo[j], hi[j], 1e-10) << t;
      EXPECT_NEAR(dlo[j], dhi[j], 1e-9) << t;
    }
  }
  // The arc stays on its circle there: radius (1 + h^2) / (2h), centre (0, h - R).
  const double R = (1 + h * h) / (2 * h);
  for (double hh : {h * (1 - 1e-12), h * (1 + 1e-12)})
    for (double t : {0.1, 0.5, 0.8}) {
      const auto p = evaluate(a, {t, hh});
      // sinc(alpha) is about 0.047 here: its quotients amplify rounding errors.
      EXPECT_NEAR(std::hypot(p[0], p[1] - (h - R)), R, 1e-11 * R) << t;
    }
}

TEST(Offset, BadInputNamesTheOperator) {
  using testing::expect_throw_naming;
  expect_throw_naming([] { normal2d(cat({u, u, u})); }, "normal2d");
  expect_throw_naming([] { normal2d(cat({v, v}), 0); }, "normal2d");
  expect_throw_naming([] { offset_curve(circle(u), cat({0.1, 0.2})); }, "offset_curve");
  expect_throw_naming([] { offset_product(circle(u), x(1)); }, "offset_product");
  expect_throw_naming([] { closed_offset(cat({u, u, u}), 0.1); }, "closed_offset");
  expect_throw_naming([] { arc_2pt_height(cat({0.0, 0.0, 0.0}), cat({1.0, 0.0}), 0.1, u); }, "arc_2pt_height");
  expect_throw_naming([] { arc_2pt_height(cat({0.0, 0.0}), cat({1.0, 0.0}), 0.1, circle(u)); }, "arc_2pt_height");
}

}  // namespace
}  // namespace genmod
