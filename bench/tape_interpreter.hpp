// A minimal interval interpreter of a tape's register form, generic over the interval type,
// for the baselines of the interval benchmark (PairInterval, protected Boost.Interval). It
// handles the operations on the Prospero tape only and throws on any other, so that a
// baseline can never silently compute something else than genmod does.
#pragma once

#include "genmod/kernel/tape.hpp"
#include "kernel/src/tape_data.hpp"

#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod::bench {

template <class I>
class TapeInterpreter {
 public:
  explicit TapeInterpreter(const Tape& tape) : tape_(tape), regs_(tape.num_registers()) {
    if (tape.num_outputs() != 1) throw std::invalid_argument("genmod bench: the baseline interpreter wants one output");
  }

  // The interval of the tape's output over `box` (box[k] is the range of input k).
  I eval(std::span<const I> box) {
    const std::span<const double> k = tape_.constants();
    I* r = regs_.data();
    // The operations resolve by argument-dependent lookup to those of I.
    for (const Clause& c : detail::clauses(tape_)) {
      switch (c.op) {
        case Op::Const: r[c.out] = I(k[c.a]); break;
        case Op::Load: r[c.out] = box[c.a]; break;
        case Op::Neg: r[c.out] = -r[c.a]; break;
        case Op::Square: r[c.out] = square(r[c.a]); break;
        case Op::Sqrt: r[c.out] = sqrt(r[c.a]); break;
        case Op::Add: r[c.out] = r[c.a] + r[c.b]; break;
        case Op::Sub: r[c.out] = r[c.a] - r[c.b]; break;
        case Op::Mul: r[c.out] = r[c.a] * r[c.b]; break;
        case Op::Min: r[c.out] = min(r[c.a], r[c.b]); break;
        case Op::Max: r[c.out] = max(r[c.a], r[c.b]); break;
        case Op::AddImm: r[c.out] = r[c.a] + k[c.b]; break;
        case Op::MulImm: r[c.out] = r[c.a] * k[c.b]; break;
        case Op::SubImm: r[c.out] = k[c.b] - r[c.a]; break;
        case Op::MinImm: r[c.out] = min(r[c.a], k[c.b]); break;
        case Op::MaxImm: r[c.out] = max(r[c.a], k[c.b]); break;
        default:
          throw std::invalid_argument("genmod bench: the baseline interpreter has no " + std::string(op_name(c.op)));
      }
    }
    return r[detail::output_registers(tape_)[0]];
  }

 private:
  Tape tape_;
  std::vector<I> regs_;
};

}  // namespace genmod::bench
