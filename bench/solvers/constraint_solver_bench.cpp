// Constraint solver benchmarks: boxes processed and time per problem, plain bisection (the
// thesis baseline: no HC4, no Newton) against the contracting solver, a tolerance sweep and
// 1 vs 2 threads. Counters: boxes (processed), out (returned boxes), unique (certified
// components).
#include "genmod/solvers/constraint_solver.hpp"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace genmod {
namespace {

struct Problem {
  const char* name;
  Fn constraint;
  std::vector<int> unknowns;
  Box box;
};

std::vector<Problem> problems() {
  const Fn X = x(0), Y = x(1), Z = x(2);
  const Fn sum = X + Y + Z;
  const Fn himmel = square(square(X) + Y - 11.0) + square(X + square(Y) - 7.0);
  const double c[] = {3628800, -10628640, 12753576, -8409500, 3416930, -902055, 157773, -18150, 1320, -55, 1};
  Fn w = c[10];
  for (int k = 9; k >= 0; --k) w = w * X + c[k];
  return {
      {"circle_line", eq(square(X) + square(Y), 1.0) && eq(X, Y), {0, 1}, Box(2, Interval(-2, 2))},
      {"two_circles", eq(square(X) + square(Y), 4.0) && eq(square(X - 1.0) + square(Y), 4.0), {0, 1}, Box(2, Interval(-3, 3))},
      {"brown3", eq(X + sum, 4.0) && eq(Y + sum, 4.0) && eq(X * Y * Z, 1.0), {0, 1, 2}, Box(3, Interval(-2, 6))},
      {"himmelblau_grad", eq(derivative(himmel, 0), 0.0) && eq(derivative(himmel, 1), 0.0), {0, 1}, Box(2, Interval(-6, 6))},
      {"wilkinson10", eq(w, 0.0), {0}, Box(1, Interval(0.5, 10.5))},
      {"sin_roots", eq(sin(X), 0.0), {0}, Box(1, Interval(-10, 10))},
      {"squares4", eq(square(X), 1.0) && eq(square(Y), 1.0), {0, 1}, Box(2, Interval(-2, 2))},
  };
}

void run(benchmark::State& state, const Problem& p, bool contracting, double eps, int threads) {
  SolveOptions o;
  o.epsilon = eps;
  o.use_hc4 = o.use_newton = contracting;
  o.threads = threads;
  SolveResult r;
  for (auto _ : state) {
    r = solve(p.constraint, p.unknowns, p.box, o);
    benchmark::DoNotOptimize(r.boxes.data());
  }
  state.counters["boxes"] = static_cast<double>(r.report.boxes_processed);
  state.counters["out"] = static_cast<double>(r.boxes.size());
  state.counters["unique"] = static_cast<double>(r.unique_components());
  state.counters["complete"] = r.complete() ? 1 : 0;
}

std::string eps_name(double eps) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", eps);
  return buf;
}

const bool registered = [] {
  static const std::vector<Problem> ps = problems();
  for (const Problem& p : ps) {
    for (bool contracting : {false, true})
      benchmark::RegisterBenchmark((std::string("solve/") + p.name + (contracting ? "/contract" : "/bisect")).c_str(),
                                   [&p, contracting](benchmark::State& s) { run(s, p, contracting, 1e-8, 1); })
          ->Unit(benchmark::kMillisecond);
  }
  for (double eps : {1e-3, 1e-6, 1e-9, 1e-12})
    for (bool contracting : {false, true})
      benchmark::RegisterBenchmark(
          (std::string("eps_sweep/himmelblau_grad/") + (contracting ? "contract/" : "bisect/") + eps_name(eps)).c_str(),
          [eps, contracting](benchmark::State& s) { run(s, ps[3], contracting, eps, 1); })
          ->Unit(benchmark::kMillisecond);
  for (int threads : {1, 2}) {
    benchmark::RegisterBenchmark((std::string("threads/himmelblau_grad_bisect_1e-9/") + std::to_string(threads)).c_str(),
                                 [threads](benchmark::State& s) { run(s, ps[3], false, 1e-9, threads); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    const Fn X = x(0), Y = x(1);
    static const Problem curve{"curve", eq(sin(3.0 * X) + square(Y), 0.5), {0, 1}, Box(2, Interval(-2, 2))};
    benchmark::RegisterBenchmark((std::string("threads/curve_1e-3/") + std::to_string(threads)).c_str(),
                                 [threads](benchmark::State& s) { run(s, curve, true, 1e-3, threads); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
  return true;
}();

}  // namespace
}  // namespace genmod
