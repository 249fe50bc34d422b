// Tape: an Fn compiled once into a flat list of fixed-size clauses.
//
// A tape is kept in two forms with the same clause order: SSA (each clause defines its own
// value id) for simplification, and register form (values packed into a small register file by
// linear-scan allocation) for the evaluators. A pruned tape keeps the value ids of the tape it
// was pruned from (ids are below num_values(), the length of the compiled tape, and increase
// along the tape), so pruning never renumbers values. Constant operands of + - * / min max are folded into the
// clause as immediates. Tapes are immutable and cheap to copy (shared), so one tape can be
// used by evaluators on many threads at once; each evaluator owns its scratch memory.
//
// Pruning: an interval evaluation records, for each min / max / select clause, whether only
// one side can be the result over the box (a Choice). `simplify(choices)` returns a shorter
// tape that equals this one at every point of that box (and of any box inside it). Callers
// that prune often (renderers, meshers) pass a TapeSimplifier, one per thread, whose scratch
// memory is reused from call to call.
#pragma once

#include "genmod/kernel/coordinates.hpp"
#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/opcode.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace genmod {

class CustomOp;

struct Clause {
  Op op;
  std::uint8_t reserved[3] = {0, 0, 0};
  std::uint32_t out;  // destination register (SSA form: the id of the value it defines)
  std::uint32_t a;    // first operand; Const: constant index; Load: input position; Call: call index; CallOut: slot
  std::uint32_t b;    // second operand; immediate forms: constant index; CallOut: the Call clause's value (SSA)
  std::uint32_t c;    // third operand (select's else branch)
};
static_assert(sizeof(Clause) == 20);

// Which operand of a min / max / select clause is the result over a box.
enum Choice : std::uint8_t {
  kChoiceBoth = 0,   // either (or the clause has no choice)
  kChoiceFirst = 1,  // min/max: operand a; select: the then-branch
  kChoiceSecond = 2  // min/max: operand b (or the immediate); select: the else-branch
};

// One application of a custom operator on the tape.
struct CallSite {
  const CustomOp* op;         // kept alive by the tape: custom_ops()[op_index]
  std::uint32_t op_index;
  std::uint32_t first_arg;    // arguments: call_args()[first_arg, first_arg + num_args)
  std::uint32_t num_args;
  std::uint32_t first_slot;   // outputs go to slots [first_slot, first_slot + num_outputs)
  std::uint32_t num_outputs;
};

class Tape;
struct TapeData;  // a tape's contents (tape.cpp)

// Scratch memory of Tape::simplify, reused from call to call (one per thread, like an
// evaluator). Its contents are private to the kernel; a copy starts with empty scratch.
class TapeSimplifier {
 public:
  TapeSimplifier();
  ~TapeSimplifier();
  TapeSimplifier(const TapeSimplifier&);
  TapeSimplifier& operator=(const TapeSimplifier&);
  TapeSimplifier(TapeSimplifier&&) noexcept;
  TapeSimplifier& operator=(TapeSimplifier&&) noexcept;

 private:
  friend class Tape;
  class Impl;
  std::unique_ptr<Impl> impl_;
};

class Tape {
 public:
  // Compiles f with inputs in the order of f.inputs().
  explicit Tape(const Fn& f);
  // Compiles f with an explicit input order: input k is x(inputs[k]). Every coordinate f
  // depends on must be listed (std::invalid_argument names a missing one).
  Tape(const Fn& f, Coordinates inputs);

  // Register form.
  std::span<const Clause> clauses() const noexcept;
  std::span<const std::uint32_t> output_registers() const noexcept;
  std::span<const std::uint32_t> call_arg_registers() const noexcept;
  std::uint32_t num_registers() const noexcept;
  // SSA form (same clause order): clause i defines value ssa()[i].out, an id below
  // num_values(); its operands are values defined earlier on the tape. Output j is value
  // output_values()[j].
  std::span<const Clause> ssa() const noexcept;
  std::span<const std::uint32_t> output_values() const noexcept;
  std::span<const std::uint32_t> call_arg_values() const noexcept;  // as call_arg_registers()
  std::uint32_t num_values() const noexcept;

  std::span<const double> constants() const noexcept;
  std::span<const int> inputs() const noexcept;
  std::size_t num_inputs() const noexcept { return inputs().size(); }
  std::size_t num_outputs() const noexcept { return output_registers().size(); }
  std::size_t size() const noexcept { return clauses().size(); }
  std::span<const CallSite> calls() const noexcept;
  // The custom operators the calls apply (shared owners: the tape keeps them alive).
  std::span<const std::shared_ptr<const CustomOp>> custom_ops() const noexcept;
  std::uint32_t num_call_slots() const noexcept;
  // True if some clause can make a choice (min / max / select), i.e. pruning can help.
  bool has_choices() const noexcept;

  // A tape equal to this one wherever `choices` (one per clause, from an interval
  // evaluation) hold. Returns this tape itself when no choice is one-sided. The first form
  // allocates scratch memory as long as the compiled tape; the second reuses `scratch`'s.
  Tape simplify(std::span<const std::uint8_t> choices) const;
  Tape simplify(std::span<const std::uint8_t> choices, TapeSimplifier& scratch) const;

  // One line per clause, for debugging and the `info` command.
  std::string disassemble() const;

  using Data = TapeData;

 private:
  explicit Tape(std::shared_ptr<const Data> data) : data_(std::move(data)) {}
  static std::shared_ptr<const Data> compile(const Fn& f, std::span<const int> inputs);
  std::shared_ptr<const Data> data_;
};

}  // namespace genmod
