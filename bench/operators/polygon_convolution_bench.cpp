// Polygonal skeletal elements (operators/polygon_convolution.hpp, issue 11): what the density
// of one polygon costs to build and to evaluate.
//
//  * BM_PolygonImageBuild/<res>: the filtered image of an L-shaped polygon (r = 0.05) at
//    <res> pixels across: rasterization with 4 x 4 coverage samples, the separable B-spline,
//    the lookup's min/max pyramid.
//  * BM_PolygonPoint/<res>: PointEvaluator on the density's tape at 256 fixed points within
//    2 r of the polygon (a mesher's samples); BM_SegmentPoint: the B-spline segment
//    convolution of convolution.hpp at the same points, for scale.
//  * BM_PolygonInterval/<res>/<side>: IntervalEvaluator on the density's tape over 256 cubes of
//    side <side>/1000 centred near the polygon (cube 0.01: a few pixels; 0.1: tens; 1.0:
//    the whole image).
//  * BM_PolygonFieldInterval/<culled>/<n>: IntervalEvaluator over 256 cubes of side 0.02 near a
//    field of n small quads (a sqrt(n) x sqrt(n) grid over [-2, 2]^2, r = 0.02, 30 pixels),
//    as the plain sum (culled = 0) or a culled field of polygon_element (culled = 1).
//  * BM_ImageRange/<res>/<pixels> against BM_ImageBruteHull/<res>/<pixels>: the enclosure of
//    the image over 256 square pixel rectangles <pixels> wide, by the pyramid and by scanning
//    the samples (what the pyramid saves: O(log^2 n) block reads instead of <pixels>^2).
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/convolution.hpp"
#include "genmod/operators/culled_field.hpp"
#include "genmod/operators/polygon_convolution.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace {

using namespace genmod;

constexpr double kRadius = 0.05;

SkeletalPolygon l_shape() {
  return {{{0, 0, 0}, {1, 0, 0}, {1, 0.3, 0}, {0.3, 0.3, 0}, {0.3, 1, 0}, {0, 1, 0}}, {}};
}

std::vector<std::array<double, 3>> near_points() {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.1, 1.1), z(-2 * kRadius, 2 * kRadius);
  std::vector<std::array<double, 3>> ps(256);
  for (auto& p : ps) p = {u(rng), u(rng), z(rng)};
  return ps;
}

void BM_PolygonImageBuild(benchmark::State& state) {
  const int res = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(ConvolutionImage(l_shape(), kRadius, {.resolution = res}).width());
}

void point_bench(benchmark::State& state, const Fn& f) {
  const int xyz[3] = {0, 1, 2};
  const Tape tape(f, xyz);
  PointEvaluator pv;
  const auto ps = near_points();
  for (auto _ : state)
    for (const auto& p : ps) benchmark::DoNotOptimize(pv.eval(tape, p)[0]);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(ps.size()));
}

void BM_PolygonPoint(benchmark::State& state) {
  point_bench(state, ConvolutionImage(l_shape(), kRadius, {.resolution = static_cast<int>(state.range(0))}).density());
}

void BM_SegmentPoint(benchmark::State& state) {
  point_bench(state, segment_convolution({0, 0, 0}, {1, 0, 0}, kRadius, kRadius, Kernel::bspline));
}

void BM_PolygonInterval(benchmark::State& state) {
  const int xyz[3] = {0, 1, 2};
  const Tape tape(ConvolutionImage(l_shape(), kRadius, {.resolution = static_cast<int>(state.range(0))}).density(), xyz);
  const double side = 1e-3 * static_cast<double>(state.range(1));
  IntervalEvaluator iv;
  const auto ps = near_points();
  std::vector<Interval> box(3);
  for (auto _ : state)
    for (const auto& p : ps) {
      for (std::size_t i = 0; i < 3; ++i) box[i] = Interval(p[i] - side / 2, p[i] + side / 2);
      benchmark::DoNotOptimize(iv.eval(tape, box)[0]);
    }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(ps.size()));
}

std::vector<SkeletalPolygon> quad_grid(int n) {
  const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(n))));
  const double pitch = 4.0 / side;
  std::vector<SkeletalPolygon> ps;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      const double x0 = -2 + i * pitch, y0 = -2 + j * pitch, z = 0.05 * ((i + j) % 3);
      ps.push_back({{{x0, y0, z}, {x0 + 0.6 * pitch, y0, z}, {x0 + 0.6 * pitch, y0 + 0.6 * pitch, z}, {x0, y0 + 0.6 * pitch, z}}, {}});
    }
  return ps;
}

void BM_PolygonFieldInterval(benchmark::State& state) {
  const auto polys = quad_grid(static_cast<int>(state.range(1)));
  Fn d;
  if (state.range(0) == 0) {
    d = polygon_convolution(polys, 0.02, {.resolution = 30});
  } else {
    std::vector<FieldElement> es;
    for (const auto& p : polys) es.push_back(polygon_element(p, 0.02, {.resolution = 30}));
    d = culled_field(es);
  }
  const int xyz[3] = {0, 1, 2};
  const Tape tape(d, xyz);
  IntervalEvaluator iv;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2, 2), z(-0.05, 0.15);
  std::vector<std::array<double, 3>> cs(256);
  for (auto& c : cs) c = {u(rng), u(rng), z(rng)};
  std::vector<Interval> box(3);
  for (auto _ : state)
    for (const auto& c : cs) {
      for (std::size_t i = 0; i < 3; ++i) box[i] = Interval(c[i] - 0.01, c[i] + 0.01);
      benchmark::DoNotOptimize(iv.eval(tape, box)[0]);
    }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(cs.size()));
}

std::vector<std::array<double, 2>> rectangle_corners(const ConvolutionImage& image, double pixels) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0, image.width() - 1 - pixels), v(0, image.height() - 1 - pixels);
  std::vector<std::array<double, 2>> cs(256);
  for (auto& c : cs) c = {u(rng), v(rng)};
  return cs;
}

void BM_ImageRange(benchmark::State& state) {
  const ConvolutionImage image(l_shape(), kRadius, {.resolution = static_cast<int>(state.range(0))});
  const double pixels = static_cast<double>(state.range(1));
  const auto cs = rectangle_corners(image, pixels);
  for (auto _ : state)
    for (const auto& c : cs) benchmark::DoNotOptimize(image.range(Interval(c[0], c[0] + pixels), Interval(c[1], c[1] + pixels)));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(cs.size()));
}

void BM_ImageBruteHull(benchmark::State& state) {
  const ConvolutionImage image(l_shape(), kRadius, {.resolution = static_cast<int>(state.range(0))});
  const double pixels = static_cast<double>(state.range(1));
  const auto cs = rectangle_corners(image, pixels);
  for (auto _ : state)
    for (const auto& c : cs) {
      double lo = 1e300, hi = -1e300;
      const int i0 = static_cast<int>(c[0]), i1 = std::min(static_cast<int>(c[0] + pixels) + 1, image.width() - 1);
      const int j0 = static_cast<int>(c[1]), j1 = std::min(static_cast<int>(c[1] + pixels) + 1, image.height() - 1);
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) lo = std::min(lo, image.sample(i, j)), hi = std::max(hi, image.sample(i, j));
      benchmark::DoNotOptimize(lo);
      benchmark::DoNotOptimize(hi);
    }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(cs.size()));
}

}  // namespace

BENCHMARK(BM_PolygonImageBuild)->Arg(80)->Arg(320)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PolygonPoint)->Arg(80)->Arg(320);
BENCHMARK(BM_SegmentPoint);
BENCHMARK(BM_PolygonInterval)->Args({80, 10})->Args({80, 100})->Args({80, 1000})->Args({320, 10})->Args({320, 100})->Args({320, 1000});
BENCHMARK(BM_PolygonFieldInterval)->Args({0, 100})->Args({1, 100})->Args({0, 400})->Args({1, 400})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ImageRange)->Args({320, 4})->Args({320, 32})->Args({320, 256});
BENCHMARK(BM_ImageBruteHull)->Args({320, 4})->Args({320, 32})->Args({320, 256});
