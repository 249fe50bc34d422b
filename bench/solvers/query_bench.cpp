// Queries on the acceptance suite's surfaces: the crossed cylinders' intersection (issue 10,
// failure 1: the loops' turning points on kd-tree bisection lines, and the same cylinders
// shifted off them) and an implicit curve with a tangential touch. Counters: boxes processed,
// components, closed components, unresolved boxes, complete (1/0).
#include "genmod/solvers/implicit_curve.hpp"
#include "genmod/solvers/queries.hpp"

#include <benchmark/benchmark.h>

#include <numbers>

namespace genmod {
namespace {

constexpr double kPi = std::numbers::pi;

void report(benchmark::State& state, const ImplicitCurve& c) {
  std::size_t closed = 0;
  for (const Polyline& p : c.components) closed += p.closed ? 1 : 0;
  state.counters["boxes"] = static_cast<double>(c.report.boxes_processed);
  state.counters["components"] = static_cast<double>(c.components.size());
  state.counters["closed"] = static_cast<double>(closed);
  state.counters["unresolved"] = static_cast<double>(c.stats.unresolved);
  state.counters["complete"] = c.complete() ? 1.0 : 0.0;
}

// Argument: 0 = turning points on bisection lines, 1 = the second cylinder shifted by 0.05.
void BM_CrossedCylinders(benchmark::State& state) {
  const double shift = state.range(0) == 0 ? 0.0 : 0.05;
  state.SetLabel(state.range(0) == 0 ? "turning points on bisection lines" : "shifted 0.05");
  const Fn a = cat({cos(2 * kPi * x(0)), sin(2 * kPi * x(0)), 4 * x(1) - 2});
  const Fn b = cat({4 * x(0) - 2 + shift, 0.6 * cos(2 * kPi * x(1)), 0.6 * sin(2 * kPi * x(1))});
  SurfaceIntersectionOptions options;
  options.periodic_u = options.periodic_t = true;   // the two angles
  SurfaceIntersection r;
  for (auto _ : state) {
    r = surface_intersection(a, b, {}, {}, options);
    benchmark::DoNotOptimize(r.components);
  }
  report(state, r.curve);
}
BENCHMARK(BM_CrossedCylinders)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The lemniscate of Bernoulli, (x^2 + y^2)^2 = 2 (x^2 - y^2): a figure eight whose double
// point is the origin, on the first bisection lines of [-2, 2]^2, and whose extreme points in
// y touch the bisection lines y = +-1/2.
void BM_Lemniscate(benchmark::State& state) {
  const Fn r2 = square(x(0)) + square(x(1));
  const Fn f = square(r2) - 2.0 * (square(x(0)) - square(x(1)));
  const Box box = {Interval(-2, 2), Interval(-2, 2)};
  ImplicitCurve c;
  for (auto _ : state) {
    c = approximate_implicit_curve(f, {0, 1}, box);
    benchmark::DoNotOptimize(c.components);
  }
  report(state, c);
  state.counters["branch_nodes"] = static_cast<double>(c.stats.branch_nodes);
}
BENCHMARK(BM_Lemniscate)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace genmod
