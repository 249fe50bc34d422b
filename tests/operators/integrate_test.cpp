// Integration: Romberg values against closed forms, parameter-dependent limits, the
// Leibniz-rule derivative, rigorous enclosures, and nesting.
#include "genmod/operators/curve.hpp"
#include "genmod/operators/integrate.hpp"
#include "genmod/operators/vector.hpp"
#include "operators/operator_properties.hpp"

#include <gtest/gtest.h>

namespace genmod {
namespace {

using testing::check_operator_properties;
using testing::unit_domain;

const Fn u = x(0), v = x(1), t = x(2);

double at(const Fn& f, std::vector<double> p, std::size_t j = 0) { return evaluate(f, p)[j]; }

TEST(Integrate, RombergMatchesClosedForms) {
  const double pi = std::acos(-1.0);
  EXPECT_NEAR(at(integrate(sin(t), 0.0, pi, 2), {}), 2.0, 1e-12);
  EXPECT_NEAR(at(integrate(exp(t), 0.0, 1.0, 2), {}), std::exp(1.0) - 1, 1e-13);
  // Periodic integrand with few samples would alias: sin(2 pi t) over a period is 0.
  EXPECT_NEAR(at(integrate(square(sin(2 * pi * t)), 0.0, 1.0, 2), {}), 0.5, 1e-12);
  // Reversed limits change the sign; equal limits give 0.
  EXPECT_NEAR(at(integrate(t * t, 1.0, 0.0, 2), {}), -1.0 / 3, 1e-14);
  EXPECT_EQ(at(integrate(t * t, 0.5, 0.5, 2), {}), 0.0);
  // Limits and integrand depending on parameters: int_0^u v t dt = v u^2 / 2.
  const Fn f = integrate(v * t, 0.0, u, 2);
  EXPECT_NEAR(at(f, {0.8, 3.0}), 3.0 * 0.32, 1e-14);
  // The bound variable may be the curve parameter itself (as in arclength).
  const Fn g = integrate(u * u, 0.0, u, 0);
  EXPECT_NEAR(at(g, {0.6}), 0.072, 1e-14);
  // Vector integrands.
  const Fn h = integrate(cat({1.0, t}), 0.0, 2.0, 2);
  EXPECT_EQ(h.dim(), 2u);
  EXPECT_NEAR(at(h, {}, 1), 2.0, 1e-14);
  // An error in the integrand is an error in the result.
  EXPECT_TRUE(std::isnan(at(integrate(sqrt(t - 0.5), 0.0, 1.0, 2), {})));
}

TEST(Integrate, LeibnizDerivative) {
  // d/du int_{v}^{u^2} sin(u t) dt, with u in the integrand and both limits.
  const Fn f = integrate(sin(u * t) + v, v, square(u) + 0.5, 2);
  const Fn df = derivative(f, 0);
  const double uu = 0.7, vv = 0.2, hi = uu * uu + 0.5;
  // Closed form: int t cos(u t) dt over [v, hi] + f(hi) * 2u.
  auto tcos = [&](double s) { return std::cos(uu * s) / (uu * uu) + s * std::sin(uu * s) / uu; };
  const double expected = tcos(hi) - tcos(vv) + (std::sin(uu * hi) + vv) * 2 * uu;
  EXPECT_NEAR(at(df, {uu, vv}), expected, 1e-11);
  // d/dv: -f(lower) + int 1 dt.
  const double dv = -(std::sin(uu * vv) + vv) + (hi - vv);
  EXPECT_NEAR(at(derivative(f, 1), {uu, vv}), dv, 1e-11);
}

TEST(Integrate, Properties) {
  check_operator_properties(integrate(sin(u * t) + v, v, square(u) + 0.5, 2), unit_domain(2), 61);
  check_operator_properties(integrate(cat({exp(u * t), t * v}), 0.0, u, 2), unit_domain(2), 62);
  // Arclength of a curve (the integrand is a curve's derivative: a custom op inside).
  const Curve c = Curve::catmull_rom({{0, 0}, {1, 1}, {2, 0}, {3, 2}});
  const Fn arclength = integrate(length(derivative(c(t), 2)), 0.0, u, 2);
  auto spec = unit_domain(1);
  spec.breaks = {{1.0 / 3, 2.0 / 3}};
  spec.boxes = 60;
  check_operator_properties(arclength, spec, 63);
}

TEST(Integrate, EnclosureIsRigorousAndTight) {
  // int_0^u exp(t) dt = e^u - 1 over u in [0.5, 0.6].
  const Fn f = integrate(exp(t), 0.0, u, 2);
  IntervalEvaluator iv;
  const Interval y = iv.eval(Tape(f), {Interval(0.5, 0.6)})[0];
  EXPECT_LE(y.lo(), std::exp(0.5) - 1);
  EXPECT_GE(y.hi(), std::exp(0.6) - 1);
  EXPECT_LT(y.hi() - y.lo(), (std::exp(0.6) - std::exp(0.5)) * 1.2 + 0.03);
  // Nested integrals: int_0^1 int_0^s t dt ds = 1/6.
  const Fn inner = integrate(t, 0.0, x(3), 2);
  const Fn outer = integrate(inner, 0.0, 1.0, 3);
  EXPECT_NEAR(at(outer, {}), 1.0 / 6, 1e-12);
  const Interval z = iv.eval(Tape(outer), std::vector<Interval>{})[0];
  EXPECT_TRUE(z.contains(1.0 / 6));
  EXPECT_THROW(integrate(t, cat({0.0, 1.0}), 1.0, 2), std::invalid_argument);
  EXPECT_THROW(integrate(t, 0.0, 1.0, -1), std::invalid_argument);
}

}  // namespace
}  // namespace genmod
