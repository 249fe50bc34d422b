// Offsets and the offset plate (research/snyder.md 7.13-7.14, claim 30): every level of the
// offsets surface is at distance |r| from its curve, the unit circle offsets by 0.25 to the
// circle of radius 0.75 through the same code, and the plate's walls are the cross section
// offset by d1(v) at height d2(v).
#include "genmod/models/gallery.hpp"

#include "models/model_testing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace genmod::models {
namespace {

using namespace testing;  // the shared helpers of models/model_testing.hpp

// The closed curve sampled at n + 1 points (t = k / n).
std::vector<P2> dense(const Curve& c, int n) {
  std::vector<P2> points;
  for (int k = 0; k <= n; ++k) {
    const auto q = at(c, double(k) / n);
    points.push_back({q[0], q[1]});
  }
  return points;
}

const std::vector<double> kV{0.0, 0.1, 0.3, 0.45, 0.5, 0.62, 0.8, 0.95, 1.0};

// 7.13: each level z = r of the surface is the offset of the curve by r, at distance |r| from
// it (|r| <= 0.35, below the curve's smallest radius of curvature), inward for r > 0.
TEST(Offsets, EveryLevelIsAtDistanceRFromTheCurve) {
  const Model& m = find_model("offsets");
  const ParameterValues p = resolve_parameters(m);
  ASSERT_EQ(p.at("r_max"), 0.25);
  for (double r_max : {0.25, 0.35}) {
    const Fn s = build_model(m, {{"r_max", r_max}});
    const auto line = dense(offsets_curve(p), 20000);
    for (int i = 0; i < 40; ++i)
      for (double v : kV) {
        const double u = (i + 0.37) / 40.0;
        const auto S = at(s, u, v);
        const double r = -r_max + 2.0 * r_max * v;
        EXPECT_NEAR(S[2], r, 1e-15);
        EXPECT_NEAR(distance(line, {S[0], S[1]}), std::abs(r), 2e-6) << "u " << u << " v " << v;
      }
  }
  // Periodic: the closed curve's surface agrees at u = 0 and 1.
  const Fn s = build_model(m);
  for (double v : kV)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(at(s, 0.0, v)[j], at(s, 1.0, v)[j], 1e-12);
}

// Claim 30 through the model's own construction: the unit CCW circle offset by r is the circle
// of radius 1 - r (printed normal: positive r inward), so 0.25 -> 0.75.
TEST(Offsets, UnitCircleOffsetByAQuarterHasRadiusThreeQuarters) {
  const Fn t = x(0) * (2.0 * std::numbers::pi);
  const Fn s = offsets_surface(cat({cos(t), sin(t)}), 0.25);
  for (int i = 0; i < 16; ++i) {
    const double u = i / 16.0;
    const auto inner = at(s, u, 1.0), middle = at(s, u, 0.5), outer = at(s, u, 0.0);
    EXPECT_NEAR(std::hypot(inner[0], inner[1]), 0.75, 1e-14);
    EXPECT_NEAR(inner[2], 0.25, 1e-15);
    EXPECT_NEAR(std::hypot(middle[0], middle[1]), 1.0, 1e-14);
    EXPECT_NEAR(std::hypot(outer[0], outer[1]), 1.25, 1e-14);
    EXPECT_NEAR(std::atan2(inner[1], inner[0]), std::atan2(std::sin(2 * std::numbers::pi * u), std::cos(2 * std::numbers::pi * u)), 1e-13);
  }
}

TEST(Offsets, RMaxIsValidated) {
  const Model& m = find_model("offsets");
  for (double bad : {0.0, -0.1, 0.4}) {
    const std::string msg = error_of([&] { build_model(m, {{"r_max", bad}}); });
    EXPECT_NE(msg.find("r_max"), std::string::npos) << msg;
  }
}

// 7.14: for each v the wall is the cross section offset inward by d1(v) (xy distance |d1|) at
// height z = d2(v); the profile runs from the bottom face (d1 = edge_radius) out to the wall
// (d1 = 0) and back in to the top face.
TEST(OffsetPlate, WallsAreTheCrossSectionOffsetByTheProfile) {
  const Model& m = find_model("offset_plate");
  for (const ParameterValues& overrides :
       {ParameterValues{}, ParameterValues{{"edge_radius", 0.09}, {"thickness", 0.18}}}) {
    const ParameterValues p = resolve_parameters(m, overrides);
    const Fn s = m.build(p);
    const Curve cross = offset_plate_cross(p), profile = offset_plate_profile(p);
    const auto line = dense(cross, 20000);
    const double rho = p.at("edge_radius"), half = p.at("thickness") / 2.0;
    EXPECT_NEAR(at(profile, 0.0)[0], rho, 1e-15);
    EXPECT_NEAR(at(profile, 0.0)[1], -half, 1e-15);
    EXPECT_NEAR(at(profile, 0.5)[0], 0.0, 1e-15);
    EXPECT_NEAR(at(profile, 1.0)[0], rho, 1e-15);
    EXPECT_NEAR(at(profile, 1.0)[1], half, 1e-15);
    for (int i = 0; i < 60; ++i)
      for (double v : kV) {
        const double u = (i + 0.29) / 60.0;
        const auto S = at(s, u, v), d = at(profile, v);
        EXPECT_GE(d[0], -1e-15);
        EXPECT_NEAR(S[2], d[1], 1e-15);
        EXPECT_NEAR(distance(line, {S[0], S[1]}), d[0], 2e-6) << "u " << u << " v " << v;
      }
    // The edge is a quarter circle: (d1 - rho)^2 + (d2 -+ (half - rho))^2 = rho^2 on the arcs.
    for (double v : {0.02, 0.05, 0.1}) {
      const auto d = at(profile, v);
      EXPECT_NEAR(std::hypot(d[0] - rho, d[1] + half - rho), rho, 1e-14) << v;
    }
  }
}

TEST(OffsetPlate, CrossSectionIsClosedAndCounterclockwise) {
  const Curve cross = gallery_curve("offset_plate_cross");
  const auto a = at(cross, 0.0), b = at(cross, 1.0);
  EXPECT_NEAR(a[0], b[0], 1e-15);
  EXPECT_NEAR(a[1], b[1], 1e-15);
  const auto line = dense(cross, 4000);
  double area = 0;
  for (std::size_t i = 0; i + 1 < line.size(); ++i) area += line[i][0] * line[i + 1][1] - line[i + 1][0] * line[i][1];
  EXPECT_GT(area / 2, 2.0);  // 2 x 1.2 less the corners and notches, positive: CCW
  EXPECT_LT(area / 2, 2.4);
}

TEST(OffsetPlate, ParametersAreValidated) {
  const Model& m = find_model("offset_plate");
  EXPECT_NO_THROW(build_model(m, {{"edge_radius", 0.05}, {"thickness", 0.1}}));  // full round edge
  for (const ParameterValues& bad : {ParameterValues{{"edge_radius", 0.1}}, ParameterValues{{"edge_radius", 0.0}},
                                     ParameterValues{{"edge_radius", 0.06}, {"thickness", 0.1}}}) {
    const std::string msg = error_of([&] { build_model(m, bad); });
    EXPECT_NE(msg.find("edge_radius"), std::string::npos) << msg;
  }
  EXPECT_NE(error_of([&] { build_model(m, {{"thickness", -1.0}}); }).find("thickness"), std::string::npos);
}

}  // namespace
}  // namespace genmod::models
