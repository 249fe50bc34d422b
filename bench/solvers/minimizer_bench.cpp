// Global minimization (Algorithm 5.2) on standard test functions: time per solve, with the
// bracket width reached, boxes processed and candidate boxes as counters.
#include "genmod/solvers/minimizer.hpp"
#include "solvers/minimizer_problems.hpp"

#include <benchmark/benchmark.h>

#include <string>

namespace genmod {
namespace {

void report(benchmark::State& state, const MinimizeResult& r) {
  state.counters["bracket_width"] = r.minimum.hi() - r.minimum.lo();
  state.counters["boxes"] = static_cast<double>(r.report.boxes_processed);
  state.counters["candidates"] = static_cast<double>(r.candidates.size());
  state.counters["limit_hit"] = r.report.limit == LimitHit::None ? 0.0 : 1.0;
}

// Arguments: problem index, 0 = minimize (candidates to epsilon), 1 = minimum value only.
void BM_StandardFunction(benchmark::State& state) {
  static const std::vector<minimizer_problems::Problem> problems = minimizer_problems::standard_problems();
  const minimizer_problems::Problem& p = problems.at(static_cast<std::size_t>(state.range(0)));
  const bool value_only = state.range(1) != 0;
  state.SetLabel(p.name + (value_only ? " value" : " minimize"));
  MinimizeOptions opt;
  opt.epsilon = p.epsilon;
  opt.delta = p.delta;
  MinimizeResult r;
  for (auto _ : state) {
    r = value_only ? minimize_value(p.objective, Fn(1.0), p.unknowns, p.box, opt)
                   : minimize(p.objective, Fn(1.0), p.unknowns, p.box, opt);
    benchmark::DoNotOptimize(r.minimum);
  }
  report(state, r);
  state.counters["delta"] = p.delta;
}
BENCHMARK(BM_StandardFunction)
    ->ArgsProduct({{0, 1, 2, 3, 4, 5, 6, 7}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

// Claim 21's constrained example, with and without the monotonicity test and local search.
void BM_ConstrainedQuadratic(benchmark::State& state) {
  const Fn f = square(x(0) - 0.3) + square(x(1) + 0.2);
  const Fn c = x(0) + x(1) >= 1.0;
  const int unknowns[] = {0, 1};
  const Box box = {Interval(-1, 1), Interval(-1, 1)};
  MinimizeOptions opt;
  opt.monotonicity_test = state.range(0) != 0;
  opt.local_search = state.range(1) != 0;
  MinimizeResult r;
  for (auto _ : state) {
    r = minimize(f, c, unknowns, box, opt);
    benchmark::DoNotOptimize(r.minimum);
  }
  report(state, r);
}
BENCHMARK(BM_ConstrainedQuadratic)->ArgsProduct({{0, 1}, {0, 1}})->Unit(benchmark::kMillisecond);

// Issue 10's constrained problems. Argument 0: Rosen-Suzuki (4 unknowns, 3 inequalities,
// [-3, 3]^4, f* = -44), delta 1e-4 / 1e-6; 1: min x + y on the unit circle with an exact
// equality (eta = 0), epsilon 1e-3. At most 1e6 boxes. Argument 2: threads (1 or 2; the
// result is the same, the wall time is what changes).
void BM_Issue10Constrained(benchmark::State& state) {
  const Fn x1 = x(0), x2 = x(1), x3 = x(2), x4 = x(3);
  Fn f, c;
  Box box;
  MinimizeOptions opt;
  if (state.range(0) == 0) {
    f = square(x1) + square(x2) + 2.0 * square(x3) + square(x4) - 5.0 * x1 - 5.0 * x2 - 21.0 * x3 + 7.0 * x4;
    c = (square(x1) + square(x2) + square(x3) + square(x4) + x1 - x2 + x3 - x4 - 8.0 <= 0.0) &&
        (square(x1) + 2.0 * square(x2) + square(x3) + 2.0 * square(x4) - x1 - x4 - 10.0 <= 0.0) &&
        (2.0 * square(x1) + square(x2) + square(x3) + 2.0 * x1 - x2 - x4 - 5.0 <= 0.0);
    box = Box(4, Interval(-3, 3));
    opt.delta = state.range(1) == 0 ? 1e-4 : 1e-6;
    state.SetLabel(state.range(1) == 0 ? "RosenSuzuki delta 1e-4" : "RosenSuzuki delta 1e-6");
  } else {
    f = x1 + x2;
    c = eq(square(x1) + square(x2), 1.0);
    box = Box(2, Interval(-2, 2));
    opt.epsilon = 1e-3;
    state.SetLabel("circle equality eta 0");
  }
  opt.threads = static_cast<int>(state.range(2));
  const int unknowns[] = {0, 1, 2, 3};
  MinimizeResult r;
  for (auto _ : state) {
    r = minimize(f, c, std::span<const int>(unknowns, box.size()), box, opt);
    benchmark::DoNotOptimize(r.minimum);
  }
  report(state, r);
}
BENCHMARK(BM_Issue10Constrained)
    ->ArgsProduct({{0}, {0, 1}, {1, 2}})
    ->Args({1, 0, 1})
    ->Args({1, 0, 2})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

}  // namespace
}  // namespace genmod
