// The CPG path builder (snyder.md sections 7.18-7.19): the thesis's regular screwdriver tip
// ({|x| <= w/2} intersected with the disk of radius 0.5) at several slot widths, sharp and
// filleted; the Phillips half path completed by mirror_x; properties and misuse.
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/operators/path.hpp"
#include "operators/operator_properties.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace genmod {
namespace {

const Fn u = x(0), v = x(1);
const Fn origin = cat({0.0, 0.0});

std::vector<std::vector<double>> sample(const Fn& c, double vv, int n) {
  std::vector<std::vector<double>> pts;
  for (int i = 0; i <= n; ++i) pts.push_back(evaluate(c, std::vector<double>{double(i) / n, vv}));
  return pts;
}

double shoelace(const std::vector<std::vector<double>>& pts) {
  double a = 0.0;
  for (std::size_t i = 1; i < pts.size(); ++i) a += pts[i - 1][0] * pts[i][1] - pts[i][0] * pts[i - 1][1];
  return 0.5 * a;
}

// The thesis's regular tip with slot width w(v) = 0.015 + 0.735 v (App. B.2).
Path regular_tip(const Fn& fillet = Fn(0.0)) {
  const Fn w = 0.015 + 0.735 * v;
  const Fn p0 = cat({w / 2, -1.0}), p1 = cat({w / 2, 1.0}), p2 = cat({-w / 2, 1.0}), p3 = cat({-w / 2, -1.0});
  Path p(0);
  p.move_to(p0);
  p.line_to_arc(p1, origin, 0.5, true, true, fillet);   // thesis min = 0
  p.arc_to_line(origin, 0.5, p2, p3, false, true, fillet);  // thesis min = 1
  p.line_to_arc(p3, origin, 0.5, true, true, fillet);
  p.arc_to_line(origin, 0.5, p0, p1, false, true, fillet);
  p.close();
  return p;
}

TEST(Path, RegularTipIsSlotIntersectDisk) {
  const Path path = regular_tip();
  EXPECT_EQ(path.pieces(), 4U);  // closing onto the starting line adds no degenerate piece
  const Fn c = path.curve(u);
  for (double vv : {0.0, 0.2, 0.5, 0.9, 1.0}) {
    const double w = 0.015 + 0.735 * vv, h = std::sqrt(0.25 - w * w / 4);
    const auto pts = sample(c, vv, 4000);
    for (const auto& p : pts) {
      const bool on_chord = std::abs(std::abs(p[0]) - w / 2) < 1e-14 && std::abs(p[1]) <= h + 1e-14;
      const bool on_circle = std::abs(std::hypot(p[0], p[1]) - 0.5) < 1e-14 && std::abs(p[0]) <= w / 2 + 1e-14;
      EXPECT_TRUE(on_chord || on_circle) << p[0] << " " << p[1] << " w=" << w;
    }
    EXPECT_NEAR(pts.front()[0], pts.back()[0], 1e-15);
    EXPECT_NEAR(pts.front()[1], pts.back()[1], 1e-15);
    for (std::size_t i = 1; i < pts.size(); ++i)  // continuous: no jumps between samples
      EXPECT_LT(std::hypot(pts[i][0] - pts[i - 1][0], pts[i][1] - pts[i - 1][1]), 4.0 / 4000 * 1.5);
    // Area of {|x| <= w/2} in the disk: 2 (x h(x) + R^2 asin(x/R)) at x = w/2.
    const double xw = w / 2, area = 2 * (xw * h + 0.25 * std::asin(xw / 0.5));
    EXPECT_NEAR(shoelace(pts), area, 2e-6 * area + 1e-9);
  }
  testing::PropertySpec spec = testing::unit_domain(2);
  spec.breaks = {{0.25, 0.5, 0.75}, {}};
  testing::check_operator_properties(c, spec, 501);
}

TEST(Path, FilletedTipIsTangentContinuousAndInsideTheSharpOne) {
  const double f = 0.04;
  const Path path = regular_tip(Fn(f));
  EXPECT_EQ(path.pieces(), 8U);
  const Fn c = path.curve(u);
  const Fn dc = derivative(c, 0);
  for (double vv : {0.3, 0.6, 1.0}) {
    const double w = 0.015 + 0.735 * vv, h = std::sqrt(0.25 - w * w / 4);
    const auto pts = sample(c, vv, 4000);
    for (const auto& p : pts) {  // inside the sharp region
      EXPECT_LE(std::abs(p[0]), w / 2 + 1e-14);
      EXPECT_LE(std::hypot(p[0], p[1]), 0.5 + 1e-14);
    }
    EXPECT_NEAR(pts.front()[0], pts.back()[0], 1e-14);
    EXPECT_NEAR(pts.front()[1], pts.back()[1], 1e-14);
    // G1 at every joint (including the closing one): unit tangents agree on both sides.
    for (int k = 0; k <= 8; ++k) {
      const double j = k / 8.0;
      const auto a = evaluate(dc, std::vector<double>{k == 0 ? 1.0 - 1e-12 : j - 1e-12, vv});
      const auto b = evaluate(dc, std::vector<double>{k == 8 ? 1e-12 : j + 1e-12, vv});
      const double cross = (a[0] * b[1] - a[1] * b[0]) / (std::hypot(a[0], a[1]) * std::hypot(b[0], b[1]));
      const double dotp = a[0] * b[0] + a[1] * b[1];
      EXPECT_LT(std::abs(cross), 1e-9) << "joint " << j << " v " << vv;
      EXPECT_GT(dotp, 0.0) << "joint " << j << " v " << vv;
    }
    // The fillets cut off area: less than the sharp tip, more than the sharp tip minus the four corner squares.
    const double xw = w / 2, sharp = 2 * (xw * h + 0.25 * std::asin(xw / 0.5));
    const double area = shoelace(pts);
    EXPECT_LT(area, sharp);
    EXPECT_GT(area, sharp - 4 * f * f);
  }
  testing::PropertySpec spec = testing::unit_domain(2);
  spec.domain[1] = Interval(0.2, 1.0);
  for (int k = 1; k < 8; ++k) spec.breaks.resize(2), spec.breaks[0].push_back(k / 8.0);
  testing::check_operator_properties(c, spec, 502);
}

TEST(Path, PhillipsHalfPathMirroredIsClosedAndSymmetric) {
  const Fn r = 0.5 - 0.4 * (1.0 - v);  // radius shrinks toward the tip
  const Fn depth = 0.3 * v + 0.02;     // wedge vertex distance D
  const Fn p = cat({depth, 0.0}), p1 = cat({0.0, depth}), p2 = cat({0.0, -depth});
  const double s = std::sqrt(0.5);
  const Fn d1 = cat({s, s}), d2 = cat({s, -s}), d0 = cat({s, s}), d3 = cat({s, -s});
  Path path(0);
  path.move_to(p2);
  path.line_to_arc(p2 + d3, origin, r, true, true);
  path.arc_to_line(origin, r, p + d2, p, false, true);
  path.line_to(p);
  path.line_to_arc(p + d1, origin, r, true, true);
  path.arc_to_line(origin, r, p1 + d0, p1, false, true);
  path.line_to(p1);
  EXPECT_EQ(path.pieces(), 6U);
  const Fn c = mirror_x(path.curve(u));
  for (double vv : {0.0, 0.5, 1.0}) {
    const double D = 0.3 * vv + 0.02, R = 0.5 - 0.4 * (1 - vv);
    const auto first = evaluate(c, std::vector<double>{0.0, vv}), mid = evaluate(c, std::vector<double>{0.5, vv}),
               last = evaluate(c, std::vector<double>{1.0, vv});
    EXPECT_NEAR(first[0], 0.0, 1e-15);
    EXPECT_NEAR(first[1], -D, 1e-15);
    EXPECT_NEAR(mid[0], 0.0, 1e-15);
    EXPECT_NEAR(mid[1], D, 1e-15);
    EXPECT_NEAR(last[0], first[0], 1e-15);
    EXPECT_NEAR(last[1], first[1], 1e-15);
    const auto vertex = evaluate(c, std::vector<double>{0.25, vv});  // the end of the third half piece: (D, 0)
    EXPECT_NEAR(vertex[0], D, 1e-14);
    EXPECT_NEAR(vertex[1], 0.0, 1e-14);
    for (int i = 0; i <= 200; ++i) {
      const double t = i / 400.0;
      const auto a = evaluate(c, std::vector<double>{t, vv}), b = evaluate(c, std::vector<double>{1.0 - t, vv});
      EXPECT_NEAR(a[0], -b[0], 1e-15);  // mirror symmetry
      EXPECT_NEAR(a[1], b[1], 1e-15);
      EXPECT_GE(a[0], -1e-15);
      EXPECT_LE(std::hypot(a[0], a[1]), R + 1e-14);
    }
    // Counter-clockwise (positive area).
    const auto pts = sample(c, vv, 8000);
    EXPECT_GT(shoelace(pts), 0.0);
  }
  testing::PropertySpec spec = testing::unit_domain(2);
  spec.breaks = {{1.0 / 12, 2.0 / 12, 3.0 / 12, 4.0 / 12, 5.0 / 12, 0.5, 7.0 / 12, 8.0 / 12, 9.0 / 12, 10.0 / 12, 11.0 / 12}, {}};
  testing::check_operator_properties(c, spec, 503);
}

TEST(Path, OpenPolylineAndClosingSegment) {
  Path path(0);
  path.move_to(cat({0.0, 0.0}));
  path.line_to(cat({1.0, 0.0}));
  path.line_to(cat({1.0, v}));
  path.close();
  EXPECT_EQ(path.pieces(), 3U);
  const Fn c = path.curve(u);
  const auto mid = evaluate(c, std::vector<double>{0.5, 0.6});
  EXPECT_NEAR(mid[0], 1.0, 1e-15);
  EXPECT_NEAR(mid[1], 0.3, 1e-15);
  EXPECT_NEAR(shoelace(sample(c, 0.6, 300)), 0.3, 1e-12);
}

TEST(Path, MisuseNamesThePath) {
  using testing::expect_throw_naming;
  expect_throw_naming([] { Path p; p.line_to(cat({1.0, 0.0})); }, "Path::line_to");
  expect_throw_naming([] { Path p; p.move_to(cat({u, 0.0})); }, "Path::move_to");
  expect_throw_naming([] { Path p; p.move_to(cat({0.0, 0.0, 0.0})); }, "Path::move_to");
  expect_throw_naming([] { Path p; p.move_to(origin); p.line_to(cat({1.0, 0.0})); p.close(); p.line_to(origin); }, "Path::line_to");
  expect_throw_naming([] { Path p; p.move_to(origin); p.line_to_arc(cat({1.0, 0.0}), origin, 0.5, true, true, -0.1); },
                      "Path::line_to_arc");
  expect_throw_naming([] { Path p; (void)p.curve(u); }, "Path::curve");
  expect_throw_naming([] { mirror_x(cat({u, u, u})); }, "mirror_x");
}

}  // namespace
}  // namespace genmod
