// Implicit curve approximation (Algorithm 5.3): snyder.md section 11 claims 33 (circle, Fig 5.7),
// 34 (torus silhouette), 35 (Interval Implicit Function Theorem), a 4-D surface/surface
// intersection, coverage of the true curve by the returned boxes, and bad input.
#include "genmod/solvers/implicit_curve.hpp"

#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <stdexcept>

namespace genmod {
namespace {

constexpr double kPi = std::numbers::pi;
const int kXY[] = {0, 1};
const Fn X = x(0), Y = x(1);

// Distance (max norm) from a point to a box; 0 inside.
double distance(const Box& b, std::span<const double> p) {
  double d = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (p[i] < b[i].lo()) d = std::max(d, b[i].lo() - p[i]);
    if (p[i] > b[i].hi()) d = std::max(d, p[i] - b[i].hi());
  }
  return d;
}

bool covered(const ImplicitCurve& c, std::span<const double> p, double tol) {
  for (const CurveBox& b : c.boxes)
    if (distance(b.box, p) <= tol) return true;
  return false;
}

// max over all output points of max_j |F_j(p)|.
double max_residual(const Fn& F, std::span<const int> coords, const ImplicitCurve& c) {
  Tape t(F, coords);
  PointEvaluator ev;
  double worst = 0;
  for (const Polyline& pl : c.components)
    for (const auto& p : pl.points)
      for (double v : ev.eval(t, p)) worst = std::max(worst, std::abs(v));
  return worst;
}

// Every output point lies in X.
void expect_inside(const ImplicitCurve& c, const Box& Xb) {
  for (const Polyline& pl : c.components)
    for (const auto& p : pl.points) EXPECT_EQ(distance(Xb, p), 0.0);
}

// Roots of the scalar g on [a, b] by dense sign-change scanning and bisection.
std::vector<double> scan_roots(const std::function<double(double)>& g, double a, double b, int samples) {
  std::vector<double> roots;
  double x0 = a, g0 = g(a);
  for (int i = 1; i <= samples; ++i) {
    const double x1 = a + (b - a) * i / samples, g1 = g(x1);
    if (g0 == 0.0) roots.push_back(x0);
    else if (g0 * g1 < 0) {
      double lo = x0, hi = x1, glo = g0;
      for (int it = 0; it < 80; ++it) {
        const double m = 0.5 * (lo + hi), gm = g(m);
        if ((gm < 0) == (glo < 0)) lo = m, glo = gm;
        else hi = m;
      }
      roots.push_back(0.5 * (lo + hi));
    }
    x0 = x1, g0 = g1;
  }
  return roots;
}

// --- Fig 5.7's function, as an Fn and in double. ---
Fn fig57() {
  const double tp = 2 * kPi;
  return square(X) + square(Y) + cos(tp * X) + sin(tp * Y) + sin(tp * square(X)) * cos(tp * square(Y)) - 1.0;
}
double fig57(double x, double y) {
  const double tp = 2 * kPi;
  return x * x + y * y + std::cos(tp * x) + std::sin(tp * y) + std::sin(tp * x * x) * std::cos(tp * y * y) - 1.0;
}

// --- The torus silhouette E·(S_u × S_v) = 0 (Fig 5.13). ---
Fn torus_silhouette() {
  const double R = 1.0, r = 0.3, tp = 2 * kPi;
  const double en = std::hypot(0.3, 1.0);
  const double ex = 0.0, ey = 0.3 / en, ez = 1.0 / en;
  const Fn u = X, v = Y;
  const Fn ring = R + r * cos(tp * v);
  const Fn S = cat({ring * cos(tp * u), ring * sin(tp * u), r * sin(tp * v)});
  const Fn Su = derivative(S, 0), Sv = derivative(S, 1);
  const Fn nx = Su[1] * Sv[2] - Su[2] * Sv[1];
  const Fn ny = Su[2] * Sv[0] - Su[0] * Sv[2];
  const Fn nz = Su[0] * Sv[1] - Su[1] * Sv[0];
  return ex * nx + ey * ny + ez * nz;
}

void expect_well_formed(const ImplicitCurve& c) {
  EXPECT_TRUE(c.complete()) << limit_name(c.report.limit) << " unresolved " << c.stats.unresolved;
  EXPECT_EQ(c.stats.branch_nodes, 0u);  // every point has <= 2 neighbors
  for (const Polyline& pl : c.components) {
    EXPECT_GE(pl.points.size(), 2u);
    if (pl.closed) {
      EXPECT_EQ(pl.front, CurveEnd::None);
      EXPECT_GE(pl.points.size(), 3u);
    } else {  // Assumption 1: both ends on ∂X
      EXPECT_EQ(pl.front, CurveEnd::Boundary);
      EXPECT_EQ(pl.back, CurveEnd::Boundary);
    }
  }
}

// Claim 33, first part: one closed linked list for the circle (at several widths; the circle
// passes exactly through kd-tree corners such as (0.5, 0.5)).
TEST(ImplicitCurve, Claim33CircleIsOneClosedList) {
  const Fn f = square(X) + square(Y) - 0.5;
  const Box Xb = {Interval(-1, 1), Interval(-1, 1)};
  for (double w : {0.4, 0.2, 0.1, 0.05}) {
    ImplicitCurveOptions opt;
    opt.acceptance_width = w;
    const ImplicitCurve c = approximate_implicit_curve(f, kXY, Xb, opt);
    expect_well_formed(c);
    ASSERT_EQ(c.components.size(), 1u) << "w = " << w;
    EXPECT_TRUE(c.components[0].closed);
    EXPECT_LE(max_residual(f, kXY, c), 1e-8);
    expect_inside(c, Xb);
    // Every proximate box is narrower than w; the polyline goes once around the circle.
    for (const CurveBox& b : c.boxes) EXPECT_LT(width(b.box), w);
    double turn = 0;
    const auto& P = c.components[0].points;
    for (std::size_t i = 0; i < P.size(); ++i) {
      const auto& a = P[i];
      const auto& b = P[(i + 1) % P.size()];
      turn += std::remainder(std::atan2(b[1], b[0]) - std::atan2(a[1], a[0]), 2 * kPi);
    }
    EXPECT_NEAR(std::abs(turn), 2 * kPi, 1e-9);
    // No piece lost: the circle is inside the union of the returned boxes.
    for (int i = 0; i < 2000; ++i) {
      const double t = 2 * kPi * i / 2000, p[] = {std::sqrt(0.5) * std::cos(t), std::sqrt(0.5) * std::sin(t)};
      EXPECT_TRUE(covered(c, p, 1e-12)) << i;
    }
  }
}

// Claim 33, second part: Fig 5.7's curve with w(Y) < 0.2 and with half that width.
TEST(ImplicitCurve, Claim33Fig57) {
  const Fn f = fig57();
  const Box Xb = {Interval(-1.1, 1.1), Interval(-1.1, 1.1)};
  std::vector<std::size_t> counts;
  for (double w : {0.19, 0.095}) {
    ImplicitCurveOptions opt;
    opt.acceptance_width = w;
    const ImplicitCurve c = approximate_implicit_curve(f, kXY, Xb, opt);
    expect_well_formed(c);
    expect_inside(c, Xb);
    // |f| at each point <= C w (C = 1 here; the points are solve() boxes' midpoints, so it is
    // far smaller in fact).
    EXPECT_LE(max_residual(f, kXY, c), 1.0 * w);
    EXPECT_LE(max_residual(f, kXY, c), 1e-7);
    // The chords stay near the curve too: |f| at segment midpoints <= C w with C = the
    // gradient bound (|grad f| <= 2.2 + 2π + 2π + 2π(2.2) + 2π(2.2) ≈ 43) times w / 2 is trivial;
    // check a tighter practical bound.
    for (const Polyline& pl : c.components)
      for (std::size_t i = 0; i + 1 < pl.points.size(); ++i) {
        const auto& a = pl.points[i];
        const auto& b = pl.points[i + 1];
        EXPECT_LE(std::abs(fig57(0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]))), 10.0 * w);
      }
    counts.push_back(c.components.size());
    // No piece lost: roots of dense row and column scans lie in the union of the boxes.
    int checked = 0;
    for (int i = 0; i <= 220; ++i) {
      const double s = -1.1 + 2.2 * i / 220;
      for (double r : scan_roots([&](double t) { return fig57(t, s); }, -1.1, 1.1, 4000)) {
        const double p[] = {r, s};
        EXPECT_TRUE(covered(c, p, 1e-9)) << r << " " << s;
        ++checked;
      }
      for (double r : scan_roots([&](double t) { return fig57(s, t); }, -1.1, 1.1, 4000)) {
        const double p[] = {s, r};
        EXPECT_TRUE(covered(c, p, 1e-9)) << s << " " << r;
        ++checked;
      }
    }
    EXPECT_GT(checked, 500);
  }
  EXPECT_EQ(counts[0], counts[1]);  // component count unchanged when w is halved
  EXPECT_GE(counts[0], 3u);         // several components (closed loops and boundary arcs)
}

// The heuristic parameterizability test (section 5.2.4) finds the same components with
// fewer proximate boxes, and every point of the curve is still covered.
TEST(ImplicitCurve, HeuristicTestAgreesWithTheRobustOne) {
  const Fn f = fig57();
  const Box Xb = {Interval(-1.1, 1.1), Interval(-1.1, 1.1)};
  ImplicitCurveOptions robust_opt;
  robust_opt.acceptance_width = 0.19;
  ImplicitCurveOptions heuristic_opt = robust_opt;
  heuristic_opt.parameterizability = ImplicitCurveOptions::Test::Heuristic;
  const ImplicitCurve robust = approximate_implicit_curve(f, kXY, Xb, robust_opt);
  const ImplicitCurve heuristic = approximate_implicit_curve(f, kXY, Xb, heuristic_opt);
  expect_well_formed(heuristic);
  EXPECT_EQ(heuristic.components.size(), robust.components.size());
  EXPECT_LE(heuristic.stats.proximate, robust.stats.proximate);
  EXPECT_LE(max_residual(f, kXY, heuristic), 1e-7);
  for (int i = 0; i <= 110; ++i) {
    const double s = -1.1 + 2.2 * i / 110;
    for (double r : scan_roots([&](double t) { return fig57(t, s); }, -1.1, 1.1, 4000)) {
      const double p[] = {r, s};
      EXPECT_TRUE(covered(heuristic, p, 1e-9)) << r << " " << s;
    }
  }
  // The circle: one closed list.
  const Fn circle = square(x(0)) + square(x(1)) - 0.5;
  const ImplicitCurve c = approximate_implicit_curve(circle, kXY, {Interval(-1, 1), Interval(-1, 1)}, heuristic_opt);
  ASSERT_EQ(c.components.size(), 1u);
  EXPECT_TRUE(c.components[0].closed);
}

// Claim 34, the non-periodic form: on u in [0,1], v in [-0.25, 0.75] the silhouette is exactly
// 2 open segments, each from u = 0 to u = 1 with the same v at both ends.
TEST(ImplicitCurve, Claim34TorusSilhouetteOpenSegments) {
  const Fn f = torus_silhouette();
  const Box Xb = {Interval(0, 1), Interval(-0.25, 0.75)};
  ImplicitCurveOptions opt;
  opt.acceptance_width = 0.1;
  const ImplicitCurve c = approximate_implicit_curve(f, kXY, Xb, opt);
  expect_well_formed(c);
  ASSERT_EQ(c.components.size(), 2u);
  for (const Polyline& pl : c.components) {
    EXPECT_FALSE(pl.closed);
    const auto& a = pl.points.front();
    const auto& b = pl.points.back();
    EXPECT_NEAR(std::min(a[0], b[0]), 0.0, 1e-12);
    EXPECT_NEAR(std::max(a[0], b[0]), 1.0, 1e-12);
    EXPECT_NEAR(a[1], b[1], 1e-8);
  }
  EXPECT_LE(max_residual(f, kXY, c), 1e-7);
  // Closed form: tan(2πv) = -(e_y / e_z) sin(2πu), v = v0(u) and v0(u) + 1/2.
  for (int i = 0; i <= 1000; ++i) {
    const double u = i / 1000.0;
    const double v0 = std::atan(-0.3 * std::sin(2 * kPi * u)) / (2 * kPi);
    for (double v : {v0, v0 + 0.5}) {
      const double p[] = {u, v};
      EXPECT_TRUE(covered(c, p, 1e-12)) << u << " " << v;
    }
  }
}

// Claim 34, the periodic form: joined across the periodic u and v boundaries the silhouette is
// exactly 2 closed components.
TEST(ImplicitCurve, Claim34TorusSilhouettePeriodic) {
  const Fn f = torus_silhouette();
  for (const Box& Xb : {Box{Interval(0, 1), Interval(0, 1)}, Box{Interval(0, 1), Interval(-0.25, 0.75)}}) {
    ImplicitCurveOptions opt;
    opt.acceptance_width = 0.1;
    opt.periodic = {0, 1};
    const ImplicitCurve c = approximate_implicit_curve(f, kXY, Xb, opt);
    expect_well_formed(c);
    ASSERT_EQ(c.components.size(), 2u) << Xb[1];
    for (const Polyline& pl : c.components) {
      EXPECT_TRUE(pl.closed);
      EXPECT_FALSE(pl.wraps.empty());
      for (std::size_t i : pl.wraps) {  // two images of one point: each side equal or one period apart
        const auto& a = pl.points[i];
        const auto& b = pl.points[(i + 1) % pl.points.size()];
        int shifted = 0;
        for (int k = 0; k < 2; ++k) {
          const double d = std::abs(a[k] - b[k]);
          EXPECT_TRUE(d < 1e-8 || std::abs(d - 1.0) < 1e-8) << d;
          shifted += d > 0.5;
        }
        EXPECT_GE(shifted, 1);
      }
    }
  }
}

// Claim 35 (Theorem 5.5): on boxes where the Jacobian minor J_k is regular, random x_k-slices
// hold at most one curve point (dense 1-D root scanning). Checked on Fig 5.7's curve, the
// circle and the torus silhouette, over random boxes of several sizes.
TEST(ImplicitCurve, Claim35ImplicitFunctionTheorem) {
  struct Case {
    Fn f;
    std::function<double(double, double)> g;
    Box X;
  };
  const Fn tor = torus_silhouette();
  Tape tor_tape(tor, kXY);
  PointEvaluator ev;
  const std::vector<Case> cases = {
      {fig57(), [](double x, double y) { return fig57(x, y); }, {Interval(-1.1, 1.1), Interval(-1.1, 1.1)}},
      {square(X) + square(Y) - 0.5, [](double x, double y) { return x * x + y * y - 0.5; }, {Interval(-1, 1), Interval(-1, 1)}},
      {tor, [&](double u, double v) { return ev.eval(tor_tape, {u, v})[0]; }, {Interval(0, 1), Interval(-0.25, 0.75)}},
  };
  std::mt19937_64 rng(35);
  std::uniform_real_distribution<double> unit(0, 1);
  int passing = 0, multi_root_slices = 0;
  for (const Case& cs : cases) {
    for (int trial = 0; trial < 200; ++trial) {
      const double w = std::pow(2.0, -1 - 5 * unit(rng));  // 1/2 .. 1/64 of X
      Box b(2);
      for (int i = 0; i < 2; ++i) {
        const double span = cs.X[i].width(), lo = cs.X[i].lo() + (span * (1 - w)) * unit(rng);
        b[i] = Interval(lo, lo + span * w);
      }
      const std::vector<int> ks = parameterizable_coordinates(cs.f, kXY, b);
      for (int k = 0; k < 2; ++k) {
        const bool regular = std::find(ks.begin(), ks.end(), k) != ks.end();
        const int o = 1 - k;
        for (int s = 0; s < 8; ++s) {
          const double c = b[k].lo() + b[k].width() * unit(rng);
          auto g = [&](double t) { return k == 0 ? cs.g(c, t) : cs.g(t, c); };
          const std::size_t roots = scan_roots(g, b[o].lo(), b[o].hi(), 1500).size();
          if (regular) EXPECT_LE(roots, 1u) << "k " << k << " box " << b[0] << " x " << b[1];
          else if (roots > 1) ++multi_root_slices;
        }
        passing += regular;
      }
    }
  }
  EXPECT_GT(passing, 150);            // the test passes on many boxes ...
  EXPECT_GT(multi_root_slices, 10);   // ... and the slices it rejects include multi-root ones
}

// The determinant and the preconditioned test on small matrices.
TEST(ImplicitCurve, JacobianMinorRegularity) {
  // 1 x 2: d/dx, d/dy.
  const Interval j1[] = {Interval(1, 2), Interval(-1, 1)};
  EXPECT_TRUE(jacobian_minor_regular(j1, 1, 1));   // minor = [1,2]
  EXPECT_FALSE(jacobian_minor_regular(j1, 1, 0));  // minor = [-1,1]
  EXPECT_TRUE(jacobian_minor_determinant(j1, 1, 1).contains(1.5));
  // 2 x 3, minor without column 2 = [[2, 1], [1, 2]] ± 0.1: regular; det in [3 - ..., 3 + ...].
  const Interval e(-0.1, 0.1);
  const Interval j2[] = {2.0 + e, 1.0 + e, Interval(0), 1.0 + e, 2.0 + e, Interval(0)};
  EXPECT_TRUE(jacobian_minor_regular(j2, 2, 2));
  EXPECT_TRUE(jacobian_minor_determinant(j2, 2, 2).contains(3.0));
  EXPECT_FALSE(jacobian_minor_regular(j2, 2, 0));  // [[1,0],[2,0]]: singular
  // 3 x 3: regular with +-0.5 on every entry, not with +-3 (it holds singular matrices).
  const double a[3][4] = {{4, 1, 1, 0}, {1, 4, 1, 0}, {1, 1, 4, 0}};
  for (double r : {0.5, 3.0}) {
    std::vector<Interval> j3;
    for (auto& row : a)
      for (double v : row) j3.push_back(v + Interval(-r, r));
    EXPECT_EQ(jacobian_minor_regular(j3, 3, 3), r < 1);
    EXPECT_TRUE(jacobian_minor_determinant(j3, 3, 3).contains(54.0));
  }
}

// A curve in a 4-D parameter space: the intersection of the unit sphere S1(u, v) with the plane
// S2(s, t) = (s, t, 1/2), F = S1 - S2 (3 equations, 4 unknowns). Its points map to the circle
// z = 1/2, x^2 + y^2 = 3/4.
TEST(ImplicitCurve, SurfaceSurfaceIntersection4D) {
  const Fn u = x(0), v = x(1), s = x(2), t = x(3);
  const Fn S1 = cat({cos(2 * kPi * u) * cos(kPi * v), sin(2 * kPi * u) * cos(kPi * v), sin(kPi * v)});
  const Fn S2 = cat({s, t, Fn(0.5)});
  const Fn F = S1 - S2;
  const int coords[] = {0, 1, 2, 3};
  const Box Xb = {Interval(0, 1), Interval(-0.45, 0.45), Interval(-1, 1), Interval(-1, 1)};
  for (bool periodic : {false, true}) {
    ImplicitCurveOptions opt;
    opt.acceptance_width = 0.3;
    if (periodic) opt.periodic = {0};
    const ImplicitCurve c = approximate_implicit_curve(F, coords, Xb, opt);
    expect_well_formed(c);
    ASSERT_EQ(c.components.size(), 1u);
    const Polyline& pl = c.components[0];
    EXPECT_EQ(pl.closed, periodic);
    if (!periodic) {
      EXPECT_NEAR(std::min(pl.points.front()[0], pl.points.back()[0]), 0.0, 1e-12);
      EXPECT_NEAR(std::max(pl.points.front()[0], pl.points.back()[0]), 1.0, 1e-12);
    }
    EXPECT_GE(pl.points.size(), 10u);
    EXPECT_LE(max_residual(F, coords, c), 1e-7);
    for (const auto& p : pl.points) {
      const double ph = 2 * kPi * p[0], th = kPi * p[1];
      const double X3[] = {std::cos(ph) * std::cos(th), std::sin(ph) * std::cos(th), std::sin(th)};
      EXPECT_NEAR(X3[2], 0.5, 1e-7);
      EXPECT_NEAR(std::hypot(X3[0], X3[1]), std::sqrt(0.75), 1e-7);
      EXPECT_NEAR(p[2], X3[0], 1e-7);
      EXPECT_NEAR(p[3], X3[1], 1e-7);
    }
    // Coverage: the true curve (u, 1/6, cos 2πu sqrt(3)/2, sin 2πu sqrt(3)/2).
    for (int i = 0; i <= 500; ++i) {
      const double uu = i / 500.0, r = std::sqrt(0.75);
      const double p[] = {uu, 1.0 / 6.0, r * std::cos(2 * kPi * uu), r * std::sin(2 * kPi * uu)};
      EXPECT_TRUE(covered(c, p, 1e-12)) << uu;
    }
  }
}

// Two disjoint circles and an arc through the boundary: 3 linked lists (Fig 5.6's picture).
TEST(ImplicitCurve, SeveralComponentsFig56) {
  // (((x+0.5)^2 + y^2 - 0.09) ((x-0.4)^2 + (y-0.3)^2 - 0.04) (x + y - 1.6)).
  const Fn f = (square(X + 0.5) + square(Y) - 0.09) * (square(X - 0.4) + square(Y - 0.3) - 0.04) * (X + Y - 1.6);
  const Box Xb = {Interval(-1, 1), Interval(-1, 1)};
  ImplicitCurveOptions opt;
  opt.acceptance_width = 0.15;
  const ImplicitCurve c = approximate_implicit_curve(f, kXY, Xb, opt);
  expect_well_formed(c);
  ASSERT_EQ(c.components.size(), 3u);
  int closed = 0;
  for (const Polyline& pl : c.components) closed += pl.closed;
  EXPECT_EQ(closed, 2);
}

// A singular point (the figure eight x^2 - y^2 = 0 crossing at the origin) cannot be resolved:
// the box around it is reported, and the curves that reach it say so. Nothing is silently lost.
TEST(ImplicitCurve, SingularPointIsReported) {
  const Fn f = square(X) - square(Y);
  const Box Xb = {Interval(-0.9, 1.1), Interval(-0.95, 1.05)};
  ImplicitCurveOptions opt;
  opt.acceptance_width = 0.2;
  opt.min_width = 1e-3;
  const ImplicitCurve c = approximate_implicit_curve(f, kXY, Xb, opt);
  EXPECT_FALSE(c.complete());
  EXPECT_GE(c.stats.unresolved, 1u);
  int unresolved_ends = 0;
  for (const Polyline& pl : c.components)
    unresolved_ends += (pl.front == CurveEnd::Unresolved) + (pl.back == CurveEnd::Unresolved);
  EXPECT_EQ(unresolved_ends, 4);  // four branches end at the crossing
  const double origin[] = {0.0, 0.0};
  EXPECT_TRUE(covered(c, origin, 0.0));
}

TEST(ImplicitCurve, LimitsAreReported) {
  const Fn f = fig57();
  ImplicitCurveOptions opt;
  opt.acceptance_width = 0.1;
  opt.limits.max_boxes = 20;
  const ImplicitCurve c = approximate_implicit_curve(f, kXY, {Interval(-1.1, 1.1), Interval(-1.1, 1.1)}, opt);
  EXPECT_EQ(c.report.limit, LimitHit::MaxBoxes);
  EXPECT_FALSE(c.complete());
  EXPECT_GT(c.stats.unexplored, 0u);
  // Still no piece lost.
  for (int i = 0; i <= 100; ++i) {
    const double s = -1.1 + 2.2 * i / 100;
    for (double r : scan_roots([&](double t) { return fig57(t, s); }, -1.1, 1.1, 2000)) {
      const double p[] = {r, s};
      EXPECT_TRUE(covered(c, p, 1e-9));
    }
  }
}

TEST(ImplicitCurve, BadInput) {
  const Fn f = square(X) + square(Y) - 0.5;
  const Box Xb = {Interval(-1, 1), Interval(-1, 1)};
  const int one[] = {0};
  const int three[] = {0, 1, 2};
  const int twice[] = {0, 0};
  const int other[] = {0, 2};
  EXPECT_THROW(approximate_implicit_curve(f, one, {Interval(-1, 1)}), std::invalid_argument);
  EXPECT_THROW(approximate_implicit_curve(f, three, {Interval(-1, 1), Interval(-1, 1), Interval(-1, 1)}),
               std::invalid_argument);
  EXPECT_THROW(approximate_implicit_curve(f, twice, Xb), std::invalid_argument);
  EXPECT_THROW(approximate_implicit_curve(f, other, Xb), std::invalid_argument);
  EXPECT_THROW(approximate_implicit_curve(f, kXY, {Interval(-1, 1)}), std::invalid_argument);
  EXPECT_THROW(approximate_implicit_curve(f, kXY, {Interval(-1, 1), Interval::entire()}), std::invalid_argument);
  ImplicitCurveOptions opt;
  opt.acceptance_width = 0;
  EXPECT_THROW(approximate_implicit_curve(f, kXY, Xb, opt), std::invalid_argument);
  opt.acceptance_width = std::nan("");
  EXPECT_THROW(approximate_implicit_curve(f, kXY, Xb, opt), std::invalid_argument);
  opt = {};
  opt.periodic = {3};
  EXPECT_THROW(approximate_implicit_curve(f, kXY, Xb, opt), std::invalid_argument);
}

TEST(ImplicitCurve, Deterministic) {
  const Fn f = torus_silhouette();
  const Box Xb = {Interval(0, 1), Interval(-0.25, 0.75)};
  ImplicitCurveOptions opt;
  opt.acceptance_width = 0.1;
  const ImplicitCurve a = approximate_implicit_curve(f, kXY, Xb, opt);
  const ImplicitCurve b = approximate_implicit_curve(f, kXY, Xb, opt);
  ASSERT_EQ(a.components.size(), b.components.size());
  for (std::size_t i = 0; i < a.components.size(); ++i) EXPECT_EQ(a.components[i].points, b.components[i].points);
}

}  // namespace
}  // namespace genmod
