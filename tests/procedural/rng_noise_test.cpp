#include "genmod/procedural/noise.hpp"
#include "genmod/procedural/rng.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace genmod {
namespace {

// Claim 7: java.util.Random's values (the spec's table, checked there by running Java).
TEST(Rng, JavaRandomVectors) {
  EXPECT_EQ(Rng(42).next_int(), -1170105035);
  EXPECT_EQ(Rng(42).next_double(), 0.7275636800328681);
  EXPECT_EQ(Rng(0).next_int(), -1155484576);
  EXPECT_EQ(Rng(0).next_double(), 0.730967787376657);
  Rng r(12345);
  const double expected[] = {0.3618031071604718, 0.932993485288541, 0.8330913489710237, 0.32647575623792624,
                             0.2355237906476252};
  for (double e : expected) EXPECT_EQ(r.next_double(), e);
}

// Values printed by OpenJDK's java.util.Random on this machine (seed 7: nextInt(10),
// nextInt(16), nextFloat, nextLong, nextBoolean in that order; seed 99: four nextGaussian).
TEST(Rng, JavaRandomOtherDraws) {
  Rng r(7);
  EXPECT_EQ(r.next_int(10), 6);
  EXPECT_EQ(r.next_int(16), 10);
  EXPECT_EQ(r.next_float(), 0.7491696f);
  EXPECT_EQ(r.next_long(), 177623051241444105LL);
  EXPECT_FALSE(r.next_boolean());
  // Gaussians go through log and sqrt, so within a few ulps rather than bitwise (header).
  Rng g(99);
  const double gauss[] = {1.2948166272574204, -0.8890594164103023, 0.23432196963807342, 0.27245230229217654};
  for (double e : gauss) EXPECT_DOUBLE_EQ(g.next_gaussian(), e);
}

TEST(Rng, BoundedDrawsAndSeedAddition) {
  Rng r(7);
  for (int i = 0; i < 1000; ++i) {
    int v = r.next_int(10);
    EXPECT_GE(v, 0);
    EXPECT_LT(v, 10);
    int p = r.next_int(16);
    EXPECT_GE(p, 0);
    EXPECT_LT(p, 16);
    float f = r.next_float();
    EXPECT_GE(f, 0.0f);
    EXPECT_LT(f, 1.0f);
  }
  EXPECT_THROW(r.next_int(0), std::invalid_argument);
  // A user seed is added to the context seed.
  EXPECT_EQ(Rng(40, 2).next_int(), Rng(42).next_int());
  // next_long is two next(32) draws: high word then low word.
  Rng a(5), b(5);
  std::int64_t high = b.next_int(), low = b.next_int();
  EXPECT_EQ(a.next_long(), static_cast<std::int64_t>((static_cast<std::uint64_t>(high) << 32) + static_cast<std::uint64_t>(low)));
  // Gaussians: sample mean and variance near 0 and 1.
  double sum = 0, sq = 0;
  Rng g(99);
  for (int i = 0; i < 20000; ++i) {
    double x = g.next_gaussian();
    sum += x;
    sq += x * x;
  }
  EXPECT_NEAR(sum / 20000, 0.0, 0.05);
  EXPECT_NEAR(sq / 20000, 1.0, 0.05);
}

// Claim 8: Perlin's reference values, bitwise.
TEST(ImprovedNoise, ReferenceValues) {
  EXPECT_EQ(improved_noise(3.14, 42, 7), 0.13691995878400012);
  EXPECT_EQ(improved_noise(0.5, 0.5, 0.5), -0.25);
  EXPECT_EQ(improved_noise(0.1, 0.2, 0.3), 0.35122924878110723);
  EXPECT_EQ(improved_noise(-1.5, 2.25, 10.75), -0.15302419662475586);
}

TEST(ImprovedNoise, ZeroOnTheLatticeAndBounded) {
  for (int i = -20; i <= 20; i += 3)
    for (int j = -20; j <= 20; j += 4)
      for (int k = -300; k <= 300; k += 37) EXPECT_EQ(improved_noise(i, j, k), 0.0) << i << " " << j << " " << k;
  Rng r(1);
  for (int n = 0; n < 10000; ++n) {
    double v = improved_noise(100 * r.next_double() - 50, 100 * r.next_double() - 50, 100 * r.next_double() - 50);
    EXPECT_LE(std::abs(v), 1.0);
  }
}

}  // namespace
}  // namespace genmod
