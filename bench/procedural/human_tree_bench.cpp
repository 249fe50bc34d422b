// Experiments 4 and 6 of research/morkel.md (section 4) on the real models of
// models/procedural_models.hpp, with the figures of claims 13, 14 and 30:
//
//   Experiment 4 (model complexity): polygon counts (counter "faces", and "triangles" as
//   written) and build times of the Luggage on 6, 12, 18, 24, 30 human legs and of the
//   L-system tree at levels 3-6 (counter "branches"). Caches emptied before every build.
//   Experiment 6 (caching), each as off (caching switched off), cold (caches emptied before
//   every build: the thesis's "first") and warm (caches kept: its "remainder"):
//     * the Luggage on 30 human legs (luggage_bench.cpp: BM_LuggageCache*);
//     * the tree at level 6, the whole tree cacheable (warm = one tree hit) and with only its
//       branches cacheable (the thesis's "cylinders": warm = 63 branch hits);
//     * the human with only its feet cached (the leg procedure's cacheable flag switched off:
//       2 foot misses cold, 2 hits warm; claim 14), and with its legs cached too.
// Compare medians of one run; bench/procedural/experiment_ratios.py prints them and the
// ratios to "off":
//   genmod_procedural_bench --benchmark_filter='Exp4|Cache|LegAlone' --benchmark_repetitions=10
//       --benchmark_out=exp.json --benchmark_out_format=json
//   python3 bench/procedural/experiment_ratios.py exp.json
#include "genmod/models/procedural_models.hpp"
#include "genmod/procedural/poly_mesh.hpp"

#include <benchmark/benchmark.h>

#include <memory>
#include <set>
#include <string>

namespace genmod {
namespace {

// A registry of its own per benchmark, some procedures' cacheable flag switched off.
std::unique_ptr<ProcedureRegistry> registry(std::set<std::string> uncached = {}) {
  auto r = std::make_unique<ProcedureRegistry>();
  models::register_procedural_models(*r, [&](ProcedureSpec& spec) {
    if (uncached.count(spec.name)) spec.cacheable = false;
  });
  return r;
}

enum class Cache { Off, Cold, Warm };

void run(benchmark::State& state, ProcedureRegistry& r, const std::string& name, const NamedArgs& args, Cache cache,
         const char* counted) {
  Context context;
  context.seed = 7;
  if (cache == Cache::Off) r.set_caching(false);
  if (cache == Cache::Warm) r.call(name, args, context);
  r.reset_cache_stats(counted);
  std::size_t faces = 0;
  for (auto _ : state) {
    if (cache == Cache::Cold) r.clear_caches();
    PolyMesh mesh = r.call(name, args, context);
    faces = mesh.n_faces();
    benchmark::DoNotOptimize(mesh);
  }
  const CacheStats s = r.cache_stats(counted);
  const double n = static_cast<double>(state.iterations());
  state.counters["faces"] = static_cast<double>(faces);
  state.counters[std::string(counted) + "_misses"] = static_cast<double>(s.misses) / n;
  state.counters[std::string(counted) + "_hits"] = static_cast<double>(s.hits) / n;
}

// Experiment 4.
void BM_Exp4_Luggage(benchmark::State& state) {
  auto r = registry();
  run(state, *r, "luggage", {{"numLegs", state.range(0)}}, Cache::Cold, "leg");
  state.counters["triangles"] = static_cast<double>(to_triangle_mesh(r->call("luggage", {{"numLegs", state.range(0)}})).triangles.size());
}
void BM_Exp4_Tree(benchmark::State& state) {
  auto r = registry();
  run(state, *r, "tree", {{"levels", state.range(0)}}, Cache::Cold, "branch");
  state.counters["branches"] = static_cast<double>((1 << state.range(0)) - 1);
  state.counters["triangles"] = static_cast<double>(to_triangle_mesh(r->call("tree", {{"levels", state.range(0)}})).triangles.size());
}
BENCHMARK(BM_Exp4_Luggage)->ArgName("legs")->DenseRange(6, 30, 6)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Exp4_Tree)->ArgName("levels")->DenseRange(3, 6, 1)->Unit(benchmark::kMillisecond);

// Experiment 6: the tree at level 6.
const NamedArgs kTree{{"levels", 6}};
void BM_TreeCacheOff(benchmark::State& state) { auto r = registry(); run(state, *r, "tree", kTree, Cache::Off, "tree"); }
void BM_TreeCacheCold(benchmark::State& state) { auto r = registry(); run(state, *r, "tree", kTree, Cache::Cold, "tree"); }
void BM_TreeCacheWarm(benchmark::State& state) { auto r = registry(); run(state, *r, "tree", kTree, Cache::Warm, "tree"); }
void BM_TreeBranchesCachedCold(benchmark::State& state) {
  auto r = registry({"tree"});
  run(state, *r, "tree", kTree, Cache::Cold, "branch");
}
void BM_TreeBranchesCachedWarm(benchmark::State& state) {
  auto r = registry({"tree"});
  run(state, *r, "tree", kTree, Cache::Warm, "branch");
}
BENCHMARK(BM_TreeCacheOff)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TreeCacheCold)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TreeCacheWarm)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TreeBranchesCachedCold)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TreeBranchesCachedWarm)->Unit(benchmark::kMicrosecond);

// Experiment 6: the human (claim 14: only the feet cached).
void BM_HumanCacheOff(benchmark::State& state) { auto r = registry(); run(state, *r, "human", {}, Cache::Off, "foot"); }
void BM_HumanFeetCachedCold(benchmark::State& state) {
  auto r = registry({"leg", "arm", "torso", "head"});
  run(state, *r, "human", {}, Cache::Cold, "foot");
}
void BM_HumanFeetCachedWarm(benchmark::State& state) {
  auto r = registry({"leg", "arm", "torso", "head"});
  run(state, *r, "human", {}, Cache::Warm, "foot");
}
void BM_HumanLegsCachedWarm(benchmark::State& state) { auto r = registry(); run(state, *r, "human", {}, Cache::Warm, "leg"); }
BENCHMARK(BM_HumanCacheOff)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HumanFeetCachedCold)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HumanFeetCachedWarm)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HumanLegsCachedWarm)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace genmod
