// Shared helpers for running custom-operator clauses in the point evaluators.
#pragma once

#include "genmod/kernel/custom_op.hpp"
#include "genmod/kernel/tape.hpp"
#include "tape_data.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace genmod::detail {

// Calls custom call site `call` with argument values args (already gathered); writes its
// outputs into slots.
inline void run_call_point(const Tape& tape, std::uint32_t call, std::span<const double> args,
                           std::span<double> slots) {
  const CallSite& cs = detail::calls(tape)[call];
  cs.op->eval(args, slots.subspan(cs.first_slot, cs.num_outputs));
}

inline void check_inputs(const Tape& tape, std::size_t given, const char* who) {
  if (given != tape.num_inputs())
    throw std::invalid_argument(std::string("genmod: ") + who + ": the tape has " +
                                std::to_string(tape.num_inputs()) + " inputs, got " + std::to_string(given));
}

}  // namespace genmod::detail
