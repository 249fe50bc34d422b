#include "genmod/procedural/rng.hpp"

#include <cmath>
#include <stdexcept>

namespace genmod {
namespace {
constexpr std::uint64_t kMultiplier = 0x5DEECE66DULL;
constexpr std::uint64_t kMask = (std::uint64_t{1} << 48) - 1;
}  // namespace

Rng::Rng(std::int64_t seed) : state_((static_cast<std::uint64_t>(seed) ^ kMultiplier) & kMask) {}

Rng::Rng(std::int64_t context_seed, std::int64_t user_seed)
    : Rng(static_cast<std::int64_t>(static_cast<std::uint64_t>(context_seed) + static_cast<std::uint64_t>(user_seed))) {}

std::int32_t Rng::next(int bits) {
  state_ = (state_ * kMultiplier + 0xB) & kMask;
  // Java: (int)(seed >>> (48 - bits)), a truncation to the low 32 bits.
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(state_ >> (48 - bits)));
}

std::int32_t Rng::next_int() { return next(32); }

std::int32_t Rng::next_int(std::int32_t bound) {
  if (bound <= 0) throw std::invalid_argument("Rng::next_int: bound must be positive");
  if ((bound & -bound) == bound)  // a power of two: the high bits are the better ones
    return static_cast<std::int32_t>((static_cast<std::int64_t>(bound) * next(31)) >> 31);
  std::int32_t bits, value;
  do {  // rejection keeps the draw uniform, exactly as Java's loop
    bits = next(31);
    value = bits % bound;
  } while (static_cast<std::int64_t>(bits) - value + (bound - 1) > 0x7FFFFFFF);
  return value;
}

std::int64_t Rng::next_long() {
  std::uint64_t high = static_cast<std::uint64_t>(static_cast<std::int64_t>(next(32))) << 32;
  return static_cast<std::int64_t>(high + static_cast<std::uint64_t>(static_cast<std::int64_t>(next(32))));
}

bool Rng::next_boolean() { return next(1) != 0; }

float Rng::next_float() { return static_cast<float>(next(24)) / static_cast<float>(1 << 24); }

double Rng::next_double() {
  std::int64_t high = static_cast<std::int64_t>(next(26)) << 27;
  return static_cast<double>(high + next(27)) * 0x1.0p-53;
}

double Rng::next_gaussian() {
  if (have_next_next_gaussian_) {
    have_next_next_gaussian_ = false;
    return next_next_gaussian_;
  }
  double v1, v2, s;
  do {
    v1 = 2 * next_double() - 1;
    v2 = 2 * next_double() - 1;
    s = v1 * v1 + v2 * v2;
  } while (s >= 1 || s == 0);
  double multiplier = std::sqrt(-2 * std::log(s) / s);
  next_next_gaussian_ = v2 * multiplier;
  have_next_next_gaussian_ = true;
  return v1 * multiplier;
}

}  // namespace genmod
