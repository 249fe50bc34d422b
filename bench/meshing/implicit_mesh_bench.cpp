// mesh_implicit on the peers' benchmark shapes: libfive's sphere-gyroid over [-5,5]^3 and the
// tanglecube over [-2.5,2.5]^3, as min_feature halves, on 1 and 2 threads. Counters: triangles,
// surface cells, and (measured once, outside the timing) the certified vertex distance and the
// estimated face distance from validate().
#include "benchmark_shapes.hpp"
#include "genmod/tessellate/implicit_mesher.hpp"
#include "genmod/tessellate/validate.hpp"

#include <benchmark/benchmark.h>

#include <string>

namespace {

using namespace genmod;

using bench::BenchmarkShape;

void mesh_shape(benchmark::State& state, const BenchmarkShape& shape, double min_feature, int threads) {
  const ImplicitSurface surface(shape.load());
  const Box3 box = shape.box();
  const ImplicitMeshSettings settings{.min_feature = min_feature, .threads = threads};
  ImplicitMesh m;
  for (auto _ : state) {
    m = mesh_implicit(surface, box, settings);
    benchmark::DoNotOptimize(m.mesh.triangles.data());
  }
  const MeshValidity v = validate(m.mesh, {.surface = &surface.value(), .face_samples = 1});
  state.counters["triangles"] = static_cast<double>(m.mesh.triangles.size());
  state.counters["surface_cells"] = static_cast<double>(m.stats.surface_cells);
  state.counters["valid"] = v.valid() ? 1 : 0;
  state.counters["max_vertex_dist"] = v.surface.max_vertex_bound;
  state.counters["max_face_est"] = v.surface.max_face_estimate;
  state.counters["uncert_vertices"] = static_cast<double>(m.stats.uncertified_vertices);
}

const bool registered = [] {
  for (const BenchmarkShape& shape : bench::kBenchmarkShapes)
    for (double h : {0.1, 0.05, 0.025})
      for (int threads : {1, 2})
        benchmark::RegisterBenchmark(
            (std::string("BM_MeshImplicit/") + shape.name + "/min_feature:" + std::to_string(h).substr(0, 5) +
             "/threads:" + std::to_string(threads))
                .c_str(),
            [shape, h, threads](benchmark::State& s) { mesh_shape(s, shape, h, threads); })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime()
            ->MeasureProcessCPUTime();
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
