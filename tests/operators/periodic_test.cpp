// periodic(c, parm, s) (periodic.hpp): a closed curve continued periodically, with enclosures
// that stay tight across the seam (the reason it is one operator).
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/operators/curve_file.hpp"
#include "genmod/operators/periodic.hpp"
#include "operators/operator_properties.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

namespace genmod {
namespace {

constexpr double kTurn = 2.0 * std::numbers::pi;

// A closed, C^2 periodic cubic B-spline (an oval; the first three points repeated).
Fn oval() {
  std::istringstream in(
      "crv 1\ntype bspline\ndimension 2\ndegree 3\nclamped no\n"
      "point -0.45 0\npoint -0.32 -0.26\npoint 0 -0.3\npoint 0.32 -0.26\npoint 0.45 0\n"
      "point 0.32 0.26\npoint 0 0.3\npoint -0.32 0.26\npoint -0.45 0\npoint -0.32 -0.26\npoint 0 -0.3\n");
  return read_curve(in)(x(0));
}

TEST(Periodic, PointValuesRepeatTheCurve) {
  const Fn c = oval();
  const Fn p = periodic(c, 0, x(1));
  PointEvaluator ev;
  const Tape curve(c, std::vector<int>{0}), wrapped(p, std::vector<int>{1});
  for (double t : {0.0, 0.125, 0.4375, 0.75, 0.9990234375}) {  // k + t is exact
    const std::span<const double> at = ev.eval(curve, {t});
    const std::vector<double> want(at.begin(), at.end());
    for (double k : {-3.0, -1.0, 0.0, 1.0, 2.0}) {
      const std::span<const double> got = ev.eval(wrapped, {k + t});
      EXPECT_EQ(got[0], want[0]) << k + t;
      EXPECT_EQ(got[1], want[1]) << k + t;
    }
  }
  EXPECT_TRUE(std::isnan(ev.eval(wrapped, {INFINITY})[0]));
}

TEST(Periodic, ContainmentDerivativesAndBatch) {
  testing::PropertySpec spec;
  spec.domain = {Interval(-1.5, 2.5)};
  spec.breaks.emplace_back();
  for (int k = -12; k <= 20; ++k) spec.breaks[0].push_back(k / 8.0);  // the oval's knots
  testing::check_operator_properties(periodic(oval(), 0, x(0)), spec, 3);
  const Fn circle = cat({cos(kTurn * x(0)), sin(kTurn * x(0))});
  testing::check_operator_properties(periodic(circle, 0, 0.5 * x(0) - 0.25), spec, 5);
}

// Across the seam, the enclosures of the value and of the derivatives shrink with the box. With
// the curve wrapped by clamps and a select (below), the second derivative of the squared
// distance to a point near the seam keeps 0 however small the box: a minimum there is never
// proved unique.
TEST(Periodic, EnclosuresShrinkAcrossTheSeam) {
  const Fn c = oval();
  const Fn point = cat({Fn(-0.6), Fn(0.01)});  // closest to the oval near c(0) = c(1)
  auto squared_distance = [&](const Fn& q) { return square(q[0] - point[0]) + square(q[1] - point[1]); };
  auto clamped = [](const Fn& t) { return min(max(t, Fn(0.0)), Fn(1.0)); };
  const Fn s = x(1);
  const Fn by_select = select(s > 1.0, compose(c, 0, clamped(s - 1.0)), compose(c, 0, clamped(s)));
  const Fn by_periodic = periodic(c, 0, s);
  IntervalEvaluator ev;
  for (const Fn& f : {by_periodic, by_select}) {
    const Fn fss = derivative(derivative(squared_distance(f), 1), 1);
    const Tape tape(fss, std::vector<int>{1});
    const bool periodic_form = identical(f, by_periodic);
    for (double h : {1e-2, 1e-4, 1e-6}) {
      const Interval e = ev.eval(tape, {Interval(1.0 - h, 1.0 + h)})[0];
      if (periodic_form) {
        EXPECT_GT(e.lo(), 0.0) << h;  // convex: one minimum
        EXPECT_LT(e.width(), 1e3 * h) << h;
      } else {
        EXPECT_LE(e.lo(), 0.0) << h;  // what the operator is for
      }
    }
  }
  // The value's enclosure over a straddling box is as wide as the curve's over the two pieces.
  const Tape value(by_periodic, std::vector<int>{1});
  const Interval v = ev.eval(value, {Interval(1.0 - 1e-6, 1.0 + 1e-6)})[0];
  EXPECT_LT(v.width(), 1e-5);
  // The B-spline's ends evaluate to the same doubles: continuous across the seam. A circle
  // with 2 pi rounded ends 2.4e-16 from its start: a jump there, continuous inside a period.
  EXPECT_TRUE(ev.continuous());
  const Fn circle = cat({cos(kTurn * x(0)), sin(kTurn * x(0))});
  const Tape around(periodic(circle, 0, x(1)), std::vector<int>{1});
  ev.eval(around, {Interval(0.9, 1.1)});
  EXPECT_FALSE(ev.continuous());
  ev.eval(around, {Interval(1.1, 1.9)});
  EXPECT_TRUE(ev.continuous());
}

TEST(Periodic, BadCurvesAreRefused) {
  EXPECT_TRUE(is_closed_curve(oval(), 0));
  EXPECT_FALSE(is_closed_curve(oval(), 1));                       // depends on x(0), not x(1)
  EXPECT_FALSE(is_closed_curve(cat({x(0), x(0) * x(0)}), 0));    // open
  EXPECT_FALSE(is_closed_curve(cat({x(0), x(1)}), 0));           // another coordinate
  testing::expect_throw_naming([] { periodic(cat({x(0), x(0) * x(0)}), 0, x(1)); }, "periodic");  // open
  testing::expect_throw_naming([] { periodic(cat({cos(kTurn * x(0)), x(2)}), 0, x(1)); }, "periodic");
  testing::expect_throw_naming([] { periodic(Fn(1.0), 0, x(1)); }, "periodic");
  testing::expect_throw_naming([] { periodic(cat({cos(kTurn * x(0)), sin(kTurn * x(0))}), 0, cat({x(1), x(2)})); },
                               "periodic");
}

}  // namespace
}  // namespace genmod
