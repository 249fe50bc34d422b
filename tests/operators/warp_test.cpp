// Warp (snyder.md section 7.16): the key's invariants (no warp at v = 0, warp proportional to
// v), the parabola in x, properties and dimension errors.
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/operators/warp.hpp"
#include "operators/operator_properties.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace genmod {
namespace {

const Fn u = x(0), v = x(1);

TEST(Warp, ParabolaInXProportionalToTheSweep) {
  const Fn cross = cat({cos(6.0 * u), sin(6.0 * u), 0.3 * u});
  const Fn w = warp_z_by_x(cross, 0.2 * v, -0.05 * v);
  ASSERT_EQ(w.dim(), 3U);
  for (double a : {0.0, 0.3, 0.71, 1.0})
    for (double b : {0.0, 0.5, 1.0}) {
      const std::vector<double> p{a, b};
      const auto s = evaluate(w, p), c = evaluate(cross, p);
      EXPECT_EQ(s[0], c[0]);
      EXPECT_EQ(s[1], c[1]);
      EXPECT_NEAR(s[2], c[2] + 0.2 * b * c[0] * c[0] - 0.05 * b, 1e-15);
      if (b == 0.0) {
        EXPECT_EQ(s[2], c[2]);  // no warp at the bottom of the key
      }
    }
  testing::check_operator_properties(w, testing::unit_domain(2), 401);
}

TEST(Warp, BadInputNamesTheOperator) {
  for (auto f : {+[] { warp_z_by_x(cat({u, v}), 1.0, 0.0); }, +[] { warp_z_by_x(cat({u, v, u}), cat({u, v}), 0.0); }}) {
    try {
      f();
      ADD_FAILURE() << "no throw";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("warp_z_by_x"), std::string::npos);
    }
  }
}

}  // namespace
}  // namespace genmod
