// The Prospero challenge: render_sign at 1024 x 1024 with the default tile hierarchy, on 1
// and 2 threads (wall-clock time). The counters say how much of the tape survives pruning:
// the mean tape length of the deepest interval tiles and of the tiles evaluated per pixel,
// as fractions of the full tape.
#include "prospero.hpp"

#include "genmod/tessellate/raster2d.hpp"

#include <benchmark/benchmark.h>

namespace genmod::bench {
namespace {

// The last level whose tiles were evaluated (a level can be skipped for small images).
const RasterLevelStats& deepest_level(const RasterStats& stats) {
  for (auto it = stats.levels.rbegin(); it != stats.levels.rend(); ++it)
    if (it->tiles > 0) return *it;
  return stats.levels.front();
}

void BM_RenderProspero(benchmark::State& state) {
  RasterOptions options;
  options.size = 1024;
  options.threads = static_cast<int>(state.range(0));
  RasterStats stats;
  for (auto _ : state) {
    Image image = render_sign(prospero_tape(), options, &stats);
    benchmark::DoNotOptimize(image.pixels.data());
  }
  const double full = static_cast<double>(stats.full_tape);
  state.counters["full_tape"] = full;
  state.counters["deepest_tile_tape"] = deepest_level(stats).mean_tape() / full;
  state.counters["pixel_tape"] = stats.mean_pixel_tape() / full;
}
// CPU time is the process's (both threads), so the table can tell extra work from busy cores.
BENCHMARK(BM_RenderProspero)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace
}  // namespace genmod::bench
