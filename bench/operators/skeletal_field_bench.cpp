// Skeletal implicit fields of many Gaussian segment convolutions (issue 11): what users do
// with them, timed for the plain sum, the culled field with a linear scan of the elements and
// the culled field with its hierarchy, in one run (compare the *_median rows: CPU time).
//
//  * BM_FieldOctree/<mode>/<n>/<depth>/<side>: the interval classification of f = 1/2 - D
//    over an octree of the cube of side <side>/1000 centred at the origin down to <depth> (a
//    box whose bound excludes 0 is a leaf, the others are split). Modes: 0 the plain sum of the
//    n densities as one tape, 1 the culled field with culling disabled (cull_below = 0: the
//    same sum as one custom operator), 2 the culled field with a linear scan of the elements,
//    3 with the hierarchy. Counters: boxes visited, boxes left ambiguous at the deepest level.
//    Registered: the cube 0.55 to depth 3 (cells 0.069, about two radii) in every mode, and
//    the whole field (cube 4.4, depth 6) for the linear scan and the hierarchy (the sums would
//    take about 100 times longer).
//  * BM_GradientOctree/<mode>/...: the same octree, and at each box that may hold surface the
//    gradient's inclusion as well (the mesher's normal-cone test): modes 1-3.
//  * BM_PointField/<mode>/<n>/<where>: point evaluations of the density (PointEvaluator on its
//    tape) at 256 fixed points: <where> 0 near the skeleton (within 0.06 of a random
//    segment's end, as a mesher's samples are), 1 anywhere in [-2.2, 2.2]^3 (mostly empty
//    space). Modes 1 (every element: the sum without culling) and 3 (the hierarchy).
//  * BM_MeshField/<mode>/<n>: mesh_implicit of the field in the cube of side 0.16 at the origin
//    at cell size 0.02, one thread: modes 1, 3 and 4 at 1,000 elements, and mode 3 at 10,000
//    once. Mode 4 is the hierarchy without culling the second derivatives (the mesher's Hessian
//    inclusions sum every element, as before that culling): 4 against 3 is its gain.
//
// The skeleton: a random walk of n segments of length 0.05 with direction persistence in
// [-2, 2]^3, branching from a random earlier node one time in ten; radius 0.02 .. 0.04.
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/convolution.hpp"
#include "genmod/operators/culled_field.hpp"
#include "genmod/tessellate/implicit_mesher.hpp"

#include "random_skeleton.hpp"

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace {

using namespace genmod;

std::vector<FieldElement> walk(int n) {
  std::vector<FieldElement> es;
  for (const bench::SkeletonSegment& s : bench::random_skeleton(n))
    es.push_back(gaussian_segment_element(s.a, s.b, s.radius, s.radius));
  return es;
}

Fn balanced_sum(const std::vector<FieldElement>& es) {
  std::vector<Fn> terms;
  for (const FieldElement& e : es) terms.push_back(e.density);
  while (terms.size() > 1) {
    std::vector<Fn> next;
    for (std::size_t i = 0; i + 1 < terms.size(); i += 2) next.push_back(terms[i] + terms[i + 1]);
    if (terms.size() % 2) next.push_back(terms.back());
    terms = std::move(next);
  }
  return terms[0];
}

// The density of mode 0 (plain sum), 1 (culling disabled), 2 (linear scan), 3 (hierarchy),
// 4 (hierarchy, second derivatives not culled).
Fn density(const std::vector<FieldElement>& es, int mode) {
  switch (mode) {
    case 0: return balanced_sum(es);
    case 1: return culled_field(es, {.cull_below = 0});
    case 2: return culled_field(es, {.hierarchy = false});
    case 4: return culled_field(es, {.cull_second_derivatives = false});
    default: return culled_field(es);
  }
}

const std::vector<FieldElement>& field(int n) {
  static std::vector<FieldElement> cache;
  if (static_cast<int>(cache.size()) != n) cache = walk(n);
  return cache;
}

struct OctreeCount {
  std::size_t boxes = 0, ambiguous = 0;
};

// The octree classification of f (and its gradient, when given) over the cube of side `side`
// centred at the origin, down to `depth`.
OctreeCount octree(const Tape& f, const Tape* gradient, double side, int depth) {
  IntervalEvaluator iv;
  OctreeCount count;
  struct Cell {
    std::array<double, 3> lo;
    double size;
    int depth;
  };
  std::vector<Cell> stack{{{-side / 2, -side / 2, -side / 2}, side, 0}};
  std::vector<Interval> box(3);
  while (!stack.empty()) {
    const Cell c = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i) box[static_cast<std::size_t>(i)] = Interval(c.lo[static_cast<std::size_t>(i)], c.lo[static_cast<std::size_t>(i)] + c.size);
    ++count.boxes;
    const Interval y = iv.eval(f, box)[0];
    if (!y.contains(0.0)) continue;
    if (gradient) benchmark::DoNotOptimize(iv.eval(*gradient, box)[0]);
    if (c.depth == depth) {
      ++count.ambiguous;
      continue;
    }
    const double h = c.size / 2;
    for (int k = 0; k < 8; ++k)
      stack.push_back({{c.lo[0] + (k & 1) * h, c.lo[1] + ((k >> 1) & 1) * h, c.lo[2] + ((k >> 2) & 1) * h}, h, c.depth + 1});
  }
  return count;
}

void BM_FieldOctree(benchmark::State& state) {
  const auto& es = field(static_cast<int>(state.range(1)));
  const int xyz[3] = {0, 1, 2};
  const Tape f(density_to_implicit(density(es, static_cast<int>(state.range(0)))), xyz);
  OctreeCount c;
  for (auto _ : state) c = octree(f, nullptr, 1e-3 * static_cast<double>(state.range(3)), static_cast<int>(state.range(2)));
  state.counters["boxes"] = static_cast<double>(c.boxes);
  state.counters["ambiguous"] = static_cast<double>(c.ambiguous);
}

void BM_GradientOctree(benchmark::State& state) {
  const auto& es = field(static_cast<int>(state.range(1)));
  const int xyz[3] = {0, 1, 2};
  const Fn d = density_to_implicit(density(es, static_cast<int>(state.range(0))));
  const Tape f(d, xyz), g(cat({derivative(d, 0), derivative(d, 1), derivative(d, 2)}), xyz);
  OctreeCount c;
  for (auto _ : state) c = octree(f, &g, 1e-3 * static_cast<double>(state.range(3)), static_cast<int>(state.range(2)));
  state.counters["boxes"] = static_cast<double>(c.boxes);
  state.counters["ambiguous"] = static_cast<double>(c.ambiguous);
}

void BM_PointField(benchmark::State& state) {
  const auto& es = field(static_cast<int>(state.range(1)));
  const int xyz[3] = {0, 1, 2};
  const Tape f(density(es, static_cast<int>(state.range(0))), xyz);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> near(-0.06, 0.06), anywhere(-2.2, 2.2);
  std::vector<std::array<double, 3>> points;
  for (int i = 0; i < 256; ++i) {
    if (state.range(2) == 0) {
      const Point3& c = es[std::uniform_int_distribution<std::size_t>(0, es.size() - 1)(rng)].b;
      points.push_back({c[0] + near(rng), c[1] + near(rng), c[2] + near(rng)});
    } else {
      points.push_back({anywhere(rng), anywhere(rng), anywhere(rng)});
    }
  }
  PointEvaluator pv;
  double total = 0;
  for (auto _ : state)
    for (const auto& p : points) total += pv.eval(f, p)[0];
  benchmark::DoNotOptimize(total);
  state.counters["points/s"] = benchmark::Counter(static_cast<double>(state.iterations() * points.size()), benchmark::Counter::kIsRate);
}

void BM_MeshField(benchmark::State& state) {
  const auto& es = field(static_cast<int>(state.range(1)));
  const ImplicitSurface s(density_to_implicit(density(es, static_cast<int>(state.range(0)))));
  const Box3 box = {Interval(-0.08, 0.08), Interval(-0.08, 0.08), Interval(-0.08, 0.08)};
  ImplicitMesh m;
  for (auto _ : state) m = mesh_implicit(s, box, {.min_feature = 0.02, .max_cell = 0.02, .threads = 1});
  state.counters["triangles"] = static_cast<double>(m.mesh.triangles.size());
  state.counters["surface_cells"] = static_cast<double>(m.stats.surface_cells);
}

// Arguments: mode, elements, octree depth, cube side in thousandths.
BENCHMARK(BM_FieldOctree)->ArgsProduct({{0, 1, 2, 3}, {10000}, {3}, {550}})->Iterations(1)->Repetitions(3)->ReportAggregatesOnly(true)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FieldOctree)->ArgsProduct({{2, 3}, {10000}, {6}, {4400}})->Iterations(1)->Repetitions(3)->ReportAggregatesOnly(true)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GradientOctree)->ArgsProduct({{1, 2, 3}, {10000}, {3}, {550}})->Iterations(1)->Repetitions(3)->ReportAggregatesOnly(true)->Unit(benchmark::kMillisecond);
// Arguments: mode, elements, where.
BENCHMARK(BM_PointField)->ArgsProduct({{1, 3}, {1000, 10000}, {0, 1}})->Repetitions(3)->ReportAggregatesOnly(true)->Unit(benchmark::kMicrosecond);
// Arguments: mode, elements.
BENCHMARK(BM_MeshField)->ArgsProduct({{1, 3, 4}, {1000}})->Iterations(1)->Repetitions(3)->ReportAggregatesOnly(true)->Unit(benchmark::kMillisecond);
// The hierarchy at 10,000 elements, once (point evaluations walk the hierarchy too).
BENCHMARK(BM_MeshField)->Args({3, 10000})->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
