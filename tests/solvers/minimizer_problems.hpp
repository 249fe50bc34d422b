// Standard global optimization test functions with known minima, shared by the minimizer's
// tests and benchmarks (definitions as in the Virtual Library of Simulation Experiments,
// sfu.ca/~ssurjano). Header-only; nothing here is used by the solver itself.
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/solvers/box.hpp"

#include <numbers>
#include <string>
#include <vector>

namespace genmod::minimizer_problems {

struct Problem {
  std::string name;
  Fn objective;
  std::vector<int> unknowns;
  Box box;
  double f_star;                  // known global minimum
  double known_tolerance;         // precision to which f_star is known
  std::vector<std::vector<double>> minimizers;  // known global minimizers
  double minimizer_tolerance;     // precision to which they are known
  double best_point_tolerance;    // how close the solver's best point should come
  double epsilon;                 // suggested box tolerance
  double delta;                   // suggested bracket width
};

inline Fn six_hump_camel() {
  const Fn a = x(0), b = x(1);
  return (4.0 - 2.1 * square(a) + pow(a, 4.0) / 3.0) * square(a) + a * b + (-4.0 + 4.0 * square(b)) * square(b);
}

inline Fn rosenbrock() { return 100.0 * square(x(1) - square(x(0))) + square(1.0 - x(0)); }

// Levy, d = 2: w_i = 1 + (x_i - 1) / 4.
inline Fn levy() {
  const double pi = std::numbers::pi;
  const Fn w1 = 1.0 + (x(0) - 1.0) / 4.0, w2 = 1.0 + (x(1) - 1.0) / 4.0;
  return square(sin(pi * w1)) + square(w1 - 1.0) * (1.0 + 10.0 * square(sin(pi * w1 + 1.0))) +
         square(w2 - 1.0) * (1.0 + square(sin(2.0 * pi * w2)));
}

// Shekel with m = 5 terms, d = 4.
inline Fn shekel5() {
  const double beta[5] = {0.1, 0.2, 0.2, 0.4, 0.4};
  const double c[5][4] = {{4, 4, 4, 4}, {1, 1, 1, 1}, {8, 8, 8, 8}, {6, 6, 6, 6}, {3, 7, 3, 7}};
  Fn sum(0.0);
  for (int i = 0; i < 5; ++i) {
    Fn d(beta[i]);
    for (int j = 0; j < 4; ++j) d = d + square(x(j) - c[i][j]);
    sum = sum - 1.0 / d;
  }
  return sum;
}

inline Fn goldstein_price() {
  const Fn a = x(0), b = x(1);
  const Fn p = 1.0 + square(a + b + 1.0) * (19.0 - 14.0 * a + 3.0 * square(a) - 14.0 * b + 6.0 * a * b + 3.0 * square(b));
  const Fn q = 30.0 + square(2.0 * a - 3.0 * b) *
                          (18.0 - 32.0 * a + 12.0 * square(a) + 48.0 * b - 36.0 * a * b + 27.0 * square(b));
  return p * q;
}

inline Fn branin() {
  const double pi = std::numbers::pi;
  const double b = 5.1 / (4.0 * pi * pi), c = 5.0 / pi, r = 6.0, s = 10.0, t = 1.0 / (8.0 * pi);
  return square(x(1) - b * square(x(0)) + c * x(0) - r) + s * (1.0 - t) * cos(x(0)) + s;
}

// Hartmann, d = 3, on [0, 1]^3.
inline Fn hartmann3() {
  const double alpha[4] = {1.0, 1.2, 3.0, 3.2};
  const double a[4][3] = {{3, 10, 30}, {0.1, 10, 35}, {3, 10, 30}, {0.1, 10, 35}};
  const double p[4][3] = {{0.3689, 0.1170, 0.2673}, {0.4699, 0.4387, 0.7470},
                          {0.1091, 0.8732, 0.5547}, {0.0381, 0.5743, 0.8828}};
  Fn sum(0.0);
  for (int i = 0; i < 4; ++i) {
    Fn e(0.0);
    for (int j = 0; j < 3; ++j) e = e + a[i][j] * square(x(j) - p[i][j]);
    sum = sum - alpha[i] * exp(-e);
  }
  return sum;
}

// Griewank, d = 2: a shallow bowl covered with many local minima.
inline Fn griewank2() {
  return 1.0 + (square(x(0)) + square(x(1))) / 4000.0 - cos(x(0)) * cos(x(1) / std::numbers::sqrt2);
}

inline std::vector<Problem> standard_problems() {
  const double pi = std::numbers::pi;
  std::vector<Problem> p;
  p.push_back({"SixHumpCamel", six_hump_camel(), {0, 1}, {Interval(-3, 3), Interval(-2, 2)}, -1.0316284534898774,
               1e-15, {{0.0898420131003, -0.7126564030207}, {-0.0898420131003, 0.7126564030207}}, 1e-9, 1e-3, 1e-4,
               1e-6});
  p.push_back({"Rosenbrock", rosenbrock(), {0, 1}, {Interval(-5, 10), Interval(-5, 10)}, 0.0, 0.0, {{1.0, 1.0}}, 0.0,
               1e-2, 1e-4, 1e-6});
  p.push_back({"Levy", levy(), {0, 1}, {Interval(-10, 10), Interval(-10, 10)}, 0.0, 0.0, {{1.0, 1.0}}, 0.0, 1e-3,
               1e-4, 1e-6});
  p.push_back({"GoldsteinPrice", goldstein_price(), {0, 1}, {Interval(-2, 2), Interval(-2, 2)}, 3.0, 1e-12,
               {{0.0, -1.0}}, 0.0, 1e-3, 1e-4, 1e-5});
  p.push_back({"Branin", branin(), {0, 1}, {Interval(-5, 10), Interval(0, 15)}, 5.0 / (4.0 * pi), 1e-12,
               {{-pi, 12.275}, {pi, 2.275}, {3.0 * pi, 2.475}}, 1e-12, 1e-3, 1e-4, 1e-6});
  p.push_back({"Shekel5", shekel5(), {0, 1, 2, 3}, {Interval(0, 10), Interval(0, 10), Interval(0, 10), Interval(0, 10)},
               -10.153199679058222, 1e-9, {{4.0000371552, 4.0001332806, 4.0000371552, 4.0001332806}}, 1e-6, 1e-2, 1e-3, 1e-5});
  // Hartmann-3's minimum to 40 digits (mpmath: the gradient's root from the usual rounded
  // minimizer); the often quoted -3.86278 is rounded.
  p.push_back({"Hartmann3", hartmann3(), {0, 1, 2}, Box(3, Interval(0, 1)), -3.8627797873326626676, 1e-15,
               {{0.11458887665506896, 0.55564889461693005, 0.85254698468667744}}, 1e-9, 1e-3, 1e-4, 1e-6});
  p.push_back({"Griewank2", griewank2(), {0, 1}, {Interval(-600, 600), Interval(-600, 600)}, 0.0, 0.0, {{0.0, 0.0}},
               0.0, 1e-3, 1e-4, 1e-6});
  return p;
}

}  // namespace genmod::minimizer_problems
