// Parameter schedules (snyder.md 7.20-7.21): resample_by_curve (the bottle's
// m_resample_y_by_curve), match_schedule and warp_by_length (m_warp).
#include "genmod/solvers/schedule.hpp"

#include "genmod/kernel/point_evaluator.hpp"
#include "operators/operator_properties.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace genmod {
namespace {

using testing::check_operator_properties;

std::vector<double> at(const Fn& f, double u, double v) { return evaluate(f, std::vector<double>{u, v}); }

testing::PropertySpec spec_2d(Interval u, Interval v) {
  testing::PropertySpec spec;
  spec.domain = {u, v};
  spec.boxes = 40;
  spec.derivative_points = 10;
  return spec;
}

TEST(Schedule, ResampleByCurveMatchesTheComponent) {
  const Fn v = x(1);
  const Fn c1 = cat({square(v), 0.5 * (v * v * v + v)});  // y increasing in v
  const Fn c2 = cat({Fn(3.0), 0.8 * v});
  const Fn r = resample_by_curve(c1, c2, 1);
  EXPECT_EQ(r.inputs(), std::vector<int>{1});
  for (double t : {0.0, 0.2, 0.5, 0.77, 1.0}) {
    const auto p = at(r, 0.0, t);
    EXPECT_NEAR(p[1], 0.8 * t, 1e-10) << t;
    // Still a point of c1: x = s^2 where (s^3 + s) / 2 = y.
    const double s = std::sqrt(p[0]);
    EXPECT_NEAR(0.5 * (s * s * s + s), p[1], 1e-10) << t;
  }
  // Component 0 instead: c1's x matched to c2's x.
  const Fn r0 = resample_by_curve(c1, cat({0.25 * v, Fn(0.0)}), 1, 0);
  EXPECT_NEAR(at(r0, 0.0, 0.64)[0], 0.16, 1e-10);
  EXPECT_NEAR(at(r0, 0.0, 0.64)[1], 0.5 * (0.064 + 0.4), 1e-10);
  check_operator_properties(r, spec_2d(Interval(0, 1), Interval(0.05, 0.95)), 301);
}

TEST(Schedule, MatchScheduleEvaluatesWhereXEqualsTheSchedule) {  // 7.21
  const Fn v = x(1);
  const Fn radius = cat({square(v), 0.5 + 0.5 * v});  // (z, r), parameter v
  const Fn z = 0.2 + 0.6 * v;                         // the z translation schedule
  const Fn r = match_schedule(radius, z, 1);
  for (double t : {0.0, 0.3, 0.5, 1.0}) EXPECT_NEAR(at(r, 0.0, t)[0], 0.5 + 0.5 * std::sqrt(0.2 + 0.6 * t), 1e-10);
  // d r / d v = 0.5 * 0.6 / (2 sqrt(z)).
  const Fn dr = derivative(r, 1);
  EXPECT_NEAR(at(dr, 0.0, 0.5)[0], 0.15 / std::sqrt(0.5), 1e-8);
  check_operator_properties(r, spec_2d(Interval(0, 1), Interval(0, 1)), 302);
}

TEST(Schedule, WarpByLengthAddsAFunctionOfTheLength) {  // the bottle's m_warp
  const Fn u = x(0), v = x(1);
  const Fn w = cat({v, sin(v)});  // z = sin(distance), parameter v
  // m depends on the warp's parameter too: its length is matched at the outer point.
  const Fn m = cat({0.5 * u + 0.3 * v, Fn(0.2)});
  const Fn s = warp_by_length(m, w, 1);
  ASSERT_EQ(s.dim(), 3u);
  for (double a : {0.0, 0.4, 1.0})
    for (double b : {0.0, 0.5, 1.0}) {
      const auto p = at(s, a, b);
      const double len = std::hypot(0.5 * a + 0.3 * b, 0.2);
      EXPECT_NEAR(p[0], 0.5 * a + 0.3 * b, 1e-15);
      EXPECT_NEAR(p[1], 0.2, 1e-15);
      EXPECT_NEAR(p[2], std::sin(len), 1e-10) << a << " " << b;
    }
  check_operator_properties(s, spec_2d(Interval(0, 1), Interval(0, 1)), 303);
  // A length outside w's x range is not bracketed: the error condition.
  const Fn far = warp_by_length(cat({2.0 + u, Fn(0.0)}), w, 1);
  EXPECT_TRUE(std::isnan(at(far, 0.5, 0.5)[2]));
}

TEST(Schedule, BadInputIsNamed) {
  const Fn v = x(1);
  const Fn c = cat({v, square(v)});
  auto message = [](auto&& call) {
    try {
      call();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  EXPECT_NE(message([&] { resample_by_curve(c, c, 1, 2); }).find("resample_by_curve: component 2"), std::string::npos);
  EXPECT_NE(message([&] { resample_by_curve(c, c, 0); }).find("does not depend on x(0)"), std::string::npos);
  EXPECT_NE(message([&] { resample_by_curve(c, c, 70); }).find("outside"), std::string::npos);
  EXPECT_NE(message([&] { match_schedule(v, v, 1); }).find("match_schedule: the curve has dimension 1"),
            std::string::npos);
  EXPECT_NE(message([&] { match_schedule(c, c, 1); }).find("x1 has dimension 2"), std::string::npos);
  EXPECT_NE(message([&] { warp_by_length(c, v, 1); }).find("warp_by_length"), std::string::npos);
  EXPECT_NE(message([&] { resample_by_curve(c, c, 1, 1, Interval(1, 1)); }).find("resample_by_curve"),
            std::string::npos);
}

}  // namespace
}  // namespace genmod
