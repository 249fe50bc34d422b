// Batch point evaluation throughput: the full Prospero tape over a 256 x 256 grid of points
// in [-1,1]^2, on one core. The counter is clause evaluations (clauses x points) per second.
#include "prospero.hpp"

#include "genmod/kernel/batch_evaluator.hpp"

#include <benchmark/benchmark.h>

#include <vector>

namespace genmod::bench {
namespace {

void BM_BatchProspero(benchmark::State& state) {
  const Tape& tape = prospero_tape();
  constexpr int kSide = 256;
  std::vector<double> xs, ys;
  for (int j = 0; j < kSide; ++j)
    for (int i = 0; i < kSide; ++i) {
      // Cell centers, so no point lies on the boundary of the square.
      xs.push_back(-1.0 + (2.0 * i + 1.0) / kSide);
      ys.push_back(-1.0 + (2.0 * j + 1.0) / kSide);
    }
  std::vector<double> out(xs.size());
  const double* inputs[] = {xs.data(), ys.data()};
  double* outputs[] = {out.data()};

  BatchEvaluator ev;
  for (auto _ : state) {
    ev.eval(tape, inputs, xs.size(), outputs);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.counters["clause_evals/s"] = benchmark::Counter(static_cast<double>(tape.size() * xs.size()),
                                                        benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_BatchProspero)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace genmod::bench
