// Branch and prune (Algorithm 5.1) end to end: snyder.md section 11 claims 14-18, statuses,
// limits, bad input, determinism across thread counts, free parameters.
#include "genmod/solvers/constraint_solver.hpp"
#include "solvers/solver_test_util.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>
#include <numbers>
#include <random>

namespace genmod {
namespace {

using test::covered;

const int kU[] = {0, 1};
const Fn X = x(0), Y = x(1);
const Box kSquare = {Interval(-2, 2), Interval(-2, 2)};

SolveOptions plain(double eps) {  // the thesis baseline: bisection only
  SolveOptions o;
  o.epsilon = eps;
  o.use_hc4 = o.use_newton = false;
  return o;
}

double area(const SolveResult& r) {
  double a = 0;
  for (const SolutionBox& b : r.boxes) a += b.box[0].width() * b.box[1].width();
  return a;
}

// Claim 14: superset (1000 circle points covered, every box near the circle) and emptiness.
TEST(ConstraintSolver, Claim14SupersetAndEmptiness) {
  for (bool contracting : {false, true}) {
    SolveOptions o = plain(1.0 / 64);
    o.use_hc4 = o.use_newton = contracting;
    SolveResult r = solve(eq(square(X) + square(Y), 1.0), kU, kSquare, o);
    ASSERT_TRUE(r.complete());
    for (int i = 0; i < 1000; ++i) {
      const double t = 2 * std::numbers::pi * i / 1000;
      EXPECT_TRUE(covered(r, {std::cos(t), std::sin(t)}, 1e-15)) << i;
    }
    for (const SolutionBox& b : r.boxes) {  // |x^2 + y^2 - 1| <= K w on the box
      const double w = width(b.box);
      const double lo = std::hypot(std::max({0.0, b.box[0].lo(), -b.box[0].hi()}), std::max({0.0, b.box[1].lo(), -b.box[1].hi()}));
      const double hi = std::hypot(std::max(std::abs(b.box[0].lo()), std::abs(b.box[0].hi())),
                                   std::max(std::abs(b.box[1].lo()), std::abs(b.box[1].hi())));
      EXPECT_LE(lo, 1.0);
      EXPECT_GE(hi, 1.0);
      EXPECT_LT(w, 1.0 / 64);
    }
  }
  SolveResult none = solve(eq(square(X) + square(Y) + 1.0, 0.0), kU, kSquare, plain(1e-3));
  EXPECT_TRUE(none.boxes.empty());
  EXPECT_TRUE(none.complete());
}

// Claim 15: area shrinks with epsilon (roughly in proportion); the disk's inner boxes.
TEST(ConstraintSolver, Claim15ConvergenceAndFeasibility) {
  double previous = 1e9;
  for (int k = 4; k <= 10; ++k) {
    SolveResult r = solve(eq(square(X) + square(Y), 1.0), kU, kSquare, plain(std::ldexp(1.0, -k)));
    const double a = area(r);
    EXPECT_LT(a, previous);
    EXPECT_LT(a, 2 * std::numbers::pi * 2 * std::ldexp(1.0, -k) * 1.5);  // ~ perimeter * eps
    previous = a;
  }
  double last_total = 1e9;
  for (int k : {3, 5, 7}) {
    SolveResult r = solve(square(X) + square(Y) < 1.0, kU, kSquare, plain(std::ldexp(1.0, -k)));
    double feasible = 0, total = 0;
    for (const SolutionBox& b : r.boxes) {
      const double a = b.box[0].width() * b.box[1].width();
      total += a;
      if (b.status == SolutionStatus::Feasible) {
        feasible += a;
        // Inner boxes lie inside the disk.
        EXPECT_LE(std::hypot(std::max(std::abs(b.box[0].lo()), std::abs(b.box[0].hi())),
                             std::max(std::abs(b.box[1].lo()), std::abs(b.box[1].hi()))), 1.0);
      } else {
        EXPECT_EQ(b.status, SolutionStatus::Boundary);
      }
    }
    EXPECT_LE(feasible, std::numbers::pi);
    EXPECT_GE(total, std::numbers::pi);
    EXPECT_LT(total, last_total);
    last_total = total;
  }
  EXPECT_LT(last_total - std::numbers::pi, 0.1);
}

// Claim 16: (x^2 - 1, y^2 - 1) = 0 aggregates into 4 disjoint components around (±1, ±1).
TEST(ConstraintSolver, Claim16AggregationCount) {
  for (bool contracting : {false, true}) {
    SolveOptions o = plain(1e-6);
    o.use_hc4 = o.use_newton = contracting;
    SolveResult r = solve(eq(square(X), 1.0) && eq(square(Y), 1.0), kU, kSquare, o);
    ASSERT_EQ(r.components.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_LE(width(r.components[i].hull), 4e-6);
      int inside = 0;
      for (double a : {-1.0, 1.0})
        for (double b : {-1.0, 1.0}) inside += contains(r.components[i].hull, std::vector<double>{a, b});
      EXPECT_EQ(inside, 1);
      for (std::size_t j = i + 1; j < 4; ++j) EXPECT_FALSE(touches(r.components[i].hull, r.components[j].hull));
    }
    if (contracting) {
      EXPECT_EQ(r.unique_components(), 4u);
    }
  }
}

// Claim 17: cyclic subdivision splits dimension (d mod n) + 1 at exactly (a + b) / 2.
TEST(ConstraintSolver, Claim17CyclicSubdivision) {
  EXPECT_EQ(cyclic_next(2, 3), 0u);  // initial d = n: the first split is in dimension 1
  EXPECT_EQ(cyclic_next(0, 3), 1u);
  EXPECT_EQ(cyclic_next(1, 3), 2u);
  const Box b = {Interval(0.25, 3.0), Interval(-1, 5), Interval(2, 2.5)};
  for (std::size_t d = 0; d < 3; ++d) {
    const auto [lo, hi] = bisect(b, d);
    EXPECT_EQ(lo[d].hi(), (b[d].lo() + b[d].hi()) / 2);
    EXPECT_EQ(hi[d].lo(), lo[d].hi());
    EXPECT_EQ(hull(lo, hi), b);
    for (std::size_t k = 0; k < 3; ++k) {
      if (k != d) {
        EXPECT_TRUE(lo[k] == b[k] && hi[k] == b[k]);
      }
    }
  }
  // The solver's boxes under plain cyclic bisection are dyadic cells of the initial box.
  SolveResult r = solve(eq(X + Y, 0.3), kU, {Interval(0, 1), Interval(0, 1)}, plain(1.0 / 16));
  for (const SolutionBox& s : r.boxes) {
    EXPECT_EQ(std::fmod(s.box[0].lo() * 32, 1.0), 0.0);
    EXPECT_EQ(std::fmod(s.box[1].lo() * 32, 1.0), 0.0);
  }
}

// Claim 18: tags give identical results with strictly fewer relational evaluations.
TEST(ConstraintSolver, Claim18TagEnhancement) {
  const Fn c = (square(X) + square(Y) < 1.0) && (X > -0.5) && (Y < X + 0.7);
  SolveOptions with = plain(1.0 / 128), without = with;
  without.use_tags = false;
  SolveResult a = solve(c, kU, kSquare, with), b = solve(c, kU, kSquare, without);
  ASSERT_EQ(a.boxes.size(), b.boxes.size());
  for (std::size_t i = 0; i < a.boxes.size(); ++i) {
    EXPECT_EQ(a.boxes[i].box, b.boxes[i].box);
    EXPECT_EQ(a.boxes[i].status, b.boxes[i].status);
  }
  EXPECT_LT(a.stats.atom_evaluations, b.stats.atom_evaluations);
}

// Every status, rule and discipline keeps every solution; certified counts match.
TEST(ConstraintSolver, RulesAndDisciplinesAgree) {
  const Fn c = eq(square(X) + square(Y), 1.0) && eq(Y, X * X * X);
  // y = x^3 on the unit circle: x^2 + x^6 = 1, x = ±0.826031357654187...
  const double x0 = 0.82603135765418707;
  for (Subdivision rule : {Subdivision::Cyclic, Subdivision::Widest, Subdivision::Smear})
    for (Discipline order : {Discipline::Fifo, Discipline::Lifo, Discipline::Priority}) {
      SolveOptions o;
      o.epsilon = 1e-9;
      o.rule = rule;
      o.order = order;
      SolveResult r = solve(c, kU, kSquare, o);
      EXPECT_TRUE(covered(r, {x0, x0 * x0 * x0}, 1e-12));
      EXPECT_TRUE(covered(r, {-x0, -x0 * x0 * x0}, 1e-12));
      EXPECT_EQ(r.unique_components(), 2u);
      EXPECT_EQ(r.components.size(), 2u);
    }
}

// Determinism: bitwise identical output for 1 and 2 threads.
TEST(ConstraintSolver, IdenticalForAnyThreadCount) {
  const Fn c = eq(sin(3.0 * X) + Y * Y, 0.5) || (square(X - 1.0) + square(Y) < 0.1);
  SolveOptions o;
  o.epsilon = 1e-2;
  o.batch = 16;
  o.threads = 1;
  SolveResult a = solve(c, kU, kSquare, o);
  o.threads = 2;
  SolveResult b = solve(c, kU, kSquare, o);
  ASSERT_EQ(a.boxes.size(), b.boxes.size());
  for (std::size_t i = 0; i < a.boxes.size(); ++i) {
    EXPECT_EQ(a.boxes[i].status, b.boxes[i].status);
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_EQ(a.boxes[i].box[k].lo(), b.boxes[i].box[k].lo());
      EXPECT_EQ(a.boxes[i].box[k].hi(), b.boxes[i].box[k].hi());
    }
  }
  EXPECT_EQ(a.report.boxes_processed, b.report.boxes_processed);
  EXPECT_EQ(a.components.size(), b.components.size());
}

// Limits are reported, and what was not explored is returned (nothing lost).
TEST(ConstraintSolver, LimitsAreReported) {
  const Fn circle = eq(square(X) + square(Y), 1.0);
  SolveOptions o = plain(1e-6);
  o.limits.max_boxes = 50;
  SolveResult r = solve(circle, kU, kSquare, o);
  EXPECT_EQ(r.report.limit, LimitHit::MaxBoxes);
  EXPECT_EQ(r.report.boxes_processed, 50u);
  EXPECT_GT(r.box_count(SolutionStatus::Unexplored), 0u);
  for (int i = 0; i < 360; ++i) {
    const double t = 2 * std::numbers::pi * i / 360;
    EXPECT_TRUE(covered(r, {std::cos(t), std::sin(t)}, 1e-15));
  }
  o = plain(1e-9);
  o.limits.max_depth = 6;
  r = solve(circle, kU, kSquare, o);
  EXPECT_EQ(r.report.limit, LimitHit::MaxDepth);
  EXPECT_LE(r.report.deepest, 6);
  EXPECT_TRUE(covered(r, {1.0, 0.0}));
  o = plain(1e-12);
  o.limits.time_limit = 1e-9;
  r = solve(eq(sin(X * Y), 0.1), kU, kSquare, o);
  EXPECT_EQ(r.report.limit, LimitHit::TimeLimit);
  EXPECT_FALSE(r.complete());
}

// A caller's stop request (SearchLimits::cancel, what Python's Ctrl-C sets) stops the search
// at its next round, reported as Cancelled, with every solution still covered.
TEST(ConstraintSolver, CancellationStopsTheSearchAndKeepsEverySolution) {
  const Fn circle = eq(square(X) + square(Y), 1.0);
  std::atomic<bool> stop{true};
  SolveOptions o = plain(1e-6);
  o.limits.cancel = &stop;
  SolveResult r = solve(circle, kU, kSquare, o);
  EXPECT_EQ(r.report.limit, LimitHit::Cancelled);
  EXPECT_EQ(limit_name(r.report.limit), "cancelled");
  EXPECT_FALSE(r.complete());
  for (int i = 0; i < 360; ++i) {
    const double t = 2 * std::numbers::pi * i / 360;
    EXPECT_TRUE(covered(r, {std::cos(t), std::sin(t)}, 1e-15));
  }
  // Set from another thread while a long search runs (one that would take minutes).
  stop = false;
  o = plain(1e-12);
  o.limits.max_boxes = std::numeric_limits<std::size_t>::max();
  o.limits.time_limit = 600;
  o.limits.cancel = &stop;
  std::thread canceller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    stop = true;
  });
  r = solve(circle, kU, kSquare, o);
  canceller.join();
  EXPECT_EQ(r.report.limit, LimitHit::Cancelled);
  EXPECT_LT(r.report.seconds, 60.0);
  for (int i = 0; i < 360; ++i) {
    const double t = 2 * std::numbers::pi * i / 360;
    EXPECT_TRUE(covered(r, {std::cos(t), std::sin(t)}, 1e-15));
  }
}

// Issue 10, failure 5: a box that max_depth stopped from being split was not accepted (it is
// wider than epsilon): it is Unexplored like every box a limit leaves, never Possible or
// Boundary, and the search is not complete.
TEST(ConstraintSolver, DepthLimitedBoxesAreUnexplored) {
  SolveOptions o = plain(1e-9);
  o.limits.max_depth = 6;
  for (const Fn& c : {eq(square(X) + square(Y), 1.0), square(X) + square(Y) <= 1.0}) {
    const SolveResult r = solve(c, kU, kSquare, o);
    EXPECT_EQ(r.report.limit, LimitHit::MaxDepth);
    EXPECT_FALSE(r.complete());
    EXPECT_GT(r.box_count(SolutionStatus::Unexplored), 0u);
    EXPECT_EQ(r.box_count(SolutionStatus::Possible), 0u);
    EXPECT_EQ(r.box_count(SolutionStatus::Boundary), 0u);
    for (const SolutionBox& b : r.boxes) {
      if (b.status == SolutionStatus::Unexplored) {
        EXPECT_EQ(b.depth, 6);
        EXPECT_GT(width(b.box), o.epsilon);
      }
    }
    for (int i = 0; i < 360; ++i) {
      const double t = 2 * std::numbers::pi * i / 360;
      EXPECT_TRUE(covered(r, {std::cos(t), std::sin(t)}, 1e-15)) << i;
    }
  }
}

TEST(ConstraintSolver, BadInput) {
  const Fn c = eq(X, Y);
  const double nan = std::nan("");
  EXPECT_THROW(solve(c, kU, {Interval(0, 1), Interval(nan)}, {}), std::invalid_argument);  // NaN side
  EXPECT_THROW(solve(c, kU, {Interval(0, 1)}, {}), std::invalid_argument);                  // dimension
  EXPECT_THROW(solve(c, kU, {Interval(0, 1), Interval::entire()}, {}), std::invalid_argument);
  SolveOptions o;
  for (double eps : {0.0, -1e-3, nan}) {
    o.epsilon = eps;
    EXPECT_THROW(solve(c, kU, kSquare, o), std::invalid_argument);
  }
  o = {};
  o.delta = 0;
  EXPECT_THROW(solve(c, kU, kSquare, o), std::invalid_argument);
  o = {};
  o.batch = 0;
  EXPECT_THROW(solve(c, kU, kSquare, o), std::invalid_argument);
  const int one[] = {0}, twice[] = {0, 0};
  EXPECT_THROW(solve(c, one, {Interval(0, 1)}, {}), std::invalid_argument);  // depends on x(1)
  EXPECT_THROW(solve(c, twice, kSquare, {}), std::invalid_argument);
  EXPECT_THROW(solve(cat({X, Y}), kU, kSquare, {}), std::invalid_argument);  // not scalar
  try {
    solve(c, one, {Interval(0, 1)}, {});
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("x(1)"), std::string::npos);
  }
  // Unsatisfiable: an empty, complete result.
  SolveResult r = solve((X > 1.0) && (X < 0.0), kU, kSquare, {});
  EXPECT_TRUE(r.boxes.empty());
  EXPECT_TRUE(r.complete());
  // Errors are not solutions: sqrt of a negative never satisfies.
  r = solve(eq(sqrt(X - 5.0), 0.0), kU, kSquare, {});
  EXPECT_TRUE(r.boxes.empty());
}

// Free parameters: x^2 = p for p in [1, 4]: every solution x in [1, 2] is covered, and with
// a narrow parameter interval the root is certified for every p in it.
TEST(ConstraintSolver, FreeParameters) {
  const int u[] = {0};
  const Fn c = eq(square(X), x(5));
  FreeParameters p{{5}, {Interval(1, 4)}};
  SolveOptions o;
  o.epsilon = 1e-3;
  SolveResult r = solve(c, u, {Interval(0, 3)}, o, p);
  for (int i = 0; i <= 100; ++i) EXPECT_TRUE(covered(r, {1.0 + i / 100.0}));
  p.values = {Interval(2.0, 2.0 + 1e-12)};
  o.epsilon = 1e-6;
  r = solve(c, u, {Interval(-3, 3)}, o, p);
  EXPECT_EQ(r.unique_components(), 2u);
  EXPECT_TRUE(covered(r, {std::sqrt(2.0)}, 1e-12));
  EXPECT_THROW(solve(c, u, {Interval(0, 3)}, o, FreeParameters{{5}, {}}), std::invalid_argument);
}

TEST(Aggregation, MergesTouchingAndHullOverlaps) {
  std::vector<Box> boxes = {
      {Interval(0, 1), Interval(0, 1)},     {Interval(1, 2), Interval(0.5, 1.5)},  // touch
      {Interval(5, 6), Interval(5, 6)},                                          // alone
      {Interval(1.8, 1.9), Interval(-1, 0.2)},  // touches only the hull of the first pair
      {Interval(3, 3), Interval(3, 3)},
  };
  std::vector<Aggregate> g = aggregate(boxes);
  ASSERT_EQ(g.size(), 3u);
  EXPECT_EQ(g[0].members, (std::vector<std::size_t>{0, 1, 3}));
  EXPECT_EQ(g[1].members, (std::vector<std::size_t>{2}));
  EXPECT_EQ(g[2].members, (std::vector<std::size_t>{4}));
  EXPECT_EQ(g[0].hull, (Box{Interval(0, 2), Interval(-1, 1.5)}));
  EXPECT_EQ(aggregate(boxes, 1.5).size(), 2u);  // (3,3) joins; (5,6) is 2 away
  EXPECT_EQ(aggregate(boxes, 2.0).size(), 1u);
  EXPECT_THROW(aggregate(std::vector<Box>{{Interval(0, 1)}, {Interval(0, 1), Interval(0, 1)}}), std::invalid_argument);
}

}  // namespace
}  // namespace genmod
