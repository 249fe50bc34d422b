// Screwdriver tips (research/snyder.md 7.18, App. B.2): the regular tip's section is the slab
// |x| <= w/2 cut from the disk (points on the flats or the circle, area = the analytic area);
// the Phillips tip's section is closed, symmetric under x -> -x, made of the circle and the
// 45-degree wedge edges, with the wedge vertices at (0, +-D) and (+-D, 0).
#include "genmod/models/gallery.hpp"

#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "models/model_testing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace genmod::models {
namespace {

using namespace testing;  // the shared helpers of models/model_testing.hpp

// The section at v sampled at n + 1 points u = k / n.
// (One tape for all the points: the sections are large DAGs.)
std::vector<P2> section(const Fn& s, double v, int n) {
  const Tape tape(s);
  EXPECT_EQ(tape.inputs().size(), 2u);
  PointEvaluator ev;
  std::vector<P2> points;
  for (int k = 0; k <= n; ++k) {
    const auto q = ev.eval(tape, {double(k) / n, v});
    points.push_back({q[0], q[1]});
  }
  return points;
}

double shoelace(const std::vector<P2>& p) {
  double twice = 0;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) twice += p[i][0] * p[i + 1][1] - p[i + 1][0] * p[i][1];
  return twice / 2;
}

const std::vector<double> kV{0.0, 0.1, 0.25, 0.5, 0.73, 0.9, 1.0};

// Area of {|x| <= a} intersected with the disk of radius r.
double slab_disk_area(double a, double r) { return 2.0 * (a * std::sqrt(r * r - a * a) + r * r * std::asin(a / r)); }

TEST(ScrewdriverRegular, SectionIsTheSlabCutFromTheDisk) {
  const Model& m = find_model("screwdriver_regular");
  for (const ParameterValues& overrides : {ParameterValues{}, ParameterValues{{"radius", 0.8}, {"blade_width", 1.2}}}) {
    const ParameterValues p = resolve_parameters(m, overrides);
    const Fn s = m.build(p), sec = screwdriver_regular_section(p);
    const double r = p.at("radius");
    for (double v : kV) {
      const double w = p.at("tip_width") + (p.at("blade_width") - p.at("tip_width")) * v;
      const auto pts = section(s, v, 20000);
      EXPECT_NEAR(at(s, 0.3, v)[2], v, 1e-15);
      EXPECT_NEAR(pts.front()[0], pts.back()[0], 1e-12);
      EXPECT_NEAR(pts.front()[1], pts.back()[1], 1e-12);
      int on_flats = 0, on_arcs = 0;
      for (const P2& q : pts) {
        const bool flat = std::abs(std::abs(q[0]) - w / 2) < 1e-12 && std::hypot(q[0], q[1]) <= r + 1e-12;
        const bool arc = std::abs(std::hypot(q[0], q[1]) - r) < 1e-12 && std::abs(q[0]) <= w / 2 + 1e-12;
        ASSERT_TRUE(flat || arc) << "(" << q[0] << ", " << q[1] << ") at v " << v;
        on_flats += flat;
        on_arcs += arc;
      }
      EXPECT_GT(on_flats, 100);
      EXPECT_GT(on_arcs, 100);
      EXPECT_NEAR(shoelace(pts), slab_disk_area(w / 2, r), 1e-6) << "v " << v;
      EXPECT_EQ(at(sec, 0.4, v)[0], at(s, 0.4, v)[0]);
    }
  }
}

// With fillets the section stays inside the slab and the disk, closed, and loses area.
TEST(ScrewdriverRegular, FilletsRoundTheCorners) {
  const Model& m = find_model("screwdriver_regular");
  const ParameterValues p = resolve_parameters(m, {{"fillet", 0.005}});
  const Fn s = m.build(p);
  for (double v : kV) {
    const double w = p.at("tip_width") + (p.at("blade_width") - p.at("tip_width")) * v, r = p.at("radius");
    const auto pts = section(s, v, 4000);
    EXPECT_NEAR(pts.front()[0], pts.back()[0], 1e-12);
    EXPECT_NEAR(pts.front()[1], pts.back()[1], 1e-12);
    for (const P2& q : pts) {
      ASSERT_TRUE(std::isfinite(q[0]) && std::isfinite(q[1])) << "v " << v;
      EXPECT_LE(std::abs(q[0]), w / 2 + 1e-12);
      EXPECT_LE(std::hypot(q[0], q[1]), r + 1e-12);
    }
    const double area = shoelace(pts), sharp = slab_disk_area(w / 2, r);
    EXPECT_LT(area, sharp);
    EXPECT_GT(area, sharp - 4 * 0.005 * 0.005);  // four corners, each less than f^2
  }
}

TEST(ScrewdriverRegular, ParametersAreValidated) {
  const Model& m = find_model("screwdriver_regular");
  EXPECT_NE(error_of([&] { build_model(m, {{"blade_width", 1.0}}); }).find("blade_width"), std::string::npos);
  EXPECT_NE(error_of([&] { build_model(m, {{"tip_width", 0.0}}); }).find("tip_width"), std::string::npos);
  EXPECT_NE(error_of([&] { build_model(m, {{"fillet", 0.01}}); }).find("fillet"), std::string::npos);
  EXPECT_NE(error_of([&] { build_model(m, {{"fillet", -0.01}}); }).find("fillet"), std::string::npos);
  EXPECT_NE(error_of([&] { build_model(m, {{"radius", -1.0}}); }).find("radius"), std::string::npos);
}

// Every section point is on the circle of radius r(v) or on a 45-degree wedge edge
// ||x| - |y|| = D(v); the section is closed and symmetric under x -> -x, and passes through the
// wedge vertices (0, +-D), (+-D, 0).
TEST(ScrewdriverPhillips, SectionIsTheDiskMinusFourWedges) {
  const Model& m = find_model("screwdriver_phillips");
  for (const ParameterValues& overrides : {ParameterValues{}, ParameterValues{{"depth_scale", 1.5}}}) {
    const ParameterValues p = resolve_parameters(m, overrides);
    const Fn s = m.build(p), radius = screwdriver_phillips_radius(p), depth = screwdriver_phillips_depth(p);
    for (double v : kV) {
      const double r = at(radius, 0.0, v)[0], D = at(depth, 0.0, v)[0];
      ASSERT_GT(D, 0.0);
      ASSERT_LT(D, std::sqrt(2.0) * r);
      const auto pts = section(s, v, 12000);
      EXPECT_NEAR(pts.front()[0], pts.back()[0], 1e-12);
      EXPECT_NEAR(pts.front()[1], pts.back()[1], 1e-12);
      for (const P2& q : pts) {
        const double on_circle = std::abs(std::hypot(q[0], q[1]) - r);
        const double on_edge = std::abs(std::abs(std::abs(q[0]) - std::abs(q[1])) - D);
        ASSERT_LT(std::min(on_circle, on_edge), 1e-12) << "(" << q[0] << ", " << q[1] << ") at v " << v;
        ASSERT_LE(std::hypot(q[0], q[1]), r + 1e-12);
      }
      for (std::size_t k = 0; k < pts.size(); k += 37)
        EXPECT_LT(distance(pts, {-pts[k][0], pts[k][1]}), 1e-9) << "mirror of (" << pts[k][0] << ", " << pts[k][1] << ")";
      for (P2 vertex : {P2{0, D}, P2{0, -D}, P2{D, 0}, P2{-D, 0}}) {
        double best = std::numeric_limits<double>::infinity();
        for (const P2& q : pts) best = std::min(best, std::hypot(q[0] - vertex[0], q[1] - vertex[1]));
        EXPECT_LT(best, 1e-12) << "vertex (" << vertex[0] << ", " << vertex[1] << ") at v " << v;
      }
      EXPECT_NEAR(at(s, 0.2, v)[2], at(gallery_curve("screwdriver_phillips_depth")(x(1)), 0.0, v)[0], 1e-15);
    }
  }
}

TEST(ScrewdriverPhillips, ParametersAreValidated) {
  const Model& m = find_model("screwdriver_phillips");
  EXPECT_NE(error_of([&] { build_model(m, {{"depth_scale", 2.0}}); }).find("depth_scale"), std::string::npos);
  EXPECT_NE(error_of([&] { build_model(m, {{"length", 0.0}}); }).find("length"), std::string::npos);
  const auto tall = at(build_model(m, {{"length", 2.0}}), 0.1, 1.0), base = at(build_model(m), 0.1, 1.0);
  EXPECT_NEAR(tall[2], 2.0 * base[2], 1e-15);
}

}  // namespace
}  // namespace genmod::models
