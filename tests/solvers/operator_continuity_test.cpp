// Issue 10, failure 2: custom operators say where they are continuous, box by box, so that
// interval Newton and Krawczyk (which need a continuous function) go through them; and they
// never claim continuity where the function may jump.
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/integrate.hpp"
#include "genmod/solvers/constraint_solver.hpp"
#include "genmod/solvers/inverse_operator.hpp"
#include "genmod/solvers/minimize_operator.hpp"
#include "genmod/solvers/solve_operator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace genmod {
namespace {

// Whether the interval evaluator calls `f` (a function of x(1) only) continuous on [lo, hi].
bool continuous_on(const Fn& f, double lo, double hi) {
  const int inputs[] = {1};
  const Tape tape(f, inputs);
  IntervalEvaluator ev;
  const std::vector<Interval> box = {Interval(lo, hi)};
  ev.eval(tape, box);
  return ev.continuous();
}

const int kY[] = {1};

// f(x1) = value has one root in `range`, at `root`: the solver finds one component and
// certifies it (Krawczyk on the component: the boxes Newton leaves are as wide as their
// Krawczyk image), which needs Newton to go through the operators in f.
void expect_certified_root(const Fn& f, double value, Interval range, double root) {
  SolveOptions o;
  o.epsilon = 1e-10;
  const SolveResult s = solve(eq(f, value), kY, {range}, o);
  ASSERT_TRUE(s.complete());
  ASSERT_EQ(s.components.size(), 1u);
  EXPECT_TRUE(s.components[0].unique);
  EXPECT_EQ(s.unique_components(), 1u);
  EXPECT_TRUE(s.components[0].hull[0].contains(root));
}

// t in [0,1] with t^3 + t = x(1): strictly increasing, one root, continuous in x(1).
TEST(OperatorContinuity, MonotoneInverseIsContinuous) {
  const Fn t = x(0);
  const Fn r = inverse(t * t * t + t, x(1), 0);
  EXPECT_TRUE(continuous_on(r, 0.4, 0.6));
  EXPECT_TRUE(continuous_on(r, 0.5, 0.5));
  // Not bracketed for every value (x(1) > 2 has no root): no claim.
  EXPECT_FALSE(continuous_on(r, 1.9, 2.5));
}

// (t - 0.2)(t - 0.5)(t - 0.8) = x(1) has three roots in [0,1] for small |x(1)|: Brent's root
// is one of them, and which one may change with x(1). Bracketed, but not continuous.
TEST(OperatorContinuity, InverseWithSeveralRootsIsNotContinuous) {
  const Fn t = x(0);
  const Fn r = inverse((t - 0.2) * (t - 0.5) * (t - 0.8), x(1), 0);
  EXPECT_FALSE(continuous_on(r, -0.001, 0.001));
}

// The reproduction of the issue: a simple root of a function built on inverse() is certified.
TEST(OperatorContinuity, InverseNestedInSolveIsCertified) {
  const Fn t = x(0);
  const Fn r = inverse(t * t * t + t, x(1), 0);  // r(0.625) = 0.5
  expect_certified_root(r, 0.5, Interval(0.0, 2.0), 0.625);
}

// sqrt(1 - x1^2) as a solve: one solution in x0 in [0, 2] (continuous); in [-2, 2] the first of
// two solutions (the operator picks one; no claim).
TEST(OperatorContinuity, SolveIsContinuousWhereTheSolutionIsUnique) {
  const int u[] = {0};
  const Fn c = eq(square(x(0)) + square(x(1)), 1.0);
  const Fn one = solve_operator(c, u, {Interval(0.0, 2.0)}, 1e-9);
  const Fn two = solve_operator(c, u, {Interval(-2.0, 2.0)}, 1e-9);
  EXPECT_TRUE(continuous_on(one, 0.2, 0.4));
  EXPECT_TRUE(continuous_on(one, 0.3, 0.3));
  EXPECT_FALSE(continuous_on(two, 0.2, 0.4));
  EXPECT_FALSE(continuous_on(solve_all_operator(c, u, {Interval(0.0, 2.0)}, 1e-9, 2), -0.5, 0.5));
  // Nested in solve: sqrt(1 - x1^2) = 0.8 at x1 = 0.6, certified.
  expect_certified_root(one, 0.8, Interval(0.0, 0.9), 0.6);
}

// The integral of a continuous integrand is continuous; a step in the parameter is not.
// (Certifying a root through integrate() needs a tighter inclusion: its Riemann enclosure keeps
// a width of about max |df/dt| / pieces however small the box, so Newton cannot contract.)
TEST(OperatorContinuity, IntegrateIsContinuousWhereTheIntegrandIs) {
  const Fn smooth = integrate(x(0) * x(1), Fn(0.0), Fn(1.0), 0);  // x1 / 2
  EXPECT_TRUE(continuous_on(smooth, 0.2, 0.7));
  const Fn limit = integrate(x(0), Fn(0.0), x(1), 0);  // x1^2 / 2: continuous in the limit
  EXPECT_TRUE(continuous_on(limit, 0.2, 0.7));
  const Fn step = integrate(x(0) + (x(1) < 0.5), Fn(0.0), Fn(1.0), 0);  // 1/2 + [x1 < 1/2]
  EXPECT_FALSE(continuous_on(step, 0.4, 0.6));
}

// The minimizer point may jump when the argmin changes: the operators make no claim.
TEST(OperatorContinuity, MinimizeMakesNoClaim) {
  const int u[] = {0};
  const Fn f = square(square(x(0)) - 1.0) + x(0) * x(1);  // argmin jumps from +1 to -1 at x1 = 0
  EXPECT_FALSE(continuous_on(minimize_operator(f, Fn(1.0), u, {Interval(-2.0, 2.0)}, 1e-6), -0.1, 0.1));
}

}  // namespace
}  // namespace genmod
