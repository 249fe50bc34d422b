// Private helpers: dimension checks with messages that name the operator and the sizes.
#pragma once

#include "genmod/kernel/fn.hpp"

#include <cstddef>
#include <stdexcept>
#include <string>

namespace genmod::detail {

[[noreturn]] inline void dimension_error(const char* op, const std::string& what) {
  throw std::invalid_argument(std::string("genmod: ") + op + ": " + what);
}

inline void require_same_dim(const char* op, std::size_t a, std::size_t b) {
  if (a != b)
    dimension_error(op, "operands have dimensions " + std::to_string(a) + " and " + std::to_string(b) +
                            ", expected equal dimensions");
}

// f must have dimension `expected`; `what` names the operand ("the center").
inline void require_dim(const char* op, const char* what, const Fn& f, std::size_t expected) {
  if (f.dim() != expected)
    dimension_error(op, std::string(what) + " has dimension " + std::to_string(f.dim()) + ", expected " +
                            std::to_string(expected));
}

}  // namespace genmod::detail
