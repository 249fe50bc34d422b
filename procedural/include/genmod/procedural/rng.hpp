// Reproducible pseudo-random numbers: java.util.Random's 48-bit LCG, bit for bit, so that a
// seed gives the same draws as Morkel's Java procedures (claim 7). This is the only mode: it is
// deterministic, portable and cheap, which is all reproducibility needs.
#pragma once

#include <cstdint>

namespace genmod {

class Rng {
 public:
  // As new java.util.Random(seed).
  explicit Rng(std::int64_t seed);
  // The procedure's seed supplemented by a modeller's seed (§1.11: "added to the call"): the
  // two are added with Java long wrap-around.
  Rng(std::int64_t context_seed, std::int64_t user_seed);

  std::int32_t next_int();
  // Uniform in [0, bound); throws std::invalid_argument unless bound > 0 (as Java).
  std::int32_t next_int(std::int32_t bound);
  std::int64_t next_long();
  bool next_boolean();
  float next_float();
  double next_double();
  // Java's polar method. Uses std::log / std::sqrt, which may differ from Java's StrictMath in
  // the last ulp, so only the uniform draws are claimed bit-exact.
  double next_gaussian();

 private:
  std::int32_t next(int bits);
  std::uint64_t state_;
  double next_next_gaussian_ = 0;
  bool have_next_next_gaussian_ = false;
};

}  // namespace genmod
