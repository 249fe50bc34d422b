// Inclusion functions tighter than the natural interval extension (snyder.md section 4.5-4.6):
//
//  * mean value form: f(c) + J(X) (X - c), second order in the box width (needs f continuous
//    on X, which the interval evaluation checks);
//  * monotonicity form: where dF_j/dx_i has one sign over X, the extremes of F_j lie on the
//    matching faces, so F_j is bounded by natural evaluations over those faces;
//  * their intersection with the natural extension (each is an inclusion function, so the
//    intersection is one too, and never wider than any of them).
#pragma once

#include "genmod/kernel/coordinates.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/tape.hpp"

#include <span>
#include <vector>

namespace genmod {

enum InclusionForm : unsigned {
  kNaturalForm = 1,
  kMeanValueForm = 2,
  kMonotonicityForm = 4,
  kAllForms = 7,
};

class InclusionFunction {
 public:
  // Compiles f and its symbolic Jacobian, with inputs in the order of f.inputs() or `inputs`.
  explicit InclusionFunction(const Fn& f);
  InclusionFunction(const Fn& f, Coordinates inputs);

  // Encloses each component of f over `box`, intersecting the chosen forms (the natural
  // extension is always computed). Forms that do not apply (discontinuity, possible error,
  // unbounded box) are skipped. If `jacobian` is given it receives the enclosure of the
  // Jacobian over the box (component j * num_inputs + i = d f_j / d input_i) when that
  // enclosure is valid there (f continuous, no possible error, bounded box), and is left
  // empty otherwise.
  std::vector<Interval> eval(std::span<const Interval> box, unsigned forms = kAllForms,
                             std::vector<Interval>* jacobian = nullptr);
  // ErrorBits of each component from the last eval().
  std::span<const std::uint8_t> errors() const noexcept { return errors_; }

  const Tape& tape() const noexcept { return f_; }
  // Outputs j * num_inputs + i = d f_j / d input_i.
  const Tape& jacobian_tape() const noexcept { return jacobian_; }

 private:
  Tape f_, jacobian_;
  IntervalEvaluator ev_;
  std::vector<std::uint8_t> errors_;
};

}  // namespace genmod
