// Interval Newton and extended division: snyder.md section 11 claims 19 and 20.
#include "genmod/solvers/interval_newton.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace genmod {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Claim 20 (with the erratum: Hansen's conditions).
TEST(IntervalNewton, ExtendedDivisionClaim20) {
  IntervalPair q = extended_divide(Interval(0, 1), Interval(-1, 0));
  EXPECT_EQ(q.first, Interval::entire());
  EXPECT_TRUE(q.second.is_empty());
  q = extended_divide(Interval(1, 2), Interval(0, 1));
  EXPECT_EQ(q.first.lo(), 1.0);
  EXPECT_EQ(q.first.hi(), kInf);
  EXPECT_TRUE(q.second.is_empty());
  q = extended_divide(Interval(-2, -1), Interval(-1, 1));
  const Interval lo = q.first.hi() < 0 ? q.first : q.second, hi = q.first.hi() < 0 ? q.second : q.first;
  EXPECT_EQ(lo.lo(), -kInf);
  EXPECT_EQ(lo.hi(), -1.0);
  EXPECT_EQ(hi.lo(), 1.0);
  EXPECT_EQ(hi.hi(), kInf);
  q = extended_divide(Interval(1, 2), Interval(0.0));
  EXPECT_TRUE(q.first.is_empty() && q.second.is_empty());
  // 0 = q * 0 for every q: the whole line.
  q = extended_divide(Interval(-1, 1), Interval(0.0));
  EXPECT_EQ(q.first, Interval::entire());
}

TEST(IntervalNewton, ExtendedDivisionContainsQuotientsRandom) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-3, 3);
  for (int t = 0; t < 2000; ++t) {
    double a0 = d(rng), a1 = d(rng), b0 = d(rng), b1 = d(rng);
    if (t % 5 == 0) b0 = 0;
    if (a0 > a1) std::swap(a0, a1);
    if (b0 > b1) std::swap(b0, b1);
    const IntervalPair q = extended_divide(Interval(a0, a1), Interval(b0, b1));
    for (int s = 0; s < 10; ++s) {
      const double a = a0 + (a1 - a0) * (s / 9.0), b = b0 + (b1 - b0) * ((s * 7 % 10) / 9.0);
      if (b == 0.0) continue;
      const double x = a / b;
      EXPECT_TRUE(q.first.contains(x) || q.second.contains(x)) << a << "/" << b;
    }
  }
}

const int kUnknowns[] = {0, 1};

Fn claim19_system() { return cat({square(x(0)) + square(x(1)) - 1.0, x(0) - x(1)}); }

// Claim 19: iterates keep the zeros; [0.6,0.8]^2 is certified; [-2,2]^2 is not.
TEST(IntervalNewton, Claim19) {
  IntervalNewton newton(claim19_system(), kUnknowns);
  const double s = std::sqrt(0.5);
  Box b = {Interval(0.6, 0.8), Interval(0.6, 0.8)};
  EXPECT_TRUE(newton.certify(b));
  const Box k = newton.krawczyk(b);
  ASSERT_EQ(k.size(), 2u);
  EXPECT_TRUE(contains(b, k));
  for (int it = 0; it < 6; ++it) {
    ASSERT_EQ(newton.contract(b), NewtonStatus::Contracted);
    EXPECT_TRUE(b[0].contains(s) && b[1].contains(s));
  }
  EXPECT_LT(width(b), 1e-12);
  EXPECT_TRUE(newton.certify(b) || width(b) < 1e-15);

  Box big = {Interval(-2, 2), Interval(-2, 2)};
  EXPECT_FALSE(newton.certify(big));
  for (int it = 0; it < 4; ++it) {
    if (newton.contract(big) != NewtonStatus::Contracted) break;
    EXPECT_TRUE(big[0].contains(s) && big[1].contains(s));
    EXPECT_TRUE(big[0].contains(-s) && big[1].contains(-s));
  }
}

TEST(IntervalNewton, EmptyWhenNoZero) {
  IntervalNewton newton(claim19_system(), kUnknowns);
  Box b = {Interval(0.1, 0.2), Interval(0.5, 0.6)};  // x - y < 0 throughout
  EXPECT_EQ(newton.contract(b), NewtonStatus::Empty);
}

// Soundness: random boxes around the zeros never lose them.
TEST(IntervalNewton, NeverLosesZerosRandom) {
  IntervalNewton newton(claim19_system(), kUnknowns);
  const double s = std::sqrt(0.5);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> d(0.0, 0.5);
  for (int t = 0; t < 500; ++t) {
    Box b = {Interval(s - d(rng), s + d(rng)), Interval(s - d(rng), s + d(rng))};
    for (int it = 0; it < 3; ++it) {
      const NewtonStatus st = newton.contract(b);
      ASSERT_NE(st, NewtonStatus::Empty);
      ASSERT_TRUE(b[0].contains(s) && b[1].contains(s));
    }
  }
}

// With a parameter interval: x^2 = p, p in [1, 4], x in [0.5, 2.5] holds exactly one zero for
// every p (certified), and a parameter-free tape of the wrong size is rejected.
TEST(IntervalNewton, ParametersAndErrors) {
  const int u[] = {0}, p[] = {1};
  IntervalNewton newton(Fn(square(x(0)) - x(1)), u, p);
  Box b = {Interval(0.9, 2.1), Interval(1.0, 4.0)};
  EXPECT_NE(newton.contract(b), NewtonStatus::Empty);
  EXPECT_TRUE(b[0].contains(1.0) && b[0].contains(2.0));
  EXPECT_THROW(IntervalNewton(claim19_system(), u), std::invalid_argument);
  EXPECT_THROW(newton.contract(std::span<Interval>(b.data(), 1)), std::invalid_argument);
}

}  // namespace
}  // namespace genmod
