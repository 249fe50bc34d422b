// Internals of the minimizer shared by its source files (not part of the public API).
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/gradient_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/solvers/box.hpp"
#include "genmod/solvers/constraint_system.hpp"
#include "genmod/solvers/interval_newton.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <vector>

namespace genmod::minimizer_detail {

// The constraint split for local search: the residuals of the equalities and inequalities
// reached from the root through `and` (eq(a, b) -> a - b, a <= b -> max(a - b, 0), ...). A point
// with all residuals 0 satisfies those relations; Gauss-Newton on them finds feasible points.
// Empty when the constraint has none.
std::optional<Fn> constraint_residuals(const Fn& constraint);

// Non-rigorous local descent inside the search box (snyder.md section 4.13 "find feasible
// points to lower u"): Gauss-Newton on the constraint residuals when the start is not
// feasible, then projected gradient descent with backtracking that keeps the point feasible
// (by point evaluation). The caller verifies the returned point rigorously.
class LocalSearch {
 public:
  LocalSearch(const Tape& objective, const Tape& constraint, std::optional<Tape> residuals, const Box& box);
  std::vector<double> run(std::vector<double> start);

 private:
  bool feasible(std::span<const double> x);
  double value(std::span<const double> x);
  void clamp(std::vector<double>& x) const;
  void restore_feasibility(std::vector<double>& x);

  Tape f_, c_;
  std::optional<Tape> r_;
  Box box_;
  PointEvaluator pe_;
  GradientEvaluator ge_;
};

// Certified feasible points for exact equality constraints (issue 10): no floating-point point
// satisfies g(x) = 0 exactly, but a box can be proven to hold one. For the m equalities
// g_i = 0 among the top-level conjuncts (m <= n unknowns), find(box) fixes n - m coordinates
// at the box's midpoint (the columns left after pivoting the midpoint Jacobian), runs interval
// Newton on the chosen m coordinates over their sides of the box and certifies a unique zero
// with Krawczyk (epsilon-inflated, inside the box): the result B holds a point x with g(x) = 0.
// It is returned only if every other atom of the constraint is true on B without possible
// error, so x is feasible; sup f over B is then a rigorous upper bound of the minimum.
class FeasiblePointCertifier {
 public:
  // Unusable (active() false) when the constraint has no top-level equality or more
  // equalities than unknowns.
  FeasiblePointCertifier(const Fn& constraint, std::span<const int> unknowns);
  bool active() const noexcept { return !equalities_.empty(); }
  // A sub-box of `box` proven to hold a feasible point, or nothing.
  std::optional<Box> find(std::span<const Interval> box);

 private:
  IntervalNewton& newton_for(std::uint64_t chosen);

  std::vector<int> unknowns_;
  ConstraintSystem sys_;
  std::vector<std::size_t> equalities_;  // atom indices of the Eq conjuncts
  std::vector<std::uint8_t> is_equality_;
  Fn system_;                              // the equalities' functions g_i
  std::optional<Tape> jacobian_;           // dg_i / dx_j, row major, over the unknowns
  std::map<std::uint64_t, IntervalNewton> newton_;  // by the set of chosen columns
  PointEvaluator pe_;
  IntervalEvaluator ev_;
  AtomValues values_;
  std::vector<Truth> forced_;
};

}  // namespace genmod::minimizer_detail
