// Culled superposition (operators/culled_field.hpp): the interval bound of a tree-like field
// of N Gaussian segment convolutions over small boxes near the skeleton, culled against the
// plain sum's tape (every element's inclusion on every box).
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/convolution.hpp"
#include "genmod/operators/culled_field.hpp"
#include "genmod/tessellate/implicit_mesher.hpp"

#include "random_skeleton.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

using namespace genmod;

// The benchmarks' random skeleton (random_skeleton.hpp) as Gaussian or compact elements.
std::vector<FieldElement> tree(int n, Kernel kernel = Kernel::gaussian) {
  std::vector<FieldElement> es;
  for (const bench::SkeletonSegment& s : bench::random_skeleton(n)) {
    const Point3 a = s.a, b = s.b;
    const double r = s.radius;
    if (kernel == Kernel::gaussian) es.push_back({segment_convolution(a, b, r), a, b, 1.0, r, Falloff::gaussian});
    else es.push_back({segment_convolution(a, b, r, r, kernel), a, b, 1.0, std::sqrt(2.0) * kernel_support(kernel) * r, Falloff::compact});
  }
  return es;
}

std::vector<std::vector<Interval>> boxes(const std::vector<FieldElement>& es) {
  std::mt19937 rng(8);
  std::vector<std::vector<Interval>> out;
  for (int i = 0; i < 64; ++i) {
    const Point3& c = es[static_cast<std::size_t>(i * 37) % es.size()].b;
    out.push_back({Interval(c[0] - 0.02, c[0] + 0.02), Interval(c[1] - 0.02, c[1] + 0.02), Interval(c[2] - 0.02, c[2] + 0.02)});
  }
  return out;
}

// The culled field of the elements, or the plain sum of their densities.
Fn field(const std::vector<FieldElement>& es, bool culled) {
  if (culled) return culled_field(es);
  Fn f = es[0].density;
  for (std::size_t i = 1; i < es.size(); ++i) f = f + es[i].density;
  return f;
}

void run(benchmark::State& state, bool culled) {
  const std::vector<FieldElement> es = tree(static_cast<int>(state.range(0)));
  const Fn f = field(es, culled);
  const int xyz[3] = {0, 1, 2};
  const Tape tape(f, xyz);
  const auto bs = boxes(es);
  IntervalEvaluator iv;
  double width = 0;
  for (auto _ : state)
    for (const auto& b : bs) {
      const Interval y = iv.eval(tape, b)[0];
      width += y.hi() - y.lo();
      benchmark::DoNotOptimize(y);
    }
  state.counters["boxes/s"] = benchmark::Counter(static_cast<double>(state.iterations() * bs.size()), benchmark::Counter::kIsRate);
  state.counters["mean_width"] = width / static_cast<double>(state.iterations() * bs.size());
}

void BM_CulledFieldInclusion(benchmark::State& state) { run(state, true); }
void BM_PlainSumInclusion(benchmark::State& state) { run(state, false); }
BENCHMARK(BM_CulledFieldInclusion)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PlainSumInclusion)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

// Meshing a field of N Wyvill segment convolutions (compact support: culled in values,
// inclusions and derivatives) against the same mesher on the plain sum's tape, at equal cell
// size (min_feature 0.02 in [-2.2, 2.2]^3).
void mesh(benchmark::State& state, bool culled) {
  const std::vector<FieldElement> es = tree(static_cast<int>(state.range(0)), Kernel::wyvill);
  const Fn f = density_to_implicit(field(es, culled));
  const Box3 box = {Interval(-2.2, 2.2), Interval(-2.2, 2.2), Interval(-2.2, 2.2)};
  std::size_t triangles = 0;
  for (auto _ : state) triangles = mesh_implicit(f, box, {.min_feature = 0.02}).mesh.triangles.size();
  state.counters["triangles"] = static_cast<double>(triangles);
}

void BM_MeshCulledField(benchmark::State& state) { mesh(state, true); }
void BM_MeshPlainSum(benchmark::State& state) { mesh(state, false); }
BENCHMARK(BM_MeshCulledField)->Arg(100)->Arg(1000)->Arg(10000)->Iterations(1)->Unit(benchmark::kMillisecond);
// The plain sum at 1000 segments was killed by the kernel's OOM killer at 22.5 GB (2026-12-02),
// so only a small size is registered.
BENCHMARK(BM_MeshPlainSum)->Arg(100)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
