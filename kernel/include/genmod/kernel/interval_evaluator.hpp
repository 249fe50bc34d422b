// Interval evaluation of a tape over a box (the natural inclusion function), with the
// per-clause choices that make tape pruning possible.
//
// Example:
//   Tape tape(min(x(0), x(1)));
//   Box box = {Interval(0, 1), Interval(2, 3)};
//   IntervalEvaluator ev;
//   auto y = ev.eval(tape, box);          // y[j] contains f_j(x) for every x in the box
//   Tape shorter = tape.simplify(ev.choices());   // x(0) alone: min's left side is live
//
// The whole tape runs inside one RoundingScope (upward rounding), so the cost per clause is
// close to plain double arithmetic.
#pragma once

#include "genmod/kernel/interval.hpp"
#include "genmod/kernel/tape.hpp"

#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

namespace genmod {

struct Clause;  // a tape instruction (private to the kernel)

class IntervalEvaluator {
 public:
  // `box[k]` is the range of input k. Throws std::invalid_argument for a wrong dimension or
  // an illegal interval. The results are valid until the next call.
  std::span<const Interval> eval(const Tape& tape, std::span<const Interval> box);
  std::span<const Interval> eval(const Tape& tape, std::initializer_list<Interval> box) {
    return eval(tape, std::span<const Interval>(box.begin(), box.size()));
  }

  // ErrorBits of each output: whether an error (NaN at a point) is possible / certain.
  std::span<const std::uint8_t> errors() const noexcept { return out_err_; }
  // One Choice per clause of the last tape; feed to Tape::simplify.
  std::span<const std::uint8_t> choices() const noexcept { return choices_; }
  // False if the function may be discontinuous (a comparison, floor, select, ... changes
  // value) or may fail somewhere in the box; derivative-based forms need continuity.
  bool continuous() const noexcept { return continuous_; }

 private:
  friend class TapeContractor;  // evaluates the SSA form (every value, by id)

  // Runs `clauses` (the tape's register or SSA form, with the matching call arguments) over a
  // register file of `num_registers`; the outputs are left in regs_ / err_.
  void run(const Tape& tape, std::span<const Interval> box, std::span<const Clause> clauses,
           std::span<const std::uint32_t> call_args, std::uint32_t num_registers);
  // run() over the SSA form: every value of the tape, by id, in regs_ / err_.
  void eval_ssa(const Tape& tape, std::span<const Interval> box);
  Interval other_op(const Clause& c, std::span<const double> k, std::uint8_t& err, bool& jump);
  bool call(const Tape& tape, std::uint32_t call);
  void finish(std::span<const std::uint32_t> output_registers);

  std::vector<Interval> regs_;
  std::vector<std::uint8_t> err_;
  std::vector<Interval> slots_;
  std::vector<std::uint8_t> slot_err_;
  std::vector<Interval> out_;
  std::vector<std::uint8_t> out_err_;
  std::vector<std::uint8_t> choices_;
  std::vector<Interval> call_args_;
  const Clause* clauses_base_ = nullptr;  // the clauses being evaluated (for choices of select)
  std::span<const std::uint32_t> call_args_src_;  // the call arguments' registers (or SSA values)
  bool jump_ = false;                             // some discontinuity may lie in the box
  bool continuous_ = true;
};

}  // namespace genmod
