// Interval evaluation cost per clause: genmod's IntervalEvaluator (one rounding scope per
// tape) against two baselines running the same clauses over the same boxes: a bare pair of
// doubles (the cost floor, not rigorous) and Boost.Interval's default interval<double>
// (rigorous, rounding mode saved and restored around every operation). The boxes are random
// squares of side 1/32 in [-1,1]^2, the size of the deepest tiles of a 1024-pixel render.
#include "pair_interval.hpp"
#include "prospero.hpp"
#include "tape_interpreter.hpp"

#include "genmod/kernel/interval_evaluator.hpp"

#include <benchmark/benchmark.h>
#include <boost/numeric/interval.hpp>

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace genmod::bench {
namespace {

using Box = std::array<Interval, 2>;
using BoostInterval = boost::numeric::interval<double>;

const std::vector<Box>& boxes() {
  static const std::vector<Box> result = [] {
    constexpr double kSide = 1.0 / 32.0;
    std::mt19937 rng(2024);
    std::uniform_real_distribution<double> corner(-1.0, 1.0 - kSide);
    std::vector<Box> v(64);
    for (Box& b : v) {
      const double x = corner(rng), y = corner(rng);
      b = {Interval(x, x + kSide), Interval(y, y + kSide)};
    }
    return v;
  }();
  return result;
}

void set_per_clause_counter(benchmark::State& state) {
  const double clauses = static_cast<double>(prospero_tape().size() * boxes().size());
  state.counters["time/clause"] = benchmark::Counter(
      clauses, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_IntervalGenmod(benchmark::State& state) {
  const Tape& tape = prospero_tape();
  IntervalEvaluator ev;
  for (auto _ : state)
    for (const Box& b : boxes()) benchmark::DoNotOptimize(ev.eval(tape, b)[0]);
  set_per_clause_counter(state);
}

// True if the baseline's bounds are genmod's up to rounding: a baseline that computed another
// function would make the ratios meaningless.
template <class I>
bool agrees_with_genmod(TapeInterpreter<I>& interpreter, const std::vector<std::array<I, 2>>& in) {
  IntervalEvaluator ev;
  const auto close = [](double a, double b) { return std::abs(a - b) <= 1e-9 * (1.0 + std::abs(a)); };
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Interval g = ev.eval(prospero_tape(), boxes()[i])[0];
    const I v = interpreter.eval(in[i]);
    if (!close(g.lo(), v.lower()) || !close(g.hi(), v.upper())) return false;
  }
  return true;
}

// Both baselines run the same interpreter; only the interval type differs.
template <class I>
void run_baseline(benchmark::State& state) {
  std::vector<std::array<I, 2>> in;
  for (const Box& b : boxes()) in.push_back({I(b[0].lo(), b[0].hi()), I(b[1].lo(), b[1].hi())});
  TapeInterpreter<I> interpreter(prospero_tape());
  if (!agrees_with_genmod(interpreter, in)) {
    state.SkipWithError("the baseline's result differs from genmod's");
    return;
  }
  for (auto _ : state)
    for (const auto& b : in) benchmark::DoNotOptimize(interpreter.eval(b).lower());
  set_per_clause_counter(state);
}

void BM_IntervalPairBaseline(benchmark::State& state) { run_baseline<PairInterval>(state); }
void BM_IntervalBoostProtected(benchmark::State& state) { run_baseline<BoostInterval>(state); }

// Pruning the whole tape for the same boxes, from the choices of their interval evaluation:
// the cost a renderer pays per ambiguous tile on top of the evaluation (time/clause counts
// the clauses of the tape pruned, as BM_IntervalGenmod counts those evaluated).
void BM_SimplifyGenmod(benchmark::State& state) {
  const Tape& tape = prospero_tape();
  IntervalEvaluator ev;
  std::vector<std::vector<std::uint8_t>> choices;
  for (const Box& b : boxes()) {
    ev.eval(tape, b);
    choices.emplace_back(ev.choices().begin(), ev.choices().end());
  }
  TapeSimplifier scratch;
  for (auto _ : state)
    for (const auto& c : choices) benchmark::DoNotOptimize(tape.simplify(c, scratch).size());
  set_per_clause_counter(state);
}

BENCHMARK(BM_IntervalGenmod)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SimplifyGenmod)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_IntervalPairBaseline)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_IntervalBoostProtected)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace genmod::bench
