// The minimize operators (m_minimize, snyder.md section 2.4.13): minimizer point and minimum
// value as functions of the free coordinates; inclusion over parameter boxes; the envelope
// theorem derivative of the minimum value.
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/solvers/minimize_operator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

namespace genmod {
namespace {

double at(const Fn& f, std::vector<double> coords, std::size_t j = 0) { return evaluate(f, coords)[j]; }

// min over x0 in [-2, 2] of (x0 - x1)^2 + x1^2 = x1^2, at x0 = x1.
Fn objective() { return square(x(0) - x(1)) + square(x(1)); }
const int kUnknowns[] = {0};

TEST(MinimizeOperator, PointValues) {
  const Fn v = minimum_value_operator(objective(), Fn(1.0), kUnknowns, {Interval(-2, 2)}, 1e-8);
  const Fn m = minimize_operator(objective(), Fn(1.0), kUnknowns, {Interval(-2, 2)}, 1e-8);
  EXPECT_EQ(v.dim(), 1u);
  EXPECT_EQ(m.dim(), 1u);
  EXPECT_EQ(v.inputs(), std::vector<int>{1});
  for (double p : {-0.7, 0.0, 0.4, 1.1}) {
    EXPECT_NEAR(at(v, {0, p}), p * p, 1e-7) << p;
    EXPECT_NEAR(at(m, {0, p}), p, 1e-4) << p;
  }
}

TEST(MinimizeOperator, EnvelopeDerivativeOfTheMinimumValue) {
  const Fn v = minimum_value_operator(objective(), Fn(1.0), kUnknowns, {Interval(-2, 2)}, 1e-9);
  const Fn d = derivative(v, 1);
  const double h = 1e-3;
  for (double p : {-0.6, 0.2, 0.9}) {
    EXPECT_NEAR(at(d, {0, p}), 2 * p, 1e-3) << p;
    EXPECT_NEAR(at(d, {0, p}), (at(v, {0, p + h}) - at(v, {0, p - h})) / (2 * h), 1e-3) << p;
  }
  // The minimizer x0 = x1 has derivative 1 (implicit function theorem on grad f = 0).
  const Fn m = minimize_operator(objective(), Fn(1.0), kUnknowns, {Interval(-2, 2)}, 1e-8);
  EXPECT_NEAR(at(derivative(m, 1), {0, 0.3}), 1.0, 1e-9);
}

// The minimizer's derivative by the implicit function theorem on grad f = 0.
TEST(MinimizeOperator, MinimizerDerivative) {
  const int unknowns[] = {0, 1};
  // (x0 - sin p)^2 + (2 x1 - p^2)^2 has the minimizer (sin p, p^2 / 2).
  const Fn p = x(2);
  const Fn f = square(x(0) - sin(p)) + square(2 * x(1) - square(p));
  const Fn m = minimize_operator(f, Fn(1.0), unknowns, {Interval(-2, 2), Interval(-2, 2)}, 1e-9);
  const Fn dm = derivative(m, 2);
  for (double q : {-0.7, 0.3, 1.1}) {
    const auto v = evaluate(m, std::vector<double>{0, 0, q});
    EXPECT_NEAR(v[0], std::sin(q), 1e-6);
    EXPECT_NEAR(v[1], q * q / 2, 1e-6);
    const auto d = evaluate(dm, std::vector<double>{0, 0, q});
    EXPECT_NEAR(d[0], std::cos(q), 1e-5);
    EXPECT_NEAR(d[1], q, 1e-5);
  }
}

// All global minimizers up to a maximum: (x^2 - p)^2 has two, -sqrt p and sqrt p.
TEST(MinimizeOperator, AllMinimizersUpToAMaximum) {
  const int unknowns[] = {0};
  const Fn f = square(square(x(0)) - x(1));
  const Fn all = minimize_all_operator(f, Fn(1.0), unknowns, {Interval(-2, 2)}, 1e-7, 3);
  ASSERT_EQ(all.dim(), 4u);
  const Fn d = derivative(all, 1);
  for (double p : {0.5, 1.5}) {
    const auto v = evaluate(all, std::vector<double>{0, p});
    EXPECT_EQ(v[0], 2.0);
    EXPECT_NEAR(v[1], -std::sqrt(p), 1e-5);
    EXPECT_NEAR(v[2], std::sqrt(p), 1e-5);
    EXPECT_TRUE(std::isnan(v[3]));
    const auto dv = evaluate(d, std::vector<double>{0, p});
    EXPECT_NEAR(dv[1], -0.5 / std::sqrt(p), 1e-3);
    EXPECT_NEAR(dv[2], 0.5 / std::sqrt(p), 1e-3);
  }
  EXPECT_THROW(minimize_all_operator(f, Fn(1.0), unknowns, {Interval(-2, 2)}, 1e-7, 0), std::invalid_argument);
}

TEST(MinimizeOperator, InclusionContainsSampledValues) {
  const Fn v = minimum_value_operator(objective(), Fn(1.0), kUnknowns, {Interval(-2, 2)}, 1e-8);
  const Fn m = minimize_operator(objective(), Fn(1.0), kUnknowns, {Interval(-2, 2)}, 1e-8);
  const Tape tv(v), tm(m);
  IntervalEvaluator iv;
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int i = 0; i < 8; ++i) {
    double a = u(rng), b = u(rng);
    if (a > b) std::swap(a, b);
    const Interval yv = iv.eval(tv, {Interval(a, b)})[0];
    EXPECT_EQ(iv.errors()[0], kNoError);
    const Interval ym = iv.eval(tm, {Interval(a, b)})[0];
    for (int k = 0; k <= 6; ++k) {
      const double p = a + (b - a) * k / 6.0;
      EXPECT_TRUE(yv.contains(at(v, {0, p}))) << yv << " misses " << at(v, {0, p});
      EXPECT_TRUE(ym.contains(at(m, {0, p}))) << ym << " misses " << at(m, {0, p});
    }
  }
}

// One unknown without a constraint (the closest point of a curve) is enclosed without a search
// per box: point values are in the enclosures on boxes of every width, for a convex objective,
// a double well whose global minimizer jumps at p = 0, minima held at the domain's ends, and a
// closest point on a closed curve (the minimizer wraps around at s = 0 = 1); and on a small
// box of a convex objective the enclosure is about as wide as the minimizer's true range.
TEST(MinimizeOperator, OneUnknownInclusionHoldsEveryPointValue) {
  const double pi = std::numbers::pi;
  const Fn s = x(0), p = x(1);
  const Fn ellipse = cat({1.3 * cos(2 * pi * s), 0.7 * sin(2 * pi * s)});
  const Fn circle = cat({2.0 * cos(2 * pi * p), 2.0 * sin(2 * pi * p)});
  struct Case {
    const char* name;
    Fn f;
    Interval domain, params;
  };
  const std::vector<Case> cases{
      {"convex", objective(), Interval(-2, 2), Interval(-1.5, 1.5)},
      {"double well", square(square(s) - 1.0) + 0.3 * p * s, Interval(-2, 2), Interval(-1, 1)},
      {"ends", square(s - p), Interval(0, 1), Interval(-0.5, 1.5)},
      {"closest point", square(ellipse[0] - circle[0]) + square(ellipse[1] - circle[1]), Interval(0, 1),
       Interval(0, 1)},
  };
  std::mt19937 rng(23);
  for (const Case& c : cases) {
    const Fn v = minimum_value_operator(c.f, Fn(1.0), kUnknowns, {c.domain}, 1e-8);
    const Fn m = minimize_operator(c.f, Fn(1.0), kUnknowns, {c.domain}, 1e-8);
    const Tape tv(v), tm(m);
    IntervalEvaluator iv;
    for (double w : {0.3, 0.02, 1e-3, 1e-5}) {
      std::uniform_real_distribution<double> u(c.params.lo(), c.params.hi() - w);
      for (int i = 0; i < 6; ++i) {
        const double a = u(rng);
        const Interval box(a, a + w);
        const Interval yv = iv.eval(tv, {box})[0];
        const Interval ym = iv.eval(tm, {box})[0];
        for (int k = 0; k <= 8; ++k) {
          const double q = a + w * k / 8.0;
          const double mq = at(m, {0, q}), vq = at(v, {0, q});
          EXPECT_TRUE(ym.contains(mq)) << c.name << ": " << ym << " misses the minimizer " << mq << " at " << q;
          EXPECT_TRUE(yv.contains(vq)) << c.name << ": " << yv << " misses the minimum " << vq << " at " << q;
        }
      }
    }
  }
  // (x0 - x1)^2 + x1^2: the minimizer is x1, so over a box of width 1e-3 its range is 1e-3 wide.
  // There the minimizer is unique: no error and continuous (Newton and the meshers' linear
  // bound may use it); where the double well's minimizer jumps (p = 0) neither is claimed.
  const Fn m = minimize_operator(objective(), Fn(1.0), kUnknowns, {Interval(-2, 2)}, 1e-8);
  IntervalEvaluator iv;
  const Interval ym = iv.eval(Tape(m), {Interval(0.3, 0.301)})[0];
  EXPECT_TRUE(ym.contains(Interval(0.3, 0.301))) << ym;
  EXPECT_LT(ym.width(), 1.05e-3) << ym;
  EXPECT_EQ(iv.errors()[0], kNoError);
  EXPECT_TRUE(iv.continuous());
  const Fn jumps = minimize_operator(cases[1].f, Fn(1.0), kUnknowns, {cases[1].domain}, 1e-8);
  const Interval yj = iv.eval(Tape(jumps), {Interval(-0.01, 0.01)})[0];
  EXPECT_LT(yj.lo(), -0.9);
  EXPECT_GT(yj.hi(), 0.9);
  EXPECT_NE(iv.errors()[0], kNoError);
  EXPECT_FALSE(iv.continuous());
}

TEST(MinimizeOperator, InfeasibleIsAnError) {
  // x0 >= x1 + 3 has no solution in [-2, 2] for x1 > -1.
  const Fn v = minimum_value_operator(objective(), x(0) >= x(1) + 3.0, kUnknowns, {Interval(-2, 2)}, 1e-8);
  EXPECT_TRUE(std::isnan(at(v, {0, 0.5})));
  IntervalEvaluator iv;
  const Interval y = iv.eval(Tape(v), {Interval(0.0, 1.0)})[0];
  EXPECT_TRUE(y.is_empty());
  EXPECT_EQ(iv.errors()[0], kCertainError);
}

TEST(MinimizeOperator, BadInputThrows) {
  EXPECT_THROW(minimize_operator(cat({x(0), x(0)}), Fn(1.0), kUnknowns, {Interval(0, 1)}, 1e-6), std::invalid_argument);
  EXPECT_THROW(minimize_operator(x(0), cat({x(0), x(0)}), kUnknowns, {Interval(0, 1)}, 1e-6), std::invalid_argument);
  EXPECT_THROW(minimum_value_operator(x(0), Fn(1.0), kUnknowns, {Interval(0, 1), Interval(0, 1)}, 1e-6), std::invalid_argument);
  EXPECT_THROW(minimum_value_operator(x(0), Fn(1.0), kUnknowns, {Interval(0, 1)}, 0.0), std::invalid_argument);
  EXPECT_THROW(minimum_value_operator(x(0), Fn(1.0), kUnknowns, {Interval::entire()}, 1e-6), std::invalid_argument);
}

}  // namespace
}  // namespace genmod
