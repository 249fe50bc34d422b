// Private: argument checks shared by the solver operators (solve, minimize).
#pragma once


#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>

namespace genmod::detail {

// The unknowns as a coordinate mask; throws std::invalid_argument (message prefixed by `who`)
// for none, one out of range, or one listed twice.
inline std::uint64_t unknowns_mask(std::span<const int> unknowns, const std::string& who) {
  if (unknowns.empty()) throw std::invalid_argument(who + "no unknowns");
  std::uint64_t mask = 0;
  for (int u : unknowns) {
    if (u < 0 || u >= kMaxInputs)
      throw std::invalid_argument(who + "unknown " + std::to_string(u) + " is outside [0, " + std::to_string(kMaxInputs) + ")");
    if (mask & (std::uint64_t{1} << u)) throw std::invalid_argument(who + "unknown x(" + std::to_string(u) + ") is listed twice");
    mask |= std::uint64_t{1} << u;
  }
  return mask;
}

}  // namespace genmod::detail
