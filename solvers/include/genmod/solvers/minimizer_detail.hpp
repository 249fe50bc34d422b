// Internals of the minimizer shared by its source files (not part of the public API).
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/gradient_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/solvers/box.hpp"

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

}  // namespace genmod::minimizer_detail
