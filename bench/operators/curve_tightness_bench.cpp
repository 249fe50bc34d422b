// Tightness of the curve inclusion function: for clamped uniform B-splines of degree 1-5,
// the width of the enclosure over a parameter box against the true range (sampled densely),
// for boxes of 1/8 span, one span and three spans. Counters:
//   ratio        mean enclosure width / sampled range (1 = exact)
//   hull_ratio   the same for the plain control-polygon hull of the overlapped spans
//                (the classic convex hull bound without sub-span blossoms), for comparison
// The time is one interval evaluation of the curve's tape.
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/operators/curve.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <random>

namespace genmod {
namespace {

constexpr int kPoints = 12;

struct Setup {
  Curve curve;
  std::vector<Interval> boxes;
};

Setup make(int degree, int box_kind) {
  std::mt19937_64 rng(static_cast<unsigned>(degree));
  std::uniform_real_distribution<double> c(-1, 1);
  Curve::Points pts(kPoints, std::vector<double>(1));
  for (auto& p : pts) p[0] = c(rng);
  Setup s{Curve::uniform_bspline(pts, degree), {}};
  const double span = 1.0 / (kPoints - degree);
  const double width = box_kind == 0 ? span / 8 : box_kind == 1 ? span : 3 * span;
  std::uniform_real_distribution<double> start(0, 1 - width);
  for (int i = 0; i < 64; ++i) {
    const double a = start(rng);
    s.boxes.push_back(Interval(a, a + width));
  }
  return s;
}

double sampled_range(const Tape& tape, const Interval& box) {
  PointEvaluator pv;
  double lo = 1e300, hi = -1e300;
  for (int k = 0; k <= 2000; ++k) {
    const double v = pv.eval(tape, {box.lo() + (box.hi() - box.lo()) * k / 2000})[0];
    lo = std::min(lo, v), hi = std::max(hi, v);
  }
  return hi - lo;
}

// The control-polygon hull of the spans the box overlaps (no sub-span refinement).
double hull_width(const Curve& c, const Interval& box) {
  const auto& knots = c.knots();
  const auto pts = c.control_points();
  const int p = c.degree();
  double lo = 1e300, hi = -1e300;
  for (int k = p; k < static_cast<int>(pts.size()); ++k) {
    const auto ku = static_cast<std::size_t>(k);
    if (knots[ku + 1] <= box.lo() || knots[ku] >= box.hi() || knots[ku] == knots[ku + 1]) continue;
    for (int i = k - p; i <= k; ++i) lo = std::min(lo, pts[static_cast<std::size_t>(i)][0]), hi = std::max(hi, pts[static_cast<std::size_t>(i)][0]);
  }
  return hi - lo;
}

void BM_CurveTightness(benchmark::State& state) {
  const int degree = static_cast<int>(state.range(0));
  const Setup s = make(degree, static_cast<int>(state.range(1)));
  const Tape tape(s.curve(x(0)));
  IntervalEvaluator iv;
  double ratio = 0, hull = 0;
  for (const Interval& box : s.boxes) {
    const double range = sampled_range(tape, box);
    ratio += iv.eval(tape, {box})[0].width() / range;
    hull += hull_width(s.curve, box) / range;
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(iv.eval(tape, {s.boxes[i++ % s.boxes.size()]}).data());
  }
  state.counters["ratio"] = ratio / static_cast<double>(s.boxes.size());
  state.counters["hull_ratio"] = hull / static_cast<double>(s.boxes.size());
}

// Degrees 1-5; boxes of 1/8 span (0), one span (1), three spans (2).
BENCHMARK(BM_CurveTightness)->ArgNames({"degree", "box"})->ArgsProduct({{1, 2, 3, 4, 5}, {0, 1, 2}});

}  // namespace
}  // namespace genmod
