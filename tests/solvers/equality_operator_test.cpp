// `f == c` in a constraint is the relation (issue: it used to compare handles, turn the C++
// bool into the constant 0, and return no box, marked complete).
#include "genmod/solvers/constraint_solver.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace genmod {
namespace {

SolveOptions accepting(double epsilon) {
  SolveOptions o;
  o.epsilon = epsilon;
  return o;
}

TEST(EqualityOperator, SolveFindsTheRootOfXEqualsAHalf) {
  const std::vector<int> unknowns{0};
  const SolveResult r = solve(x(0) == 0.5, unknowns, Box{Interval(0, 1)}, accepting(1e-6));
  ASSERT_TRUE(r.complete());
  ASSERT_FALSE(r.boxes.empty());
  bool holds = false;
  for (const SolutionBox& b : r.boxes) {
    holds = holds || b.box[0].contains(0.5);
    EXPECT_LE(b.box[0].width(), 1e-6);
  }
  EXPECT_TRUE(holds);
  // != is the complement: everything but the point.
  const SolveResult other = solve(x(0) != 0.5, unknowns, Box{Interval(0, 1)}, accepting(1e-3));
  ASSERT_TRUE(other.complete());
  double covered = 0;
  for (const SolutionBox& b : other.boxes) covered += b.box[0].width();
  EXPECT_GT(covered, 0.99);
}

}  // namespace
}  // namespace genmod
