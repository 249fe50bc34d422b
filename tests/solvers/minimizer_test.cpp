// Global minimization (Algorithm 5.2): snyder.md section 11 claims 21-23, limits, errors.
#include "genmod/solvers/minimizer.hpp"

#include <gtest/gtest.h>

#include <atomic>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace genmod {
namespace {

const int kXY[] = {0, 1};

Box square_box(double lo, double hi) { return {Interval(lo, hi), Interval(lo, hi)}; }

// True if some candidate box, widened by tol, contains the point.
bool covered(const MinimizeResult& r, std::span<const double> p, double tol = 1e-9) {
  for (const Box& b : r.candidates) {
    bool in = true;
    for (std::size_t i = 0; i < p.size(); ++i) in = in && b[i].lo() - tol <= p[i] && p[i] <= b[i].hi() + tol;
    if (in) return true;
  }
  return false;
}

Fn claim21_objective() { return square(x(0) - 0.3) + square(x(1) + 0.2); }

struct Trace {
  std::vector<MinimizeStep> steps;
  void attach(MinimizeOptions& opt) {
    opt.on_step = [this](const MinimizeStep& s) { steps.push_back(s); };
  }
  // Claim 21: l_n <= f* <= u_n, l_n nondecreasing, u_n nonincreasing.
  void check(double f_star) const {
    ASSERT_FALSE(steps.empty());
    for (std::size_t n = 0; n < steps.size(); ++n) {
      EXPECT_LE(steps[n].lower, f_star) << "step " << n;
      EXPECT_GE(steps[n].upper, f_star) << "step " << n;
      if (n > 0) {
        EXPECT_GE(steps[n].lower, steps[n - 1].lower) << "l_n decreased at step " << n;
        EXPECT_LE(steps[n].upper, steps[n - 1].upper) << "u_n increased at step " << n;
      }
    }
  }
};

TEST(Minimizer, Claim21BracketInvariantUnconstrained) {
  MinimizeOptions opt;
  Trace trace;
  trace.attach(opt);
  const MinimizeResult r = minimize(claim21_objective(), Fn(1.0), kXY, square_box(-1, 1), opt);
  trace.check(0.0);
  EXPECT_TRUE(r.minimum.contains(0.0)) << r.minimum;
  EXPECT_TRUE(r.feasible_found);
  EXPECT_TRUE(r.delta_reached);
  EXPECT_LE(r.minimum.hi() - r.minimum.lo(), opt.delta);
  EXPECT_EQ(r.report.limit, LimitHit::None);
  const double minimizer[] = {0.3, -0.2};
  EXPECT_TRUE(covered(r, minimizer));
  for (const Box& b : r.candidates) EXPECT_LE(width(b), opt.epsilon);
  ASSERT_EQ(r.best_point.size(), 2u);
  EXPECT_NEAR(r.best_point[0], 0.3, 1e-3);
  EXPECT_NEAR(r.best_point[1], -0.2, 1e-3);
}

TEST(Minimizer, Claim21BracketInvariantWithConstraint) {
  // x + y >= 1: f* = 0.9^2 / 2 = 0.405 at (0.75, 0.25).
  MinimizeOptions opt;
  Trace trace;
  trace.attach(opt);
  const Fn c = x(0) + x(1) >= 1.0;
  const MinimizeResult r = minimize(claim21_objective(), c, kXY, square_box(-1, 1), opt);
  trace.check(0.405);
  EXPECT_TRUE(r.minimum.contains(0.405)) << r.minimum;
  EXPECT_TRUE(r.feasible_found);
  EXPECT_LE(r.minimum.hi() - r.minimum.lo(), opt.delta);
  const double minimizer[] = {0.75, 0.25};
  EXPECT_TRUE(covered(r, minimizer));
  // The best point is proven feasible.
  ASSERT_EQ(r.best_point.size(), 2u);
  EXPECT_GE(r.best_point[0] + r.best_point[1], 1.0);
  EXPECT_NEAR(r.best_point[0], 0.75, 1e-2);
  EXPECT_NEAR(r.best_point[1], 0.25, 1e-2);
}

TEST(Minimizer, Claim22BracketShrinksWithEpsilon) {
  double previous = std::numeric_limits<double>::infinity();
  for (double eps : {1e-2, 1e-4, 1e-7}) {
    MinimizeOptions opt;
    opt.epsilon = eps;
    opt.delta = eps;
    const MinimizeResult r = minimize(claim21_objective(), Fn(1.0), kXY, square_box(-1, 1), opt);
    EXPECT_EQ(r.report.limit, LimitHit::None);
    const double w = r.minimum.hi() - r.minimum.lo();
    EXPECT_TRUE(r.minimum.contains(0.0));
    EXPECT_LE(w, previous);
    previous = w;
    if (eps == 1e-7) {
      EXPECT_LT(w, 1e-6);
    }
  }
  // The constrained example too.
  MinimizeOptions opt;
  opt.epsilon = 1e-7;
  opt.delta = 1e-7;
  const MinimizeResult r = minimize(claim21_objective(), x(0) + x(1) >= 1.0, kXY, square_box(-1, 1), opt);
  EXPECT_TRUE(r.minimum.contains(0.405)) << r.minimum;
  EXPECT_LT(r.minimum.hi() - r.minimum.lo(), 1e-6);
}

TEST(Minimizer, Claim23MonotonicityTest) {
  const Fn f = x(0) + square(x(1));
  MinimizeOptions with, without;
  without.monotonicity_test = false;
  const MinimizeResult a = minimize(f, Fn(1.0), kXY, square_box(0, 1), with);
  const MinimizeResult b = minimize(f, Fn(1.0), kXY, square_box(0, 1), without);
  // Same answer: both brackets contain f* = 0 and meet the target; both cover (0, 0).
  const double minimizer[] = {0.0, 0.0};
  for (const MinimizeResult* r : {&a, &b}) {
    EXPECT_TRUE(r->minimum.contains(0.0)) << r->minimum;
    EXPECT_LE(r->minimum.hi() - r->minimum.lo(), with.delta);
    EXPECT_TRUE(covered(*r, minimizer, 0.0));
    EXPECT_EQ(r->report.limit, LimitHit::None);
  }
  EXPECT_TRUE(overlaps(a.minimum, b.minimum));
  // With the test, the box touching x = 0 is reduced to that face: every candidate has x = 0.
  EXPECT_GE(a.monotone_reductions, 1u);
  for (const Box& c : a.candidates) EXPECT_EQ(c[0], Interval(0.0));
  EXPECT_EQ(b.monotone_reductions + b.monotone_discards, 0u);
  EXPECT_LT(a.report.boxes_processed, b.report.boxes_processed);
}

TEST(Minimizer, MonotonicityTestDiscardsInteriorFeasibleBoxes) {
  // f = x + y^2 on [0,1]^2 outside the disc of radius 0.25 around (0.5, 0): boxes strictly
  // outside the disc and away from x = 0 are discarded by the test; the minimizer (0, 0) stays.
  const Fn f = x(0) + square(x(1));
  const Fn c = square(x(0) - 0.5) + square(x(1)) >= 0.0625;
  const MinimizeResult r = minimize(f, c, kXY, square_box(0, 1));
  EXPECT_TRUE(r.minimum.contains(0.0)) << r.minimum;
  const double minimizer[] = {0.0, 0.0};
  EXPECT_TRUE(covered(r, minimizer, 0.0));
  EXPECT_GE(r.monotone_discards + r.monotone_reductions, 1u);
}

TEST(Minimizer, MonotonicityTestKeepsActiveConstraints) {
  // f = x on [0, 1] with x >= 0.5: f increases on every box, but on boxes touching x = 0.5 the
  // constraint is active, so they must not be discarded.
  const int unknown[] = {0};
  const Box box = {Interval(0.0, 1.0)};
  MinimizeOptions opt;
  opt.epsilon = 1e-6;
  const MinimizeResult r = minimize(x(0), x(0) >= 0.5, unknown, box, opt);
  EXPECT_TRUE(r.minimum.contains(0.5)) << r.minimum;
  const double minimizer[] = {0.5};
  EXPECT_TRUE(covered(r, minimizer, 0.0));
}

TEST(Minimizer, MinimumValueVariantStopsEarly) {
  MinimizeOptions opt;
  opt.delta = 1e-4;
  const MinimizeResult full = minimize(claim21_objective(), Fn(1.0), kXY, square_box(-1, 1), opt);
  const MinimizeResult value = minimize_value(claim21_objective(), Fn(1.0), kXY, square_box(-1, 1), opt);
  EXPECT_TRUE(value.minimum.contains(0.0));
  EXPECT_LE(value.minimum.hi() - value.minimum.lo(), opt.delta);
  EXPECT_TRUE(value.delta_reached);
  EXPECT_LE(value.report.boxes_processed, full.report.boxes_processed);
  EXPECT_EQ(minimum_value(claim21_objective(), Fn(1.0), kXY, square_box(-1, 1), opt), value.minimum);
}

TEST(Minimizer, LimitsAreReportedAndBoundsStaySound) {
  // Six-hump camel with a tiny box budget: the bracket is wide but still contains f*.
  const Fn a = x(0), b = x(1);
  const Fn camel = (4.0 - 2.1 * square(a) + pow(a, 4.0) / 3.0) * square(a) + a * b + (-4.0 + 4.0 * square(b)) * square(b);
  const Box box = {Interval(-3, 3), Interval(-2, 2)};
  const double f_star = -1.0316284534898774;
  MinimizeOptions opt;
  opt.limits.max_boxes = 20;
  MinimizeResult r = minimize(camel, Fn(1.0), kXY, box, opt);
  EXPECT_EQ(r.report.limit, LimitHit::MaxBoxes);
  EXPECT_EQ(r.report.boxes_processed, 20u);
  EXPECT_TRUE(r.minimum.contains(f_star)) << r.minimum;
  EXPECT_FALSE(r.delta_reached);
  const double m1[] = {0.0898420131003, -0.7126564030207}, m2[] = {-0.0898420131003, 0.7126564030207};
  EXPECT_TRUE(covered(r, m1, 1e-9));
  EXPECT_TRUE(covered(r, m2, 1e-9));

  MinimizeOptions depth;
  depth.limits.max_depth = 6;
  r = minimize(camel, Fn(1.0), kXY, box, depth);
  EXPECT_EQ(r.report.limit, LimitHit::MaxDepth);
  EXPECT_TRUE(r.minimum.contains(f_star));
  EXPECT_TRUE(covered(r, m1, 1e-9));
  EXPECT_TRUE(covered(r, m2, 1e-9));

  MinimizeOptions time;
  time.limits.time_limit = 1e-9;
  r = minimize(camel, Fn(1.0), kXY, box, time);
  EXPECT_EQ(r.report.limit, LimitHit::TimeLimit);
  EXPECT_TRUE(r.minimum.contains(f_star));

  const std::atomic<bool> stop{true};
  MinimizeOptions cancelled;
  cancelled.limits.cancel = &stop;
  r = minimize(camel, Fn(1.0), kXY, box, cancelled);
  EXPECT_EQ(r.report.limit, LimitHit::Cancelled);
  EXPECT_TRUE(r.minimum.contains(f_star));
  EXPECT_TRUE(covered(r, m1, 1e-9));
  EXPECT_TRUE(covered(r, m2, 1e-9));
}

TEST(Minimizer, InfeasibleProblemIsProven) {
  const Fn c = square(x(0)) + square(x(1)) < -1.0;
  const MinimizeResult r = minimize(x(0), c, kXY, square_box(-1, 1));
  EXPECT_TRUE(r.infeasible);
  EXPECT_FALSE(r.feasible_found);
  EXPECT_TRUE(r.minimum.is_empty());
  EXPECT_TRUE(r.candidates.empty());
}

TEST(Minimizer, EqualityConstraintWithTolerance) {
  // min x + y on the unit circle: f* = -sqrt(2) at (-1/sqrt2, -1/sqrt2).
  const Fn c = eq(square(x(0)) + square(x(1)), Fn(1.0));
  MinimizeOptions exact;
  exact.limits.max_boxes = 2000;
  const MinimizeResult none = minimize_value(x(0) + x(1), c, kXY, square_box(-2, 2), exact);
  // Without relaxation the upper bound comes from boxes certified to hold a point of the circle
  // and the lower bound from the Lagrangian (ExactEqualityGetsCertifiedFeasiblePoints): well
  // within 2000 boxes, a bracket of width delta.
  EXPECT_EQ(none.report.limit, LimitHit::None);
  EXPECT_TRUE(none.delta_reached);
  EXPECT_TRUE(none.minimum.contains(-std::sqrt(2.0))) << none.minimum;
  if (none.feasible_found) {
    const double px = none.best_point[0], py = none.best_point[1];
    EXPECT_NEAR(px * px + py * py, 1.0, 1e-9);
  }

  MinimizeOptions opt;
  opt.equality_tolerance = 1e-6;
  opt.epsilon = 1e-5;
  opt.delta = 1e-4;
  const MinimizeResult r = minimize(x(0) + x(1), c, kXY, square_box(-2, 2), opt);
  ASSERT_TRUE(r.feasible_found);
  // lo bounds the exact problem from below; hi comes from a point with |x^2 + y^2 - 1| <= eta.
  EXPECT_LE(r.minimum.lo(), -std::sqrt(2.0));
  EXPECT_NEAR(r.minimum.hi(), -std::sqrt(2.0), 1e-4);
  EXPECT_LE(std::abs(r.best_point[0] * r.best_point[0] + r.best_point[1] * r.best_point[1] - 1.0), 1e-6 + 1e-12);
  const double minimizer[] = {-std::sqrt(0.5), -std::sqrt(0.5)};
  EXPECT_TRUE(covered(r, minimizer));
}

// Issue 10, failure 4: with an exact equality (eta = 0) the search used to split boxes down to
// machine precision until max_boxes. Interval Newton on the equality in a sub-box certifies
// boxes that hold a feasible point; their objective bound is a rigorous upper bound, so the
// search terminates with a bracket of width delta around f* = -sqrt(2).
TEST(Minimizer, ExactEqualityGetsCertifiedFeasiblePoints) {
  const Fn c = eq(square(x(0)) + square(x(1)), Fn(1.0));
  MinimizeOptions opt;
  opt.epsilon = 1e-3;
  opt.limits.max_boxes = 100000;
  const MinimizeResult r = minimize(x(0) + x(1), c, kXY, square_box(-2, 2), opt);
  EXPECT_EQ(r.report.limit, LimitHit::None);
  ASSERT_TRUE(r.feasible_found);
  EXPECT_GT(r.certified_points, 0u);
  EXPECT_TRUE(r.delta_reached);
  EXPECT_TRUE(r.minimum.contains(-std::sqrt(2.0))) << r.minimum;
  EXPECT_LE(r.minimum.width(), opt.delta);
  const double minimizer[] = {-std::sqrt(0.5), -std::sqrt(0.5)};
  EXPECT_TRUE(covered(r, minimizer));
  // best_point is the midpoint of a tiny certified box around a point on the circle.
  EXPECT_NEAR(r.best_point[0] * r.best_point[0] + r.best_point[1] * r.best_point[1], 1.0, 1e-9);
  // Two equalities in three unknowns: the circle x^2 + y^2 = 1 in the plane z = x; min x + y + z.
  const int xyz[] = {0, 1, 2};
  const Fn c3 = eq(square(x(0)) + square(x(1)), Fn(1.0)) && eq(x(2), x(0));
  const Box b3 = {Interval(-2, 2), Interval(-2, 2), Interval(-2, 2)};
  MinimizeOptions opt3 = opt;
  opt3.delta = 1e-5;
  const MinimizeResult r3 = minimize_value(x(0) + x(1) + x(2), c3, xyz, b3, opt3);
  EXPECT_EQ(r3.report.limit, LimitHit::None);
  ASSERT_TRUE(r3.feasible_found);
  EXPECT_GT(r3.certified_points, 0u);
  EXPECT_TRUE(r3.minimum.contains(-std::sqrt(5.0))) << r3.minimum;  // (2x + y) on the circle
  EXPECT_LE(r3.minimum.width(), opt3.delta);
}

// Issue 10, failure 3: Rosen-Suzuki (4 unknowns, 3 inequalities, [-3, 3]^4, f* = -44 at
// (0, 1, 2, -1), the first and third constraints active) converges well under 1e5 boxes, at
// the default delta too (before Newton's method on the KKT conditions gave u: 110,204 boxes).
TEST(Minimizer, RosenSuzukiConverges) {
  const Fn x1 = x(0), x2 = x(1), x3 = x(2), x4 = x(3);
  const Fn f = square(x1) + square(x2) + 2.0 * square(x3) + square(x4) - 5.0 * x1 - 5.0 * x2 - 21.0 * x3 + 7.0 * x4;
  const Fn g1 = square(x1) + square(x2) + square(x3) + square(x4) + x1 - x2 + x3 - x4 - 8.0;
  const Fn g2 = square(x1) + 2.0 * square(x2) + square(x3) + 2.0 * square(x4) - x1 - x4 - 10.0;
  const Fn g3 = 2.0 * square(x1) + square(x2) + square(x3) + 2.0 * x1 - x2 - x4 - 5.0;
  const Fn c = (g1 <= 0.0) && (g2 <= 0.0) && (g3 <= 0.0);
  const int u[] = {0, 1, 2, 3};
  const Box box(4, Interval(-3, 3));
  for (double delta : {1e-4, MinimizeOptions{}.delta}) {
    SCOPED_TRACE(delta);
    MinimizeOptions opt;
    opt.epsilon = 1e-4;
    opt.delta = delta;
    opt.limits.max_boxes = 50000;
    const MinimizeResult r = minimize(f, c, u, box, opt);
    EXPECT_EQ(r.report.limit, LimitHit::None) << r.report.boxes_processed;
    ASSERT_TRUE(r.feasible_found);
    EXPECT_TRUE(r.minimum.contains(-44.0)) << r.minimum;
    EXPECT_LE(r.minimum.width(), opt.delta);
    const double minimizer[] = {0.0, 1.0, 2.0, -1.0};
    EXPECT_TRUE(covered(r, minimizer));
  }
}

// The two halves of each split are bounded in parallel and entered in order: the result is
// bitwise the same for 1 and 2 threads, with inequalities (Rosen-Suzuki, HC4 and the
// Lagrangian bound) and with an exact equality (the feasible-point certifier).
TEST(Minimizer, SameResultForOneAndTwoThreads) {
  const Fn x1 = x(0), x2 = x(1), x3 = x(2), x4 = x(3);
  const Fn rosen_suzuki = square(x1) + square(x2) + 2.0 * square(x3) + square(x4) - 5.0 * x1 - 5.0 * x2 - 21.0 * x3 + 7.0 * x4;
  const Fn rosen_suzuki_constraint =
      (square(x1) + square(x2) + square(x3) + square(x4) + x1 - x2 + x3 - x4 - 8.0 <= 0.0) &&
      (square(x1) + 2.0 * square(x2) + square(x3) + 2.0 * square(x4) - x1 - x4 - 10.0 <= 0.0) &&
      (2.0 * square(x1) + square(x2) + square(x3) + 2.0 * x1 - x2 - x4 - 5.0 <= 0.0);
  struct Problem {
    Fn f, c;
    std::vector<int> unknowns;
    Box box;
    double delta;
  };
  const Problem problems[] = {
      {rosen_suzuki, rosen_suzuki_constraint, {0, 1, 2, 3}, Box(4, Interval(-3, 3)), 1e-3},
      {x1 + x2, eq(square(x1) + square(x2), 1.0), {0, 1}, Box(2, Interval(-2, 2)), 1e-6}};
  for (const Problem& p : problems) {
    MinimizeOptions opt;
    opt.delta = p.delta;
    opt.epsilon = 1e-3;
    std::vector<MinimizeResult> r;
    for (int threads : {1, 2, 1}) {
      opt.threads = threads;
      r.push_back(minimize(p.f, p.c, p.unknowns, p.box, opt));
    }
    EXPECT_TRUE(r[0].feasible_found);
    for (std::size_t k = 1; k < r.size(); ++k) {
      SCOPED_TRACE(k);
      EXPECT_EQ(r[k].minimum.lo(), r[0].minimum.lo());
      EXPECT_EQ(r[k].minimum.hi(), r[0].minimum.hi());
      EXPECT_EQ(r[k].best_point, r[0].best_point);
      EXPECT_EQ(r[k].report.boxes_processed, r[0].report.boxes_processed);
      EXPECT_EQ(r[k].certified_points, r[0].certified_points);
      ASSERT_EQ(r[k].candidates.size(), r[0].candidates.size());
      for (std::size_t i = 0; i < r[0].candidates.size(); ++i)
        for (std::size_t j = 0; j < p.unknowns.size(); ++j) {
          EXPECT_EQ(r[k].candidates[i][j].lo(), r[0].candidates[i][j].lo());
          EXPECT_EQ(r[k].candidates[i][j].hi(), r[0].candidates[i][j].hi());
        }
    }
  }
  MinimizeOptions bad;
  bad.threads = -1;
  EXPECT_THROW(minimize(x1, Fn(1.0), {0}, {Interval(0, 1)}, bad), std::invalid_argument);
}

TEST(Minimizer, ObjectiveErrorsAreNotFeasiblePoints) {
  // sqrt(x) - x is undefined for x < 0; the minimum over its domain [0, 2] is at x = 2.
  const int unknown[] = {0};
  const Box box = {Interval(-1.0, 2.0)};
  const MinimizeResult r = minimize(sqrt(x(0)) - x(0), Fn(1.0), unknown, box);
  const double f_star = std::sqrt(2.0) - 2.0;
  EXPECT_TRUE(r.minimum.contains(f_star)) << r.minimum;
  EXPECT_LE(r.minimum.hi() - r.minimum.lo(), 1e-6);
}

TEST(Minimizer, BadInputNamesTheProblem) {
  const Box box = square_box(-1, 1);
  auto expect_message = [](auto&& call, const std::string& part) {
    try {
      call();
      ADD_FAILURE() << "no exception, expected one mentioning '" << part << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  };
  expect_message([&] { minimize(cat({x(0), x(1)}), Fn(1.0), kXY, box); }, "scalar");
  expect_message([&] { minimize(x(0), cat({x(0), x(1)}), kXY, box); }, "constraint must be scalar");
  expect_message([&] { minimize(x(0) + x(2), Fn(1.0), kXY, box); }, "x(2)");
  expect_message([&] { minimize(x(0), Fn(1.0), kXY, Box{Interval(0, 1)}); }, "minimize");
  const int twice[] = {0, 0};
  expect_message([&] { minimize(x(0), Fn(1.0), twice, box); }, "twice");
  const Box nan_box = {Interval(0, 1), Interval::empty()};
  expect_message([&] { minimize(x(0), Fn(1.0), kXY, nan_box); }, "minimize");
  MinimizeOptions opt;
  opt.epsilon = 0.0;
  expect_message([&] { minimize(x(0), Fn(1.0), kXY, box, opt); }, "epsilon");
  opt = {};
  opt.delta = -1.0;
  expect_message([&] { minimize(x(0), Fn(1.0), kXY, box, opt); }, "delta");
  opt = {};
  opt.equality_tolerance = std::nan("");
  expect_message([&] { minimize(x(0), Fn(1.0), kXY, box, opt); }, "equality_tolerance");
}

TEST(Minimizer, DeterministicResults) {
  const Fn f = claim21_objective();
  const MinimizeResult a = minimize(f, x(0) + x(1) >= 1.0, kXY, square_box(-1, 1));
  const MinimizeResult b = minimize(f, x(0) + x(1) >= 1.0, kXY, square_box(-1, 1));
  EXPECT_EQ(a.minimum, b.minimum);
  EXPECT_EQ(a.candidates, b.candidates);
  EXPECT_EQ(a.best_point, b.best_point);
  EXPECT_EQ(a.report.boxes_processed, b.report.boxes_processed);
}

}  // namespace
}  // namespace genmod
