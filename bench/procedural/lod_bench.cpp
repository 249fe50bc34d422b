// Level of detail (issue 12, camera.hpp): the tree of 7 levels built at lods -6..0 (levels
// 1..7), caches emptied before every build, with its face count; and the same tree seen by a
// camera at distances 4..1024 (counter "lod", the level the camera chose), including the cost
// of the frustum test and the projected size. The row at lod 0 is the tree of its parameters.
//   genmod_procedural_bench --benchmark_filter=Lod
#include "genmod/models/procedural_models.hpp"
#include "genmod/procedural/camera.hpp"

#include <benchmark/benchmark.h>

namespace genmod {
namespace {

const NamedArgs kTree{{"levels", 7}};

void measure(benchmark::State& state, const Context& context) {
  ProcedureRegistry r;
  models::register_procedural_models(r);
  std::size_t faces = 0;
  for (auto _ : state) {
    r.clear_caches();
    PolyMesh mesh = r.call("tree", kTree, context);
    faces = mesh.n_faces();
    benchmark::DoNotOptimize(mesh);
  }
  state.counters["faces"] = static_cast<double>(faces);
}

void BM_LodTree(benchmark::State& state) {
  Context c;
  c.lod = static_cast<int>(state.range(0));
  measure(state, c);
}
BENCHMARK(BM_LodTree)->ArgName("lod")->DenseRange(-6, 0, 1)->Unit(benchmark::kMicrosecond);

void BM_LodTreeCamera(benchmark::State& state) {
  Camera camera;
  camera.position = Vec3(0, 1.5, static_cast<double>(state.range(0)));
  Context c;
  c.camera = camera;
  ProcedureRegistry r;
  models::register_procedural_models(r);
  state.counters["lod"] = view_of_box(camera, *r.bounds("tree", kTree)).lod;
  measure(state, c);
}
BENCHMARK(BM_LodTreeCamera)->ArgName("distance")->RangeMultiplier(4)->Range(4, 1024)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace genmod
