// GENMOD's "all solutions up to a maximum" form of the solve operator.
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/solvers/solve_operator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace genmod {
namespace {

constexpr double kPi = std::numbers::pi;
const int kUnknown[] = {0};

// sin x = p on [0, 4 pi]: four solutions asin p, pi - asin p, 2 pi + asin p, 3 pi - asin p.
Fn sines(int k) { return solve_all_operator(eq(sin(x(0)), x(1)), kUnknown, {Interval(0, 4 * kPi)}, 1e-10, k); }

std::vector<double> expected(double p) {
  const double a = std::asin(p);
  return {a, kPi - a, 2 * kPi + a, 3 * kPi - a};
}

TEST(SolveAllOperator, CountsAndListsSolutionsInOrder) {
  const Fn three = sines(3), six = sines(6);
  ASSERT_EQ(three.dim(), 4u);
  ASSERT_EQ(six.dim(), 7u);
  for (double p : {0.1, 0.5, 0.9}) {
    const std::vector<double> want = expected(p);
    const auto a = evaluate(three, std::vector<double>{0.0, p});
    EXPECT_EQ(a[0], 3.0);
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(a[1 + j], want[j], 1e-9);
    const auto b = evaluate(six, std::vector<double>{0.0, p});
    EXPECT_EQ(b[0], 4.0);
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(b[1 + j], want[j], 1e-9);
    EXPECT_TRUE(std::isnan(b[5]) && std::isnan(b[6]));
  }
  // No solution at all: the count is 0, the slots are errors.
  const auto none = evaluate(three, std::vector<double>{0.0, 2.0});
  EXPECT_EQ(none[0], 0.0);
  EXPECT_TRUE(std::isnan(none[1]));
}

TEST(SolveAllOperator, DerivativesByTheImplicitFunctionTheorem) {
  const Fn d = derivative(sines(4), 1);
  for (double p : {0.2, 0.6}) {
    const auto v = evaluate(d, std::vector<double>{0.0, p});
    EXPECT_EQ(v[0], 0.0);
    const std::vector<double> at = expected(p);
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(v[1 + j], 1.0 / std::cos(at[j]), 1e-7) << j;
  }
}

TEST(SolveAllOperator, InclusionOverAParameterBox) {
  const Fn f = sines(6);
  Tape tape(f, std::vector<int>{1});
  IntervalEvaluator ev;
  const auto y = ev.eval(tape, {Interval(0.45, 0.55)});
  EXPECT_EQ(y[0], Interval(4.0));  // every component certified: the count is exact
  EXPECT_EQ(ev.errors()[0], kNoError);
  for (double p = 0.45; p <= 0.55; p += 0.01) {
    const std::vector<double> want = expected(p);
    for (int j = 0; j < 4; ++j) EXPECT_TRUE(y[1 + j].contains(want[j])) << p << " " << j;
  }
  EXPECT_EQ(ev.errors()[1], kNoError);
  EXPECT_NE(ev.errors()[5] & kMaybeError, 0);  // beyond the count
}

TEST(SolveAllOperator, BadInputIsNamed) {
  EXPECT_THROW(solve_all_operator(eq(x(0), x(1)), kUnknown, {Interval(0, 1)}, 1e-9, 0), std::invalid_argument);
}

}  // namespace
}  // namespace genmod
