// Throughput of the mesh tools on a closed box of about one million quads (a 408 x 408 grid per
// side: 998,784 quads, 2.0 M triangles). Counter "s_per_Mface" = seconds per million input
// faces of the mesh (the tools rebuild the whole mesh, so the mesh size is the cost driver).
#include "genmod/procedural/extrusion.hpp"
#include "genmod/procedural/grid_box.hpp"
#include "genmod/procedural/selection.hpp"
#include "genmod/procedural/sqrt2_subdivision.hpp"

#include <benchmark/benchmark.h>

namespace genmod {
namespace {

const PolyMesh& big_box() {
  static const PolyMesh mesh = make_grid_box(Vec3(-1, -1, -1), Vec3(1, 1, 1), 408);
  return mesh;
}

void per_million_faces(benchmark::State& state, std::size_t faces) {
  state.counters["Mfaces"] = static_cast<double>(faces) / 1e6;
  state.counters["s_per_Mface"] = benchmark::Counter(static_cast<double>(faces) / 1e6,
                                                     benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
}

// Extrudes the upper half of the box (the +z side and the upper halves of four sides).
void BM_ExtrudeUpperHalf(benchmark::State& state) {
  const PolyMesh& source = big_box();
  const FaceList half = select_faces(source, all_faces(source), RatioBox{0, 1, 0, 1, 0.5, 1});
  for (auto _ : state) {
    state.PauseTiming();
    PolyMesh mesh = source;
    state.ResumeTiming();
    FaceList caps = extrude(mesh, half, Vec3(0, 0, 0.25));
    benchmark::DoNotOptimize(caps.data());
  }
  state.counters["selected"] = static_cast<double>(half.size());
  per_million_faces(state, source.n_faces());
}
BENCHMARK(BM_ExtrudeUpperHalf)->Unit(benchmark::kMillisecond);

void BM_Sqrt2Global(benchmark::State& state) {
  const PolyMesh& source = big_box();
  for (auto _ : state) {
    state.PauseTiming();
    PolyMesh mesh = source;
    state.ResumeTiming();
    sqrt2_subdivide_all(mesh, 1, 1.0);
    benchmark::DoNotOptimize(mesh.n_faces());
  }
  per_million_faces(state, source.n_faces());
}
BENCHMARK(BM_Sqrt2Global)->Unit(benchmark::kMillisecond);

void BM_Sqrt2AdaptiveUpperHalf(benchmark::State& state) {
  const PolyMesh& source = big_box();
  const FaceList half = select_faces(source, all_faces(source), RatioBox{0, 1, 0, 1, 0.5, 1});
  for (auto _ : state) {
    state.PauseTiming();
    PolyMesh mesh = source;
    state.ResumeTiming();
    FaceList created = sqrt2_subdivide(mesh, half, 1, 1.0);
    benchmark::DoNotOptimize(created.data());
  }
  state.counters["selected"] = static_cast<double>(half.size());
  per_million_faces(state, source.n_faces());
}
BENCHMARK(BM_Sqrt2AdaptiveUpperHalf)->Unit(benchmark::kMillisecond);

void BM_SelectUpperHalf(benchmark::State& state) {
  const PolyMesh& source = big_box();
  const FaceList all = all_faces(source);
  for (auto _ : state) {
    FaceList half = select_faces(source, all, RatioBox{0, 1, 0, 1, 0.5, 1});
    benchmark::DoNotOptimize(half.data());
  }
  per_million_faces(state, source.n_faces());
}
BENCHMARK(BM_SelectUpperHalf)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace genmod
