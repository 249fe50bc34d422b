// Curves: every kind through the shared properties (containment on boxes crossing knots,
// derivatives, batch = scalar), the defining identities of each kind, tightness of the
// sub-span hull, exact derivatives, and bad input.
#include "genmod/operators/curve.hpp"
#include "genmod/operators/vector.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/inclusion.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "operators/operator_properties.hpp"

#include <gtest/gtest.h>

#include <random>
#include <thread>

namespace genmod {
namespace {

using testing::check_operator_properties;
using testing::PropertySpec;
using testing::unit_domain;

Curve::Points random_points(std::mt19937_64& rng, int n, int dim) {
  std::uniform_real_distribution<double> c(-2, 2);
  Curve::Points p(static_cast<std::size_t>(n), std::vector<double>(static_cast<std::size_t>(dim)));
  for (auto& q : p)
    for (auto& v : q) v = c(rng);
  return p;
}

// Clamped knots on [0, 1] with random interior knots (some repeated).
std::vector<double> random_knots(std::mt19937_64& rng, int n, int degree) {
  std::uniform_real_distribution<double> c(0.05, 0.95);
  std::vector<double> interior;
  while (static_cast<int>(interior.size()) < n - degree - 1) {
    const double k = c(rng);
    interior.push_back(k);
    if (rng() % 4 == 0 && degree > 1 && static_cast<int>(interior.size()) < n - degree - 1) interior.push_back(k);
  }
  std::sort(interior.begin(), interior.end());
  std::vector<double> knots(static_cast<std::size_t>(degree) + 1, 0.0);
  knots.insert(knots.end(), interior.begin(), interior.end());
  knots.insert(knots.end(), static_cast<std::size_t>(degree) + 1, 1.0);
  return knots;
}

PropertySpec curve_spec(const Curve& c) {
  PropertySpec spec = unit_domain(1);
  spec.domain[0] = Interval(c.domain().first, c.domain().second);
  spec.breaks.push_back(c.knots());
  spec.boxes = 200;
  return spec;
}

TEST(Curve, BSplinesOfDegree1To5Properties) {
  std::mt19937_64 rng(31);
  for (int degree = 1; degree <= 5; ++degree)
    for (int trial = 0; trial < 3; ++trial) {
      const int n = degree + 1 + static_cast<int>(rng() % 6);
      const Curve c = Curve::bspline(random_points(rng, n, 1 + trial), degree, random_knots(rng, n, degree));
      SCOPED_TRACE("degree " + std::to_string(degree) + " trial " + std::to_string(trial));
      check_operator_properties(c(x(0)), curve_spec(c), 100u + static_cast<unsigned>(degree * 3 + trial));
    }
}

TEST(Curve, OtherKindsProperties) {
  std::mt19937_64 rng(32);
  const Curve::Points pts = random_points(rng, 6, 3);
  std::vector<Curve> curves = {Curve::polyline(pts), Curve::bezier(pts), Curve::uniform_bspline(pts, 3),
                               Curve::uniform_bspline(pts, 2, false), Curve::hermite(pts, random_points(rng, 6, 3)),
                               Curve::catmull_rom(pts), Curve::nurbs(pts, {1.0, 0.5, 2.0, 1.5, 0.3, 1.0}, 3)};
  for (const Curve& c : curves) {
    SCOPED_TRACE(c.op()->name());
    check_operator_properties(c(x(0)), curve_spec(c), 33);
  }
  // Composed with a function of two variables (the argument is any scalar Fn).
  // (degree 5 on 6 points: one polynomial piece, so differences see no knot).
  const Curve c = Curve::uniform_bspline(pts, 5);
  check_operator_properties(c(x(0) * x(1)) * x(1), unit_domain(2), 34);
}

TEST(Curve, KindsSatisfyTheirDefinitions) {
  const Curve::Points pts = {{0, 0}, {1, 2}, {3, 1}, {4, 4}};
  // Polyline: vertex i at i / (n - 1), straight in between.
  const Fn poly = Curve::polyline(pts)(x(0));
  EXPECT_EQ(evaluate(poly, std::vector<double>{1.0 / 3})[1], 2.0);
  EXPECT_NEAR(evaluate(poly, std::vector<double>{0.5})[0], 2.0, 1e-15);
  // Bezier: Bernstein form.
  const double t = 0.3, s = 1 - t;
  const double bx = 3 * s * s * t * 1 + 3 * s * t * t * 3 + t * t * t * 4;
  EXPECT_NEAR(evaluate(Curve::bezier(pts)(x(0)), std::vector<double>{t})[0], bx, 1e-15);
  // Catmull-Rom interpolates; Hermite hits points and tangents.
  const Fn cr = Curve::catmull_rom(pts)(x(0));
  for (int i = 0; i < 4; ++i) {
    const auto p = evaluate(cr, std::vector<double>{i / 3.0});
    EXPECT_NEAR(p[0], pts[static_cast<std::size_t>(i)][0], 1e-14);
    EXPECT_NEAR(p[1], pts[static_cast<std::size_t>(i)][1], 1e-14);
  }
  const Curve::Points tangents = {{1, 0}, {0, 1}, {-1, 0}, {2, 2}};
  const Fn h = Curve::hermite(pts, tangents)(x(0));
  const Fn dh = derivative(h, 0);
  for (int i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 2; ++j) {
      EXPECT_NEAR(evaluate(h, std::vector<double>{i / 3.0})[j], pts[static_cast<std::size_t>(i)][j], 1e-14);
      EXPECT_NEAR(evaluate(dh, std::vector<double>{i / 3.0})[j], tangents[static_cast<std::size_t>(i)][j], 1e-13);
    }
  // NURBS: a quarter circle is exact.
  const Curve arc = Curve::nurbs({{1, 0}, {1, 1}, {0, 1}}, {1, std::sqrt(0.5), 1}, 2);
  const Fn r = length(arc(x(0)));
  for (double u = 0; u <= 1; u += 0.05) EXPECT_NEAR(evaluate(r, std::vector<double>{u})[0], 1.0, 1e-15);
  // Outside the domain: an error, flagged by the inclusion function too.
  EXPECT_TRUE(std::isnan(evaluate(poly, std::vector<double>{1.01})[0]));
  IntervalEvaluator iv;
  iv.eval(Tape(poly), {Interval(0.5, 1.5)});
  EXPECT_EQ(iv.errors()[0], kMaybeError);
  iv.eval(Tape(poly), {Interval(2, 3)});
  EXPECT_EQ(iv.errors()[0], kCertainError);
}

TEST(Curve, DerivativesAreExactSplines) {
  // A degree-p polynomial B-spline differentiated p + 1 times is 0; the p-th derivative is
  // piecewise constant.
  std::mt19937_64 rng(35);
  const Curve c = Curve::bspline(random_points(rng, 7, 2), 4, random_knots(rng, 7, 4));
  Fn d = c(x(0));
  for (int k = 0; k < 4; ++k) d = derivative(d, 0);
  const std::vector<double> knots = c.knots();
  const double mid = 0.5 * (knots[4] + knots[5]);
  const double left = knots[4] + 0.25 * (knots[5] - knots[4]);
  EXPECT_EQ(evaluate(d, std::vector<double>{mid})[0], evaluate(d, std::vector<double>{left})[0]);
  const Fn d5 = derivative(d, 0);
  EXPECT_TRUE(d5[0].is_constant() && d5[1].is_constant());
  // NURBS derivative (quotient rule) against differences, including the chain rule.
  const Curve arc = Curve::nurbs({{1, 0}, {1, 1}, {0, 1}}, {1, std::sqrt(0.5), 1}, 2);
  check_operator_properties(arc(square(x(0))), curve_spec(arc), 36);
}

// A line, a quarter circle and a line joined by double knots, as the gallery's cross
// sections are: tangent-continuous in space, only C^0 in the parameter (the speed jumps at
// the knots 0.3 and 0.6: 1 / 0.3 along the first line, about 5.2 on the arc, 1 / 0.4 along
// the second line).
Curve line_arc_line() {
  const double w = std::sqrt(0.5);
  return Curve::nurbs({{0, 0}, {0.5, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 1.5}, {2, 2}}, {1, 1, 1, w, 1, 1, 1}, 2,
                      {0, 0, 0, 0.3, 0.3, 0.6, 0.6, 1, 1, 1});
}

// The worst excess of the enclosure of f over [k - h, k + h] beyond the range of 400 samples
// (which it must contain).
double excess_at(const Fn& f, double k, double h) {
  const Tape tape(f);
  IntervalEvaluator iv;
  PointEvaluator pv;
  const auto y = iv.eval(tape, {Interval(k - h, k + h)});
  const std::vector<Interval> box(y.begin(), y.end());
  double worst = 0.0;
  for (std::size_t j = 0; j < box.size(); ++j) {
    double lo = 1e300, hi = -1e300;
    for (int i = 0; i <= 400; ++i) {
      const double v = pv.eval(tape, {k - h + 2 * h * i / 400})[j];
      lo = std::min(lo, v), hi = std::max(hi, v);
    }
    EXPECT_TRUE(box[j].contains(lo) && box[j].contains(hi)) << "knot " << k << " h " << h;
    worst = std::max(worst, box[j].width() - (hi - lo));
  }
  return worst;
}

// NURBS derivatives of any order are enclosed span by span: over a box that straddles a
// double knot each span's formula gets its own A', w' and c. (The quotient rule as kernel
// nodes, each enclosed on its own, paired the line's A' with the arc's w': an enclosure as
// wide as the jump that never shrank, about [-3.8, 16] x [-7.2, 7.2] around a tangent
// (5.8, 0) of the gallery plate's cross section.) Containment, derivatives (the second and
// third against differences) and batch = scalar hold; the excess over the true range shrinks
// with the box at the knots; c' is continuous on a box inside a span, not across a double
// knot.
TEST(Curve, RationalDerivativesAreEnclosedSpanBySpan) {
  const Curve c = line_arc_line();
  const Fn d1 = derivative(c(x(0)), 0), d2 = derivative(d1, 0);
  check_operator_properties(d1, curve_spec(c), 38);
  check_operator_properties(d2, curve_spec(c), 39);
  for (double k : {0.3, 0.6})
    for (double h : {1e-3, 1e-5, 1e-7}) EXPECT_LT(excess_at(d1, k, h), 200.0 * h) << "knot " << k << " h " << h;
  IntervalEvaluator iv;
  const Tape tape(d1);
  iv.eval(tape, {Interval(0.35, 0.4)});
  EXPECT_TRUE(iv.continuous());
  iv.eval(tape, {Interval(0.25, 0.35)});
  EXPECT_FALSE(iv.continuous());
  iv.eval(tape, {Interval(0.3, 0.35)});  // a value at the knot comes from the span starting there
  EXPECT_TRUE(iv.continuous());
  iv.eval(tape, {Interval(0.25, 0.3)});
  EXPECT_FALSE(iv.continuous());
  // The curve itself (double knots in degree 2) is continuous everywhere.
  iv.eval(Tape(c(x(0))), {Interval(0.25, 0.35)});
  EXPECT_TRUE(iv.continuous());
}

// A polyline's derivative is a degree-0 B-spline: constant on each span, so continuous on a box
// that holds no knot but at its start, and a jump across one. (It used to report no box
// continuous, so the meshers' second-order bound never applied to a polyline schedule.)
TEST(Curve, DegreeZeroPiecesAreContinuousInsideASpan) {
  const Curve polyline = Curve::bspline({{0.0}, {1.0}, {5.0}}, 1, {0, 0, 0.5, 1, 1});
  const Tape slope(derivative(polyline(x(0)), 0));
  IntervalEvaluator ev;
  EXPECT_NEAR(ev.eval(slope, {Interval(0.1, 0.4)})[0].hi(), 2.0, 1e-12);
  EXPECT_TRUE(ev.continuous());
  ev.eval(slope, {Interval(0.5, 0.7)});  // starts at the knot: the span starting there
  EXPECT_TRUE(ev.continuous());
  const Interval both = ev.eval(slope, {Interval(0.4, 0.6)})[0];
  EXPECT_TRUE(both.contains(Interval(2.0, 8.0)) && both.width() < 6.0 + 1e-12);
  EXPECT_FALSE(ev.continuous());
  ev.eval(slope, {Interval(0.3, 0.5)});  // ends at the knot, where the slope is already 8
  EXPECT_FALSE(ev.continuous());
}

// The unit tangent is enclosed span by span too: at a knot where only the speed jumps its
// enclosure shrinks with the box, where normalize(c') stays wide (the hull of two speeds
// divided by itself). Polynomial curves (a Catmull-Rom spline, triple knots) as well.
TEST(Curve, UnitTangentIsTightAcrossTangentContinuousKnots) {
  const Curve c = line_arc_line();
  const Fn t = c.unit_tangent(x(0));
  check_operator_properties(t, curve_spec(c), 40);
  for (double k : {0.3, 0.6})
    for (double h : {1e-3, 1e-5, 1e-7}) EXPECT_LT(excess_at(t, k, h), 50.0 * h) << "knot " << k << " h " << h;
  EXPECT_GT(excess_at(normalize(derivative(c(x(0)), 0)), 0.3, 1e-7), 0.1);
  const Fn n = length(t);
  for (double u = 0.0; u <= 1.0; u += 0.01) EXPECT_NEAR(evaluate(n, std::vector<double>{u})[0], 1.0, 1e-15);
  const Curve cr = Curve::catmull_rom({{0, 0}, {1, 1}, {2, 0}, {3, 1}});
  check_operator_properties(cr.unit_tangent(x(0)), curve_spec(cr), 41);
  EXPECT_THROW(Curve::polyline({{0, 0}, {1, 1}}).unit_tangent(cat({x(0), x(1)})), std::invalid_argument);
}

TEST(Curve, EnclosureTightensQuadraticallyOnSubSpans) {
  std::mt19937_64 rng(37);
  const Curve c = Curve::uniform_bspline(random_points(rng, 8, 1), 3);
  const Tape tape(c(x(0)));
  IntervalEvaluator iv;
  PointEvaluator pv;
  double previous_excess = 0.0;
  for (double w : {0.1, 0.05, 0.025}) {
    double worst = 0.0;
    for (double a = 0.0; a + w <= 1.0; a += 0.0371) {
      const Interval y = iv.eval(tape, {Interval(a, a + w)})[0];
      double lo = 1e300, hi = -1e300;
      for (int k = 0; k <= 200; ++k) {
        const double v = pv.eval(tape, {a + w * k / 200})[0];
        lo = std::min(lo, v), hi = std::max(hi, v);
      }
      worst = std::max(worst, (y.hi() - y.lo()) - (hi - lo));
    }
    if (previous_excess > 0) {
      EXPECT_LT(worst, previous_excess * 0.35) << "width " << w;  // ~1/4 when quadratic
    }
    previous_excess = worst;
  }
}

TEST(Curve, DerivativeOperatorIsSharedAcrossThreads) {
  // The derivative operator is built once (guarded), so concurrent differentiation yields
  // the same hash-consed nodes and concurrent evaluation the same values.
  const Curve c = Curve::nurbs({{1, 0}, {1, 1}, {0, 1}, {-1, 1}}, {1, 0.7, 1, 2}, 3);
  std::vector<Fn> results(4);
  std::vector<double> values(4);
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < 4; ++i)
    threads.emplace_back([&, i] {
      results[i] = derivative(c(x(0)), 0);
      values[i] = evaluate(results[i], std::vector<double>{0.3})[1];
    });
  for (auto& th : threads) th.join();
  for (std::size_t i = 1; i < 4; ++i) {
    EXPECT_TRUE(identical(results[i], results[0]));
    EXPECT_EQ(values[i], values[0]);
  }
}

TEST(Curve, BadInputIsReported) {
  EXPECT_THROW(Curve::polyline({{0, 0}}), std::invalid_argument);
  EXPECT_THROW(Curve::polyline({{0, 0}, {1}}), std::invalid_argument);
  EXPECT_THROW(Curve::bspline({{0}, {1}, {2}}, 3, {0, 0, 0, 0, 1, 1, 1}), std::invalid_argument);  // too few points
  EXPECT_THROW(Curve::bspline({{0}, {1}, {2}}, 2, {0, 0, 0, 1, 1}), std::invalid_argument);        // knot count
  try {
    Curve::bspline({{0}, {1}, {2}, {3}}, 2, {0, 0, 0, 0.7, 0.5, 1, 1});
    ADD_FAILURE() << "decreasing knots accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("nondecreasing"), std::string::npos) << e.what();
  }
  EXPECT_THROW(Curve::nurbs({{0}, {1}, {2}}, {1, 0, 1}, 2), std::invalid_argument);
  EXPECT_THROW(Curve::nurbs({{0}, {1}, {2}}, {1, 1}, 2), std::invalid_argument);
  EXPECT_THROW(Curve::hermite({{0}, {1}}, {{0}}), std::invalid_argument);
  EXPECT_THROW(Curve::bezier({{0}, {1}})(cat({x(0), x(1)})), std::invalid_argument);
  EXPECT_THROW(Curve::uniform_bspline({{0}, {1}}, 0), std::invalid_argument);
}

// Curves past double's range used to give wrong values and enclosures that missed them, with
// no error flag; now they are refused when built, naming the problem.
TEST(Curve, CurvesPastDoublesRangeAreRefusedWhenBuilt) {
  auto refused = [](auto build, const char* word) {
    try {
      build();
      ADD_FAILURE() << "accepted a curve that overflows (" << word << ")";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  };
  refused([] { Curve::bspline({{0}, {1}}, 1, {-1e308, -1e308, 1e308, 1e308}); }, "knot range");
  refused([] { Curve::nurbs({{1e300}, {0}, {1}}, {1e10, 1, 1}, 2); }, "weighted control point");
  refused([] { Curve::polyline({{-1.7e308}, {1.7e308}}); }, "exceeds");
  // Close knots make the derivative's control points overflow: refused at build time, so
  // derivative() never throws later.
  refused([] { Curve::bspline({{0}, {1e200}, {0}}, 2, {0, 0, 0, 1e-200, 1e-200, 1e-200}); }, "derivative");
  refused([] { Curve::catmull_rom({{0}, {1e308}, {0}}); }, "control point");
}

TEST(Curve, LargeCurvesInsideTheRangeStaySound) {
  // Coordinates near the limit, weights spread over many orders of magnitude: point values
  // lie in the enclosures and every derivative builds and evaluates finitely.
  const std::vector<Curve> curves = {
      Curve::polyline({{-1e300}, {1e300}, {-1e300}}),
      Curve::nurbs({{1e100, -1e100}, {-1e100, 1e100}, {1e100, 1e100}}, {1e-8, 1e8, 1}, 2),
      Curve::bspline({{0}, {1e250}, {0}, {1}}, 3, {-1e250, -1e250, -1e250, -1e250, 1e250, 1e250, 1e250, 1e250}),
  };
  for (const Curve& c : curves) {
    Fn f = c(x(0));
    for (int order = 0; order <= c.degree(); ++order) {
      InclusionFunction inc(f);
      PointEvaluator pe;
      Tape tape(f);
      const auto [lo, hi] = c.domain();
      for (int i = 0; i <= 16; ++i) {
        const double a = lo + (hi - lo) * (i / 16.0), b = lo + (hi - lo) * (std::min(i + 1, 16) / 16.0);
        const std::vector<Interval> box = inc.eval(std::vector<Interval>{Interval(a, b)});
        for (double t : {a, 0.5 * a + 0.5 * b, b}) {
          const auto v = pe.eval(tape, {t});
          for (std::size_t j = 0; j < v.size(); ++j) {
            ASSERT_TRUE(std::isfinite(v[j])) << "order " << order << " t " << t;
            EXPECT_TRUE(box[j].contains(v[j])) << "order " << order << " t " << t << " value " << v[j];
          }
        }
      }
      f = derivative(f, 0);
    }
  }
}

}  // namespace
}  // namespace genmod

namespace genmod {
namespace {

// Curves declare continuity, so the mean value and monotonicity forms work through them
// (and still contain every sampled value); a curve with a jump does not.
TEST(CurveForms, DerivativeFormsApplyThroughContinuousCurves) {
  const Curve::Points pts = {{0.0}, {1.0}, {0.5}, {2.0}, {1.5}, {3.0}};
  const Curve smooth = Curve::uniform_bspline(pts, 3);
  const Fn f = smooth(x(0)) * x(0) - square(x(0));  // dependency makes the natural form loose
  InclusionFunction inc(f);
  int narrower = 0;
  for (int k = 0; k < 40; ++k) {
    const double a = 0.02 * k, w = 0.05;
    const std::vector<Interval> box = {Interval(a, a + w)};
    const Interval natural = inc.eval(box, kNaturalForm)[0];
    const Interval all = inc.eval(box, kAllForms)[0];
    EXPECT_TRUE(natural.contains(all));
    if (all.width() < natural.width()) ++narrower;
    PointEvaluator pe;
    for (int s = 0; s <= 20; ++s) {
      const double t = a + w * s / 20;
      EXPECT_TRUE(all.contains(pe.eval(inc.tape(), {t})[0])) << t;
    }
  }
  EXPECT_GT(narrower, 20);
  // A knot of multiplicity degree + 1 inside the domain is a jump: no derivative forms.
  const Curve jump = Curve::bspline({{0.0}, {1.0}, {5.0}, {6.0}}, 1, {0, 0, 0.5, 0.5, 1, 1});
  IntervalEvaluator ev;
  ev.eval(Tape(jump(x(0))), {Interval(0.4, 0.6)});
  EXPECT_FALSE(ev.continuous());
  ev.eval(Tape(smooth(x(0))), {Interval(0.4, 0.6)});
  EXPECT_TRUE(ev.continuous());
}

}  // namespace
}  // namespace genmod
