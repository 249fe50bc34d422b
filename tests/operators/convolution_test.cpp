// Convolution surfaces, kernels, the erf enclosure and culled superposition
// (operators/convolution.hpp, culled_field.hpp): MPFR as the erf oracle, the shared
// property harness on every operator, culling soundness, and the claims of
// research/bloomenthal.md §11.
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/operators/convolution.hpp"
#include "genmod/operators/culled_field.hpp"
#include "kernel/mpfr_value.hpp"
#include "operators/operator_properties.hpp"

#include <gtest/gtest.h>
#include <mpfr.h>

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <random>

namespace genmod {
namespace {

using testing::check_operator_properties;
using testing::PropertySpec;

constexpr double kOmega = kGaussOmega;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

double at(const Fn& f, double x, double y, double z) { return evaluate(f, std::vector<double>{x, y, z})[0]; }
double at1(const Fn& f, double x) { return evaluate(f, std::vector<double>{x})[0]; }
double phi(double x) { return 0.5 * (1 + std::erf(std::sqrt(kOmega) * x)); }

PropertySpec around_skeleton() {
  PropertySpec spec;
  spec.domain.assign(3, Interval(-2.0, 2.0));
  spec.boxes = 300;
  return spec;
}

// Adaptive Simpson quadrature (the independent computation for claims 4, 19, 22).
double simpson(const std::function<double(double)>& f, double a, double b, double tol, int depth = 40) {
  const double m = (a + b) / 2, fa = f(a), fb = f(b), fm = f(m);
  std::function<double(double, double, double, double, double, double, int)> rec =
      [&](double a0, double b0, double fa0, double fm0, double fb0, double whole, int d) -> double {
    const double m0 = (a0 + b0) / 2, lm = (a0 + m0) / 2, rm = (m0 + b0) / 2, flm = f(lm), frm = f(rm);
    const double left = (m0 - a0) / 6 * (fa0 + 4 * flm + fm0), right = (b0 - m0) / 6 * (fm0 + 4 * frm + fb0);
    if (d <= 0 || std::abs(left + right - whole) < 15 * tol) return left + right + (left + right - whole) / 15;
    return rec(a0, m0, fa0, flm, fm0, left, d - 1) + rec(m0, b0, fm0, frm, fb0, right, d - 1);
  };
  return rec(a, b, fa, fm, fb, (b - a) / 6 * (fa + 4 * fm + fb), depth);
}

// ---- erf: MPFR oracle --------------------------------------------------------------------

Interval mpfr_erf_range(const Interval& x) {
  testing::Mpfr v, r;
  mpfr_set_d(v.get(), x.lo(), MPFR_RNDN);
  mpfr_erf(r.get(), v.get(), MPFR_RNDD);
  const double lo = mpfr_get_d(r.get(), MPFR_RNDD);
  mpfr_set_d(v.get(), x.hi(), MPFR_RNDN);
  mpfr_erf(r.get(), v.get(), MPFR_RNDU);
  return Interval(lo, mpfr_get_d(r.get(), MPFR_RNDU));
}

TEST(ErfEnclosure, ContainsMpfrInAllRoundingModes) {
  std::mt19937_64 rng(11);
  std::vector<double> points = {0.0, -0.0, 1e-300, -1e-300, 4.9e-324, 1e-8, 0.5, 1, 2, 3, 5.9, 6, 27, 1e10, 1e300,
                                std::numeric_limits<double>::infinity()};
  for (int i = 0; i < 4000; ++i) points.push_back(std::ldexp(std::uniform_real_distribution<double>(1, 2)(rng), std::uniform_int_distribution<int>(-40, 3)(rng)));
  const int modes[4] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
  double worst = 0;
  int checked = 0;
  for (int mode : modes) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      for (double sgn : {1.0, -1.0}) {
        const double a = sgn * points[i];
        const double b = (i % 3 == 0) ? a : sgn * points[(i * 7 + 1) % points.size()];
        const double lo = std::min(a, b), hi = std::max(a, b);
        if (lo == kInfinity || hi == -kInfinity) continue;  // [inf, inf] is not an interval
        const Interval x(lo, hi);
        const Interval want = mpfr_erf_range(x);
        std::fesetround(mode);
        const Interval got = erf_enclosure(x);
        std::fesetround(FE_TONEAREST);
        ASSERT_TRUE(got.contains(want)) << "erf" << x << " = " << got << " misses " << want << " (mode " << mode << ")";
        ++checked;
        if (x.lo() == x.hi() && std::abs(want.lo()) > 1e-300) worst = std::max(worst, (got.hi() - got.lo()) / std::abs(want.lo()));
      }
    }
  }
  EXPECT_GT(checked, 30000);
  EXPECT_LT(worst, 1e-14);  // a few ulps, not a loose bound
  std::printf("erf enclosure: %d intervals, widest point enclosure %.3g relative\n", checked, worst);
}

TEST(ErfEnclosure, OperatorProperties) {
  PropertySpec spec;
  spec.domain = {Interval(-4.0, 4.0)};
  check_operator_properties(erf(x(0)), spec, 3);
  check_operator_properties(gauss_cdf(x(0)), spec, 4);
  EXPECT_EQ(erf_enclosure(Interval(0.0)).lo(), 0.0);
  EXPECT_EQ(erf_enclosure(Interval(0.0)).hi(), 0.0);
  EXPECT_TRUE(erf_enclosure(Interval::empty()).is_empty());
}

// ---- claims ------------------------------------------------------------------------------

TEST(BloomenthalClaims, Claim01GaussianConstants) {
  EXPECT_NEAR(at1(gauss(x(0)), 0), 1, 1e-12);
  EXPECT_NEAR(at1(gauss(x(0)), 1), 0.5, 1e-12);
  EXPECT_NEAR(at1(gauss(x(0)), 2), 0.0625, 1e-12);
  EXPECT_NEAR(at1(gauss(x(0)), 3), 0.001953125, 1e-12);
  EXPECT_LT(std::abs(std::exp(-0.69314715) - 0.5), 2e-8);  // the source's literal omega
}

TEST(BloomenthalClaims, Claim03GaussIntegral) {
  const Fn gi = gauss_integral(x(0), x(1));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-5, 5);
  for (int i = 0; i < 200; ++i) {
    const double a = u(rng), b = u(rng);
    const double ab = evaluate(gi, std::vector<double>{a, b})[0], ba = evaluate(gi, std::vector<double>{b, a})[0];
    EXPECT_EQ(ab, ba);
    EXPECT_GE(ab, 0);
    EXPECT_NEAR(evaluate(gi, std::vector<double>{-std::abs(a), std::abs(a)})[0], 2 * phi(std::abs(a)) - 1, 1e-15);
  }
  EXPECT_NEAR(evaluate(gi, std::vector<double>{0, 1})[0], 0.380484054, 1e-7);
}

// The closed form against (1/(r sqrt(pi/omega))) int_0^L exp(-omega |p - s(t)|^2 / r^2) dt.
TEST(BloomenthalClaims, Claim04SegmentClosedFormIsTheConvolution) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 40; ++trial) {
    const Point3 a = {u(rng), u(rng), u(rng)}, b = {u(rng), u(rng), u(rng)};
    const double r = 0.15 + 0.3 * std::abs(u(rng));
    const Fn d = segment_convolution(a, b, r);
    const double len = std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) + (b[2] - a[2]) * (b[2] - a[2]));
    for (int k = 0; k < 5; ++k) {
      const double p[3] = {u(rng), u(rng), u(rng)};
      auto integrand = [&](double t) {
        double s = 0;
        for (int i = 0; i < 3; ++i) {
          const double q = p[i] - a[i] - t / len * (b[i] - a[i]);
          s += q * q;
        }
        return std::exp(-kOmega * s / (r * r));
      };
      const double quad = simpson(integrand, 0, len, 1e-14) / (r * std::sqrt(std::numbers::pi / kOmega));
      EXPECT_NEAR(at(d, p[0], p[1], p[2]), quad, 1e-8);
    }
  }
}

// Claim 2: the appendix's Gauss table (10000 entries over [0, 10), trapezoid, linear
// interpolation) against the exact CDF this library uses.
TEST(BloomenthalClaims, Claim02TableCdfAgreesWithErf) {
  const int size = 10000;
  const double range = 10, scale = size / range;
  std::vector<double> table(size);
  const double step = 0.5 / (std::sqrt(std::numbers::pi / 0.69314715) * scale);
  double v1 = 1;
  table[0] = 0.5;
  for (int i = 1; i < size; ++i) {
    const double v2 = std::exp(-(i / scale) * (i / scale) * 0.69314715);
    table[i] = table[i - 1] + step * (v1 + v2);
    v1 = v2;
  }
  EXPECT_EQ(table[0], 0.5);
  EXPECT_NEAR(table[size - 1], 1, 1e-9);
  auto area_pos = [&](double x) {
    const double sx = x * scale;
    const int k = std::min(size - 1, static_cast<int>(std::floor(sx)));
    double a = table[k];
    if (k < size - 1) a += (sx - k) * (table[k + 1] - a);
    return a;
  };
  auto area = [&](double x) { return x < 0 ? 1 - area_pos(-x) : area_pos(x); };
  const Fn cdf = gauss_cdf(x(0));
  double worst = 0;
  for (double xv = -12; xv <= 12; xv += 0.001) worst = std::max(worst, std::abs(area(xv) - at1(cdf, xv)));
  EXPECT_LT(worst, 1e-7);
  std::printf("Gauss table vs erf: max difference %.3g\n", worst);
}

// Claim 5: the appendix's Subtend (distances from the projection to the ends, signs reversed
// when the projection is outside) equals Phi((L - u)/r) - Phi(-u/r), the integration filter
// of segment_convolution.
TEST(BloomenthalClaims, Claim05SubtendSignLogic) {
  const Point3 a = {0.1, -0.2, 0.3}, b = {0.9, 0.4, -0.1};
  const double r = 0.25, len = std::sqrt(0.8 * 0.8 + 0.6 * 0.6 + 0.4 * 0.4);
  const Fn d = segment_convolution(a, b, r), line2 = distance2_to_line(a, b);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.5, 2.5);
  int before = 0, inside = 0, beyond = 0;
  for (int i = 0; i < 600; ++i) {
    const double p[3] = {u(rng), u(rng), u(rng)};
    double alpha = 0;
    for (int k = 0; k < 3; ++k) alpha += (p[k] - a[k]) * (b[k] - a[k]) / (len * len);
    const double proj[3] = {a[0] + alpha * (b[0] - a[0]), a[1] + alpha * (b[1] - a[1]), a[2] + alpha * (b[2] - a[2])};
    auto dist = [&](const Point3& e) {
      return std::sqrt((proj[0] - e[0]) * (proj[0] - e[0]) + (proj[1] - e[1]) * (proj[1] - e[1]) + (proj[2] - e[2]) * (proj[2] - e[2]));
    };
    double e1d = -dist(a), e2d = dist(b);
    if (alpha < 0) e1d = -e1d, ++before;
    else if (alpha > 1) e2d = -e2d, ++beyond;
    else ++inside;
    const double subtend = std::abs(phi(e2d / r) - phi(e1d / r));
    const double expected = subtend * std::exp(-kOmega * at(line2, p[0], p[1], p[2]) / (r * r));
    EXPECT_NEAR(at(d, p[0], p[1], p[2]), expected, 1e-12);
  }
  EXPECT_GT(before, 50);
  EXPECT_GT(inside, 50);
  EXPECT_GT(beyond, 50);
}

TEST(BloomenthalClaims, Claim06Superposition) {
  const Point3 a = {-0.4, 0.1, 0.2}, b = {0.8, -0.5, 0.3};
  const Fn whole = segment_convolution(a, b, 0.2);
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> u(-1, 1), t01(0.05, 0.95);
  for (int i = 0; i < 200; ++i) {
    const double t = t01(rng);
    const Point3 m = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
    const Fn parts = segment_convolution(a, m, 0.2) + segment_convolution(m, b, 0.2);
    const double px = u(rng), py = u(rng), pz = u(rng);
    EXPECT_NEAR(at(whole, px, py, pz), at(parts, px, py, pz), 1e-12);
  }
}

// Claims 7, 8, 10: a long segment's surface is at distance r from the axis, passes through
// the endpoints, and far from the ends D = 2^(-(d/r)^2).
TEST(BloomenthalClaims, Claim07Claim08Claim10IsolatedLimb) {
  const double r = 0.1, len = 12 * r;
  const Fn d = segment_convolution({0, 0, 0}, {len, 0, 0}, r);
  EXPECT_NEAR(at(d, len / 2, r, 0), 0.5, 1e-9);
  EXPECT_NEAR(at(d, len / 2, 0, -r), 0.5, 1e-9);
  EXPECT_NEAR(at(d, 0, 0, 0), 0.5, 1e-9);
  EXPECT_NEAR(at(d, len, 0, 0), 0.5, 1e-9);
  const Fn longer = segment_convolution({-1e3, 0, 0}, {1e3, 0, 0}, r);
  for (double dist : {0.0, 0.05, 0.1, 0.17, 0.3})
    EXPECT_NEAR(at(longer, 0.3, dist * 0.6, dist * 0.8), std::pow(2.0, -(dist / r) * (dist / r)), 1e-12);
}

TEST(BloomenthalClaims, Claim09TaperedEndCap) {
  const double r = 0.1, len = 10 * r;
  const Fn d = segment_convolution({0, 0, 0}, {len, 0, 0}, r);
  // root of D = 1/2 at axial offset r inside the end e2 (x = len - r), by bisection in y
  double lo = 0.5 * r, hi = 1.5 * r;
  for (int i = 0; i < 80; ++i) {
    const double m = (lo + hi) / 2;
    (at(d, len - r, m, 0) > 0.5 ? lo : hi) = m;
  }
  EXPECT_NEAR(lo / r, 0.90353, 1e-4);
  EXPECT_NEAR(at(d, len - r, r, 0), 0.440242, 1e-6);
  EXPECT_NEAR(at(d, len, r, 0), 0.25, 1e-9);
}

TEST(BloomenthalClaims, Claim11TeeBulge) {
  const double r = 0.1;
  const Fn bar = segment_convolution({0, -100, 0}, {0, 100, 0}, r);
  EXPECT_NEAR(at(bar + segment_convolution({0, 0, 0}, {100, 0, 0}, r), 0, 0, r), 0.75, 1e-6);
  EXPECT_NEAR(at(bar + segment_convolution({r, 0, 0}, {100, 0, 0}, r), r, 0, r), 0.5, 1e-6);
}

TEST(BloomenthalClaims, Claim18Ease) {
  const Fn e = ease(x(0)), de = derivative(e, 0);
  EXPECT_EQ(at1(e, 0), 0);
  EXPECT_EQ(at1(e, 1), 1);
  EXPECT_NEAR(at1(de, 1e-12), 0, 1e-10);
  EXPECT_NEAR(at1(de, 1 - 1e-12), 0, 1e-10);
  EXPECT_NEAR(at1(e, 0.5), 0.5, 1e-15);
  EXPECT_NEAR(at1(e, 0.25), 0.1455078125, 1e-15);
  EXPECT_NEAR(at1(e, 0.75), 0.8564453125, 1e-15);
  EXPECT_EQ(at1(e, -3), 0);
  EXPECT_EQ(at1(e, 4), 1);
  double prev = 0;
  for (int i = 0; i <= 1000; ++i) {
    const double v = at1(e, i / 1000.0);
    EXPECT_GE(v, prev - 1e-15);
    prev = v;
  }
}

TEST(BloomenthalClaims, Claim19WyvillKernel) {
  const Fn h = wyvill_kernel_of_square(square(x(0))), dh = derivative(h, 0);
  EXPECT_EQ(at1(h, 0), 1);
  EXPECT_NEAR(at1(h, 0.5), 0.5, 1e-15);
  EXPECT_NEAR(at1(h, 1), 0, 1e-15);
  EXPECT_NEAR(at1(dh, 1 - 1e-9), 0, 1e-7);
  const double integral = 2 * simpson([&](double t) { return at1(h, t); }, 0, 1, 1e-14);
  EXPECT_NEAR(integral, 0.998941799, 1e-9);
  // the closed-form area (spec 2.3.2) against quadrature
  auto area = [](double t) { return 0.5 + t + (-(4.0 / 7) * std::pow(t, 7) + (17.0 / 5) * std::pow(t, 5) - (22.0 / 3) * std::pow(t, 3)) / 9; };
  for (double t : {0.1, 0.3, 0.5, 0.8, 1.0})
    EXPECT_NEAR(area(t) - 0.5, simpson([&](double s) { return at1(h, s); }, 0, t, 1e-14), 1e-9);
}

TEST(BloomenthalClaims, Claim20BsplineKernel) {
  const Fn h = bspline_kernel(x(0));
  EXPECT_NEAR(at1(h, 0), 2.0 / 3, 1e-15);
  EXPECT_NEAR(at1(h, 0.72235), 1.0 / 3, 2e-6);
  EXPECT_NEAR(simpson([&](double t) { return at1(h, t); }, -2, 0, 1e-15) +
                  simpson([&](double t) { return at1(h, t); }, 0, 1, 1e-15) + simpson([&](double t) { return at1(h, t); }, 1, 2, 1e-15),
              1.0, 1e-12);
  auto area_neg = [](double t) {
    if (t < -2) return 0.0;
    if (t < -1) return std::pow(t + 2, 4);
    return -3 * std::pow(t, 4) - 8 * std::pow(t, 3) + 16 * t + 12;
  };
  auto area = [&](double t) { return t < 0 ? area_neg(t) : 24 - area_neg(-t); };
  EXPECT_NEAR(area(0) / 24, 0.5, 1e-15);
  EXPECT_NEAR(area(1) / 24, 0.9583333333333333, 1e-15);
  for (double k : {-2.0, -1.0, 0.0, 1.0, 2.0}) EXPECT_NEAR(area(k - 1e-12), area(k + 1e-12), 1e-9);
  // quadrature from -2 to t, split at the knots
  auto quad = [&](double t) {
    double sum = 0;
    for (double k = -2; k < t; k += 1) sum += simpson([&](double x) { return at1(h, x); }, k, std::min(k + 1, t), 1e-16);
    return sum;
  };
  for (double t : {-1.7, -1.0, -0.3, 0.4, 1.2, 1.9}) EXPECT_NEAR(area(t) / 24, quad(t), 1e-12) << t;
}

// Claims 19, 20 (the library's closed-form CDFs): against quadrature of the kernels.
TEST(BloomenthalClaims, Claim19Claim20KernelCdfsMatchQuadrature) {
  const Fn hb = bspline_kernel(x(0)), cb = bspline_cdf(x(0));
  const Fn hw = wyvill_kernel_of_square(square(x(0))), cw = wyvill_cdf(x(0));
  EXPECT_NEAR(at1(cb, 0), 0.5, 1e-15);
  EXPECT_NEAR(at1(cb, 1), 0.9583333333333333, 1e-15);
  EXPECT_EQ(at1(cb, -2.5), 0);
  EXPECT_EQ(at1(cb, 2.5), 1);
  for (double k : {-2.0, -1.0, 0.0, 1.0, 2.0}) EXPECT_NEAR(at1(cb, k - 1e-12), at1(cb, k + 1e-12), 1e-11);
  for (double t : {-1.7, -1.0, -0.3, 0.4, 1.2, 1.9}) {
    double q = 0;
    for (double k = -2; k < t; k += 1) q += simpson([&](double v) { return at1(hb, v); }, k, std::min(k + 1, t), 1e-16);
    EXPECT_NEAR(at1(cb, t), q, 1e-12) << t;
  }
  EXPECT_NEAR(kWyvillIntegral, 0.998941799, 1e-9);
  EXPECT_NEAR(at1(cw, -1), 0, 1e-15);
  EXPECT_NEAR(at1(cw, 1), 1, 1e-15);
  EXPECT_NEAR(at1(cw, 0), 0.5, 1e-15);
  for (double t : {-0.9, -0.5, 0.1, 0.6, 0.95})
    EXPECT_NEAR(at1(cw, t), simpson([&](double v) { return at1(hw, v); }, -1, t, 1e-15) / kWyvillIntegral, 1e-9) << t;
}

// The B-spline and Wyvill segment convolutions: iso 1/2 at distance r along a long segment and
// at the free endpoints; zero beyond sqrt(2) support.
TEST(ConvolutionProperties, KernelSegmentConvolutions) {
  for (Kernel k : {Kernel::bspline, Kernel::wyvill}) {
    const double r = 0.1, len = 12 * r;
    const Fn d = segment_convolution({0, 0, 0}, {len, 0, 0}, r, r, k);
    EXPECT_NEAR(at(d, len / 2, r, 0), 0.5, 2e-6);
    EXPECT_NEAR(at(d, 0, 0, 0), 0.5, 1e-12);
    EXPECT_NEAR(at(d, len, 0, 0), 0.5, 1e-12);
    const double support = kernel_support(k) * r;
    EXPECT_EQ(at(d, len / 2, support * 1.001, 0), 0);
    EXPECT_EQ(at(d, len + support * 1.001, 0, 0), 0);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> ang(0, 2 * std::numbers::pi), t(-1, 2);
    for (int i = 0; i < 200; ++i) {  // beyond sqrt(2) support of the segment: exactly 0
      const double a = ang(rng), s = t(rng) * len;
      const double axial = std::clamp(s, 0.0, len);
      const double need = std::sqrt(2.0) * support * 1.001;
      const double radial = std::sqrt(std::max(0.0, need * need - (s - axial) * (s - axial)));
      EXPECT_EQ(at(d, s, radial * std::cos(a), radial * std::sin(a)), 0);
    }
    check_operator_properties(segment_convolution({-0.5, 0.2, 0.1}, {0.7, -0.4, 0.3}, 0.4, 0.25, k), around_skeleton(), 30 + static_cast<int>(k));
  }
}

TEST(BloomenthalClaims, Claim21KernelNormalization) {
  for (Kernel k : {Kernel::gaussian, Kernel::bspline, Kernel::wyvill}) {
    const Fn h = normalized_kernel(k, square(x(0)));
    EXPECT_NEAR(at1(h, 0), 1, 1e-15);
    EXPECT_NEAR(at1(h, 1), 0.5, 2e-6);
    if (k != Kernel::gaussian) {
      EXPECT_EQ(at1(h, kernel_support(k) * 1.0001), 0.0);
    }
  }
}

// Claim 22: N weighted point sources (weight = the subtended normalized area of each piece)
// converge to the segment convolution.
TEST(BloomenthalClaims, Claim22PointSourceConvergence) {
  const double r = 0.2, len = 5 * r;
  const Fn seg = segment_convolution({0, 0, 0}, {len, 0, 0}, r);
  double previous = 1e9;
  for (int n : {3, 7, 15, 31}) {
    Fn sum;
    for (int i = 0; i < n; ++i) {
      const double t0 = len * i / n, t1 = len * (i + 1) / n, c = (t0 + t1) / 2;
      // the piece's share of the segment's signal, normalized by the kernel integral r sqrt(pi/omega)
      // (the filter area a unit-density piece subtends; Phi(d/2r) - Phi(-d/2r) instead gives
      // 1.45e-3 at N = 31, the far-field midpoint error)
      const double w = (t1 - t0) / (r * std::sqrt(std::numbers::pi / kOmega));
      const Fn s = point_source({c, 0, 0}, r, w);
      sum = i == 0 ? s : sum + s;
    }
    double worst = 0;
    for (double gx = -0.4; gx <= len + 0.4; gx += 0.05)
      for (double gy = 0; gy <= 0.5; gy += 0.05) worst = std::max(worst, std::abs(at(sum, gx, gy, 0) - at(seg, gx, gy, 0)));
    EXPECT_LT(worst, previous) << n;
    previous = worst;
    if (n == 31) {
      EXPECT_LT(worst, 1e-3);
    }
  }
}

// ---- operator properties -----------------------------------------------------------------

TEST(ConvolutionProperties, SegmentConvolution) {
  check_operator_properties(segment_convolution({-0.5, 0.2, 0.1}, {0.7, -0.4, 0.3}, 0.3), around_skeleton(), 21);
  check_operator_properties(segment_convolution({-0.5, 0.2, 0.1}, {0.7, -0.4, 0.3}, 0.4, 0.15), around_skeleton(), 22);
  check_operator_properties(density_to_implicit(segment_convolution({0, 0, 0}, {1, 0, 0}, 0.2)), around_skeleton(), 23);
}

TEST(ConvolutionProperties, PointSources) {
  PropertySpec spec = around_skeleton();
  spec.derivative_tol = 1e-5;
  check_operator_properties(point_source({0.1, 0.2, -0.3}, 0.5, 2.0, Kernel::gaussian), spec, 24);
  check_operator_properties(point_source({0.1, 0.2, -0.3}, 0.5, 1.0, Kernel::wyvill), spec, 25);
  check_operator_properties(point_source({0.1, 0.2, -0.3}, 0.5, 1.0, Kernel::bspline), spec, 26);
  check_operator_properties(ease(x(0)) * bspline_kernel(x(1)) + wyvill_kernel_of_square(x(2)), spec, 27);
}

// ---- culling -------------------------------------------------------------------------------

std::vector<FieldElement> random_tree(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Point3> nodes = {{0, 0, 0}};
  std::vector<FieldElement> es;
  for (int i = 0; i < n; ++i) {
    const Point3 a = nodes[std::uniform_int_distribution<std::size_t>(0, nodes.size() - 1)(rng)];
    const Point3 b = {std::clamp(a[0] + 0.3 * u(rng), -2.0, 2.0), std::clamp(a[1] + 0.3 * u(rng), -2.0, 2.0), std::clamp(a[2] + 0.3 * u(rng), -2.0, 2.0)};
    nodes.push_back(b);
    const double r = 0.03 + 0.03 * std::abs(u(rng));
    if (i % 4 == 3) es.push_back({point_source(b, r, 1.0, Kernel::wyvill), b, b, 1.0, 2 * r, Falloff::compact});
    else es.push_back({segment_convolution(a, b, r), a, b, 1.0, r, Falloff::gaussian});
  }
  return es;
}

TEST(CulledField, BoundContainsTheFullFieldOnRandomBoxes) {
  const std::vector<FieldElement> es = random_tree(200, 40);
  const Fn culled = culled_field(es);
  Fn full;
  for (std::size_t i = 0; i < es.size(); ++i) full = i == 0 ? es[i].density : full + es[i].density;
  const int xyz[3] = {0, 1, 2};
  const Tape tc(culled, xyz), tf(full, xyz);
  IntervalEvaluator iv;
  PointEvaluator pv;
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> u(-2.5, 2.5), w(0, 1);
  int narrower = 0;
  for (int b = 0; b < 400; ++b) {
    std::vector<Interval> box(3);
    const double size = std::pow(w(rng), 3) * 1.5;
    for (int i = 0; i < 3; ++i) {
      const double lo = u(rng);
      box[i] = Interval(lo, lo + size);
    }
    const Interval bound = iv.eval(tc, box)[0];
    const Interval unculled = iv.eval(tf, box)[0];
    narrower += bound.hi() - bound.lo() <= (unculled.hi() - unculled.lo()) * (1 + 1e-9) + 200 * 1e-6;
    for (int s = 0; s < 20; ++s) {
      const double p[3] = {box[0].lo() + w(rng) * size, box[1].lo() + w(rng) * size, box[2].lo() + w(rng) * size};
      const double v = pv.eval(tf, p)[0];
      ASSERT_TRUE(bound.contains(v)) << "full field " << v << " outside the culled bound " << bound;
      // The point value is the full sum within 2^-60 max(sum, cull_below) (culled_field.hpp),
      // plus rounding.
      ASSERT_NEAR(pv.eval(tc, p)[0], v, 0x1p-60 * std::max(v, 1e-6) + 0x1p-50 * v);
    }
  }
  EXPECT_GT(narrower, 390);  // culling loses at most the remainder
}

// Claim 40 (the remainder part): culled Gaussian elements change D inside a box by at most
// the sum of their bounds, N Gauss(delta/r).
TEST(BloomenthalClaims, Claim40CullingRemainderIsSound) {
  const std::vector<FieldElement> es = random_tree(120, 50);
  std::mt19937 rng(51);
  std::uniform_real_distribution<double> u(-2, 2), w(0, 1);
  for (int b = 0; b < 200; ++b) {
    const double lo[3] = {u(rng), u(rng), u(rng)}, size = 0.4 * w(rng);
    const std::vector<Interval> box = {Interval(lo[0], lo[0] + size), Interval(lo[1], lo[1] + size), Interval(lo[2], lo[2] + size)};
    for (const FieldElement& e : es) {
      const double bound = culled_element_bound(e, box);
      if (!(bound < 1e-3)) continue;
      for (int s = 0; s < 10; ++s) {
        const double v = at(e.density, lo[0] + w(rng) * size, lo[1] + w(rng) * size, lo[2] + w(rng) * size);
        ASSERT_LE(v, bound);
        ASSERT_GE(v, 0);
      }
    }
  }
}

// A field of compact (Wyvill) segment convolutions: point values skip the far elements and
// equal the plain sum bit for bit; the derivatives are culled fields too and agree with the
// plain sum's derivatives.
TEST(CulledField, CompactFieldsCullValuesAndDerivatives) {
  std::mt19937 rng(70);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::vector<FieldElement> es;
  Fn plain;
  for (int i = 0; i < 60; ++i) {
    const Point3 a = {u(rng), u(rng), u(rng)}, b = {a[0] + 0.2 * u(rng), a[1] + 0.2 * u(rng), a[2] + 0.2 * u(rng)};
    const double r = 0.1;
    const Fn d = segment_convolution(a, b, r, r, Kernel::wyvill);
    es.push_back({d, a, b, 1.0, std::sqrt(2.0) * kernel_support(Kernel::wyvill) * r, Falloff::compact});
    plain = i == 0 ? d : plain + d;
  }
  const Fn culled = culled_field(es);
  PropertySpec spec = around_skeleton();
  spec.boxes = 150;
  spec.derivative_tol = 1e-5;
  check_operator_properties(culled, spec, 71);
  for (int i = 0; i < 40; ++i) {
    const double p[3] = {u(rng), u(rng), u(rng)};
    EXPECT_EQ(at(culled, p[0], p[1], p[2]), at(plain, p[0], p[1], p[2]));
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(at(derivative(culled, k), p[0], p[1], p[2]), at(derivative(plain, k), p[0], p[1], p[2]), 1e-12);
  }
}

TEST(CulledField, OperatorProperties) {
  const std::vector<FieldElement> es = random_tree(30, 60);
  PropertySpec spec = around_skeleton();
  spec.boxes = 150;
  spec.derivative_tol = 1e-5;
  check_operator_properties(culled_field(es), spec, 61);
  testing::expect_throw_naming([] { culled_field({}); }, "culled_field");
}

}  // namespace
}  // namespace genmod
