// The culled field's hierarchy and its derivative culling (operators/culled_field.hpp, issue
// 11): the gradient bound of Gaussian convolutions against sampled symbolic derivatives, the
// hierarchy's inclusion against sampled values and against the linear scan, and derivative
// fields of many elements against sampled derivatives and finite differences.
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/convolution.hpp"
#include "genmod/operators/culled_field.hpp"
#include "operators/operator_properties.hpp"
#include "operators/random_skeleton_field.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace genmod {
namespace {

const int kXyz[3] = {0, 1, 2};

double at(const Fn& f, double x, double y, double z) { return evaluate(f, std::vector<double>{x, y, z})[0]; }

using testing::cube;
using testing::segment_distance;

// A point at distance s * r from the segment a-b along axis `axis` (a, b on that axis): beside
// it, beyond an end, or diagonally off an end.
Point3 point_near_axis_segment(const Point3& a, const Point3& b, int axis, double distance, std::mt19937& rng) {
  std::uniform_real_distribution<double> w(0, 1);
  const double pi = 3.141592653589793;
  const double lo = std::min(a[axis], b[axis]), hi = std::max(a[axis], b[axis]);
  const int o1 = (axis + 1) % 3, o2 = (axis + 2) % 3;
  Point3 p = a;
  const int kind = std::uniform_int_distribution<int>(0, 2)(rng);
  if (kind == 0) {  // beside: axial coordinate inside [lo, hi]
    const double phi = 2 * pi * w(rng);
    p[axis] = lo + w(rng) * (hi - lo);
    p[o1] += distance * std::cos(phi), p[o2] += distance * std::sin(phi);
  } else {  // beyond an end, on the axis (kind 1) or at an angle (kind 2)
    const double theta = kind == 1 ? 0.0 : 0.5 * pi * w(rng), phi = 2 * pi * w(rng);
    const bool past_hi = w(rng) < 0.5;
    p[axis] = past_hi ? hi + distance * std::cos(theta) : lo - distance * std::cos(theta);
    p[o1] += distance * std::sin(theta) * std::cos(phi), p[o2] += distance * std::sin(theta) * std::sin(phi);
  }
  return p;
}

// ---- the gradient bound of one element -------------------------------------------------

// Axis-aligned segments (their bounding box is the segment itself, so the bound is taken at
// the exact distance), tapered and not, short and long, and point sources: every sampled
// partial derivative at distance >= 1.5 radius lies within the bound, and the bound is
// reached within a small factor (so it is not vacuous).
TEST(CulledFieldGradientBound, HoldsAtSampledPointsAndIsNearlyReached) {
  std::mt19937 rng(1101);
  std::uniform_real_distribution<double> w(0, 1);
  double worst_ratio = 0;
  int checked = 0;
  for (int e = 0; e < 60; ++e) {
    const int axis = e % 3;
    const double r1 = 0.02 + 0.2 * w(rng);
    double r2 = r1;
    if (e % 4 == 1) r2 = r1 * (0.2 + 2 * w(rng));  // tapered
    if (e % 4 == 2) r2 = r1 * 4;                  // steeply tapered
    double length = r1 * (e % 5 == 0 ? 0.05 + 0.5 * w(rng) : 0.5 + 20 * w(rng));
    Point3 a = {w(rng) - 0.5, w(rng) - 0.5, w(rng) - 0.5}, b = a;
    b[axis] += length;
    const bool point = e % 7 == 3;
    const FieldElement el = point ? gaussian_point_element(a, r1, 0.5 + 2 * w(rng)) : gaussian_segment_element(a, b, r1, r2);
    if (point) b = a;
    Fn grad[3];
    for (int k = 0; k < 3; ++k) grad[k] = derivative(el.density, k);
    for (int s = 0; s < 200; ++s) {
      const double dist = el.radius * (1.5 + 8 * std::pow(w(rng), 2));
      const Point3 p = point_near_axis_segment(a, b, point ? 0 : axis, dist, rng);
      const double exact = segment_distance(a, b, p);
      // The bound for a box that is the point itself (its distance to the skeleton's box is
      // the exact distance, up to the rounding of p's coordinates).
      const double bound = culled_derivative_bound(el, cube(p, 0.0));
      if (exact < 1.5 * el.radius * (1 + 1e-9)) continue;
      ASSERT_TRUE(std::isfinite(bound)) << "no bound at distance " << exact / el.radius << " radii";
      // The derivation bounds the gradient's length, hence each partial derivative.
      double length2 = 0;
      for (int k = 0; k < 3; ++k) {
        const double g = std::abs(at(grad[k], p[0], p[1], p[2]));
        ASSERT_LE(g, bound) << "element " << e << " (r1 " << r1 << ", r2 " << r2 << ", length " << length << ") at "
                            << exact / el.radius << " radii, d/dx" << k;
        worst_ratio = std::max(worst_ratio, g / bound);
        length2 += g * g;
        ++checked;
      }
      ASSERT_LE(std::sqrt(length2), bound) << "element " << e << " at " << exact / el.radius << " radii: gradient length";
    }
  }
  EXPECT_GT(checked, 20000);
  // The bound is within a factor 2 of the largest sampled derivative (its terms are added
  // where the true gradient adds them in quadrature).
  EXPECT_GT(worst_ratio, 0.5);
}

// Randomly oriented segments over random small boxes: the bound from the skeleton's bounding
// box holds at every sampled point of the box.
TEST(CulledFieldGradientBound, HoldsOverRandomBoxes) {
  std::mt19937 rng(1102);
  std::uniform_real_distribution<double> u(-1, 1), w(0, 1);
  int bounded = 0;
  for (int e = 0; e < 40; ++e) {
    const Point3 a = {u(rng), u(rng), u(rng)};
    const Point3 b = {a[0] + 0.3 * u(rng), a[1] + 0.3 * u(rng), a[2] + 0.3 * u(rng)};
    const double r1 = 0.05 + 0.1 * w(rng), r2 = e % 2 ? r1 : 0.05 + 0.1 * w(rng);
    const FieldElement el = gaussian_segment_element(a, b, r1, r2);
    Fn grad[3];
    for (int k = 0; k < 3; ++k) grad[k] = derivative(el.density, k);
    for (int bx = 0; bx < 40; ++bx) {
      const Point3 c = {a[0] + 1.2 * u(rng), a[1] + 1.2 * u(rng), a[2] + 1.2 * u(rng)};
      const double half = 0.1 * w(rng);
      const auto box = cube(c, half);
      const double bound = culled_derivative_bound(el, box);
      if (!std::isfinite(bound)) continue;
      ++bounded;
      for (int s = 0; s < 10; ++s) {
        const double p[3] = {c[0] + half * u(rng), c[1] + half * u(rng), c[2] + half * u(rng)};
        for (int k = 0; k < 3; ++k) ASSERT_LE(std::abs(at(grad[k], p[0], p[1], p[2])), bound);
      }
    }
  }
  EXPECT_GT(bounded, 600);
}

TEST(CulledFieldGradientBound, OnlyDeclaredGaussianConvolutionsAreBounded) {
  FieldElement el = gaussian_segment_element({0, 0, 0}, {1, 0, 0}, 0.1, 0.1);
  const auto far = cube({0.5, 2, 0}, 0.1);
  EXPECT_TRUE(std::isfinite(culled_derivative_bound(el, far)));
  EXPECT_EQ(culled_derivative_bound(el, cube({0.5, 0.12, 0}, 0.01)), std::numeric_limits<double>::infinity());  // nearer than 1.5 r
  el.taper = -1;  // a density of unknown form
  EXPECT_EQ(culled_derivative_bound(el, far), std::numeric_limits<double>::infinity());
  el.taper = std::nan("");
  testing::expect_throw_naming([&] { culled_field({el}); }, "taper");
}

// ---- fields of many elements -----------------------------------------------------------

// A random tree of short segments in [-1, 1]^3 (Gaussian, tapered one time in three) with a
// few Wyvill point sources (compact).
std::vector<FieldElement> random_field(int n, unsigned seed) {
  return testing::random_skeleton_field(
      n, seed,
      [](const Point3& b, double r, std::mt19937&) {
        return FieldElement{point_source(b, r, 1.0, Kernel::wyvill), b, b, 1.0, 2 * r, Falloff::compact};
      },
      [](int i) { return i % 3 == 0; });
}

// Boxes of many sizes: points, tiny boxes on the skeleton, boxes of all sizes anywhere
// (straddling the hierarchy's nodes), the whole field.
std::vector<std::vector<Interval>> test_boxes(const std::vector<FieldElement>& es, int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.2, 1.2), w(0, 1);
  std::vector<std::vector<Interval>> out;
  for (int i = 0; i < n; ++i) {
    const FieldElement& e = es[std::uniform_int_distribution<std::size_t>(0, es.size() - 1)(rng)];
    switch (i % 4) {
      case 0: out.push_back(cube(e.b, 0.0)); break;
      case 1: out.push_back(cube(e.a, 0.05 * w(rng))); break;
      case 2: {
        const Point3 c = {u(rng), u(rng), u(rng)};
        const double h = 0.5 * std::pow(w(rng), 3);
        out.push_back({Interval(c[0] - h, c[0] + h * w(rng)), Interval(c[1] - h * w(rng), c[1] + h), Interval(c[2] - h, c[2] + h)});
        break;
      }
      default: out.push_back(i % 40 == 3 ? cube({0, 0, 0}, 1.2) : cube({u(rng), u(rng), u(rng)}, 0.2 * w(rng)));
    }
  }
  return out;
}

// The header's bound on |point value - exact sum|, 2^-60 max(M, cull_below) with M the sum of
// the elements' |values|, plus the rounding of this test's reference sum and the value's: at
// most 400-odd terms of one sign pattern, taken as 2^-50 M (sums of this size round far
// below it; an element wrongly skipped is caught once it exceeds it).
double point_tolerance(double magnitude, double cull_below) {
  return 0x1p-60 * std::max(magnitude, cull_below) + 0x1p-50 * magnitude;
}

std::vector<double> sample(const std::vector<Interval>& box, std::mt19937& rng) {
  std::uniform_real_distribution<double> w(0, 1);
  std::vector<double> p(3);
  for (int i = 0; i < 3; ++i) p[static_cast<std::size_t>(i)] = box[static_cast<std::size_t>(i)].lo() + w(rng) * (box[static_cast<std::size_t>(i)].hi() - box[static_cast<std::size_t>(i)].lo());
  return p;
}

// Values: sampled points of every box lie in the hierarchy's inclusion, which is never wider
// than the linear scan's (same culled elements, remainders at most cull_below each) and is
// contained in it up to the rounding of the sum's order. With a large cull_below the
// remainders are large enough that leaving one out would be caught.
TEST(CulledFieldHierarchy, ContainsSampledValuesAndMatchesTheLinearScan) {
  const std::vector<FieldElement> es = random_field(1500, 1201);
  for (const double cull_below : {1e-6, 1e-3}) {
    SCOPED_TRACE(cull_below);
    const Tape th(culled_field(es, {.cull_below = cull_below}), kXyz);
    const Tape tl(culled_field(es, {.cull_below = cull_below, .hierarchy = false}), kXyz);
    IntervalEvaluator iv;
    PointEvaluator pv;
    std::mt19937 rng(1202);
    int tighter = 0;
    for (const auto& box : test_boxes(es, 240, 1203)) {
      const Interval h = iv.eval(th, box)[0], l = iv.eval(tl, box)[0];
      ASSERT_LE(h.hi() - h.lo(), (l.hi() - l.lo()) * (1 + 1e-12) + 1e-14);
      ASSERT_NEAR(h.lo(), l.lo(), 1e-12 * (1 + std::abs(l.lo())));
      tighter += h.hi() < l.hi() - 1e-12;
      for (int s = 0; s < 8; ++s) {
        const std::vector<double> p = sample(box, rng);
        const double v = pv.eval(th, p)[0], vl = pv.eval(tl, p)[0];
        // Both within the point tolerance of the exact sum (they may skip different elements).
        ASSERT_NEAR(v, vl, 2 * point_tolerance(std::max(v, vl), cull_below));
        ASSERT_TRUE(h.contains(v)) << "value " << v << " outside " << h;
        ASSERT_TRUE(l.contains(vl)) << "value " << vl << " outside " << l;
      }
    }
    EXPECT_GT(tighter, 50);  // far subtrees' remainders are below cull_below
  }
}

// The point value is the exact sum within the header's tolerance, for the value and the first
// derivatives, at points near the skeleton, anywhere, and far outside; the inclusion of a
// degenerate box (a point) holds it. The reference sums the same element tapes in index order.
TEST(CulledFieldHierarchy, PointValueIsThePlainSumWithinTheTolerance) {
  const std::vector<FieldElement> es = random_field(400, 1301);
  std::mt19937 rng(1302);
  std::uniform_real_distribution<double> near(-0.1, 0.1), anywhere(-1.2, 1.2), far(1.3, 2.0);
  std::vector<std::vector<double>> points;
  for (int i = 0; i < 150; ++i) {
    const Point3& c = es[std::uniform_int_distribution<std::size_t>(0, es.size() - 1)(rng)].a;
    if (i % 3 == 0) points.push_back({c[0] + near(rng), c[1] + near(rng), c[2] + near(rng)});
    else if (i % 3 == 1) points.push_back({anywhere(rng), anywhere(rng), anywhere(rng)});
    else points.push_back({far(rng), anywhere(rng), -far(rng)});
  }
  PointEvaluator pv;
  IntervalEvaluator iv;
  for (const double cull_below : {1e-6, 1e-3}) {
    SCOPED_TRACE(cull_below);
    const Fn culled = culled_field(es, {.cull_below = cull_below});
    int differs = 0;  // points where the value is not the full sum's (elements were skipped)
    for (int k = -1; k < 3; ++k) {
      SCOPED_TRACE(k);
      const Tape tc(k < 0 ? culled : derivative(culled, k), kXyz);
      std::vector<Tape> terms;
      for (const FieldElement& e : es) terms.emplace_back(k < 0 ? e.density : derivative(e.density, k), kXyz);
      for (const std::vector<double>& p : points) {
        double sum = 0, magnitude = 0;
        for (const Tape& t : terms) {
          const double v = pv.eval(t, p)[0];
          sum += v, magnitude += std::abs(v);
        }
        const double v = pv.eval(tc, p)[0];
        ASSERT_NEAR(v, sum, point_tolerance(magnitude, cull_below)) << p[0] << " " << p[1] << " " << p[2];
        if (k < 0) {
          ASSERT_LE(v, sum);  // only elements >= 0 are skipped
        }
        differs += v != sum;
        ASSERT_TRUE(iv.eval(tc, cube({p[0], p[1], p[2]}, 0.0))[0].contains(v));
      }
    }
    EXPECT_GT(differs, 50);  // far points skip every element
  }
}

// A tiny cull_below makes the inclusion evaluate elements that a point's walk skips (its
// threshold is then above cull_below): the inclusion's widening must still hold the point
// values, of the field and of its first derivatives.
TEST(CulledFieldHierarchy, InclusionHoldsPointValuesWhenPointsSkipMore) {
  const std::vector<FieldElement> es = random_field(500, 1351);
  const Fn culled = culled_field(es, {.cull_below = 1e-30});
  IntervalEvaluator iv;
  PointEvaluator pv;
  std::mt19937 rng(1352);
  for (int k = -1; k < 3; ++k) {
    SCOPED_TRACE(k);
    const Tape tc(k < 0 ? culled : derivative(culled, k), kXyz);
    for (const auto& box : test_boxes(es, 120, 1353 + static_cast<unsigned>(k))) {
      const Interval y = iv.eval(tc, box)[0];
      for (int s = 0; s < 6; ++s) {
        const std::vector<double> p = sample(box, rng);
        const double v = pv.eval(tc, p)[0];
        ASSERT_TRUE(y.contains(v)) << v << " outside " << y;
      }
    }
  }
}

TEST(CulledFieldHierarchy, IsDeterministic) {
  const std::vector<FieldElement> es = random_field(800, 1401);
  const Tape t1(culled_field(es), kXyz), t2(culled_field(es), kXyz);
  IntervalEvaluator iv;
  for (const auto& box : test_boxes(es, 100, 1402)) {
    const Interval a = iv.eval(t1, box)[0], b = iv.eval(t2, box)[0];
    ASSERT_EQ(a.lo(), b.lo());
    ASSERT_EQ(a.hi(), b.hi());
  }
}

// Derivatives of a field of many Gaussian and compact elements: the inclusion of each partial
// derivative holds the plain sum's sampled derivatives, the culled field's derivative agrees
// with central differences of its values, and culling (a large cull_below) does not break it.
TEST(CulledFieldHierarchy, DerivativeInclusionContainsSampledDerivatives) {
  const std::vector<FieldElement> es = random_field(600, 1501);
  Fn plain = es[0].density;
  for (std::size_t i = 1; i < es.size(); ++i) plain = plain + es[i].density;
  for (const double cull_below : {1e-6, 1e-3}) {
    SCOPED_TRACE(cull_below);
    const Fn culled = culled_field(es, {.cull_below = cull_below});
    IntervalEvaluator iv;
    PointEvaluator pv;
    std::mt19937 rng(1502);
    for (int k = 0; k < 3; ++k) {
      const Tape dc(derivative(culled, k), kXyz), dp(derivative(plain, k), kXyz), vc(culled, kXyz);
      for (const auto& box : test_boxes(es, 90, 1503 + static_cast<unsigned>(k))) {
        const Interval d = iv.eval(dc, box)[0];
        for (int s = 0; s < 6; ++s) {
          const std::vector<double> p = sample(box, rng);
          const double g = pv.eval(dp, p)[0];
          ASSERT_TRUE(d.contains(g)) << "d/dx" << k << " " << g << " outside " << d;
          const double gc = pv.eval(dc, p)[0];
          ASSERT_NEAR(gc, g, 1e-9 * (1 + std::abs(g)));
          ASSERT_TRUE(d.contains(gc)) << "d/dx" << k << " " << gc << " outside " << d;
        }
      }
      // Central differences of the culled field's values.
      for (int s = 0; s < 30; ++s) {
        std::vector<double> p = sample(cube({0, 0, 0}, 1.0), rng), q = p;
        const double h = 1e-6;
        p[static_cast<std::size_t>(k)] += h, q[static_cast<std::size_t>(k)] -= h;
        const double fd = (pv.eval(vc, p)[0] - pv.eval(vc, q)[0]) / (2 * h);
        p[static_cast<std::size_t>(k)] -= h;
        const double g = pv.eval(dc, p)[0];
        EXPECT_NEAR(fd, g, 1e-4 * (1 + std::abs(g)));
      }
    }
  }
}

// Gaussian derivatives are culled only when declared: over a box far from every element, the
// derivative of a declared field is the pure remainder [-R, R] (every element culled), while
// without the declaration (taper < 0) every element is evaluated.
TEST(CulledFieldHierarchy, GaussianDerivativesAreCulledWhenDeclared) {
  std::vector<FieldElement> es = random_field(300, 1601);
  // 0.25 beyond the skeleton's largest x, half-size 0.02: at least 0.23 (5.75 to 11.5 radii)
  // from every skeleton, beyond every cull distance.
  Point3 c = es[0].a;
  for (const FieldElement& e : es)
    for (const Point3& q : {e.a, e.b})
      if (q[0] > c[0]) c = q;
  c[0] += 0.25;
  const auto far = cube(c, 0.02);
  IntervalEvaluator iv;
  const Fn declared_field = culled_field(es, {.cull_below = 1e-3});
  const Interval declared = iv.eval(Tape(derivative(declared_field, 0), kXyz), far)[0];
  EXPECT_EQ(declared.lo(), -declared.hi());
  EXPECT_GT(declared.hi(), 0);
  EXPECT_LE(declared.hi(), 300 * 1e-3);
  for (FieldElement& e : es) e.taper = -1;
  const Interval undeclared = iv.eval(Tape(derivative(culled_field(es, {.cull_below = 1e-3}), 0), kXyz), far)[0];
  EXPECT_NE(undeclared.lo(), -undeclared.hi());
  // The exact derivative (every element) there, and the culled field's point value, which
  // may skip all of them (it is within 2^-60 cull_below of the exact one).
  Fn plain = es[0].density;
  for (std::size_t i = 1; i < es.size(); ++i) plain = plain + es[i].density;
  const double g = at(derivative(plain, 0), c[0], c[1], c[2]);
  EXPECT_NE(g, 0.0);
  EXPECT_TRUE(declared.contains(g));
  EXPECT_TRUE(undeclared.contains(g));
  const double gc = at(derivative(declared_field, 0), c[0], c[1], c[2]);
  EXPECT_NEAR(gc, g, 0x1p-60 * 1e-3);
  EXPECT_TRUE(declared.contains(gc));
}

TEST(CulledFieldHierarchy, OperatorProperties) {
  const std::vector<FieldElement> es = random_field(120, 1701);
  testing::PropertySpec spec;
  spec.domain.assign(3, Interval(-1.2, 1.2));
  spec.boxes = 150;
  spec.derivative_tol = 1e-5;
  testing::check_operator_properties(culled_field(es, {.cull_below = 1e-4}), spec, 1702);
  testing::check_operator_properties(derivative(culled_field(es, {.cull_below = 1e-4}), 1), spec, 1703);
}

}  // namespace
}  // namespace genmod
