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
class Tape;
struct TapeData;  // a tape's clauses, calls and constants (kernel/src/tape_data.hpp, not installed)

namespace detail {
const TapeData& tape_data(const Tape& tape) noexcept;  // for the kernel's evaluators
}  // namespace detail

// Which operand of a min / max / select clause is the result over a box.
enum Choice : std::uint8_t {
  kChoiceBoth = 0,   // either (or the clause has no choice)
  kChoiceFirst = 1,  // min/max: operand a; select: the then-branch
  kChoiceSecond = 2  // min/max: operand b (or the immediate); select: the else-branch
};

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

  std::span<const double> constants() const noexcept;
  std::span<const int> inputs() const noexcept;
  std::size_t num_inputs() const noexcept { return inputs().size(); }
  std::size_t num_outputs() const noexcept;
  std::size_t size() const noexcept;  // number of clauses
  std::uint32_t num_registers() const noexcept;
  // Number of clauses with opcode `op`.
  std::size_t count(Op op) const noexcept;
  // Bytes of clauses, call sites and argument lists this tape holds (constants are shared
  // with the tapes pruned from it and not counted).
  std::size_t memory_bytes() const noexcept;

  // True if some clause can make a choice (min / max / select), i.e. pruning can help.
  bool has_choices() const noexcept;

  // A tape equal to this one wherever `choices` (one per clause, from an interval
  // evaluation) hold. Returns this tape itself when no choice is one-sided. The first form
  // allocates scratch memory as long as the compiled tape; the second reuses `scratch`'s.
  Tape simplify(std::span<const std::uint8_t> choices) const;
  Tape simplify(std::span<const std::uint8_t> choices, TapeSimplifier& scratch) const;

  // One line per clause, for debugging and the `info` command.
  std::string disassemble() const;

 private:
  friend const TapeData& detail::tape_data(const Tape& tape) noexcept;
  using Data = TapeData;
  explicit Tape(std::shared_ptr<const Data> data) : data_(std::move(data)) {}
  static std::shared_ptr<const Data> compile(const Fn& f, std::span<const int> inputs);
  std::shared_ptr<const Data> data_;
};

}  // namespace genmod
