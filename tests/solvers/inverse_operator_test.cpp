// The inverse operator (m_inverse, snyder.md section 2.4.12): point values, inclusion over
// parameter boxes, implicit-function-theorem derivatives, nesting and use through tapes.
#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/solvers/inverse_operator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace genmod {
namespace {

double at(const Fn& f, std::vector<double> coords, std::size_t j = 0) { return evaluate(f, coords)[j]; }

// t in [0,1] with t^3 + t = x(1).
Fn cubic_inverse() {
  const Fn t = x(0);
  return inverse(t * t * t + t, x(1), 0);
}

TEST(InverseOperator, PointValuesSolveTheEquation) {
  const Fn r = cubic_inverse();
  EXPECT_EQ(r.dim(), 1u);
  EXPECT_EQ(r.inputs(), std::vector<int>{1});
  for (double m : {0.0, 0.1, 0.5, 1.0, 1.7, 2.0}) {
    const double t = at(r, {0.0, m});
    EXPECT_NEAR(t * t * t + t, m, 1e-12) << m;
    EXPECT_GE(t, 0.0);
    EXPECT_LE(t, 1.0);
  }
  // Not bracketed on [0,1]: the error condition (NaN).
  EXPECT_TRUE(std::isnan(at(r, {0.0, 2.5})));
  EXPECT_TRUE(std::isnan(at(r, {0.0, -0.1})));
}

// A monotone invert of t alone starts Brent's method from a cell of a table of its values:
// values equal to a table entry, just beside one and between two are all solved, for an
// increasing and a decreasing invert, and every value lies in the enclosure of a small box
// around its argument.
TEST(InverseOperator, SeparableRootsAtAndBetweenTableNodes) {
  const Fn t = x(0);
  const Fn rising = inverse(t * t * t + t, x(1), 0);
  const Fn falling = inverse(2.0 - t * t * t - t, x(1), 0);
  const Tape rising_tape(rising, std::vector<int>{1}), falling_tape(falling, std::vector<int>{1});
  IntervalEvaluator iev;
  for (int k = 0; k <= 512; ++k) {
    const double node = k / 512.0;  // every table node (256 cells) and every cell's middle
    const double g = node * node * node + node;
    for (double m : {g, std::nextafter(g, -1.0), std::nextafter(g, 3.0)}) {
      if (m < 0.0 || m > 2.0) continue;
      for (const auto& [f, tape, value] : {std::tuple{&rising, &rising_tape, m}, std::tuple{&falling, &falling_tape, 2.0 - m}}) {
        const double r = at(*f, {0.0, value});
        ASSERT_NEAR(r * r * r + r, m, 1e-12) << "k " << k;
        const Interval box(value - 1e-9, value + 1e-9);
        const Interval e = iev.eval(*tape, {box})[0];
        EXPECT_TRUE(e.contains(r)) << "k " << k << " value " << value;
      }
    }
  }
}

TEST(InverseOperator, DerivativeMatchesImplicitFunctionTheoremAndFiniteDifferences) {
  const Fn r = cubic_inverse();
  const Fn d = derivative(r, 1);
  const Fn dd = derivative(d, 1);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.05, 1.95);
  const double h = 1e-5;
  for (int i = 0; i < 25; ++i) {
    const double m = u(rng);
    const double t = at(r, {0.0, m});
    const double dv = at(d, {0.0, m});
    EXPECT_NEAR(dv, 1.0 / (3 * t * t + 1), 1e-12);
    const double fd = (at(r, {0.0, m + h}) - at(r, {0.0, m - h})) / (2 * h);
    EXPECT_NEAR(dv, fd, 1e-7) << m;
    // Second derivative (the derivative Fn contains the operator itself).
    const double fd2 = (at(d, {0.0, m + h}) - at(d, {0.0, m - h})) / (2 * h);
    EXPECT_NEAR(at(dd, {0.0, m}), fd2, 1e-6) << m;
  }
}

TEST(InverseOperator, InclusionContainsSampledValues) {
  const Fn r = cubic_inverse();
  const Tape tape(r);
  IntervalEvaluator iv;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 2.0);
  for (int i = 0; i < 40; ++i) {
    double a = u(rng), b = u(rng);
    if (a > b) std::swap(a, b);
    const Interval y = iv.eval(tape, {Interval(a, b)})[0];
    if (a > 0.0 && b < 2.0) {
      EXPECT_EQ(iv.errors()[0], kNoError);
    }
    for (int s = 0; s <= 20; ++s) {
      const double m = a + (b - a) * s / 20.0;
      const double t = at(r, {0.0, m});
      ASSERT_FALSE(std::isnan(t));
      EXPECT_TRUE(y.contains(t)) << "[" << a << ", " << b << "] misses " << t << " at " << m << ": " << y;
    }
    // Not much wider than the true range (certified solver boxes may be wider than it).
    EXPECT_LE(y.width(), 1.5 * (at(r, {0.0, b}) - at(r, {0.0, a})) + 0.03);
  }
}

// Every way to enclose: a monotone F whose invert depends on a parameter (a search in t per
// box), one whose invert depends on t alone (its roots at the ends of match's range), and a
// non-monotone one, (t - 0.5)^2 = x1, with two roots (the constraint solver). Every
// root of every sampled parameter value lies in the inclusion over the parameter box.
TEST(InverseOperator, InclusionHoldsEveryRootMonotoneOrNot) {
  const Fn t = x(0);
  struct Case {
    Fn r;
    std::function<std::vector<double>(double, double)> roots;  // of F for x1, x2
  };
  const std::vector<Case> cases{
      // t^3 + x2 t = x1, x2 in [0.5, 2]: increasing in t.
      {inverse(t * t * t + x(2) * t, x(1), 0),
       [](double m, double k) {
         double lo = 0.0, hi = 1.0;  // bisection on the increasing cubic
         if (lo * lo * lo + k * lo > m || hi * hi * hi + k * hi < m) return std::vector<double>{};
         for (int i = 0; i < 200; ++i) {
           const double mid = 0.5 * (lo + hi);
           (mid * mid * mid + k * mid < m ? lo : hi) = mid;
         }
         return std::vector<double>{lo};
       }},
      // 1 - x2 t = x1: decreasing in t.
      {inverse(1.0 - x(2) * t, x(1), 0),
       [](double m, double k) {
         const double r = (1.0 - m) / k;
         return r >= 0.0 && r <= 1.0 ? std::vector<double>{r} : std::vector<double>{};
       }},
      // exp(-t) = x1: decreasing in t alone (invert found monotone once, when built).
      {inverse(exp(-t), x(1), 0),
       [](double m, double) {
         const double r = -std::log(m);
         return m > 0.0 && r >= 0.0 && r <= 1.0 ? std::vector<double>{r} : std::vector<double>{};
       }},
      // (t - 0.5)^2 = x1 (x2 unused): two roots, not monotone.
      {inverse(square(t - 0.5) + 0.0 * x(2), x(1), 0),
       [](double m, double) {
         return m >= 0.0 && m <= 0.25 ? std::vector<double>{0.5 - std::sqrt(m), 0.5 + std::sqrt(m)}
                                      : std::vector<double>{};
       }},
  };
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> um(-0.1, 1.3), uk(0.5, 2.0);
  IntervalEvaluator iv;
  for (std::size_t c = 0; c < cases.size(); ++c) {
    const Tape tape(cases[c].r, std::vector<int>{1, 2});
    for (int i = 0; i < 60; ++i) {
      double m0 = um(rng), m1 = um(rng), k0 = uk(rng), k1 = uk(rng);
      if (m0 > m1) std::swap(m0, m1);
      if (k0 > k1) std::swap(k0, k1);
      if (i % 3 == 0) m1 = m0 + 1e-3 * (m1 - m0);  // narrow boxes too
      const Interval y = iv.eval(tape, {Interval(m0, m1), Interval(k0, k1)})[0];
      for (int s = 0; s <= 12; ++s)
        for (int q = 0; q <= 4; ++q) {
          const double m = m0 + (m1 - m0) * s / 12.0, k = k0 + (k1 - k0) * q / 4.0;
          for (double root : cases[c].roots(m, k))
            EXPECT_TRUE(y.contains(root)) << "case " << c << ": " << y << " misses the root " << root << " at x1 = " << m
                                          << ", x2 = " << k;
          const double v = at(cases[c].r, {0.0, m, k});
          if (!std::isnan(v)) {
            EXPECT_TRUE(y.contains(v)) << "case " << c << ": misses the point value " << v;
          }
        }
    }
  }
}

TEST(InverseOperator, ErrorsInIntervals) {
  const Tape tape(cubic_inverse());
  IntervalEvaluator iv;
  // Entirely outside the range of invert: empty, certain error.
  Interval y = iv.eval(tape, {Interval(2.5, 3.0)})[0];
  EXPECT_TRUE(y.is_empty());
  EXPECT_EQ(iv.errors()[0], kCertainError);
  // Partly outside: maybe error, the values that exist are inside.
  y = iv.eval(tape, {Interval(1.5, 3.0)})[0];
  EXPECT_EQ(iv.errors()[0], kMaybeError);
  EXPECT_TRUE(y.contains(at(cubic_inverse(), {0.0, 1.5})));
  EXPECT_TRUE(y.contains(1.0));
  // Inside: no error.
  iv.eval(tape, {Interval(0.5, 1.5)});
  EXPECT_EQ(iv.errors()[0], kNoError);
}

// GENMOD's arclength use: match depends on the outer value of the bound coordinate.
// t with t^2 = x0 * x1 on [0, 1]: R = sqrt(x0 x1).
TEST(InverseOperator, MatchDependingOnTheBoundCoordinate) {
  const Fn r = inverse(square(x(0)), x(0) * x(1), 0);
  EXPECT_EQ(r.inputs(), (std::vector<int>{0, 1}));
  const Fn d0 = derivative(r, 0), d1 = derivative(r, 1);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.1, 0.9);
  const double h = 1e-6;
  const Tape tape(r);
  IntervalEvaluator iv;
  for (int i = 0; i < 20; ++i) {
    const double a = u(rng), b = u(rng);
    const double v = at(r, {a, b});
    EXPECT_NEAR(v, std::sqrt(a * b), 1e-12);
    EXPECT_NEAR(at(d0, {a, b}), b / (2 * std::sqrt(a * b)), 1e-10);
    EXPECT_NEAR(at(d1, {a, b}), (at(r, {a, b + h}) - at(r, {a, b - h})) / (2 * h), 1e-7);
    EXPECT_NEAR(at(d0, {a, b}), (at(r, {a + h, b}) - at(r, {a - h, b})) / (2 * h), 1e-7);
    const Interval y = iv.eval(tape, {Interval(a, a + 0.05), Interval(b, b + 0.05)})[0];
    for (double s : {0.0, 0.3, 0.7, 1.0})
      for (double q : {0.0, 0.5, 1.0}) EXPECT_TRUE(y.contains(at(r, {a + 0.05 * s, b + 0.05 * q})));
  }
}

// An inverse inside an inverse: R1(x1) = t with t^3 + t = x1; R2(x2) = s in [0, 2] with
// R1(s) = x2, so R2 = x2^3 + x2 and dR2/dx2 = 3 x2^2 + 1.
TEST(InverseOperator, NestedInverse) {
  const Fn r1 = cubic_inverse();
  const Fn r2 = inverse(r1, x(2), 1, Interval(0.0, 2.0));
  EXPECT_EQ(r2.inputs(), std::vector<int>{2});
  const Fn d = derivative(r2, 2);
  const Tape tape(r2);
  IntervalEvaluator iv;
  for (double v : {0.1, 0.4, 0.6, 0.9}) {
    EXPECT_NEAR(at(r2, {0, 0, v}), v * v * v + v, 1e-10);
    EXPECT_NEAR(at(d, {0, 0, v}), 3 * v * v + 1, 1e-8);
    const double h = 1e-5;
    EXPECT_NEAR(at(d, {0, 0, v}), (at(r2, {0, 0, v + h}) - at(r2, {0, 0, v - h})) / (2 * h), 1e-6);
    const Interval y = iv.eval(tape, {Interval(v - 0.05, v + 0.05)})[0];
    for (double s = v - 0.05; s <= v + 0.05; s += 0.01) EXPECT_TRUE(y.contains(at(r2, {0, 0, s})));
  }
}

TEST(InverseOperator, ThroughTapesAndAllEvaluators) {
  const Fn r = cubic_inverse();
  const Fn f = cat({2.0 * r + x(2), sin(r) * x(2)});
  const Tape tape(f);  // inputs x1, x2
  PointEvaluator pv;
  BatchEvaluator bv;
  IntervalEvaluator iv;
  std::vector<double> in1, in2;
  for (int i = 0; i < 300; ++i) {
    in1.push_back(0.005 * i + 0.1);
    in2.push_back(0.5 + 0.001 * i);
  }
  std::vector<double> o1(in1.size()), o2(in1.size());
  const double* ins[] = {in1.data(), in2.data()};
  double* outs[] = {o1.data(), o2.data()};
  bv.eval(tape, ins, in1.size(), outs);
  for (std::size_t i = 0; i < in1.size(); ++i) {
    const auto y = pv.eval(tape, {in1[i], in2[i]});
    EXPECT_EQ(y[0], o1[i]);
    EXPECT_EQ(y[1], o2[i]);
    const double t = at(r, {0.0, in1[i]});
    EXPECT_DOUBLE_EQ(y[0], 2 * t + in2[i]);
    const auto box = iv.eval(tape, {Interval(in1[i]), Interval(in2[i])});
    EXPECT_TRUE(box[0].contains(y[0]) && box[1].contains(y[1]));
    EXPECT_LT(box[0].width(), 1e-9);
  }
}

TEST(InverseOperator, BadInputThrows) {
  const Fn t = x(0);
  EXPECT_THROW(inverse(cat({t, t}), x(1), 0), std::invalid_argument);
  EXPECT_THROW(inverse(t, cat({x(1), x(1)}), 0), std::invalid_argument);
  EXPECT_THROW(inverse(t, x(1), -1), std::invalid_argument);
  EXPECT_THROW(inverse(t, x(1), kMaxInputs), std::invalid_argument);
  EXPECT_THROW(inverse(x(2), x(1), 0), std::invalid_argument);  // invert does not depend on x0
  EXPECT_THROW(inverse(t, x(1), 0, Interval::empty()), std::invalid_argument);
  EXPECT_THROW(inverse(t, x(1), 0, Interval(1.0, 1.0)), std::invalid_argument);
  EXPECT_THROW(inverse(t, x(1), 0, Interval::entire()), std::invalid_argument);
  EXPECT_THROW(inverse(t, x(1), 0, Interval(0, 1), 0.0), std::invalid_argument);
  EXPECT_THROW(inverse(t, x(1), 0, Interval(0, 1), std::nan("")), std::invalid_argument);
  try {
    inverse(cat({t, t}), x(1), 0);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("invert must be scalar"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace genmod
