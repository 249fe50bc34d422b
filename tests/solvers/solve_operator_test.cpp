// The solve operator (m_solve, snyder.md section 2.4.13): point values, inclusion over
// parameter boxes, implicit-function-theorem derivatives (1 and 2 unknowns), nesting and use
// through tapes.
#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/solvers/inverse_operator.hpp"
#include "genmod/solvers/solve_operator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace genmod {
namespace {

double at(const Fn& f, std::vector<double> coords, std::size_t j = 0) { return evaluate(f, coords)[j]; }

// x0 in [0, 2] with x0^2 + x1^2 = 1: sqrt(1 - x1^2).
Fn circle_solve(double epsilon = 1e-9) {
  const int unknowns[] = {0};
  return solve_operator(eq(square(x(0)) + square(x(1)), 1.0), unknowns, {Interval(0.0, 2.0)}, epsilon);
}

// Intersection of the unit circle with the circle of radius x3 around (x2, 0), upper half:
// x0 = (1 - r^2 + p^2) / (2p), x1 = sqrt(1 - x0^2).
Fn two_circles() {
  const int unknowns[] = {0, 1};
  const Fn c = eq(square(x(0)) + square(x(1)), 1.0) && eq(square(x(0) - x(2)) + square(x(1)), square(x(3)));
  return solve_operator(c, unknowns, {Interval(-2.0, 2.0), Interval(0.0, 2.0)}, 1e-9);
}

TEST(SolveOperator, PointValues) {
  const Fn r = circle_solve();
  EXPECT_EQ(r.dim(), 1u);
  EXPECT_EQ(r.inputs(), std::vector<int>{1});
  for (double p : {-0.9, -0.5, 0.0, 0.3, 0.8})
    EXPECT_NEAR(at(r, {0.0, p}), std::sqrt(1 - p * p), 1e-13) << p;
  // No solution: NaN.
  EXPECT_TRUE(std::isnan(at(r, {0.0, 1.5})));
  const Fn s = two_circles();
  EXPECT_EQ(s.dim(), 2u);
  EXPECT_EQ(s.inputs(), (std::vector<int>{2, 3}));
  const double p = 1.2, rr = 0.9;
  const double x0 = (1 - rr * rr + p * p) / (2 * p);
  EXPECT_NEAR(at(s, {0, 0, p, rr}, 0), x0, 1e-13);
  EXPECT_NEAR(at(s, {0, 0, p, rr}, 1), std::sqrt(1 - x0 * x0), 1e-13);
}

TEST(SolveOperator, DerivativeOneUnknown) {
  const Fn r = circle_solve();
  const Fn d = derivative(r, 1);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.9, 0.9);
  const double h = 1e-5;
  for (int i = 0; i < 20; ++i) {
    const double p = u(rng);
    EXPECT_NEAR(at(d, {0.0, p}), -p / std::sqrt(1 - p * p), 1e-10) << p;
    EXPECT_NEAR(at(d, {0.0, p}), (at(r, {0.0, p + h}) - at(r, {0.0, p - h})) / (2 * h), 1e-7) << p;
  }
}

TEST(SolveOperator, DerivativeTwoUnknownsByCramer) {
  const Fn s = two_circles();
  const Fn d2 = derivative(s, 2), d3 = derivative(s, 3);
  ASSERT_EQ(d2.dim(), 2u);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> up(0.8, 1.5), ur(0.7, 1.0);
  const double h = 1e-6;
  for (int i = 0; i < 15; ++i) {
    const double p = up(rng), r = ur(rng);
    for (std::size_t j = 0; j < 2; ++j) {
      const double fd_p = (at(s, {0, 0, p + h, r}, j) - at(s, {0, 0, p - h, r}, j)) / (2 * h);
      const double fd_r = (at(s, {0, 0, p, r + h}, j) - at(s, {0, 0, p, r - h}, j)) / (2 * h);
      EXPECT_NEAR(at(d2, {0, 0, p, r}, j), fd_p, 1e-6) << p << " " << r;
      EXPECT_NEAR(at(d3, {0, 0, p, r}, j), fd_r, 1e-6) << p << " " << r;
    }
    // Closed form of dx0/dp.
    EXPECT_NEAR(at(d2, {0, 0, p, r}, 0), 0.5 - (1 - r * r) / (2 * p * p), 1e-9);
  }
}

TEST(SolveOperator, InclusionContainsSampledValues) {
  std::mt19937 rng(13);
  {
    const Fn r = circle_solve();
    const Tape tape(r);
    IntervalEvaluator iv;
    std::uniform_real_distribution<double> u(-0.95, 0.95);
    for (int i = 0; i < 30; ++i) {
      double a = u(rng), b = u(rng);
      if (a > b) std::swap(a, b);
      const Interval y = iv.eval(tape, {Interval(a, b)})[0];
      // A solution exists for every parameter, but over a wide box the solver returns a chain of
      // uncertified boxes, so the flag may stay conservative ("maybe").
      EXPECT_NE(iv.errors()[0], kCertainError);
      for (int k = 0; k <= 20; ++k) {
        const double v = at(r, {0.0, a + (b - a) * k / 20.0});
        EXPECT_TRUE(y.contains(v)) << y << " misses " << v;
      }
    }
  }
  {
    const Fn s = two_circles();
    const Tape tape(s);
    IntervalEvaluator iv;
    std::uniform_real_distribution<double> up(0.8, 1.5), ur(0.7, 1.0), w(0.0, 0.1);
    for (int i = 0; i < 15; ++i) {
      const double p = up(rng), r = ur(rng), wp = w(rng), wr = w(rng);
      const auto y = iv.eval(tape, {Interval(p, p + wp), Interval(r, r + wr)});
      const Interval y0 = y[0], y1 = y[1];
      for (double sp : {0.0, 0.25, 0.5, 0.75, 1.0})
        for (double sr : {0.0, 0.5, 1.0}) {
          EXPECT_TRUE(y0.contains(at(s, {0, 0, p + wp * sp, r + wr * sr}, 0)));
          EXPECT_TRUE(y1.contains(at(s, {0, 0, p + wp * sp, r + wr * sr}, 1)));
        }
    }
  }
}

TEST(SolveOperator, NoSolutionIsAnError) {
  const Tape tape(circle_solve());
  IntervalEvaluator iv;
  Interval y = iv.eval(tape, {Interval(1.2, 1.5)})[0];
  EXPECT_TRUE(y.is_empty());
  EXPECT_EQ(iv.errors()[0], kCertainError);
  y = iv.eval(tape, {Interval(0.5, 1.5)})[0];
  EXPECT_EQ(iv.errors()[0], kMaybeError);
  EXPECT_TRUE(y.contains(0.0) && y.contains(std::sqrt(0.75)));
}

// A solve inside a function that is solved again: the outer unknown x1 with
// inner(x1) = sqrt(1 - x1^2) = x2, so outer = sqrt(1 - x2^2) again.
TEST(SolveOperator, NestedSolve) {
  const Fn inner = circle_solve(1e-11);
  const int outer_unknown[] = {1};
  const Fn outer0 = solve_operator(eq(inner, 0.6), outer_unknown, {Interval(0.0, 0.99)}, 1e-9);
  EXPECT_TRUE(outer0.inputs().empty());
  EXPECT_NEAR(at(outer0, {}), 0.8, 1e-9);
  const Fn outer = solve_operator(eq(inner, x(2)), outer_unknown, {Interval(0.0, 0.99)}, 1e-9);
  EXPECT_EQ(outer.inputs(), std::vector<int>{2});
  const Fn d = derivative(outer, 2);
  const Tape tape(outer);
  IntervalEvaluator iv;
  for (double v : {0.6}) {
    EXPECT_NEAR(at(outer, {0, 0, v}), std::sqrt(1 - v * v), 1e-9) << v;
    EXPECT_NEAR(at(d, {0, 0, v}), -v / std::sqrt(1 - v * v), 1e-6) << v;
    const Interval y = iv.eval(tape, {Interval(v - 0.02, v + 0.02)})[0];
    for (double s = v - 0.02; s <= v + 0.02; s += 0.01) EXPECT_TRUE(y.contains(at(outer, {0, 0, s}))) << y;
  }
}

// An inverse composed into a solve: x0 with inverse(t^3 + t, x1)(x0) = x2, i.e. x0 = x2^3 + x2.
TEST(SolveOperator, InverseInsideSolve) {
  const Fn t = x(0);
  const Fn inv = compose(inverse(t * t * t + t, x(1), 0), 1, x(0));  // a function of x0
  const int unknowns[] = {0};
  const Fn s = solve_operator(eq(inv, x(2)), unknowns, {Interval(0.0, 2.0)}, 1e-9);
  const Fn d = derivative(s, 2);
  for (double v : {0.2, 0.5, 0.8}) {
    EXPECT_NEAR(at(s, {0, 0, v}), v * v * v + v, 1e-9);
    EXPECT_NEAR(at(d, {0, 0, v}), 3 * v * v + 1, 1e-7);
  }
}

TEST(SolveOperator, ThroughTapesAndAllEvaluators) {
  const Fn s = two_circles();
  const Fn f = cat({s[0] + s[1], s[1] * x(2)});
  const Tape tape(f);  // inputs x2, x3
  PointEvaluator pv;
  BatchEvaluator bv;
  IntervalEvaluator iv;
  std::vector<double> in2, in3;
  for (int i = 0; i < 40; ++i) {
    in2.push_back(0.8 + 0.015 * i);
    in3.push_back(0.95 - 0.005 * i);
  }
  std::vector<double> o1(in2.size()), o2(in2.size());
  const double* ins[] = {in2.data(), in3.data()};
  double* outs[] = {o1.data(), o2.data()};
  bv.eval(tape, ins, in2.size(), outs);
  for (std::size_t i = 0; i < in2.size(); ++i) {
    const auto y = pv.eval(tape, {in2[i], in3[i]});
    EXPECT_EQ(y[0], o1[i]);
    EXPECT_EQ(y[1], o2[i]);
    const auto box = iv.eval(tape, {Interval(in2[i]), Interval(in3[i])});
    EXPECT_TRUE(box[0].contains(y[0]) && box[1].contains(y[1]));
    EXPECT_LT(box[0].width(), 1e-7);
  }
}

TEST(SolveOperator, NonSquareSystemHasNaNDerivative) {
  const int unknowns[] = {0};
  // An inequality pair is not an equality system: values work, the derivative is NaN.
  const Fn r = solve_operator(x(0) >= x(1) && x(0) <= x(1), unknowns, {Interval(0.0, 1.0)}, 1e-9);
  EXPECT_NEAR(at(r, {0.0, 0.4}), 0.4, 1e-8);
  EXPECT_TRUE(std::isnan(at(derivative(r, 1), {0.0, 0.4})));
}

TEST(SolveOperator, BadInputThrows) {
  const Fn c = eq(square(x(0)) + square(x(1)), 1.0);
  const int one[] = {0};
  const int twice[] = {0, 0};
  const int out_of_range[] = {64};
  EXPECT_THROW(solve_operator(cat({c, c}), one, {Interval(0, 1)}, 1e-6), std::invalid_argument);
  EXPECT_THROW(solve_operator(c, std::span<const int>{}, {}, 1e-6), std::invalid_argument);
  EXPECT_THROW(solve_operator(c, twice, {Interval(0, 1), Interval(0, 1)}, 1e-6), std::invalid_argument);
  EXPECT_THROW(solve_operator(c, out_of_range, {Interval(0, 1)}, 1e-6), std::invalid_argument);
  EXPECT_THROW(solve_operator(c, one, {Interval(0, 1), Interval(0, 1)}, 1e-6), std::invalid_argument);
  EXPECT_THROW(solve_operator(c, one, {Interval::empty()}, 1e-6), std::invalid_argument);
  EXPECT_THROW(solve_operator(c, one, {Interval::entire()}, 1e-6), std::invalid_argument);
  EXPECT_THROW(solve_operator(c, one, {Interval(0, 1)}, 0.0), std::invalid_argument);
  EXPECT_THROW(solve_operator(c, one, {Interval(0, 1)}, -1.0), std::invalid_argument);
  try {
    solve_operator(c, one, {Interval(0, 1)}, 0.0);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("epsilon"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace genmod
