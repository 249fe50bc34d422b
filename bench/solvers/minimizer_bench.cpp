// Global minimization (Algorithm 5.2) on standard test functions: time per solve, with the
// bracket width reached, boxes processed and candidate boxes as counters.
#include "genmod/solvers/minimizer.hpp"
#include "genmod/solvers/minimizer_problems.hpp"

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
    ->ArgsProduct({{0, 1, 2, 3, 4, 5}, {0, 1}})
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

}  // namespace
}  // namespace genmod
