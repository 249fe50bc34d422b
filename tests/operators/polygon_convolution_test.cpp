// Polygonal skeletal elements (operators/polygon_convolution.hpp, research/bloomenthal.md
// §3.9): the shared property harness (containment over near, straddling and far boxes,
// derivatives, batch = scalar), the image pyramid against a brute-force hull, bad input, and
// the chapter's claims: a wide polygon's image is 1 inside and 0 far away, the contiguity
// theorem, seamless abutting polygons, and the resolution at which the surface settles.
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/convolution.hpp"
#include "genmod/operators/polygon_convolution.hpp"
#include "operators/operator_properties.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

namespace genmod {
namespace {

using testing::check_operator_properties;
using testing::expect_throw_naming;
using testing::PropertySpec;

constexpr double kR = 0.1;

double at(const Fn& f, double x, double y, double z) { return evaluate(f, std::vector<double>{x, y, z})[0]; }

// f compiled once, for many evaluations.
struct Compiled {
  explicit Compiled(const Fn& f) : tape(f, std::vector<int>{0, 1, 2}) {}
  double operator()(double x, double y, double z) { return pv.eval(tape, std::vector<double>{x, y, z})[0]; }
  Tape tape;
  PointEvaluator pv;
};

SkeletalPolygon square(double x0, double y0, double side, double z = 0) {
  return {{{x0, y0, z}, {x0 + side, y0, z}, {x0 + side, y0 + side, z}, {x0, y0 + side, z}}, {}};
}

// An L in a tilted plane, with per-vertex weights.
SkeletalPolygon tilted_l() {
  const Point3 o{0.1, -0.2, 0.05}, e1{0.8, 0.0, 0.6}, e2{0.0, 1.0, 0.0};
  const double uv[6][2] = {{0, 0}, {1, 0}, {1, 0.4}, {0.4, 0.4}, {0.4, 1}, {0, 1}};
  SkeletalPolygon p;
  for (const auto& c : uv)
    p.vertices.push_back({o[0] + c[0] * e1[0] + c[1] * e2[0], o[1] + c[0] * e1[1] + c[1] * e2[1],
                          o[2] + c[0] * e1[2] + c[1] * e2[2]});
  p.weights = {1.0, 0.5, 0.8, 1.2, 0.3, 1.0};
  return p;
}

// The root of g in [a, b] (g(a), g(b) of opposite signs) by bisection.
template <typename G>
double root(G&& g, double a, double b) {
  double ga = g(a);
  EXPECT_LT(ga * g(b), 0) << "no sign change in [" << a << ", " << b << "]";
  for (int i = 0; i < 80; ++i) {
    const double m = 0.5 * (a + b), gm = g(m);
    if ((gm < 0) == (ga < 0)) a = m, ga = gm;
    else b = m;
  }
  return 0.5 * (a + b);
}

// The pixel lines of an axis-aligned image in world coordinate `axis` (breaks for the harness).
std::vector<double> pixel_lines(const ConvolutionImage& image, int axis) {
  std::vector<double> lines;
  const int n = axis == 0 ? image.width() : image.height();
  const Point3& dir = axis == 0 ? image.x_axis() : image.y_axis();
  const int k = std::abs(dir[0]) > 0.5 ? 0 : 1;
  for (int i = 0; i < n; ++i) lines.push_back(image.origin()[k] + dir[k] * i / image.world_to_image_scale());
  return lines;
}

// ---- bad input -----------------------------------------------------------------------------

TEST(PolygonConvolution, RejectsBadInputNamingTheProblem) {
  auto expect = [](const SkeletalPolygon& p, double r, PolygonImageOptions o, const std::string& problem) {
    try {
      ConvolutionImage image(p, r, o);
      ADD_FAILURE() << "accepted: " << problem;
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("polygon_convolution"), std::string::npos) << what;
      EXPECT_NE(what.find(problem), std::string::npos) << what;
    }
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect({{{0, 0, 0}, {1, 0, 0}}, {}}, kR, {}, "at least 3 vertices");
  expect({{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {}}, kR, {}, "degenerate");
  expect({{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, {}}, kR, {}, "degenerate");
  expect({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0.2}, {0, 1, 0}}, {}}, kR, {}, "not planar");
  expect({{{0, 0, 0}, {1, nan, 0}, {1, 1, 0}}, {}}, kR, {}, "not finite");
  expect(square(0, 0, 1), kR, {.resolution = 1}, "resolution");
  expect(square(0, 0, 1), 0.0, {}, "radius");
  expect(square(0, 0, 1), -1.0, {}, "radius");
  expect(square(0, 0, 1), nan, {}, "radius");
  expect({square(0, 0, 1).vertices, {1, 1}}, kR, {}, "weights");
  expect({square(0, 0, 1).vertices, {1, 1, nan, 1}}, kR, {}, "weight 2");
  expect(square(0, 0, 1), kR, {.x_axis = Point3{0, 0, 1}}, "x_axis");
  // Slightly non-planar within the tolerance is accepted (and flattened by the projection).
  EXPECT_NO_THROW(ConvolutionImage({{{0, 0, 0}, {1, 0, 0}, {1, 1, 1e-4}, {0, 1, 0}}, {}}, kR));
  expect_throw_naming([] { polygon_convolution(std::vector<SkeletalPolygon>{}, kR); }, "polygon_convolution");
}

// ---- the operator properties ---------------------------------------------------------------

TEST(PolygonConvolution, OperatorPropertiesAxisAligned) {
  const std::vector<SkeletalPolygon> polys = {square(0, 0, 1)};
  const ConvolutionImage image(polys[0], kR, {.resolution = 40});
  const Fn d = image.density();
  // Near: boxes inside the image, straddling its border and its pixel lines.
  PropertySpec near;
  near.domain = {Interval(-0.7, 1.7), Interval(-0.7, 1.7), Interval(-0.35, 0.35)};
  near.breaks = {pixel_lines(image, 0), pixel_lines(image, 1), {-kR * 2.769, kR * 2.769}};
  near.boxes = 400;
  near.step = 1e-5;  // well inside a pixel (pixel size 0.053)
  check_operator_properties(d, near, 41);
  // Far: most boxes miss the image or hold all of it.
  PropertySpec far;
  far.domain.assign(3, Interval(-6.0, 6.0));
  far.breaks = near.breaks;
  far.check_derivative = false;
  far.boxes = 300;
  check_operator_properties(d, far, 42);
  check_operator_properties(polygon_convolution_surface(polys, kR, {.resolution = 40}), far, 43);
}

TEST(PolygonConvolution, OperatorPropertiesTiltedWeightedSum) {
  const std::vector<SkeletalPolygon> polys = {tilted_l(), square(-0.5, -0.5, 0.6, 0.1)};
  const Fn f = polygon_convolution_surface(polys, 0.08, {.resolution = 48});
  PropertySpec spec;
  spec.domain.assign(3, Interval(-0.8, 1.2));
  spec.boxes = 400;
  spec.step = 1e-6;  // pixel lines are oblique here; a tiny step rarely crosses one
  spec.derivative_points = 40;
  spec.derivative_tol = 1e-5;
  check_operator_properties(f, spec, 44);
  // The derivatives' inclusions (the meshers bound gradients and Hessians over cells) are
  // image lookups of cell differences: sound too, first and second order.
  spec.check_derivative = false;
  testing::RandomFunctions rnd(45, 3);
  for (int i = 0; i < 3; ++i) {
    const Fn d = derivative(f, i);
    testing::check_containment(d, spec, rnd);
    for (int j = 0; j < 3; ++j) testing::check_containment(derivative(d, j), spec, rnd);
  }
}

// ---- the image and its pyramid ---------------------------------------------------------------

TEST(PolygonConvolution, PyramidRangeIsTheHullOfTheTouchedSamples) {
  const ConvolutionImage image(tilted_l(), 0.05, {.resolution = 90});
  const int w = image.width(), h = image.height();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(-8, w + 8), len(0, 1);
  for (int trial = 0; trial < 3000; ++trial) {
    double u0 = pos(rng), v0 = pos(rng);
    const double lu = std::pow(len(rng), 3) * w, lv = std::pow(len(rng), 3) * h;
    if (trial % 5 == 0) u0 = std::floor(u0);  // start exactly on a node
    const Interval u(u0, u0 + lu), v(v0, v0 + lv);
    const Interval r = image.range(u, v);
    // Dense samples of the interpolant lie inside.
    for (int a = 0; a <= 12; ++a)
      for (int b = 0; b <= 12; ++b) {
        const double pu = u.lo() + (u.hi() - u.lo()) * a / 12, pv = v.lo() + (v.hi() - v.lo()) * b / 12;
        ASSERT_TRUE(r.contains(image.at(pu, pv))) << image.at(pu, pv) << " outside " << r << " at " << pu << ", " << pv;
      }
    // And the range is the hull of the samples of the touched cells (plus 0 off the image),
    // up to the rounding pad: the pyramid loses nothing to its blocks.
    double lo = INFINITY, hi = -INFINITY;
    const double a0 = std::max(u.lo(), 0.0), a1 = std::min(u.hi(), w - 1.0);
    const double b0 = std::max(v.lo(), 0.0), b1 = std::min(v.hi(), h - 1.0);
    if (a0 <= a1 && b0 <= b1) {
      const int i0 = std::min(static_cast<int>(a0), w - 2), i1 = std::min(static_cast<int>(a1), w - 2) + 1;
      const int j0 = std::min(static_cast<int>(b0), h - 2), j1 = std::min(static_cast<int>(b1), h - 2) + 1;
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) lo = std::min(lo, image.sample(i, j)), hi = std::max(hi, image.sample(i, j));
    }
    if (!(a0 <= a1 && b0 <= b1) || u.lo() < 0 || v.lo() < 0 || u.hi() > w - 1 || v.hi() > h - 1)
      lo = std::min(lo, 0.0), hi = std::max(hi, 0.0);
    EXPECT_LE(r.lo(), lo);
    EXPECT_GE(r.hi(), hi);
    EXPECT_NEAR(r.lo(), lo, 1e-13);
    EXPECT_NEAR(r.hi(), hi, 1e-13);
  }
}

TEST(PolygonConvolution, WideSquareImageIsOneInsideHalfOnAnEdgeZeroFarAway) {
  const ConvolutionImage image(square(0, 0, 4), kR, {.resolution = 200});
  const Fn I = image.lookup();
  const double e = image.extent(), px = 1 / image.world_to_image_scale();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> inner(e + 2 * px, 4 - e - 2 * px), outside(-3, 7);
  for (int k = 0; k < 200; ++k) {
    EXPECT_NEAR(at(I, inner(rng), inner(rng), 0), 1.0, 1e-12);
    const double x = outside(rng), y = outside(rng);
    if (x < -e - 2 * px || x > 4 + e + 2 * px || y < -e - 2 * px || y > 4 + e + 2 * px) {
      EXPECT_EQ(at(I, x, y, 0), 0.0);
    }
  }
  // On a long straight edge the filter sees half the polygon (within the pixel coverage's
  // discretization), so the iso-surface 1/2 passes through the edge.
  for (double y : {1.0, 2.0, 3.1}) EXPECT_NEAR(at(I, 0.0, y, 0), 0.5, 0.01);
  EXPECT_NEAR(at(polygon_convolution_surface({square(0, 0, 4)}, kR, {.resolution = 200}), 4.0, 2.0, 0), 0.0, 0.01);
}

TEST(PolygonConvolution, PerVertexWeightsScaleTheImage) {
  // Equal weights c scale the image by c; on a large triangle with weights (1, 0, 0) the
  // interior image follows the barycentric ramp (mean value coordinates are barycentric on a
  // triangle), 2/3 of the way from the light edge toward the heavy vertex = 2/3.
  const std::vector<Point3> tri = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  const ConvolutionImage plain({tri, {}}, kR, {.resolution = 120});
  const ConvolutionImage half({tri, {0.5, 0.5, 0.5}}, kR, {.resolution = 120});
  for (int j = 0; j < plain.height(); j += 3)
    for (int i = 0; i < plain.width(); i += 3) ASSERT_NEAR(half.sample(i, j), 0.5 * plain.sample(i, j), 1e-14);
  const Fn ramp = ConvolutionImage({tri, {1, 0, 0}}, kR, {.resolution = 240}).lookup();
  // A linear ramp filters to itself (the B-spline is symmetric) away from the edges.
  EXPECT_NEAR(at(ramp, 4.0 / 3, 4.0 / 3, 0), 1.0 / 3, 0.01);
  EXPECT_NEAR(at(ramp, 0.8, 0.8, 0), 0.6, 0.01);
  EXPECT_NEAR(at(ramp, 0.8, 2.0, 0), 0.3, 0.01);
}

TEST(PolygonConvolution, SelfIntersectingPolygonFollowsTheEvenOddRule) {
  // A pentagram: its tips are inside, its central pentagon (wound twice) is outside, as the
  // subsampled coverage of a non-simple polygon decides.
  SkeletalPolygon star;
  for (int k = 0; k < 5; ++k) {
    const double t = 3.14159265358979 / 2 + k * 4 * 3.14159265358979 / 5;
    star.vertices.push_back({4 * std::cos(t), 4 * std::sin(t), 0});
  }
  const Fn I = ConvolutionImage(star, 0.05, {.resolution = 200}).lookup();
  EXPECT_NEAR(at(I, 0, 0, 0), 0.0, 1e-9);          // the centre, 1.2 from the inner edges
  EXPECT_NEAR(at(I, 0, 3.0, 0), 1.0, 1e-9);        // inside the top tip
  EXPECT_NEAR(at(I, 0, 4.5, 0), 0.0, 1e-9);        // beyond it
}

// ---- many polygons: culled superposition ------------------------------------------------

// A 5 x 5 grid of small tilted quads with random weights (slightly non-planar, within the
// tolerance), radius 0.03.
std::vector<SkeletalPolygon> quad_field() {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1, 1), w(0.3, 1.2);
  std::vector<SkeletalPolygon> ps;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      const Point3 c{0.4 * i - 0.8, 0.4 * j - 0.8, 0.2 * u(rng)};
      const Point3 e1{0.12, 0.02 * u(rng), 0.08 * u(rng)}, e2{0.02 * u(rng), 0.12, 0.08 * u(rng)};
      SkeletalPolygon p;
      for (const auto& s : {std::array<double, 2>{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
        p.vertices.push_back({c[0] + s[0] * e1[0] + s[1] * e2[0], c[1] + s[0] * e1[1] + s[1] * e2[1],
                              c[2] + s[0] * e1[2] + s[1] * e2[2] + (s[0] * s[1] > 0 ? 1e-5 : -1e-5)});
      p.weights = {w(rng), w(rng), w(rng), w(rng)};
      ps.push_back(p);
    }
  return ps;
}

TEST(PolygonElement, DensityIsZeroBeyondTheSupportDistance) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> dir(-1, 1), far(1.0, 1.5), near(0.0, 1.0);
  double farthest = 0;
  for (const SkeletalPolygon& poly : quad_field()) {
    const ConvolutionImage image(poly, 0.03, {.resolution = 30});
    Compiled d(image.density());
    const Point3 lo = image.bounds_lo(), hi = image.bounds_hi();
    double reached = 0;  // the farthest nonzero sample, as a fraction of the support distance
    for (int k = 0; k < 400; ++k) {
      // A point at a chosen distance from the bounding box: a box point plus an offset.
      Point3 q, off{dir(rng), dir(rng), dir(rng)};
      const double len = std::hypot(off[0], off[1], off[2]);
      const double frac = k % 2 ? far(rng) : near(rng);
      for (int i = 0; i < 3; ++i) q[i] = lo[i] + (hi[i] - lo[i]) * (0.5 + 0.5 * dir(rng));
      Point3 p;
      for (int i = 0; i < 3; ++i) p[i] = q[i] + off[i] / len * frac * image.support_distance();
      double gap2 = 0;  // the true distance from the box
      for (int i = 0; i < 3; ++i) {
        const double g = std::max({lo[i] - p[i], p[i] - hi[i], 0.0});
        gap2 += g * g;
      }
      const double v = d(p[0], p[1], p[2]);
      if (std::sqrt(gap2) >= image.support_distance()) {
        ASSERT_EQ(v, 0.0) << "at " << std::sqrt(gap2) / image.support_distance();
      }
      if (v > 0) reached = std::max(reached, std::sqrt(gap2) / image.support_distance());
    }
    EXPECT_GT(reached, 0.3);  // the bound is not vacuous
    farthest = std::max(farthest, reached);
  }
  std::printf("farthest nonzero density: %.3f of the support distance\n", farthest);
}

TEST(PolygonElement, CulledFieldOfManyPolygonsIsTheSumAndSound) {
  const std::vector<SkeletalPolygon> polys = quad_field();
  std::vector<FieldElement> es;
  for (const SkeletalPolygon& p : polys) es.push_back(polygon_element(p, 0.03, {.resolution = 30}));
  const Fn culled = culled_field(es);
  Compiled c(culled), sum(polygon_convolution(polys, 0.03, {.resolution = 30}));
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> u(-1.1, 1.1), z(-0.3, 0.3);
  int nonzero = 0;
  for (int k = 0; k < 3000; ++k) {
    const double x0 = u(rng), y0 = u(rng), z0 = z(rng);
    const double a = c(x0, y0, z0), b = sum(x0, y0, z0);
    ASSERT_NEAR(a, b, 1e-12 * std::max(1.0, b));
    nonzero += b > 0;
  }
  EXPECT_GT(nonzero, 100);
  PropertySpec spec;
  spec.domain = {Interval(-1.1, 1.1), Interval(-1.1, 1.1), Interval(-0.3, 0.3)};
  spec.boxes = 300;
  spec.check_derivative = false;  // pixel lines everywhere; checked on single polygons above
  check_operator_properties(density_to_implicit(culled), spec, 47);
  expect_throw_naming([] { polygon_element(square(0, 0, 1), kR, {}, -1.0); }, "polygon_convolution");
}

// ---- the chapter's claims ------------------------------------------------------------------

// The height of the surface f = 1/2 - D above the centre of a square of side w (units of r).
double centre_height(double w, int resolution) {
  const Fn f = polygon_convolution_surface({square(-w * kR / 2, -w * kR / 2, w * kR)}, kR, {.resolution = resolution});
  return root([&](double z) { return at(f, 0, 0, z); }, 0.0, 2.769 * kR) / kR;
}

TEST(PolygonConvolution, ContiguityTheoremWidthFourRadii) {
  // The B-spline's effective support is 4 r: a square that wide integrates to
  // (2 C(2 * 0.72235) - 1)^2 = 0.984 at its centre (C the kernel's CDF), not quite 1, so the
  // point r above the centre is on the surface to within about 1% of r: the continuous
  // convolution puts the surface where h(z) = 1/2 / 0.984.
  const double side = 2 * evaluate(bspline_cdf(Fn(x(0))), std::vector<double>{2 * 2 / kernel_support(Kernel::bspline)})[0] - 1;
  const Fn h = 1.5 * bspline_kernel(Fn(x(0)) * (2 / kernel_support(Kernel::bspline)));
  const double predicted = root([&](double z) { return side * side * evaluate(h, std::vector<double>{z})[0] - 0.5; }, 0.5, 1.5);
  const double h4 = centre_height(4, 160);
  std::printf("surface height above the centre, width 4r: %.5f r (continuous convolution %.5f r)\n", h4, predicted);
  EXPECT_NEAR(h4, predicted, 0.001);  // the image's discretization at 160 pixels
  EXPECT_NEAR(h4, 1.0, 0.015);
  // Wider polygons plateau at r; narrower ones give a thinner surface.
  EXPECT_NEAR(centre_height(8, 160), 1.0, 0.001);
  const double h2 = centre_height(2, 160);
  std::printf("width 2r: %.5f r\n", h2);
  EXPECT_LT(h2, 0.8);
}

TEST(PolygonConvolution, AbuttingCoplanarPolygonsGiveASeamlessPlateau) {
  // Two unit squares sharing an edge versus the 2 x 1 rectangle they tile: the images add to
  // the rectangle's (coverage is additive), so the densities agree near the seam too.
  const std::vector<SkeletalPolygon> two = {square(0, 0, 1), square(1, 0, 1)};
  const std::vector<SkeletalPolygon> one = {{{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}}, {}}};
  const Fn d2 = polygon_convolution(two, kR, {.resolution = 60});
  const Fn d1 = polygon_convolution(one, kR, {.resolution = 120});  // same pixel size
  double worst = 0;
  for (double x = 0.7; x <= 1.3; x += 0.01)
    for (double z : {0.0, 0.5 * kR, kR}) worst = std::max(worst, std::abs(at(d2, x, 0.5, z) - at(d1, x, 0.5, z)));
  std::printf("abutting squares vs one rectangle: largest density difference %.3g\n", worst);
  EXPECT_LT(worst, 0.01);
  // And the plateau is flat across the seam: the surface height stays r.
  const Fn f2 = density_to_implicit(d2);
  for (double x : {0.8, 0.95, 1.0, 1.05, 1.2})
    EXPECT_NEAR(root([&](double z) { return at(f2, x, 0.5, z); }, 0.0, 2.769 * kR), kR, 0.002);
}

TEST(PolygonConvolution, Claim39WideSquareAgainstTheAnalyticConvolution) {
  // research/bloomenthal.md §11 claim 39 with the B-spline kernel: the separable kernel
  // factorizes the convolution of a rectangle, D = h(z) [C(s (x1 - x) / r) - C(s (x0 - x) / r)]
  // [same in y], C the kernel's CDF and s = 0.72235. For a square of side 6 r: D = 1/2 at the
  // edge midpoints in the plane, the surface at height r above the centre, and the image at
  // 80 x 80 within 1% of the maximum of the analytic density everywhere.
  const double a = 3 * kR, sc = 2 / kernel_support(Kernel::bspline);
  const Fn X = x(0), Y = x(1), Z = x(2);
  const Fn exact = 1.5 * bspline_kernel(Z * (sc / kR)) * (bspline_cdf((a - X) * (sc / kR)) - bspline_cdf((-a - X) * (sc / kR))) *
                   (bspline_cdf((a - Y) * (sc / kR)) - bspline_cdf((-a - Y) * (sc / kR)));
  const std::vector<SkeletalPolygon> sq = {square(-a, -a, 2 * a)};
  const Fn d = polygon_convolution(sq, kR, {.resolution = 80});
  Compiled dc(d), ec(exact);
  double worst = 0, peak = 0;
  for (double px = -0.65; px <= 0.65; px += 0.0125)
    for (double py = -0.65; py <= 0.65; py += 0.0125)
      for (double pz : {0.0, 0.05, 0.1, 0.2}) {
        worst = std::max(worst, std::abs(dc(px, py, pz) - ec(px, py, pz)));
        peak = std::max(peak, ec(px, py, pz));
      }
  double edge = 0;
  for (const auto& m : {std::array<double, 2>{a, 0}, {-a, 0}, {0, a}, {0, -a}}) edge = std::max(edge, std::abs(at(d, m[0], m[1], 0) - 0.5));
  const Fn f = density_to_implicit(d);
  const double height = root([&](double z) { return at(f, 0, 0, z); }, 0.0, 2.769 * kR) / kR;
  std::printf("claim 39 at 80 x 80: largest |D - exact| %.5f (peak %.3f), edge midpoints |D - 1/2| %.5f, height %.5f r\n",
              worst, peak, edge, height);
  EXPECT_LT(worst, 0.01 * peak);
  EXPECT_LT(edge, 1e-3);
  EXPECT_NEAR(height, 1.0, 0.01);
}

// Surface positions that the resolution affects: the height above interior points and the
// in-plane distance of the surface beyond each edge and vertex of a triangle (scale changes
// and shifted vertices show there).
std::vector<double> triangle_surface(int resolution) {
  const SkeletalPolygon tri{{{0, 0, 0}, {1, 0.1, 0}, {0.3, 0.8, 0}}, {}};
  const Fn f = polygon_convolution_surface({tri}, kR, {.resolution = resolution});
  const double cx = 1.3 / 3, cy = 0.9 / 3;
  std::vector<double> out;
  for (const auto& p : {std::array<double, 2>{cx, cy}, {0.5, 0.2}, {0.35, 0.5}})
    out.push_back(root([&](double z) { return at(f, p[0], p[1], z); }, 0.0, 0.28));
  // Rays from the centroid through the vertices and the edge midpoints.
  for (const auto& t : {std::array<double, 2>{0, 0}, {1, 0.1}, {0.3, 0.8}, {0.5, 0.05}, {0.65, 0.45}, {0.15, 0.4}}) {
    const double dx = t[0] - cx, dy = t[1] - cy, len = std::hypot(dx, dy);
    out.push_back(root([&](double s) { return at(f, cx + dx / len * s, cy + dy / len * s, 0); }, 0.0, len + 0.2));
  }
  return out;
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

TEST(PolygonConvolution, ResolutionEightyIsEnoughAndLowResolutionsShiftTheSurface) {
  const std::vector<double> reference = triangle_surface(320);
  double error[5];
  const int res[5] = {80, 40, 20, 10, 5};
  for (int k = 0; k < 5; ++k) {
    error[k] = largest_difference(triangle_surface(res[k]), reference);
    std::printf("resolution %3d: largest surface shift %.5f (%.3f r)\n", res[k], error[k], error[k] / kR);
  }
  // Measured (largest shift from 320 x 320, units of r): 80: 0.013, 40: 0.058, 20: 0.23,
  // 10: 0.74, 5: 2.4. So 80 x 80 is within 3% of r of the limit and 40 x 40 within 8% (the
  // two agree within 8%); below 40 the shift is a fifth of r and more, and it grows as the
  // resolution drops.
  EXPECT_LT(largest_difference(triangle_surface(80), triangle_surface(40)), 0.08 * kR);
  EXPECT_LT(error[0], 0.03 * kR);
  EXPECT_LT(error[1], 0.08 * kR);
  EXPECT_GT(error[2], 0.15 * kR);
  for (int k = 0; k + 1 < 5; ++k) EXPECT_LT(error[k], error[k + 1]);
}

}  // namespace
}  // namespace genmod
