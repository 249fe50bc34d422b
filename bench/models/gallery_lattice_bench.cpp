// Lattice sampling of every gallery model at 256 x 256 (thesis §4.2.1, claim 12): plain
// lattice evaluation (one tape, every node at every point) against subfunction tables,
// timed alternately in the same run, and the speedup. Solids are sampled on their middle
// w-section. After the Google Benchmark report, a markdown table of the same figures.
//
//   genmod_model_bench [--benchmark_filter=doorknob] [--benchmark_min_time=0.2]
#include "genmod/models/gallery.hpp"
#include "genmod/tessellate/lattice.hpp"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <map>
#include <string>

namespace {

using namespace genmod;

constexpr std::size_t kSamples = 256;

struct Row {
  double plain_ms = 0, tables_ms = 0, plain_ops = 0, tables_ops = 0;
};
std::map<std::string, Row>& rows() {
  static std::map<std::string, Row> r;
  return r;
}

// The model's surface over (u, v): solids at the middle of their w domain.
Fn lattice_surface(const models::Model& m) {
  const Fn s = models::build_model(m);
  return m.solid ? compose(s, 2, Fn(m.w.mid())) : s;
}

void BM_GalleryLattice(benchmark::State& state, const models::Model* model) {
  const Fn f = lattice_surface(*model);
  const Lattice lattice({{0, model->u.lo(), model->u.hi(), kSamples}, {1, model->v.lo(), model->v.hi(), kSamples}});
  using clock = std::chrono::steady_clock;
  double plain_s = 0, tables_s = 0;
  LatticeStats plain_stats, tables_stats;
  for (auto _ : state) {
    const auto t0 = clock::now();
    benchmark::DoNotOptimize(evaluate_lattice(f, lattice, LatticeMethod::Plain, &plain_stats));
    const auto t1 = clock::now();
    benchmark::DoNotOptimize(evaluate_lattice(f, lattice, LatticeMethod::Tables, &tables_stats));
    const auto t2 = clock::now();
    plain_s += std::chrono::duration<double>(t1 - t0).count();
    tables_s += std::chrono::duration<double>(t2 - t1).count();
  }
  const double n = static_cast<double>(state.iterations());
  Row row{1e3 * plain_s / n, 1e3 * tables_s / n, static_cast<double>(plain_stats.total()),
          static_cast<double>(tables_stats.total())};
  rows()[model->name] = row;
  state.counters["plain_ms"] = row.plain_ms;
  state.counters["tables_ms"] = row.tables_ms;
  state.counters["speedup"] = row.plain_ms / row.tables_ms;
  state.counters["ops_ratio"] = row.tables_ops > 0 ? row.plain_ops / row.tables_ops : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
  for (const models::Model& m : models::gallery())
    benchmark::RegisterBenchmark(("GalleryLattice256/" + m.name).c_str(), BM_GalleryLattice, &m)
        ->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();

  std::printf("\n| model (256x256 lattice) | plain ms | tables ms | speedup | primitive ops plain / tables |\n");
  std::printf("|---|---|---|---|---|\n");
  for (const models::Model& m : models::gallery()) {
    const auto it = rows().find(m.name);
    if (it == rows().end()) continue;  // filtered out
    const Row& r = it->second;
    std::printf("| %s | %.2f | %.2f | %.2fx | %.2fx |\n", m.name.c_str(), r.plain_ms, r.tables_ms,
                r.plain_ms / r.tables_ms, r.tables_ops > 0 ? r.plain_ops / r.tables_ops : 0.0);
  }
  return 0;
}
