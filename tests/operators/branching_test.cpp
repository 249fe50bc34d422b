// Branching (index, select_case) and the higher-level operators (interp, concat,
// hermite_interp): values, thesis claims 25 and 26, and the shared properties.
#include "genmod/operators/branching.hpp"
#include "genmod/operators/curve.hpp"
#include "genmod/operators/higher_order.hpp"
#include "operators/operator_properties.hpp"

#include <gtest/gtest.h>

#include <random>

namespace genmod {
namespace {

using testing::check_operator_properties;
using testing::unit_domain;

const Fn u = x(0), v = x(1);

double at(const Fn& f, std::vector<double> p, std::size_t j = 0) { return evaluate(f, p)[j]; }

TEST(Branching, IndexChoosesByFloorAndClamps) {
  const Fn f = index({u, 2.0 * u, 3.0 * u}, v * 3.0);
  EXPECT_EQ(at(f, {1.0, 0.1}), 1.0);
  EXPECT_EQ(at(f, {1.0, 0.5}), 2.0);
  EXPECT_EQ(at(f, {1.0, 1.0}), 3.0);   // q = n clamps to the last
  EXPECT_EQ(at(f, {1.0, -1.0}), 1.0);  // q < 0 clamps to the first
  auto spec = unit_domain(2);
  spec.domain[1] = Interval(-0.5, 1.5);
  spec.breaks = {{}, {1.0 / 3, 2.0 / 3}};
  check_operator_properties(index({sin(u), cos(u) * v, u * u}, v * 3.0), spec, 51);
  EXPECT_THROW(index({u, cat({u, v})}, v), std::invalid_argument);
  EXPECT_THROW(index({}, v), std::invalid_argument);
}

TEST(Branching, CaseTakesTheFirstTrueGuard) {
  // m_case(@[f < 0, 1], @[-f, f]) is |f|.
  const Fn f = u - 0.5;
  const Fn abs_f = select_case({f < 0.0, 1.0}, {-f, f});
  EXPECT_EQ(at(abs_f, {0.2}), 0.3);
  EXPECT_EQ(at(abs_f, {0.7}), 0.7 - 0.5);
  // No true guard: an error.
  const Fn partial = select_case({u < 0.5}, {u});
  EXPECT_TRUE(std::isnan(at(partial, {0.7})));
  IntervalEvaluator iv;
  iv.eval(Tape(partial), {Interval(0.4, 0.6)});
  EXPECT_NE(iv.errors()[0] & kMaybeError, 0);
  auto spec = unit_domain(2);
  spec.breaks = {{0.5}, {0.3}};
  check_operator_properties(select_case({u < 0.5, v > 0.3, 1.0}, {cat({u, v}), cat({v * v, u}), cat({1.0, u * v})}), spec, 52);
  EXPECT_THROW(select_case({u < 0.5}, {u, v}), std::invalid_argument);
}

TEST(HigherOrder, InterpAndHermiteConstraints) {
  EXPECT_EQ(at(interp(u, cat({0.0, 0.0}), cat({1.0, 2.0})), {0.25}, 1), 0.5);
  // Claim 25: H(0) = p1, H(1) = p2, H'(0) = t1, H'(1) = t2 for random vectors.
  std::mt19937_64 rng(53);
  std::uniform_real_distribution<double> c(-3, 3);
  for (int trial = 0; trial < 20; ++trial) {
    const Fn p1 = cat({c(rng), c(rng), c(rng)}), p2 = cat({c(rng), c(rng), c(rng)});
    const Fn t1 = cat({c(rng), c(rng), c(rng)}), t2 = cat({c(rng), c(rng), c(rng)});
    const Fn h = hermite_interp(u, p1, p2, t1, t2);
    const Fn dh = derivative(h, 0);
    for (std::size_t j = 0; j < 3; ++j) {
      EXPECT_NEAR(at(h, {0.0}, j), at(p1, {}, j), 1e-14);
      EXPECT_NEAR(at(h, {1.0}, j), at(p2, {}, j), 1e-13);
      EXPECT_NEAR(at(dh, {0.0}, j), at(t1, {}, j), 1e-14);
      EXPECT_NEAR(at(dh, {1.0}, j), at(t2, {}, j), 1e-13);
    }
  }
  // With function arguments: a surface.
  const Fn surface = hermite_interp(v, cat({u, 0.0}), cat({sin(u), 1.0}), cat({0.0, u}), cat({1.0, 1.0}));
  check_operator_properties(surface, unit_domain(2), 54);
}

TEST(HigherOrder, ConcatenationClaim26) {
  const Curve c1 = Curve::polyline({{0, 0}, {1, 0}});
  const Curve c2 = Curve::bezier({{1, 0}, {1.5, 1}, {2, 0}});
  const Curve c3 = Curve::catmull_rom({{2, 0}, {2.5, -1}, {3, 0}});
  const Fn c = concat(0, u, {c1(u), c2(u), c3(u)});
  const std::vector<const Curve*> parts = {&c1, &c2, &c3};
  for (double s = 0.01; s < 1; s += 0.0123) {
    const int k = static_cast<int>(std::floor(3 * s));
    const double local = 3 * s - k;
    for (std::size_t j = 0; j < 2; ++j)
      EXPECT_NEAR(at(c, {s}, j), at((*parts[static_cast<std::size_t>(k)])(u), {local}, j), 1e-14) << s;
  }
  // Continuous at the joints (matching end points), and c3(1) at u = 1.
  for (double joint : {1.0 / 3, 2.0 / 3})
    for (std::size_t j = 0; j < 2; ++j)
      EXPECT_NEAR(at(c, {joint - 1e-12}, j), at(c, {joint + 1e-12}, j), 1e-9);
  EXPECT_EQ(at(c, {1.0}, 0), 3.0);
  auto spec = unit_domain(1);
  spec.breaks = {{0.0, 1.0 / 3, 2.0 / 3, 1.0, 1.0 / 6, 0.5, 5.0 / 6}};  // joints and curve knots
  check_operator_properties(c, spec, 55);
  // Concatenating in a coordinate other than the curve parameter's own: surfaces.
  const Fn s = concat(0, u, {cat({u, v}), cat({v, u * u})});
  check_operator_properties(s, [] {
    auto sp = unit_domain(2);
    sp.breaks = {{0.5}, {}};
    return sp;
  }(), 56);
}

}  // namespace
}  // namespace genmod
