// Polynomial and transcendental systems with known roots from the literature: every known root
// lies in a returned box, the number of components certified to hold exactly one root equals
// the known number of (simple) roots, and problems without roots return nothing.
#include "genmod/solvers/constraint_solver.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "solvers/solver_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace genmod {
namespace {

using test::covered;
using Roots = std::vector<std::vector<double>>;

constexpr double kTol = 1e-12;  // rounding of the closed-form roots

Box cube(std::size_t n, double lo, double hi) { return Box(n, Interval(lo, hi)); }

SolveOptions tight() {
  SolveOptions o;
  o.epsilon = 1e-9;
  return o;
}

// Solves the conjunction of eqs == 0 and checks roots, certified count and completeness.
// certified < 0: the count is checked by the caller.
SolveResult check_system(const std::vector<Fn>& eqs, const Box& box, const Roots& roots, int certified,
                         const SolveOptions& opt = tight()) {
  std::vector<int> u;
  for (std::size_t i = 0; i < box.size(); ++i) u.push_back(static_cast<int>(i));
  Fn c = eq(eqs[0], 0.0);
  for (std::size_t i = 1; i < eqs.size(); ++i) c = c && eq(eqs[i], 0.0);
  SolveResult r = solve(c, u, box, opt);
  EXPECT_TRUE(r.complete()) << limit_name(r.report.limit);
  for (const auto& p : roots) {
    EXPECT_TRUE(covered(r, p, kTol)) << "root (" << p[0] << ", ...) not in any returned box";
  }
  if (certified >= 0) {
    EXPECT_EQ(r.unique_components(), static_cast<std::size_t>(certified));
  }
  if (!roots.empty() && static_cast<std::size_t>(certified) == roots.size()) {
    EXPECT_EQ(r.components.size(), roots.size());  // nothing else returned
  }
  return r;
}

const Fn X = x(0), Y = x(1), Z = x(2);

TEST(PolynomialSystems, CircleAndLine) {
  const double s = std::sqrt(0.5);
  check_system({square(X) + square(Y) - 1.0, X - Y}, cube(2, -2, 2), {{s, s}, {-s, -s}}, 2);
}

TEST(PolynomialSystems, TwoCircles) {
  const double y = std::sqrt(15.0) / 2;
  check_system({square(X) + square(Y) - 4.0, square(X - 1.0) + square(Y) - 4.0}, cube(2, -3, 3),
               {{0.5, y}, {0.5, -y}}, 2);
}

TEST(PolynomialSystems, SphereAndDiagonal) {
  check_system({square(X) + square(Y) + square(Z) - 3.0, X - Y, Y - Z}, cube(3, -2, 2), {{1, 1, 1}, {-1, -1, -1}}, 2);
}

// Brown's almost-linear system, n = 3: x_i + sum x - 4 = 0 (i < 3), x1 x2 x3 = 1. Roots: a = 1
// and the roots of 3a^2 - a - 1, with x = (a, a, 4 - 3a) (Moré, Garbow, Hillstrom 1981).
TEST(PolynomialSystems, BrownAlmostLinear3) {
  const Fn sum = X + Y + Z;
  Roots roots;
  for (double a : {1.0, (1 + std::sqrt(13.0)) / 6, (1 - std::sqrt(13.0)) / 6}) roots.push_back({a, a, 4 - 3 * a});
  check_system({X + sum - 4.0, Y + sum - 4.0, X * Y * Z - 1.0}, cube(3, -2, 6), roots, 3);
}

// Wilkinson's polynomial of degree 10 in expanded (ill-conditioned) form: roots 1..10.
TEST(PolynomialSystems, Wilkinson10Expanded) {
  const double c[] = {3628800, -10628640, 12753576, -8409500, 3416930, -902055, 157773, -18150, 1320, -55, 1};
  Fn p = c[10];
  for (int k = 9; k >= 0; --k) p = p * X + c[k];
  Roots roots;
  for (int k = 1; k <= 10; ++k) roots.push_back({double(k)});
  check_system({p}, cube(1, 0.5, 10.5), roots, 10);
}

// Three close simple roots (product form): 1, 1.001, 1.002.
TEST(PolynomialSystems, CloseRoots) {
  check_system({(X - 1.0) * (X - 1.001) * (X - 1.002)}, cube(1, 0, 2), {{1.0}, {1.001}, {1.002}}, 3);
}

// A double root cannot be certified unique, but it must be found.
TEST(PolynomialSystems, DoubleRootFoundNotCertified) {
  SolveResult r = check_system({square(X) - 2.0 * X + 1.0}, cube(1, -3, 3), {{1.0}}, 0);
  EXPECT_EQ(r.box_count(SolutionStatus::CertifiedUnique), 0u);
  // Near a double root the function cannot be told from 0 over |x - 1| < ~1e-8: the boxes
  // there may form several components, all within that distance and none certified.
  ASSERT_GE(r.components.size(), 1u);
  for (const SolutionComponent& c : r.components) {
    EXPECT_LT(test::distance(c.hull, {1.0}), 1e-7);
    EXPECT_LT(width(c.hull), 1e-6);
    EXPECT_FALSE(c.unique);
  }
}

TEST(PolynomialSystems, NoRealRoots) {
  SolveResult r = check_system({square(X) + square(Y) + 1.0}, cube(2, -2, 2), {}, 0);
  EXPECT_TRUE(r.boxes.empty());
}

// sin x = 0 on [-10, 10]: 7 roots k pi, k = -3..3 (0 is on the first split face).
TEST(PolynomialSystems, SineRoots) {
  Roots roots;
  for (int k = -3; k <= 3; ++k) roots.push_back({k * std::numbers::pi});
  check_system({sin(X)}, cube(1, -10, 10), roots, 7);
}

// A curve of solutions: x - y = 0. No certificate; the boxes cover the diagonal.
TEST(PolynomialSystems, DiagonalCurve) {
  SolveOptions o;
  o.epsilon = 1e-2;
  SolveResult r = check_system({X - Y}, cube(2, -1, 1), {}, 0, o);
  for (int i = 0; i <= 200; ++i) {
    const double t = -1 + i / 100.0;
    EXPECT_TRUE(covered(r, {t, t}));
  }
  EXPECT_EQ(r.box_count(SolutionStatus::CertifiedUnique), 0u);
  EXPECT_EQ(r.components.size(), 1u);
}

// Rosenbrock's gradient: one critical point, (1, 1).
TEST(PolynomialSystems, RosenbrockGradient) {
  const Fn f = 100.0 * square(Y - square(X)) + square(1.0 - X);
  check_system({derivative(f, 0), derivative(f, 1)}, cube(2, -2, 2), {{1, 1}}, 1);
}

// Himmelblau's function has 9 critical points (4 minima, 4 saddles, 1 maximum). Closed forms
// are not known: the test polishes literature approximations with point Newton first.
TEST(PolynomialSystems, HimmelblauGradient) {
  const Fn f = square(square(X) + Y - 11.0) + square(X + square(Y) - 7.0);
  const Fn gx = derivative(f, 0), gy = derivative(f, 1);
  Roots approx = {{3, 2}, {-2.805118, 3.131312}, {-3.779310, -3.283186}, {3.584428, -1.848126},
                  {-0.270845, -0.923039}, {0.086678, 2.884255}, {-3.073026, -0.081353},
                  {3.385154, 0.073852}, {-0.127961, -1.953715}};
  const Fn hxx = derivative(gx, 0), hxy = derivative(gx, 1), hyy = derivative(gy, 1);
  for (auto& p : approx)
    for (int it = 0; it < 20; ++it) {
      const double a = evaluate(hxx, p)[0], b = evaluate(hxy, p)[0], d = evaluate(hyy, p)[0];
      const double u = evaluate(gx, p)[0], v = evaluate(gy, p)[0];
      const double det = a * d - b * b;
      p = {p[0] - (d * u - b * v) / det, p[1] - (a * v - b * u) / det};
    }
  check_system({gx, gy}, cube(2, -6, 6), approx, 9);
}

// A trigonometric system: sin x = cos y, x = y; roots pi/4 + k pi in [-4, 4] (k = -1, 0, 1).
TEST(PolynomialSystems, Trigonometric) {
  Roots roots;
  for (int k = -1; k <= 1; ++k) {
    const double t = std::numbers::pi / 4 + k * std::numbers::pi;
    roots.push_back({t, t});
  }
  check_system({sin(X) - cos(Y), X - Y}, cube(2, -4, 4), roots, 3);
}

// Chebyquad, n = 2 (Moré et al.): x1 + x2 = 1 and the T2 moment; roots 1/2 +- 1/(2 sqrt 3).
TEST(PolynomialSystems, Chebyquad2) {
  auto t1 = [](const Fn& v) { return 2.0 * v - 1.0; };
  auto t2 = [&](const Fn& v) { return 2.0 * square(t1(v)) - 1.0; };
  const double a = 0.5 - 0.5 / std::sqrt(3.0), b = 0.5 + 0.5 / std::sqrt(3.0);
  check_system({0.5 * (t1(X) + t1(Y)), 0.5 * (t2(X) + t2(Y)) + 1.0 / 3.0}, cube(2, 0, 1), {{a, b}, {b, a}}, 2);
}

// x e^x = 1: the omega constant W(1).
TEST(PolynomialSystems, LambertOmega) {
  check_system({X * exp(X) - 1.0}, cube(1, -1, 2), {{0.56714329040978387}}, 1);
}

// Broyden's tridiagonal function, n = 4: (3 - 2x_i) x_i - x_{i-1} - 2 x_{i+1} + 1 = 0. The root
// near -0.5 is polished with point Newton; every returned component must be certified.
TEST(PolynomialSystems, BroydenTridiagonal4) {
  const int n = 4;
  std::vector<Fn> eqs;
  for (int i = 0; i < n; ++i) {
    Fn e = (3.0 - 2.0 * x(i)) * x(i) + 1.0;
    if (i > 0) e = e - x(i - 1);
    if (i + 1 < n) e = e - 2.0 * x(i + 1);
    eqs.push_back(e);
  }
  SolveResult r = check_system(eqs, cube(n, -1, 0), {}, -1);
  EXPECT_GE(r.unique_components(), 1u);
  EXPECT_EQ(r.unique_components(), r.components.size());
}

}  // namespace
}  // namespace genmod
