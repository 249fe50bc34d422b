// HC4 forward-backward contraction never removes a point that satisfies the constraint.
#include "genmod/solvers/contractor.hpp"

#include "genmod/kernel/point_evaluator.hpp"

#include <gtest/gtest.h>

#include <random>

namespace genmod {
namespace {

const int kU[] = {0, 1};

std::vector<Fn> constraints() {
  const Fn X = x(0), Y = x(1);
  return {
      eq(square(X) + square(Y), 1.0),
      square(X) + square(Y) < 1.0,
      eq(exp(X) - Y, 0.5) && (Y >= 0.2),
      eq(sqrt(X + 1.0) * Y, 0.3),
      eq(log(Y + 2.0) + abs(X), 1.0),
      (min(X, Y) > 0.1) || eq(max(X, 2.0 * Y), 0.5),
      !(X * Y > 0.2) && eq(X / (Y + 3.0) - 0.1 * Y, 0.05),
      eq(sin(X) + cos(Y) * X, 0.3),
      eq((3.0 - X) / (Y + 1.5), 1.2) || (X - Y <= -0.5),
      eq(square(X - 0.3) * (Y + 0.2), 0.01),
  };
}

TEST(Contractor, ShrinksCircleBox) {
  ConstraintSystem sys(eq(square(x(0)) + square(x(1)), 1.0), kU);
  Hc4Contractor hc4(sys);
  Box b = {Interval(0.9, 2.0), Interval(-0.1, 0.1)};
  ASSERT_TRUE(hc4.contract(b));
  EXPECT_LE(b[0].hi(), 1.0 + 1e-12);
  EXPECT_GE(b[0].lo(), 0.99 - 1e-12);
  Box none = {Interval(1.5, 2.0), Interval(1.5, 2.0)};
  EXPECT_FALSE(hc4.contract(none));
}

// Sampling: points where the constraint evaluates to 1 stay in the contracted box.
TEST(Contractor, NeverRemovesSolutionsSampled) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2, 2), w(0, 1.5);
  int kept = 0;
  for (const Fn& c : constraints()) {
    ConstraintSystem sys(c, kU);
    Hc4Contractor hc4(sys);
    for (std::size_t a = 0; a < sys.num_atoms(); ++a) EXPECT_TRUE(hc4.supports(a));
    for (int t = 0; t < 200; ++t) {
      const double x0 = u(rng), y0 = u(rng);
      Box b = {Interval(x0, x0 + w(rng)), Interval(y0, y0 + w(rng))};
      const Box original = b;
      const bool maybe = hc4.contract(b);
      for (int s = 0; s < 60; ++s) {
        std::uniform_real_distribution<double> px(original[0].lo(), original[0].hi()), py(original[1].lo(), original[1].hi());
        std::vector<double> p = {px(rng), py(rng)};
        if (s == 0) p = {original[0].lo(), original[1].lo()};
        const double v = evaluate(c, p)[0];
        if (v == 1.0) {
          ++kept;
          ASSERT_TRUE(maybe) << "rejected a box holding a solution";
          ASSERT_TRUE(contains(b, p)) << "removed a solution point";
        }
      }
    }
  }
  EXPECT_GT(kept, 100);  // the sample did hit solutions
}

// Points on an equality's solution set (constructed exactly) are never removed either.
TEST(Contractor, KeepsPointsOnCurve) {
  ConstraintSystem sys(eq(x(1), square(x(0)) * x(0) - x(0)), kU);
  Hc4Contractor hc4(sys);
  for (int i = 0; i <= 100; ++i) {
    const double t = -1.5 + 3.0 * i / 100.0;
    // y is t^3 - t rounded, but the exact point (t, t^3 - t) lies in the box too, so the
    // contracted box must keep t itself: no slack.
    const double y = t * t * t - t;
    Box b = {Interval(t - 0.25, t + 0.3), Interval(y - 0.4, y + 0.2)};
    ASSERT_TRUE(hc4.contract(b));
    EXPECT_TRUE(b[0].contains(t)) << "t " << t << " box [" << b[0].lo() << ", " << b[0].hi() << "]";
  }
}

}  // namespace
}  // namespace genmod
