// Level of detail (issue 12, camera.hpp): the tree of 7 levels built at lods -6..0 (levels
// 1..7), caches emptied before every build, with its face count; and the same tree seen by a
// camera at distances 4..1024 (counter "lod", the level the camera chose), including the cost
// of the frustum test and the projected size. The row at lod 0 is the tree of its parameters.
// The furniture (chair with arms, couch, round table, luggage with 30 legs) at lods -3..2: build
// time and faces, what a camera saves on a far piece and costs on a near one.
//   genmod_procedural_bench --benchmark_filter=Lod
#include "genmod/models/procedural_models.hpp"
#include "genmod/procedural/camera.hpp"

#include <benchmark/benchmark.h>

#include <utility>

namespace genmod {
namespace {

const NamedArgs kTree{{"levels", 7}};

void measure(benchmark::State& state, const Context& context, const char* name = "tree",
             const NamedArgs& args = kTree) {
  ProcedureRegistry r;
  models::register_procedural_models(r);
  std::size_t faces = 0;
  for (auto _ : state) {
    r.clear_caches();
    PolyMesh mesh = r.call(name, args, context);
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

template <int Model>
void BM_LodFurniture(benchmark::State& state) {
  static const std::pair<const char*, NamedArgs> models[] = {{"chair", {{"arms", true}}},
                                                             {"couch", {}},
                                                             {"table", {{"roundTable", true}}},
                                                             {"luggage", {{"numLegs", 30}}}};
  Context c;
  c.lod = static_cast<int>(state.range(0));
  measure(state, c, models[Model].first, models[Model].second);
}
BENCHMARK(BM_LodFurniture<0>)->Name("BM_LodChair")->ArgName("lod")->DenseRange(-3, 2, 1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LodFurniture<1>)->Name("BM_LodCouch")->ArgName("lod")->DenseRange(-3, 2, 1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LodFurniture<2>)->Name("BM_LodRoundTable")->ArgName("lod")->DenseRange(-3, 2, 1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LodFurniture<3>)->Name("BM_LodLuggage30")->ArgName("lod")->DenseRange(-3, 2, 1)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace genmod
