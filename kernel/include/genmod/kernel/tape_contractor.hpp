// Forward-backward contraction (HC4-revise, Benhamou et al. 1999) of a box against one
// constraint f(x) in target, on the tape of f.
//
// Forward: the IntervalEvaluator runs the tape's SSA form, so every value gets the same
// enclosure and error bits as in every other interval evaluation. The output is intersected
// with `target`; then each clause's (narrowed) value is projected back onto its operands
// (the inverse of + - * / neg square sqrt exp log abs min max and their immediate forms;
// other operations leave their operands unchanged), down to the loads, which narrow the box.
//
// Soundness: projections use outward-rounded interval operations, so a point where f is a
// number in `target` is never removed. Points where f is an error (NaN) are not solutions and
// may be removed. The projections assume that every value on the tape is a number wherever f
// is; a tape with a clause that can hide an error of its operand (select, is-error, a custom
// operator call) therefore gets the forward check only (projects() is false).
//
// Example:
//   Tape t(square(x(0)) + square(x(1)));
//   std::vector<Interval> box = {Interval(0.9, 2.0), Interval(-0.1, 0.1)};
//   TapeContractor ctc;
//   bool maybe = ctc.contract(t, box, Interval(1.0), 2);  // box[0] shrinks to about [0.99, 1]
#pragma once

#include "genmod/kernel/interval.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/tape.hpp"

#include <cstddef>
#include <span>
#include <vector>

namespace genmod {

class TapeContractor {
 public:
  // Narrows box[0, narrowable) in place (the inputs after them are read, never narrowed).
  // `tape` must have one output. Returns false when no point of the box has f(x) in `target`
  // (then `box` is unspecified). Throws std::invalid_argument for a tape with several outputs
  // or a box of the wrong dimension.
  bool contract(const Tape& tape, std::span<Interval> box, const Interval& target, std::size_t narrowable);

  // Whether the backward projection applies to `tape` (see above); the forward check always does.
  static bool projects(const Tape& tape) noexcept;

 private:
  bool project(const Tape& tape, std::span<Interval> box, std::size_t narrowable);

  IntervalEvaluator forward_;
  std::vector<Interval> v_;  // by SSA value id
};

}  // namespace genmod
