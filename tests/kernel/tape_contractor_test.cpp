// TapeContractor (HC4-revise on a tape): never removes a point where f is a number in the
// target, rejects boxes where f cannot reach it, and narrows where it can.
#include "genmod/kernel/tape_contractor.hpp"

#include "genmod/kernel/point_evaluator.hpp"
#include "kernel/random_functions.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace genmod {
namespace {

bool inside(std::span<const Interval> box, std::span<const double> p) {
  for (std::size_t i = 0; i < box.size(); ++i)
    if (!box[i].contains(p[i])) return false;
  return true;
}

TEST(TapeContractor, NarrowsTheCircleBoxAndRejectsAnEmptyOne) {
  const Tape t(square(x(0)) + square(x(1)), {0, 1});
  TapeContractor ctc;
  std::vector<Interval> box = {Interval(0.9, 2.0), Interval(-0.1, 0.1)};
  ASSERT_TRUE(ctc.contract(t, box, Interval(1.0), 2));
  EXPECT_LE(box[0].hi(), 1.0);
  EXPECT_GE(box[0].lo(), 0.99);
  std::vector<Interval> far = {Interval(1.5, 2.0), Interval(1.5, 2.0)};
  EXPECT_FALSE(ctc.contract(t, far, Interval(1.0), 2));
}

TEST(TapeContractor, ReadsButNeverNarrowsParameters) {
  const Tape t(x(0) - x(1), {0, 1});  // x(1) is a parameter
  TapeContractor ctc;
  std::vector<Interval> box = {Interval(-5.0, 5.0), Interval(1.0, 2.0)};
  ASSERT_TRUE(ctc.contract(t, box, Interval(0.0), 1));
  EXPECT_EQ(box[0].lo(), 1.0);
  EXPECT_EQ(box[0].hi(), 2.0);
  EXPECT_EQ(box[1].lo(), 1.0);
  EXPECT_EQ(box[1].hi(), 2.0);
}

// A certain error of f (the evaluator's error bits) is no solution; an error in a branch that
// a select does not take hides nothing.
TEST(TapeContractor, UsesTheEvaluatorsErrorBits) {
  TapeContractor ctc;
  std::vector<Interval> box = {Interval(-3.0, -1.0)};
  EXPECT_FALSE(ctc.contract(Tape(sqrt(x(0))), box, Interval::entire(), 1));
  box = {Interval(-3.0, -1.0)};
  const Fn masked = select(x(0) < 0.0, Fn(0.0), sqrt(x(0)));
  EXPECT_TRUE(ctc.contract(Tape(masked), box, Interval(0.0), 1));
  EXPECT_EQ(box[0].lo(), -3.0);
}

// select(x < 0, 1, sqrt(x)) - 1 is 0 at x = -1, where sqrt(x) is an error that the select
// does not take: projecting through sqrt would cut x to [0, 2] and lose that solution.
TEST(TapeContractor, DoesNotProjectBelowAClauseThatHidesErrors) {
  const Tape t(select(x(0) < 0.0, Fn(1.0), sqrt(x(0))) - 1.0);
  EXPECT_FALSE(TapeContractor::projects(t));
  EXPECT_TRUE(TapeContractor::projects(Tape(sqrt(x(0)) - 1.0)));
  TapeContractor ctc;
  std::vector<Interval> box = {Interval(-2.0, 2.0)};
  ASSERT_TRUE(ctc.contract(t, box, Interval(0.0), 1));
  EXPECT_TRUE(box[0].contains(-1.0));
  EXPECT_TRUE(box[0].contains(1.0));
}

TEST(TapeContractor, RefusesSeveralOutputsAndAWrongBox) {
  TapeContractor ctc;
  std::vector<Interval> box = {Interval(0.0, 1.0)};
  EXPECT_THROW(ctc.contract(Tape(cat({x(0), x(0)})), box, Interval(0.0), 1), std::invalid_argument);
  std::vector<Interval> two = {Interval(0.0, 1.0), Interval(0.0, 1.0)};
  EXPECT_THROW(ctc.contract(Tape(x(0)), two, Interval(0.0), 1), std::invalid_argument);
}

// Random functions over every opcode: for a target around f at a sample point, every sampled
// point where f is a number in the target stays in the contracted box.
TEST(TapeContractor, NeverRemovesASolutionOfRandomFunctions) {
  testing::RandomFunctions gen(2027, 2);
  PointEvaluator pe;
  TapeContractor ctc;
  int solutions = 0, narrowed = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const Fn f = gen.function(5);
    const std::vector<int> inputs = {0, 1};
    const Tape tape(f, inputs);
    const std::vector<Interval> original = {gen.small_interval(), gen.small_interval()};
    std::vector<double> p0 = {gen.sample(original[0], gen.integer(0, 5)), gen.sample(original[1], gen.integer(0, 5))};
    const double f0 = pe.eval(tape, p0)[0];
    if (!std::isfinite(f0)) continue;
    const double w = gen.integer(0, 2) == 0 ? 0.0 : gen.uniform(0.0, 0.5);
    const Interval target(f0 - w, f0 + w);
    std::vector<Interval> box = original;
    ASSERT_TRUE(ctc.contract(tape, box, target, 2)) << "rejected a box holding a solution, trial " << trial;
    if (box[0].width() < original[0].width() || box[1].width() < original[1].width()) ++narrowed;
    ASSERT_TRUE(inside(box, p0)) << "removed the sample point, trial " << trial;
    for (int s = 0; s < 40; ++s) {
      const std::vector<double> p = {gen.sample(original[0], s), gen.sample(original[1], s + 1)};
      const double v = pe.eval(tape, p)[0];
      if (std::isnan(v) || !target.contains(v)) continue;
      ++solutions;
      ASSERT_TRUE(inside(box, p)) << "removed a solution, trial " << trial << " sample " << s;
    }
  }
  EXPECT_GT(solutions, 1000);
  EXPECT_GT(narrowed, 100);  // the contractor does narrow
}

}  // namespace
}  // namespace genmod
