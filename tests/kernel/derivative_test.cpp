// Symbolic derivatives against central differences, and the forward-mode gradient evaluator
// against the symbolic derivative.
#include "genmod/kernel/gradient_evaluator.hpp"
#include "genmod/kernel/inclusion.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "kernel/random_functions.hpp"

#include <gtest/gtest.h>

namespace genmod {
namespace {

using testing::RandomFunctions;

const std::vector<int> kXyz = {0, 1, 2};

// Richardson-extrapolated central difference of f_j along coordinate i.
double central_difference(PointEvaluator& ev, const Tape& t, std::vector<double> p, std::size_t i) {
  auto diff = [&](double h) {
    std::vector<double> a = p, b = p;
    a[i] += h;
    b[i] -= h;
    const double fa = ev.eval(t, a)[0];
    const double fb = ev.eval(t, b)[0];
    return (fa - fb) / (2 * h);
  };
  const double h = 1e-4 * std::max(1.0, std::abs(p[i]));
  return (4 * diff(h / 2) - diff(h)) / 3;
}

// Points where f is smooth enough that the difference quotient is trustworthy.
bool well_conditioned(PointEvaluator& ev, const Tape& t, const std::vector<double>& p) {
  const double v = ev.eval(t, p)[0];
  return std::isfinite(v) && std::abs(v) < 1e6;
}

void expect_derivatives_match(const Fn& f, RandomFunctions& rnd, int points, int* compared) {
  const Tape tf(f, kXyz);
  std::vector<Tape> dtapes;
  for (int i = 0; i < 3; ++i) dtapes.emplace_back(derivative(f, i), kXyz);
  PointEvaluator ev;
  for (int s = 0; s < points; ++s) {
    const std::vector<double> p = {rnd.uniform(-2, 2), rnd.uniform(-2, 2), rnd.uniform(-2, 2)};
    if (!well_conditioned(ev, tf, p)) continue;
    for (std::size_t i = 0; i < 3; ++i) {
      const double symbolic = ev.eval(dtapes[i], p)[0];
      const double numeric = central_difference(ev, tf, p, i);
      const double numeric2 = [&] {  // a second step size: skip points near a kink
        std::vector<double> q = p;
        q[i] += 1e-3;
        return central_difference(ev, tf, q, i);
      }();
      if (!std::isfinite(symbolic) || std::abs(numeric - numeric2) > 1e-2 * (1 + std::abs(numeric))) continue;
      EXPECT_NEAR(symbolic, numeric, 1e-6 * std::max(1.0, std::abs(numeric)))
          << "d/dx" << i << " at (" << p[0] << ", " << p[1] << ", " << p[2] << ")\n"
          << tf.disassemble();
      ++*compared;
    }
  }
}

TEST(Derivative, EveryOpcodeAgreesWithCentralDifferences) {
  RandomFunctions rnd(11);
  int compared = 0;
  for (const auto& info : testing::all_dag_ops()) {
    // Arguments kept in the domain of every op: asin/acos need |a| < 1, log/sqrt/pow a > 0.
    const Fn a = 0.8 * sin(x(0) + 0.3 * x(2)), b = 1.5 + 0.5 * cos(x(1)), c = x(2);
    const Fn f = testing::apply_op(info.op, info.op == Op::Log || info.op == Op::Sqrt || info.op == Op::Pow ? b : a,
                                   info.op == Op::Pow ? a : b, c);
    expect_derivatives_match(f, rnd, 40, &compared);
  }
  EXPECT_GT(compared, 2000);
}

TEST(Derivative, RandomCompositionsAgreeWithCentralDifferences) {
  RandomFunctions rnd(12);
  int compared = 0;
  for (int trial = 0; trial < 300; ++trial) expect_derivatives_match(rnd.function(5, true), rnd, 10, &compared);
  EXPECT_GT(compared, 3000);
}

TEST(Derivative, GradientEvaluatorEqualsSymbolic) {
  RandomFunctions rnd(13);
  GradientEvaluator grad;
  PointEvaluator ev;
  int compared = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Fn f = cat({rnd.function(5), rnd.function(4)});
    const Tape tf(f, kXyz);
    std::vector<Tape> dtapes;
    for (int i = 0; i < 3; ++i) dtapes.emplace_back(derivative(f, i), kXyz);
    for (int s = 0; s < 5; ++s) {
      const std::vector<double> p = {rnd.uniform(-2, 2), rnd.uniform(-2, 2), rnd.uniform(-2, 2)};
      grad.eval(tf, p);
      const auto point_values = ev.eval(tf, p);
      const std::vector<double> values(point_values.begin(), point_values.end());
      for (std::size_t j = 0; j < 2; ++j) {
        EXPECT_TRUE(grad.values()[j] == values[j] || (std::isnan(values[j]) && std::isnan(grad.values()[j])));
        for (std::size_t i = 0; i < 3; ++i) {
          const double symbolic = ev.eval(dtapes[i], p)[j];
          const double forward = grad.jacobian()[j * 3 + i];
          if (!std::isfinite(symbolic) || !std::isfinite(values[j])) continue;
          EXPECT_NEAR(forward, symbolic, 1e-9 * std::max(1.0, std::abs(symbolic))) << tf.disassemble();
          ++compared;
        }
      }
    }
  }
  EXPECT_GT(compared, 5000);
}

TEST(Derivative, SharedSubexpressionsKeepDerivativeDagsSmall) {
  // Repeated squaring: without sharing the derivative would double in size per level; with
  // hash-consing its tape grows linearly with the depth.
  auto derivative_tape_size = [](int levels) {
    Fn f = x(0);
    for (int k = 0; k < levels; ++k) f = square(f) * 0.5 + x(0);
    return static_cast<double>(Tape(derivative(f, 0)).size());
  };
  const double at20 = derivative_tape_size(20), at40 = derivative_tape_size(40);
  EXPECT_LT(at40 / at20, 2.2);
  EXPECT_LT(at40, 40 * 10);
}

// A chain 70,000 operations deep (a `.vm` file can be one) is differentiated, composed and
// bounded without recursion on its depth (these walks used to overflow the stack at 60,000).
TEST(Derivative, DeepChainsNeedNoStack) {
  Fn f = x(0);
  for (int k = 0; k < 70000; ++k) f = k % 2 ? sin(f) : f * 1.0001 + x(1);
  const Fn df = derivative(f, 0);
  const Fn g = compose(f, 1, x(0) * 2.0);
  const Fn dg = derivative(g, 0);
  // Spot values against the gradient evaluator on the same tape.
  GradientEvaluator grad;
  const Tape tape(f, std::vector<int>{0, 1});
  grad.eval(tape, std::vector<double>{0.3, 0.1});
  EXPECT_DOUBLE_EQ(evaluate(df, std::vector<double>{0.3, 0.1})[0], grad.jacobian()[0]);
  EXPECT_TRUE(std::isfinite(evaluate(dg, std::vector<double>{0.3})[0]));
  InclusionFunction bound(f);
  const Interval r = bound.eval(std::vector<Interval>{Interval(0.25, 0.35), Interval(0.05, 0.15)})[0];
  EXPECT_TRUE(r.contains(evaluate(f, std::vector<double>{0.3, 0.1})[0]));
}

}  // namespace
}  // namespace genmod
