// Interval Newton on a square system F(x, p) = 0 (n equations, n unknowns x, optional
// parameters p given as intervals): snyder.md sections 4.11 and 4.11.3.
//
//  * contract(): one preconditioned interval Gauss-Seidel step (Hansen-Sengupta). With
//    c = mid(X), Y = inverse of the midpoint Jacobian (Eigen, in the .cpp), M = Y J(X),
//    b = Y F(c): X_i := X_i ∩ (c_i - (b_i + Σ_{j≠i} M_ij (X_j - c_j)) / M_ii), extended
//    division (two pieces when M_ii holds 0), components updated in order. No zero of F in X is
//    ever lost; an empty result proves there is none.
//  * certify(): the Krawczyk operator K(X) = c - Y F(c) + (I - Y J(X)) (X - c). If K(X) lies
//    in the interior of X, F has exactly one zero in X (Krawczyk / Moore / Rump; the
//    Bao-Rokne condition of Theorem 5.3 with Q replaced by a superset). With parameters, F(c)
//    and J are enclosed over the parameter box, so the statement holds for every p in it.
//
// J is the symbolic Jacobian (kernel derivative()) compiled into one tape once, evaluated with
// the IntervalEvaluator. Both steps need F continuously differentiable on X: when the interval
// evaluation says F or J may be discontinuous or fail on X, the step is skipped (Skipped).
//
// Example:
//   Fn F = cat({square(x(0)) + square(x(1)) - 1.0, x(0) - x(1)});
//   int u[] = {0, 1};
//   IntervalNewton newton(F, u);
//   Box X = {Interval(0.6, 0.8), Interval(0.6, 0.8)};
//   newton.certify(X);          // true: exactly one zero, (1/sqrt2, 1/sqrt2)
//   newton.contract(X);         // X shrinks around it
#pragma once

#include "genmod/kernel/coordinates.hpp"
#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/interval.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/solvers/box.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace genmod {

enum class NewtonStatus : std::uint8_t {
  Skipped,    // not applicable on this box (discontinuity, possible error, unbounded values)
  Empty,      // proved: no zero in the box
  Contracted  // the box may have shrunk (possibly not at all)
};

class IntervalNewton {
 public:
  // `system` has n = unknowns.size() components. Inputs of the boxes passed below are the
  // unknowns, then the parameters. Throws std::invalid_argument when the system is not square
  // or depends on a coordinate that is neither an unknown nor a parameter.
  IntervalNewton(const Fn& system, Coordinates unknowns, Coordinates parameters = {});

  std::size_t dim() const noexcept { return n_; }

  // One Gauss-Seidel step on `box` (unknowns then parameters; only unknowns change).
  NewtonStatus contract(std::span<Interval> box);
  // True if F has exactly one zero in the box (for every parameter value in the box).
  bool certify(std::span<const Interval> box);
  // The Krawczyk image of the unknowns' sides (empty vector when not applicable).
  Box krawczyk(std::span<const Interval> box);

 private:
  // Evaluates F(c) and J(X) and the preconditioner; false when not applicable.
  bool prepare(std::span<const Interval> box);

  std::size_t n_ = 0, inputs_ = 0;
  Tape f_, j_;
  IntervalEvaluator ev_;
  std::vector<double> c_;
  std::vector<Interval> point_, fc_, jx_, m_, b_;  // m_ = Y J (row-major), b_ = Y F(c)
  std::vector<double> y_;                          // the preconditioner, row-major
};

}  // namespace genmod
