// The cache experiment of claims 13-14: a chest on N identical cacheable legs, each leg a
// non-trivial mesh (a column of boxes, jittered by the seeded Rng and displaced by noise).
// Three runs: caching off, cold (the cache is emptied before every chest, so the legs cost one
// miss and N-1 hits), warm (the chest is cacheable too and already stored). Compare the
// medians: warm/off (target <= 0.1) and a single cold leg vs an uncached leg (penalty < 5%).
#include "genmod/procedural/procedural.hpp"

#include <benchmark/benchmark.h>

namespace genmod {
namespace {

// The context every run uses (seed 7, identity transform, default level of detail).
Context seed7() {
  Context c;
  c.seed = 7;
  return c;
}

constexpr int kBoxesPerLeg = 60;

PolyMesh build_leg(const Arguments& a, const CallContext& c) {
  PolyMesh m;
  Rng rng(c.seed());
  double step = a.real("length") / kBoxesPerLeg;
  for (int i = 0; i < kBoxesPerLeg; ++i) {
    double r = 0.1 + 0.05 * rng.next_double();
    append_mesh(m, make_box(Vec3(-r, -r, -step * (i + 1)), Vec3(r, r, -step * i), "leg"));
  }
  for (PolyMesh::VertexHandle v : m.vertices()) {
    Vec3 p = m.point(v);
    m.set_point(v, p + 0.02 * improved_noise(p[0] * 9, p[1] * 9, p[2] * 9) * Vec3(1, 1, 0));
  }
  return m;
}

void register_chest(ProcedureRegistry& r, bool chest_cacheable) {
  ProcedureSpec leg;
  leg.name = "Leg";
  leg.mode = Mode::Out;
  leg.cacheable = true;
  leg.params = {param("length", 2.0)};
  leg.out_body = build_leg;
  r.add(leg);
  ProcedureSpec chest;
  chest.name = "Chest";
  chest.mode = Mode::Out;
  chest.cacheable = chest_cacheable;
  chest.params = {param("legs", 30)};
  chest.out_body = [](const Arguments& a, const CallContext& c) {
    PolyMesh m = make_box(Vec3(0, 0, 0), Vec3(6, 5, 1), "chest");
    for (std::int64_t i = 0; i < a.integer("legs"); ++i)
      append_mesh(m, c.call("Leg"), Affine::translation(Vec3(0.3 + 0.9 * (i % 6), 0.3 + 0.9 * (i / 6), 0)));
    return m;
  };
  r.add(chest);
}

void BM_ChestCacheOff(benchmark::State& state) {
  ProcedureRegistry r;
  register_chest(r, true);
  r.set_caching(false);
  for (auto _ : state) benchmark::DoNotOptimize(r.call("Chest", {{"legs", state.range(0)}}, seed7()));
}

void BM_ChestCacheCold(benchmark::State& state) {
  ProcedureRegistry r;
  register_chest(r, false);
  for (auto _ : state) {
    r.clear_caches();
    benchmark::DoNotOptimize(r.call("Chest", {{"legs", state.range(0)}}, seed7()));
  }
}

void BM_ChestCacheWarm(benchmark::State& state) {
  ProcedureRegistry r;
  register_chest(r, true);
  r.call("Chest", {{"legs", state.range(0)}}, seed7());
  for (auto _ : state) benchmark::DoNotOptimize(r.call("Chest", {{"legs", state.range(0)}}, seed7()));
}

// The cold penalty of one cacheable call: key, lookup, miss, store (a copy) vs the bare body.
void BM_LegOff(benchmark::State& state) {
  ProcedureRegistry r;
  register_chest(r, false);
  r.set_caching(false);
  for (auto _ : state) benchmark::DoNotOptimize(r.call("Leg", {}, seed7()));
}

void BM_LegCold(benchmark::State& state) {
  ProcedureRegistry r;
  register_chest(r, false);
  for (auto _ : state) {
    r.clear_caches();
    benchmark::DoNotOptimize(r.call("Leg", {}, seed7()));
  }
}

BENCHMARK(BM_ChestCacheOff)->Arg(30);
BENCHMARK(BM_ChestCacheCold)->Arg(30);
BENCHMARK(BM_ChestCacheWarm)->Arg(30);
BENCHMARK(BM_LegOff);
BENCHMARK(BM_LegCold);

}  // namespace
}  // namespace genmod
