// A tape's contents: its clauses in both forms, call sites and constants. Private to the
// kernel (not installed): the evaluators, the simplifier and the contractor read tapes
// through the accessors at the end; everyone else uses Tape's public API.
#pragma once

#include "genmod/kernel/tape.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace genmod {

struct Clause {
  Op op;
  std::uint8_t reserved[3] = {0, 0, 0};
  std::uint32_t out;  // destination register (SSA form: the id of the value it defines)
  std::uint32_t a;    // first operand; Const: constant index; Load: input position; Call: call index; CallOut: slot
  std::uint32_t b;    // second operand; immediate forms: constant index; CallOut: the Call clause's value (SSA)
  std::uint32_t c;    // third operand (select's else branch)
};
static_assert(sizeof(Clause) == 20);


// The opcodes of the interval evaluator's error-free loop (interval_evaluator.cpp): arithmetic,
// min / max and square root, whose only errors come from non-finite bounds or a negative root.
constexpr bool plain_op(Op op) noexcept {
  switch (op) {
    case Op::Const: case Op::Load: case Op::Add: case Op::Sub: case Op::Mul: case Op::Neg: case Op::Square:
    case Op::Sqrt: case Op::Min: case Op::Max: case Op::AddImm: case Op::SubImm: case Op::MulImm:
    case Op::MinImm: case Op::MaxImm:
      return true;
    default:
      return false;
  }
}

// One application of a custom operator on the tape.
struct CallSite {
  const CustomOp* op;         // kept alive by the tape: custom_ops()[op_index]
  std::uint32_t op_index;
  std::uint32_t first_arg;    // arguments: call_args()[first_arg, first_arg + num_args)
  std::uint32_t num_args;
  std::uint32_t first_slot;   // outputs go to slots [first_slot, first_slot + num_outputs)
  std::uint32_t num_outputs;
};

// What a tape shares with every tape pruned from it.
struct TapeCommon {
  std::vector<double> constants;
  std::vector<int> inputs;
  // The operators the call sites point to, kept alive as long as the tape (and the tapes
  // simplified from it) even when the Fn it was compiled from is gone.
  std::vector<std::shared_ptr<const CustomOp>> ops;
  std::uint32_t num_values = 0;  // SSA ids are below this
  std::uint32_t num_slots = 0;
};

// Both forms in one vector each, so a pruned tape costs few allocations.
struct TapeData {
  std::shared_ptr<const TapeCommon> common;
  std::vector<Clause> clauses;           // register form [0, size), then SSA form [size, 2 size)
  std::vector<std::uint32_t> outputs;    // output registers, then output values
  std::vector<CallSite> calls;
  std::vector<std::uint32_t> call_args;  // argument registers, then argument values
  std::uint32_t num_registers = 0;
  bool has_choices = false;
  bool plain = false;  // every clause is a plain_op(): the interval evaluator's error-free loop applies

  std::size_t size() const noexcept { return clauses.size() / 2; }
  std::span<const Clause> reg() const noexcept { return std::span(clauses).first(size()); }
  std::span<const Clause> ssa() const noexcept { return std::span(clauses).subspan(size()); }
  std::span<const std::uint32_t> reg_outputs() const noexcept { return std::span(outputs).first(outputs.size() / 2); }
  std::span<const std::uint32_t> ssa_outputs() const noexcept { return std::span(outputs).subspan(outputs.size() / 2); }
  std::span<const std::uint32_t> reg_call_args() const noexcept { return std::span(call_args).first(call_args.size() / 2); }
  std::span<const std::uint32_t> ssa_call_args() const noexcept { return std::span(call_args).subspan(call_args.size() / 2); }
};

namespace detail {

// Register form: clauses over a register file of num_registers.
inline std::span<const Clause> clauses(const Tape& t) noexcept { return tape_data(t).reg(); }
inline std::span<const std::uint32_t> output_registers(const Tape& t) noexcept { return tape_data(t).reg_outputs(); }
inline std::span<const std::uint32_t> call_arg_registers(const Tape& t) noexcept { return tape_data(t).reg_call_args(); }
// SSA form (same clause order): clause i defines value ssa(t)[i].out, an id below
// num_values(t); its operands are values defined earlier. Output j is value output_values(t)[j].
inline std::span<const Clause> ssa(const Tape& t) noexcept { return tape_data(t).ssa(); }
inline std::span<const std::uint32_t> output_values(const Tape& t) noexcept { return tape_data(t).ssa_outputs(); }
inline std::span<const std::uint32_t> call_arg_values(const Tape& t) noexcept { return tape_data(t).ssa_call_args(); }
inline std::uint32_t num_values(const Tape& t) noexcept { return tape_data(t).common->num_values; }
inline std::span<const CallSite> calls(const Tape& t) noexcept { return tape_data(t).calls; }
// The custom operators the calls apply (shared owners: the tape keeps them alive).
inline std::span<const std::shared_ptr<const CustomOp>> custom_ops(const Tape& t) noexcept {
  return tape_data(t).common->ops;
}
inline std::uint32_t num_call_slots(const Tape& t) noexcept { return tape_data(t).common->num_slots; }

}  // namespace detail
}  // namespace genmod
