// Private helpers: dimension checks with messages that name the operator and the sizes.
#pragma once

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

}  // namespace genmod::detail
