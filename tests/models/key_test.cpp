// The keyboard key (thesis Fig 3.15, research/snyder.md 7.16): its cross section is a rounded
// square, its sections span the profile curves, its dimensions follow the parameters, its
// caps close the sides and the top is dished by the warp z += a x^2 + b.
#include "genmod/models/gallery.hpp"

#include "models/model_testing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace genmod::models {
namespace {

using namespace testing;  // the shared helpers of models/model_testing.hpp

const std::vector<double> kV{0.0, 0.07, 0.2, 0.33, 0.5, 0.61, 0.75, 0.88, 0.96, 1.0};

// Signed distance from (x, y) to the boundary of the square [-1, 1]^2 with corners rounded
// by r (negative inside).
double rounded_square_distance(double x, double y, double r) {
  const double qx = std::abs(x) - (1.0 - r), qy = std::abs(y) - (1.0 - r);
  return std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0) - r;
}

TEST(Key, CrossSectionIsARoundedSquare) {
  for (double r : {0.3, 0.05, 0.9}) {
    const ParameterValues p = resolve_parameters(find_model("key"), {{"corner_radius", r}});
    const Curve cross = key_cross(p);
    Eval c(cross(x(0))), dc(derivative(cross(x(0)), 0));
    double max_x = 0.0, area = 0.0;
    const int n = 4000;
    std::vector<double> prev = c({0.0});
    for (int i = 0; i <= n; ++i) {
      const auto q = c({static_cast<double>(i) / n});
      EXPECT_NEAR(rounded_square_distance(q[0], q[1], r), 0.0, 1e-12) << r << " at " << i;
      max_x = std::max(max_x, std::abs(q[0]));
      area += 0.5 * (prev[0] * q[1] - q[0] * prev[1]);  // shoelace: positive = counterclockwise
      prev = q;
    }
    EXPECT_NEAR(max_x, 1.0, 1e-15);
    EXPECT_NEAR(area, 4.0 - (4.0 - std::numbers::pi) * r * r, 1e-5) << r;
    // Starts at the middle of the right side, closed, and the tangent turns smoothly: the
    // direction is continuous (the curve is G1), across the start too.
    EXPECT_NEAR(c({0.0})[0], 1.0, 1e-15);
    EXPECT_NEAR(c({0.0})[1], 0.0, 1e-15);
    EXPECT_NEAR(c({1.0})[0], 1.0, 1e-15);
    EXPECT_NEAR(c({1.0})[1], 0.0, 1e-15);
    for (int i = 0; i <= 400; ++i) {
      const double t0 = std::max(0.0, i / 400.0 - 1e-7), t1 = std::min(1.0, i / 400.0 + 1e-7);
      const auto a = dc({t0}), b = dc({t1});
      const double cosine = (a[0] * b[0] + a[1] * b[1]) / (std::hypot(a[0], a[1]) * std::hypot(b[0], b[1]));
      EXPECT_GT(cosine, 1.0 - 1e-9) << r << " at " << i;
    }
    const auto a = dc({0.0}), b = dc({1.0});
    EXPECT_NEAR(a[0] * b[1] - a[1] * b[0], 0.0, 1e-12 * std::hypot(a[0], a[1]) * std::hypot(b[0], b[1]));
  }
}

// The unwarped sides span the key's outline: the cross section's x in [-1, 1] maps to
// [-xz_x, xz_x], and its y in [-1, 1] to the segment from yz_left(v) to yz_right(v).
TEST(Key, SectionsSpanTheProfileCurves) {
  const ParameterValues p = resolve_parameters(find_model("key"));
  const Fn sides = key_unwarped(p);
  const Curve cross = key_cross(p), left = key_yz_left(p), right = key_yz_right(p), xz = key_xz(p);
  for (int i = 0; i <= 16; ++i)
    for (double v : kV) {
      const double u = i / 16.0;
      const auto c = at(cross, u), s = at(sides, u, v), l = at(left, v), r = at(right, v);
      const double a = (c[0] + 1) / 2, b = (c[1] + 1) / 2, h = at(xz, v)[0];
      EXPECT_NEAR(s[0], -h + 2 * h * a, 1e-14);
      EXPECT_NEAR(s[1], l[0] + (r[0] - l[0]) * b, 1e-14);
      EXPECT_NEAR(s[2], l[1] + (r[1] - l[1]) * b, 1e-14);
    }
}

// The footprint is a bottom_width square at z = 0, the top edge a top_width square whose
// front and back are at height -+ tilt / 2 before the warp; the sides rise monotonically.
TEST(Key, DimensionsFollowTheParameters) {
  const Model& m = find_model("key");
  for (const ParameterValues& overrides :
       {ParameterValues{}, ParameterValues{{"bottom_width", 2.0}, {"top_width", 1.2}, {"height", 1.5}, {"tilt", -0.3}}}) {
    const ParameterValues p = resolve_parameters(m, overrides);
    const double bw = p.at("bottom_width"), tw = p.at("top_width"), h = p.at("height"), tilt = p.at("tilt");
    Eval s(key_unwarped(p)), key(m.build(p));
    double lo[2] = {1e9, 1e9}, hi[2] = {-1e9, -1e9}, top_lo[3] = {1e9, 1e9, 1e9}, top_hi[3] = {-1e9, -1e9, -1e9};
    for (int i = 0; i <= 400; ++i) {
      const double u = i / 400.0;
      const auto b = s({u, 0.0}), t = s({u, 1.0});
      EXPECT_EQ(b[2], 0.0);
      for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], b[k]), hi[k] = std::max(hi[k], b[k]);
      for (int k = 0; k < 3; ++k) top_lo[k] = std::min(top_lo[k], t[k]), top_hi[k] = std::max(top_hi[k], t[k]);
      // The top edge is planar: z = height + tilt y / top_width.
      EXPECT_NEAR(t[2], h + tilt * t[1] / tw, 1e-12);
      // Every section is above the previous one (the sides do not fold), warped too.
      double z_prev = -1.0;
      for (int j = 0; j <= 50; ++j) {
        const double z = key({u, j / 50.0})[2];
        EXPECT_GT(z, z_prev) << u << ", " << j;
        z_prev = z;
      }
    }
    for (int k = 0; k < 2; ++k) {
      EXPECT_NEAR(lo[k], -bw / 2, 1e-12);
      EXPECT_NEAR(hi[k], bw / 2, 1e-12);
      EXPECT_NEAR(top_lo[k], -tw / 2, 1e-12);
      EXPECT_NEAR(top_hi[k], tw / 2, 1e-12);
    }
    EXPECT_NEAR(top_lo[2], h - std::abs(tilt) / 2, 1e-12);
    EXPECT_NEAR(top_hi[2], h + std::abs(tilt) / 2, 1e-12);
  }
}

// The top cap is the parabolic warp of the plane of the top edge: z = height + tilt y /
// top_width + warp_scale x^2 + warp_offset, concave (dished) for warp_scale > 0: its middle
// is warp_scale (top_width / 2)^2 below its left and right edges, and its normal points up.
TEST(Key, TopIsDishedByTheWarp) {
  const Model& m = find_model("key");
  for (double a : {0.2, 0.5, 0.0}) {
    const ParameterValues p = resolve_parameters(m, {{"warp_scale", a}});
    const double tw = p.at("top_width"), h = p.at("height"), tilt = p.at("tilt"), b = p.at("warp_offset");
    const std::vector<ModelPatch> caps = key_caps(p);
    ASSERT_EQ(caps.size(), 2u);
    const Fn top = caps[0].surface;
    Eval t(top), normal(cross(derivative(top, 0), derivative(top, 1)));
    double min_x = 1e9, max_x = -1e9;
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; j <= 40; ++j) {
        const double s = i / 40.0, r = j / 40.0;
        const auto q = t({s, r});
        EXPECT_NEAR(q[2], h + tilt * q[1] / tw + a * q[0] * q[0] + b, 1e-12) << s << ", " << r;
        EXPECT_LE(std::abs(q[0]), tw / 2 + 1e-12);
        EXPECT_LE(std::abs(q[1]), tw / 2 + 1e-12);
        min_x = std::min(min_x, q[0]), max_x = std::max(max_x, q[0]);
        if (i > 0 && i < 40 && j > 0 && j < 40) {
          EXPECT_GT(normal({s, r})[2], 0.0) << s << ", " << r;  // no fold, facing up
        }
      }
    EXPECT_NEAR(min_x, -tw / 2, 1e-12);
    EXPECT_NEAR(max_x, tw / 2, 1e-12);
    // The middle against the left and right edges of the top edge at y = 0 (u = 0 and 1/2
    // are the middles of the cross section's right and left sides).
    Eval key(m.build(p));
    const auto right = key({0.0, 1.0}), left = key({0.5, 1.0});
    const double middle = h + b;
    EXPECT_NEAR(right[2] - middle, a * tw * tw / 4, 1e-12);
    EXPECT_NEAR(left[2] - middle, a * tw * tw / 4, 1e-12);
  }
}

// The caps' edges are the sides' top and bottom edges (point for point, both ways), and the
// three patches enclose a volume: the divergence theorem's x, y and z volumes agree.
TEST(Key, CapsCloseTheSides) {
  const Model& m = find_model("key");
  const ParameterValues p = resolve_parameters(m);
  const Fn sides = m.build(p);
  const std::vector<ModelPatch> caps = key_caps(p);
  Eval s(sides), top(caps[0].surface), bottom(caps[1].surface);
  for (auto [cap, v] : {std::pair<Eval*, double>{&top, 1.0}, std::pair<Eval*, double>{&bottom, 0.0}}) {
    const SpaceCurve edge = [&s, v = v](double u) { return s({u, v}); };
    const std::vector<SpaceCurve> cap_edges = patch_edges(*cap);
    for (const SpaceCurve& e : cap_edges)
      for (int i = 0; i <= 20; ++i) EXPECT_LT(distance_to_curve(edge, e(i / 20.0)), 1e-9) << v << ", " << i;
    for (int i = 0; i <= 40; ++i) {
      const auto q = edge(i / 40.0);
      double d = 1e9;
      for (const SpaceCurve& e : cap_edges) d = std::min(d, distance_to_curve(e, q));
      EXPECT_LT(d, 1e-9) << v << ", " << i;
    }
  }
  const auto vol = flux_volumes({{sides}, {caps[0].surface}, {caps[1].surface}}, 300);
  EXPECT_GT(vol[2], 0.5);
  EXPECT_NEAR(vol[0], vol[2], 1e-3 * vol[2]);
  EXPECT_NEAR(vol[1], vol[2], 1e-3 * vol[2]);
  // Without the top the z volume is not the enclosed one.
  const auto open = flux_volumes({{sides}, {caps[1].surface}}, 300);
  EXPECT_GT(std::abs(open[2] - open[0]), 0.1 * vol[2]);
}

TEST(Key, ParametersAreValidated) {
  const Model& m = find_model("key");
  for (const auto& [name, value] : std::vector<std::pair<std::string, double>>{
           {"corner_radius", 0.0}, {"corner_radius", 1.0}, {"bottom_width", -1.0}, {"top_width", 0.0},
           {"height", 0.0}, {"tilt", 0.7}, {"tilt", -0.8}}) {
    const std::string msg = error_of([&] { build_model(m, {{name, value}}); });
    EXPECT_NE(msg.find("'" + name + "'"), std::string::npos) << name << ": " << msg;
  }
  // A warp that would push the top below the bottom folds the sides.
  std::string msg = error_of([&] { build_model(m, {{"warp_offset", -0.7}}); });
  EXPECT_NE(msg.find("warp_offset"), std::string::npos) << msg;
  EXPECT_NO_THROW(build_model(m, {{"warp_offset", -0.5}}));
  // So does a strong warp on a strongly tapered key: x^2 shrinks faster toward the top than
  // warp_scale v grows (z_v gains warp_scale (x^2 + 2 v x x_v) < 0 at the top's sides); the
  // same warp on the default taper is fine.
  msg = error_of([&] { build_model(m, {{"bottom_width", 2.0}, {"top_width", 1.2}, {"warp_scale", 5.0}}); });
  EXPECT_NE(msg.find("warp_scale"), std::string::npos) << msg;
  EXPECT_NO_THROW(build_model(m, {{"warp_scale", 5.0}}));
}

}  // namespace
}  // namespace genmod::models
