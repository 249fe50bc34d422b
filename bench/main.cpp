// genmod_bench: runs the benchmarks (all Google Benchmark flags apply, e.g.
// --benchmark_filter, --benchmark_min_time, --benchmark_repetitions), then prints the summary
// table of the figures.
#include "summary_table.hpp"

#include <benchmark/benchmark.h>

#include <cstdio>

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  genmod::bench::SummaryReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_table(stdout);
  benchmark::Shutdown();
  return 0;
}
