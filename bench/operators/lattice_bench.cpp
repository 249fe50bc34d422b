// Lattice sampling of a parametric surface at 256 x 256: plain lattice evaluation against the
// subfunction-table method (Snyder §4.2.1), and the speedup measured in the same run.
#include "genmod/tessellate/lattice.hpp"
#include "genmod/tessellate/mesh.hpp"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <numbers>

namespace {

using namespace genmod;

// A tube of varying radius swept along a helix with its Frenet frame (thesis §4.2.1.2):
// S(u, v) = s(v) + r(u, v) (n(v) cos u + b(v) sin u). Frame terms depend on v only, the
// circle terms on u only: the case the tables are for.
Fn helix_tube() {
  const Fn u = x(0), v = x(1);
  const double c = 0.3, k = 1.0 / std::sqrt(1.0 + c * c);
  const Fn s = cat({cos(v), sin(v), c * v});
  const Fn n = cat({-cos(v), -sin(v), Fn(0.0)});
  const Fn b = cat({c * k * sin(v), -c * k * cos(v), Fn(k)});
  const Fn r = 0.2 + 0.05 * sin(3.0 * u) * (1.0 + 0.5 * cos(2.0 * v));
  const Fn cu = cos(u), su = sin(u);
  return cat({s[0] + r * (n[0] * cu + b[0] * su), s[1] + r * (n[1] * cu + b[1] * su),
              s[2] + r * (n[2] * cu + b[2] * su)});
}

const Lattice& lattice256() {
  static const Lattice lat({{0, 0.0, 2 * std::numbers::pi, 256}, {1, 0.0, 6 * std::numbers::pi, 256}});
  return lat;
}

void BM_Lattice256(benchmark::State& state, LatticeMethod method) {
  const Fn f = helix_tube();
  LatticeStats stats;
  for (auto _ : state) benchmark::DoNotOptimize(evaluate_lattice(f, lattice256(), method, &stats));
  state.counters["prim_ops"] = static_cast<double>(stats.total());
  state.counters["points"] = static_cast<double>(lattice256().num_points());
}
BENCHMARK_CAPTURE(BM_Lattice256, plain, LatticeMethod::Plain)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Lattice256, tables, LatticeMethod::Tables)->Unit(benchmark::kMillisecond);

// Both methods timed alternately in one benchmark: counters give the ratio directly.
void BM_Lattice256_TableSpeedup(benchmark::State& state) {
  const Fn f = helix_tube();
  double plain_s = 0, tables_s = 0;
  using clock = std::chrono::steady_clock;
  for (auto _ : state) {
    auto t0 = clock::now();
    benchmark::DoNotOptimize(evaluate_lattice(f, lattice256(), LatticeMethod::Plain));
    auto t1 = clock::now();
    benchmark::DoNotOptimize(evaluate_lattice(f, lattice256(), LatticeMethod::Tables));
    auto t2 = clock::now();
    plain_s += std::chrono::duration<double>(t1 - t0).count();
    tables_s += std::chrono::duration<double>(t2 - t1).count();
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["plain_ms"] = 1e3 * plain_s / n;
  state.counters["tables_ms"] = 1e3 * tables_s / n;
  state.counters["speedup"] = plain_s / tables_s;
}
BENCHMARK(BM_Lattice256_TableSpeedup)->Unit(benchmark::kMillisecond);

// The whole surface-to-mesh path (tables), periodic in u.
void BM_MeshParametric256(benchmark::State& state) {
  const Fn f = helix_tube();
  for (auto _ : state)
    benchmark::DoNotOptimize(mesh_parametric(f, {0, 0.0, 2 * std::numbers::pi, 256},
                                             {1, 0.0, 6 * std::numbers::pi, 256}, {true, false}));
}
BENCHMARK(BM_MeshParametric256)->Unit(benchmark::kMillisecond);

}  // namespace
