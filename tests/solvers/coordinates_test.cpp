// Every call that takes a list of coordinates (tape inputs, unknowns, parameters) accepts a
// braced list, as a new user writes it first (issue 10: std::span<const int> could not take
// {0, 1}). These calls did not compile before; the values check the lists reach the callee
// in order.
#include "genmod/kernel/inclusion.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/solvers/constraint_solver.hpp"
#include "genmod/solvers/implicit_curve.hpp"
#include "genmod/solvers/interval_newton.hpp"
#include "genmod/solvers/minimizer.hpp"
#include "genmod/solvers/solve_operator.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace genmod {
namespace {

const Box unit_square = {Interval(-2, 2), Interval(-2, 2)};

std::vector<int> copy(Coordinates c) { return {c.begin(), c.end()}; }

TEST(Coordinates, TakesBracedListsVectorsArraysAndSpansInOrder) {
  const std::vector<int> expected = {2, 0};
  std::vector<int> from_vector = {2, 0};
  std::array<int, 2> from_array = {2, 0};
  const int from_c_array[] = {2, 0};
  EXPECT_EQ(copy({2, 0}), expected);   // a braced list lives to the end of the call
  EXPECT_EQ(copy(from_vector), expected);
  EXPECT_EQ(copy(from_array), expected);
  EXPECT_EQ(copy(from_c_array), expected);
  EXPECT_EQ(copy(std::span<const int>(from_vector)), expected);
  const Coordinates c = from_vector;
  const std::span<const int> s = c;
  EXPECT_EQ(s.data(), from_vector.data());   // a view, not a copy
  EXPECT_EQ(c.size(), 2u);
  EXPECT_TRUE(Coordinates{}.empty());
}

TEST(Coordinates, KernelCallsTakeBracedLists) {
  Fn f = x(0) - 2.0 * x(1);
  PointEvaluator pe;
  EXPECT_EQ(pe.eval(Tape(f, {1, 0}), {1.0, 3.0})[0], 1.0);   // x(1) = 1, x(0) = 3
  InclusionFunction inc(f, {0, 1});
  std::vector<Interval> unit = {Interval(0, 1), Interval(0, 1)};
  Interval r = inc.eval(unit)[0];
  EXPECT_LE(r.lo(), -2.0);
  EXPECT_GE(r.hi(), 1.0);
  Fn g = compose_all(f, {0, 1}, cat({x(1), x(0)}));   // swap the coordinates
  EXPECT_EQ(evaluate(g, {1.0, 3.0})[0], 3.0 - 2.0);
}

TEST(Coordinates, SolverCallsTakeBracedLists) {
  Fn circle_diagonal = eq(square(x(0)) + square(x(1)), 1.0) && eq(x(0), x(1));
  SolveResult s = solve(circle_diagonal, {0, 1}, unit_square);
  EXPECT_TRUE(s.complete());
  EXPECT_EQ(s.unique_components(), 2u);

  MinimizeResult m = minimize(x(0) + x(1), square(x(0)) + square(x(1)) <= 1.0, {0, 1}, unit_square);
  EXPECT_TRUE(m.minimum.contains(-std::sqrt(2.0)));
  EXPECT_TRUE(minimum_value(x(0) + x(1), Fn(1.0), {0, 1}, unit_square).contains(-4.0));

  Fn root = solve_operator(eq(square(x(0)), x(1)), {0}, {Interval(0, 2)}, 1e-10);   // sqrt(x(1))
  EXPECT_NEAR(evaluate(root, {0.0, 2.0})[0], std::sqrt(2.0), 1e-8);

  Fn newton_system = cat({x(0) * x(0) - x(1), x(1) - 0.25});
  IntervalNewton newton(newton_system, {0, 1});
  EXPECT_EQ(newton.dim(), 2u);
  std::vector<Interval> near_root = {Interval(0.4, 0.6), Interval(0.2, 0.3)};
  EXPECT_TRUE(newton.certify(near_root));

  ImplicitCurve curve = approximate_implicit_curve(square(x(0)) + square(x(1)) - 1.0, {0, 1}, unit_square);
  EXPECT_TRUE(curve.complete());
  EXPECT_EQ(curve.components.size(), 1u);
}

}  // namespace
}  // namespace genmod
