// Claim 27: reparameterization by arclength of a quarter circle traced at nonuniform speed.
#include "genmod/solvers/arclength.hpp"

#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace genmod {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Arclength, QuarterCircleAtConstantSpeed) {
  const Fn theta = (kPi / 4) * (x(0) + square(x(0)));
  const Fn gamma = cat({cos(theta), sin(theta)});
  const Fn even = reparameterize_by_arclength(gamma, 0);
  const Fn velocity = derivative(even, 0);
  for (double s : {0.0, 0.1, 0.37, 0.5, 0.8, 1.0}) {
    const auto p = evaluate(even, std::vector<double>{s});
    EXPECT_NEAR(p[0], std::cos(kPi * s / 2), 1e-6) << s;
    EXPECT_NEAR(p[1], std::sin(kPi * s / 2), 1e-6) << s;
    if (s > 0.0 && s < 1.0) {  // |gamma_new'(s)| = pi / 2 everywhere
      const auto v = evaluate(velocity, std::vector<double>{s});
      EXPECT_NEAR(std::hypot(v[0], v[1]), kPi / 2, 1e-5) << s;
    }
  }
  // Inclusion over a parameter box contains the sampled values.
  Tape tape(even);
  IntervalEvaluator ev;
  const auto box = ev.eval(tape, {Interval(0.3, 0.35)});
  for (double s = 0.3; s <= 0.35; s += 0.01) {
    EXPECT_TRUE(box[0].contains(std::cos(kPi * s / 2)));
    EXPECT_TRUE(box[1].contains(std::sin(kPi * s / 2)));
  }
  EXPECT_THROW(reparameterize_by_arclength(gamma, 3), std::invalid_argument);
}

}  // namespace
}  // namespace genmod
