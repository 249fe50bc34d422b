// The sweep models of the gallery (research/snyder.md 7.5-7.10): tennis racket (wire
// product), briefcase handle (rail product), banana and turbine blade (quasi-linear), gear
// (linear interpolation of cross sections). Each keeps its defining invariant (claims 28 and
// 32), checked at sample points against the model's own curves.
#include "genmod/models/gallery.hpp"

#include "genmod/operators/sweep.hpp"
#include "genmod/operators/vector.hpp"
#include "models/model_testing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace genmod::models {
namespace {

using namespace testing;  // the shared helpers of models/model_testing.hpp

// Claim 28, wire product: (S - (wire, 0)) . (t, 0) = 0, |S_xy - wire| = |g1|, S_z = g2.
TEST(TennisRacket, CrossSectionIsPerpendicularToTheHeadWire) {
  const Model& m = find_model("tennis_racket");
  const ParameterValues p = resolve_parameters(m);
  expect_wire_product(m.build(p), tennis_racket_cross(p), curve_in(tennis_racket_wire(p), 1));
  Eval s(m.build(p)), cross(tennis_racket_cross(p)), wire(tennis_racket_wire(p));
  // Closed in both directions (a closed tube), with the section's size from the parameters.
  for (double t : kSamples) {
    const auto a = s({0.0, t}), b = s({1.0, t}), c = s({t, 0.0}), d = s({t, 1.0});
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(a[k], b[k], 1e-12);
      EXPECT_NEAR(c[k], d[k], 1e-12);
    }
  }
  EXPECT_NEAR(cross({0.0})[0], p.at("frame_width") / 2, 1e-12);   // starts at a side midpoint
  EXPECT_NEAR(cross({0.0})[1], 0.0, 1e-12);
  EXPECT_NEAR(cross({0.25})[1], p.at("frame_depth") / 2, 1e-12);
  EXPECT_NEAR(wire({0.5})[1], p.at("head_length") / 2, 1e-3);       // tip of the head
  EXPECT_NEAR(wire({0.0})[1], -p.at("head_length") / 2, 1e-3);      // throat
  EXPECT_NE(error_of([&] { build_model(m, {{"frame_width", 0.5}}); }).find("frame_width"), std::string::npos);
}

// Claim 28, rail product: g1 = -1 lands on rail1, g1 = +1 on rail2 (in xy), z = g2, and every
// point is m + g1 (rail2 - rail1) / 2.
TEST(BriefcaseHandle, CrossSectionSpansTheRails) {
  const Model& m = find_model("briefcase_handle");
  const ParameterValues p = resolve_parameters(m);
  Eval s(m.build(p)), cross(briefcase_handle_cross(p));
  Eval rail1(briefcase_handle_rail1(p)), rail2(briefcase_handle_rail2(p));
  EXPECT_NEAR(cross({0.0})[0], 1.0, 1e-15);
  EXPECT_NEAR(cross({0.5})[0], -1.0, 1e-15);
  for (double v : kSamples) {
    const auto r1 = rail1({v}), r2 = rail2({v});
    const auto on2 = s({0.0, v}), on1 = s({0.5, v});
    EXPECT_NEAR(on1[0], r1[0], 1e-12) << v;
    EXPECT_NEAR(on1[1], r1[1], 1e-12) << v;
    EXPECT_NEAR(on2[0], r2[0], 1e-12) << v;
    EXPECT_NEAR(on2[1], r2[1], 1e-12) << v;
    for (double u : kSamples) {
      const auto S = s({u, v}), g = cross({u});
      for (int k = 0; k < 2; ++k)
        EXPECT_NEAR(S[k], 0.5 * (r1[k] + r2[k]) + 0.5 * g[0] * (r2[k] - r1[k]), 1e-12) << u << ", " << v;
      EXPECT_NEAR(S[2], g[1], 1e-15) << u << ", " << v;
    }
  }
  // The grip stays within the rails (x of the cross section in [-1, 1] up to the Hermite
  // curve's tiny overshoot), and its thickness is `depth`.
  double lo = 0, hi = 0, zmax = 0;
  for (int k = 0; k <= 1000; ++k) {
    const auto g = cross({k / 1000.0});
    lo = std::min(lo, g[0]);
    hi = std::max(hi, g[0]);
    zmax = std::max(zmax, g[1]);
  }
  EXPECT_NEAR(lo, -1.0, 5e-3);
  EXPECT_NEAR(hi, 1.0, 5e-3);
  EXPECT_NEAR(2 * zmax, p.at("depth"), 5e-3);
  // Nested arches: at the top the outer rail is above the inner one.
  EXPECT_GT(rail1({0.5})[1], rail2({0.5})[1]);
}

// Claim 32: the factor written last applies first. S(u, v) = R_y(-bend v) (s g1, s g2,
// -1 + 2v) with s = thickness banscale(v); v = 0 lies in z = -1; at v = 1 the section (a
// point: the tip) is (0, 0, 1) rotated by -0.4 pi about y.
TEST(Banana, QuasiLinearOrderMatchesTheThesis) {
  const Model& m = find_model("banana");
  const ParameterValues p = resolve_parameters(m);
  EXPECT_NEAR(p.at("bend"), 0.4 * std::numbers::pi, 1e-15);
  Eval s(m.build(p));
  Eval cross(gallery_curve("banana_cross")(x(0))), schedule(gallery_curve("banana_scale")(x(0)));
  for (double v : kSamples) {
    const double theta = -p.at("bend") * v, z = -1.0 + 2.0 * v, sc = schedule({v})[1] * p.at("thickness");
    for (double u : kSamples) {
      const auto S = s({u, v}), g = cross({u});
      const double q[3] = {sc * g[0], sc * g[1], z};
      EXPECT_NEAR(S[0], std::cos(theta) * q[0] + std::sin(theta) * q[2], 1e-12) << u << ", " << v;
      EXPECT_NEAR(S[1], q[1], 1e-12) << u << ", " << v;
      EXPECT_NEAR(S[2], -std::sin(theta) * q[0] + std::cos(theta) * q[2], 1e-12) << u << ", " << v;
    }
  }
  // v = 0 in the plane z = -1; the v = 1 centroid rotated by -0.4 pi about y.
  double c[3] = {0, 0, 0};
  const int n = 64;
  for (int k = 0; k < n; ++k) {
    EXPECT_NEAR(s({k / double(n), 0.0})[2], -1.0, 1e-15);
    const auto S = s({k / double(n), 1.0});
    for (int j = 0; j < 3; ++j) c[j] += S[j] / n;
  }
  EXPECT_NEAR(c[0], std::sin(-0.4 * std::numbers::pi), 1e-12);
  EXPECT_NEAR(c[1], 0.0, 1e-12);
  EXPECT_NEAR(c[2], std::cos(-0.4 * std::numbers::pi), 1e-12);
  // Mid-way the section is a real pentagon of radius about 0.3 (the schedule's peak) in the
  // plane z = 0 turned by -0.2 pi about y.
  double rmax = 0;
  for (int k = 0; k < n; ++k) {
    const auto S = s({k / double(n), 0.5});
    // Undo the rotation by -0.2 pi: back in the plane z = 0.
    const double t = 0.2 * std::numbers::pi;
    const double x0 = std::cos(t) * S[0] + std::sin(t) * S[2], z0 = -std::sin(t) * S[0] + std::cos(t) * S[2];
    EXPECT_NEAR(z0, 0.0, 1e-12);
    rmax = std::max(rmax, std::hypot(x0, S[1]));
  }
  EXPECT_GT(rmax, 0.28);
  EXPECT_LT(rmax, 0.4);
}

// Section at v: the cross section scaled by (sx(v), sy(v)), turned by twist pi bladerot(v)
// about (pivot, 0), and lifted to z = interp(v, -span/2, span/2), written out by hand.
TEST(TurbineBlade, SectionsAreScaledTwistedAboutThePivotAndLifted) {
  const Model& m = find_model("turbine_blade");
  const ParameterValues p = resolve_parameters(m, {{"twist", 1.3}});
  Eval s(m.build(p));
  Eval cross(gallery_curve("turbine_blade_cross")(x(0))), rot(gallery_curve("turbine_blade_rotation")(x(0)));
  Eval xs(gallery_curve("turbine_blade_xscale")(x(0))), ys(gallery_curve("turbine_blade_yscale")(x(0)));
  const double pivot = p.at("pivot"), half = p.at("span") / 2;
  for (double v : kSamples) {
    const double phi = 1.3 * std::numbers::pi * rot({v})[1], sx = xs({v})[1], sy = ys({v})[1];
    for (double u : kSamples) {
      const auto S = s({u, v}), g = cross({u});
      const double a = sx * g[0] - pivot, b = sy * g[1];
      EXPECT_NEAR(S[0], pivot + std::cos(phi) * a - std::sin(phi) * b, 1e-12) << u << ", " << v;
      EXPECT_NEAR(S[1], std::sin(phi) * a + std::cos(phi) * b, 1e-12) << u << ", " << v;
      EXPECT_NEAR(S[2], -half + 2 * half * v, 1e-12) << u << ", " << v;
    }
  }
  // At the defaults the tip is twisted by 45 degrees against the root: a chord direction of
  // the tip section is the root's (scaled) turned by pi / 4.
  const Model& d = find_model("turbine_blade");
  Eval s0(build_model(d));
  const auto a0 = s0({0.0, 1.0}), b0 = s0({0.5, 1.0});
  const auto ga = cross({0.0}), gb = cross({0.5});
  const double chord_tip = std::atan2(b0[1] - a0[1], b0[0] - a0[0]);
  const double chord_root = std::atan2(ys({1.0})[1] * (gb[1] - ga[1]), xs({1.0})[1] * (gb[0] - ga[0]));
  EXPECT_NEAR(std::remainder(chord_tip - chord_root, 2 * std::numbers::pi), std::numbers::pi / 4, 1e-12);
}

// Section 7.10: interp_y = 1 is the hole circle (radius hole_radius, the gear point's polar
// angle); interp_y = 0 is the gear curve; the faces and walls follow the closed schedule.
TEST(Gear, InterpolatesTheGearTowardItsRadialProjection) {
  const Model& m = find_model("gear");
  const ParameterValues p = resolve_parameters(m);
  Eval s(m.build(p)), gear(gear_cross(p));
  const double hole = p.at("hole_radius"), thick = p.at("thickness");
  for (double u : kSamples) {
    const auto g = gear({u});
    const double angle = std::atan2(g[1], g[0]);
    for (double v : {0.25, 0.3, 0.41, 0.5}) {  // hole wall: interp_y = 1
      const auto S = s({u, v});
      EXPECT_NEAR(std::hypot(S[0], S[1]), hole, 1e-12) << u << ", " << v;
      EXPECT_NEAR(std::remainder(std::atan2(S[1], S[0]) - angle, 2 * std::numbers::pi), 0.0, 1e-12);
      EXPECT_NEAR(S[2], thick * (4 * v - 1), 1e-12);
    }
    for (double v : {0.0, 0.75, 0.8, 0.93, 1.0}) {  // outer wall: interp_y = 0, the gear curve
      const auto S = s({u, v});
      EXPECT_NEAR(S[0], g[0], 1e-12) << u << ", " << v;
      EXPECT_NEAR(S[1], g[1], 1e-12) << u << ", " << v;
    }
    for (double v : {0.1, 0.2}) {  // bottom face: z = 0, on the ray through the gear point
      const auto S = s({u, v});
      EXPECT_NEAR(S[2], 0.0, 1e-15);
      EXPECT_NEAR(std::remainder(std::atan2(S[1], S[0]) - angle, 2 * std::numbers::pi), 0.0, 1e-12);
      const double r = std::hypot(g[0], g[1]), a = 4 * v;
      EXPECT_NEAR(std::hypot(S[0], S[1]), r + a * (hole - r), 1e-12);
    }
    for (double v : {0.6, 0.7}) EXPECT_NEAR(s({u, v})[2], thick, 1e-12);  // top face
  }
  // The gear curve has `teeth` teeth (local maxima of the radius) between 0.7 and 0.8.
  for (double teeth : {12.0, 7.0}) {
    Eval g(gear_cross(resolve_parameters(m, {{"teeth", teeth}})));
    const int n = 2000;
    std::vector<double> r;
    for (int k = 0; k < n; ++k) {
      const auto q = g({k / double(n)});
      r.push_back(std::hypot(q[0], q[1]));
    }
    int maxima = 0;
    for (int k = 0; k < n; ++k)
      if (r[k] > r[(k + n - 1) % n] && r[k] >= r[(k + 1) % n]) ++maxima;
    EXPECT_EQ(maxima, static_cast<int>(teeth));
    EXPECT_NEAR(*std::max_element(r.begin(), r.end()), 0.8, 5e-3);
    EXPECT_NEAR(*std::min_element(r.begin(), r.end()), 0.7, 5e-3);
  }
  EXPECT_NE(error_of([&] { build_model(m, {{"teeth", 2.5}}); }).find("teeth"), std::string::npos);
  EXPECT_NE(error_of([&] { build_model(m, {{"tooth_depth", 0.6}}); }).find("tooth_depth"), std::string::npos);
}

}  // namespace
}  // namespace genmod::models
