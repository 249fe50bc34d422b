// render_shaded at 1024^2 on the peers' benchmark shapes (viewed from the top, voxels cubic)
// against the per-pixel ray march that evaluates every voxel center down to the first hit.
#include "benchmark_shapes.hpp"
#include "genmod/tessellate/shaded_render.hpp"

#include <benchmark/benchmark.h>

#include <string>

namespace {

using namespace genmod;

using bench::BenchmarkShape;

void render(benchmark::State& state, const BenchmarkShape& shot, bool brute_force, int size) {
  const Tape tape(shot.load());
  const ShadedOptions options{.size = size, .box = shot.box()};
  ShadedStats stats;
  for (auto _ : state) {
    ShadedImage image = brute_force ? render_shaded_brute_force(tape, options) : render_shaded(tape, options, &stats);
    benchmark::DoNotOptimize(image.heights.data());
  }
  if (!brute_force) {
    state.counters["cubes"] = static_cast<double>(stats.cubes);
    state.counters["voxels"] = static_cast<double>(stats.voxels_evaluated);
  }
}

const bool registered = [] {
  for (const BenchmarkShape& shot : bench::kBenchmarkShapes)
    for (bool brute_force : {false, true})
      benchmark::RegisterBenchmark(
          (std::string("BM_RenderShaded/") + shot.name + (brute_force ? "/ray_march" : "/subdivision") + "/1024").c_str(),
          [shot, brute_force](benchmark::State& s) { render(s, shot, brute_force, 1024); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->MeasureProcessCPUTime()
          ->Iterations(brute_force ? 1 : 3);
  return true;
}();

}  // namespace
