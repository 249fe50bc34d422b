// Culling of second derivatives (operators/culled_field.hpp, issue 11): the Hessian bound of
// constant-radius Gaussian elements against sampled symbolic second derivatives, and the
// culled field's Hessian (the derivative of its derivative, as an implicit mesher builds it)
// against the plain sum's on boxes near, far from and straddling the skeleton.
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/convolution.hpp"
#include "genmod/operators/culled_field.hpp"
#include "operators/random_skeleton_field.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace genmod {
namespace {

const int kXyz[3] = {0, 1, 2};
constexpr double kInf = std::numeric_limits<double>::infinity();
// The six second partials xx xy xz yy yz zz.
const int kPairs[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};

using testing::cube;
using testing::segment_distance;

std::vector<Tape> hessian_tapes(const Fn& f) {
  std::vector<Tape> out;
  for (const auto& jk : kPairs) out.emplace_back(derivative(derivative(f, jk[0]), jk[1]), kXyz);
  return out;
}

// ---- the bound of one element ------------------------------------------------------------

// Randomly oriented constant-radius segments (short and long) and point sources: at points
// 2 to 10 radii from the skeleton (beside it, beyond the ends, anywhere around), every second
// partial lies within the bound taken on the point's own box, and the bound is reached within
// a small factor somewhere (it is not vacuous).
TEST(CulledFieldHessianBound, HoldsAtSampledPointsAndIsNearlyReached) {
  std::mt19937 rng(2101);
  std::uniform_real_distribution<double> u(-1, 1), w(0, 1);
  PointEvaluator pv;
  double worst_ratio = 0;
  int checked = 0;
  for (int e = 0; e < 48; ++e) {
    const double r = 0.02 + 0.2 * w(rng);
    const Point3 a = {u(rng), u(rng), u(rng)};
    const double length = r * (e % 5 == 0 ? 0.05 + 0.5 * w(rng) : 0.5 + 20 * w(rng));
    Point3 dir = {u(rng), u(rng), u(rng)};
    // Axis-aligned one time in three (the skeleton's box is then the segment: the bound is
    // taken at the exact distance, where it is tightest).
    if (e % 3 == 0) dir = {0, 0, 0}, dir[static_cast<std::size_t>(e % 2)] = 1;
    const double n = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    const bool point = e % 7 == 3;
    const Point3 b = point ? a : Point3{a[0] + length * dir[0] / n, a[1] + length * dir[1] / n, a[2] + length * dir[2] / n};
    const FieldElement el = point ? gaussian_point_element(a, r, 0.5 + 2 * w(rng)) : gaussian_segment_element(a, b, r, r);
    const std::vector<Tape> h = hessian_tapes(el.density);
    for (int s = 0; s < 150; ++s) {
      // Around a point of the segment or beyond an end.
      const double t = -0.5 + 2 * w(rng);
      const double dist = r * (2 + 8 * std::pow(w(rng), 2));
      Point3 off = {u(rng), u(rng), u(rng)};
      const double on = std::sqrt(off[0] * off[0] + off[1] * off[1] + off[2] * off[2]);
      Point3 p;
      for (int i = 0; i < 3; ++i) p[i] = a[i] + t * (b[i] - a[i]) + dist * off[i] / on;
      if (segment_distance(a, b, p) < 2 * r * (1 + 1e-9)) continue;
      const double bound = culled_derivative_bound(el, cube(p, 0.0), 2);
      const bool aligned = e % 3 == 0 || point;
      if (!std::isfinite(bound)) {
        ASSERT_FALSE(aligned) << "no bound beyond 2 radii of an axis-aligned skeleton";
        continue;
      }
      const std::vector<double> x{p[0], p[1], p[2]};
      for (std::size_t k = 0; k < 6; ++k) {
        const double v = std::abs(pv.eval(h[k], x)[0]);
        ASSERT_LE(v, bound) << "element " << e << " (r " << r << ", length " << length << ") at "
                            << segment_distance(a, b, p) / r << " radii, pair " << k;
        if (aligned) worst_ratio = std::max(worst_ratio, v / bound);
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 20000);
  // The bound adds the Hessian's blocks' norms; somewhere a sampled entry reaches a fifth of it.
  EXPECT_GT(worst_ratio, 0.2);
}

// The bound from the skeleton's bounding box holds over random boxes (points sampled in them).
TEST(CulledFieldHessianBound, HoldsOverRandomBoxes) {
  std::mt19937 rng(2102);
  std::uniform_real_distribution<double> u(-1, 1), w(0, 1);
  PointEvaluator pv;
  int bounded = 0;
  for (int e = 0; e < 30; ++e) {
    const Point3 a = {u(rng), u(rng), u(rng)};
    const Point3 b = {a[0] + 0.3 * u(rng), a[1] + 0.3 * u(rng), a[2] + 0.3 * u(rng)};
    const double r = 0.03 + 0.1 * w(rng);
    const FieldElement el = gaussian_segment_element(a, b, r, r);
    const std::vector<Tape> h = hessian_tapes(el.density);
    for (int bx = 0; bx < 40; ++bx) {
      const Point3 c = {a[0] + 1.2 * u(rng), a[1] + 1.2 * u(rng), a[2] + 1.2 * u(rng)};
      const double half = 0.1 * w(rng);
      const auto box = cube(c, half);
      const double bound = culled_derivative_bound(el, box, 2);
      if (!std::isfinite(bound)) continue;
      ++bounded;
      for (int s = 0; s < 10; ++s) {
        const std::vector<double> p{c[0] + half * u(rng), c[1] + half * u(rng), c[2] + half * u(rng)};
        for (const Tape& t : h) ASSERT_LE(std::abs(pv.eval(t, p)[0]), bound);
      }
    }
  }
  EXPECT_GT(bounded, 500);
}

TEST(CulledFieldHessianBound, OnlyConstantRadiusGaussiansAreBounded) {
  const auto far = cube({0.5, 2, 0}, 0.1);
  FieldElement el = gaussian_segment_element({0, 0, 0}, {1, 0, 0}, 0.1, 0.1);
  EXPECT_TRUE(std::isfinite(culled_derivative_bound(el, far, 2)));
  EXPECT_EQ(culled_derivative_bound(el, cube({0.5, 0.18, 0}, 0.01), 2), kInf);  // nearer than 2 r
  EXPECT_EQ(culled_derivative_bound(gaussian_segment_element({0, 0, 0}, {1, 0, 0}, 0.1, 0.12), far, 2), kInf);
  EXPECT_TRUE(std::isfinite(culled_derivative_bound(gaussian_point_element({0, 0, 0}, 0.1), far, 2)));
  el.taper = -1;
  EXPECT_EQ(culled_derivative_bound(el, far, 2), kInf);
  EXPECT_THROW(culled_derivative_bound(el, far, 3), std::invalid_argument);
}

// ---- the Hessian of a field of many elements ---------------------------------------------

// A random tree of short constant-radius segments in [-1, 1]^3 with a few point sources and,
// with `tapered`, one tapered segment in eight (their second derivatives are never culled).
std::vector<FieldElement> random_field(int n, unsigned seed, bool tapered) {
  return genmod::testing::random_skeleton_field(
      n, seed,
      [](const Point3& b, double r, std::mt19937& rng) {
        return gaussian_point_element(b, r, 0.5 + std::uniform_real_distribution<double>(0, 1)(rng));
      },
      [tapered](int i) { return tapered && i % 8 == 0; });
}

// Boxes near the skeleton (points and small boxes on it), straddling it (boxes of all sizes
// anywhere), far from it (beyond every element's cull distance) and the whole field.
std::vector<std::vector<Interval>> test_boxes(const std::vector<FieldElement>& es, int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.2, 1.2), w(0, 1);
  std::vector<std::vector<Interval>> out;
  for (int i = 0; i < n; ++i) {
    const FieldElement& e = es[std::uniform_int_distribution<std::size_t>(0, es.size() - 1)(rng)];
    switch (i % 5) {
      case 0: out.push_back(cube(e.b, 0.0)); break;
      case 1: out.push_back(cube(e.a, 0.05 * w(rng))); break;
      case 2: out.push_back(cube({u(rng), u(rng), u(rng)}, 0.5 * std::pow(w(rng), 3))); break;
      case 3: out.push_back(cube({1.4 + w(rng), u(rng), -1.3 - w(rng)}, 0.1 * w(rng))); break;
      default: out.push_back(i % 50 == 4 ? cube({0, 0, 0}, 1.2) : cube({u(rng), u(rng), u(rng)}, 0.2 * w(rng)));
    }
  }
  return out;
}

std::vector<double> sample(const std::vector<Interval>& box, std::mt19937& rng) {
  std::uniform_real_distribution<double> w(0, 1);
  std::vector<double> p(3);
  for (std::size_t i = 0; i < 3; ++i) p[i] = box[i].lo() + w(rng) * (box[i].hi() - box[i].lo());
  return p;
}

// Every sampled second partial of the plain sum, and of the culled field itself, lies in the
// culled Hessian's inclusion; the culled point value is the plain one up to the header's
// tolerance; over far boxes the Hessian of a field without tapered segments is a pure
// remainder [-R, R] (every element culled) while without Hessian culling it is not, and both
// contain the samples.
class CulledFieldHessian : public ::testing::TestWithParam<bool> {};

TEST_P(CulledFieldHessian, InclusionContainsThePlainSumsSecondDerivatives) {
  const bool tapered = GetParam();
  const std::vector<FieldElement> es = random_field(500, 2201, tapered);
  Fn plain = es[0].density;
  for (std::size_t i = 1; i < es.size(); ++i) plain = plain + es[i].density;
  const std::vector<Tape> hp = hessian_tapes(plain);
  IntervalEvaluator iv;
  PointEvaluator pv;
  for (const double cull_below : {1e-6, 1e-3}) {
    SCOPED_TRACE(cull_below);
    const std::vector<Tape> hc = hessian_tapes(culled_field(es, {.cull_below = cull_below}));
    const std::vector<Tape> hn = hessian_tapes(culled_field(es, {.cull_below = cull_below, .cull_second_derivatives = false}));
    std::mt19937 rng(2202);
    int pure = 0, far_boxes = 0;
    for (const auto& box : test_boxes(es, 150, 2203)) {
      for (std::size_t k = 0; k < 6; ++k) {
        const Interval d = iv.eval(hc[k], box)[0], n = iv.eval(hn[k], box)[0];
        if (k == 0 && box[0].lo() >= 1.3) {
          ++far_boxes;
          pure += d.lo() == -d.hi() && n.lo() != -n.hi();
        }
        for (int s = 0; s < 4; ++s) {
          const std::vector<double> p = sample(box, rng);
          const double g = pv.eval(hp[k], p)[0], gc = pv.eval(hc[k], p)[0];
          ASSERT_TRUE(d.contains(g)) << "pair " << k << ": " << g << " outside " << d;
          ASSERT_TRUE(n.contains(g)) << "pair " << k << " (not culled): " << g << " outside " << n;
          ASSERT_TRUE(d.contains(gc)) << "pair " << k << ": culled point value " << gc << " outside " << d;
          ASSERT_NEAR(gc, g, 1e-9 * (1 + std::abs(g)));
        }
      }
    }
    EXPECT_GT(far_boxes, 20);
    // 0.3 or more from [-1, 1]^3 (7.5 radii): beyond every cull distance.
    if (!tapered) {
      EXPECT_EQ(pure, far_boxes);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Tapered, CulledFieldHessian, ::testing::Bool());

// A tiny cull_below makes the inclusion evaluate elements that a point's walk skips: its
// widening must still hold the Hessian's point values.
TEST(CulledFieldHessianPoints, InclusionHoldsPointValuesWhenPointsSkipMore) {
  const std::vector<FieldElement> es = random_field(400, 2301, true);
  const std::vector<Tape> hc = hessian_tapes(culled_field(es, {.cull_below = 1e-30}));
  IntervalEvaluator iv;
  PointEvaluator pv;
  std::mt19937 rng(2302);
  for (const auto& box : test_boxes(es, 100, 2303))
    for (const Tape& t : hc) {
      const Interval y = iv.eval(t, box)[0];
      for (int s = 0; s < 4; ++s) {
        const double v = pv.eval(t, sample(box, rng))[0];
        ASSERT_TRUE(y.contains(v)) << v << " outside " << y;
      }
    }
}

// The culled Hessian agrees with central differences of the culled gradient.
TEST(CulledFieldHessianPoints, AgreesWithDifferencesOfTheGradient) {
  const std::vector<FieldElement> es = random_field(300, 2401, true);
  const Fn f = culled_field(es);
  PointEvaluator pv;
  std::mt19937 rng(2402);
  for (const auto& jk : kPairs) {
    const Tape g(derivative(f, jk[0]), kXyz), h(derivative(derivative(f, jk[0]), jk[1]), kXyz);
    for (int s = 0; s < 40; ++s) {
      std::vector<double> p = sample(cube({0, 0, 0}, 1.0), rng), q = p;
      const double step = 1e-6;
      p[static_cast<std::size_t>(jk[1])] += step, q[static_cast<std::size_t>(jk[1])] -= step;
      const double fd = (pv.eval(g, p)[0] - pv.eval(g, q)[0]) / (2 * step);
      p[static_cast<std::size_t>(jk[1])] -= step;
      const double v = pv.eval(h, p)[0];
      EXPECT_NEAR(fd, v, 1e-3 * (1 + std::abs(v)));
    }
  }
}

}  // namespace
}  // namespace genmod
