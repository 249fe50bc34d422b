// The model gallery: every model meshes at its defaults, the thesis models keep their
// profile-product invariants (research/snyder.md 7.1-7.4), overrides change the shape, and
// bad names are reported.
#include "genmod/models/gallery.hpp"
#include "genmod/kernel/expression.hpp"

#include "models/model_testing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace genmod::models {
namespace {

using namespace testing;  // the shared helpers of models/model_testing.hpp

// S(u, v) = (g1(u) d1(v), g2(u) d1(v), d2(v)): the profile product of cross section g and
// profile d (snyder.md section 7.1), at the sample grid.
void expect_profile_product(const Fn& s, const Curve& cross, const Curve& profile) {
  for (double u : kSamples)
    for (double v : kSamples) {
      const auto S = at(s, u, v), g = at(cross, u), d = at(profile, v);
      EXPECT_NEAR(S[0], g[0] * d[0], 1e-12) << u << ", " << v;
      EXPECT_NEAR(S[1], g[1] * d[0], 1e-12) << u << ", " << v;
      EXPECT_NEAR(S[2], d[1], 1e-12) << u << ", " << v;
    }
}

TEST(Gallery, HasTheThesisAndStandardModels) {
  std::vector<std::string> names;
  for (const Model& m : gallery()) names.push_back(m.name);
  // The 23 examples of thesis Chapter 3 / Appendix B in thesis order, then standard shapes.
  const std::vector<std::string> expected{
      "doorknob", "patio_tile", "lamp_stand", "tennis_racket", "briefcase_handle", "banana", "turbine_blade",
      "gear", "sphere_cylinder_fillet", "cross_section_matching", "offsets", "offset_plate", "spoon", "key",
      "cpg", "screwdriver_regular", "screwdriver_phillips", "cpg_fillet", "bottle", "circular_beam",
      "time_varying_curve", "wing", "furry_bear", "sphere", "torus"};
  EXPECT_EQ(names, expected);
  for (const Model& m : gallery()) {
    EXPECT_FALSE(m.description.empty()) << m.name;
    EXPECT_FALSE(m.parameters.empty()) << m.name;
    for (const ModelParameter& p : m.parameters) EXPECT_FALSE(p.doc.empty()) << m.name << "." << p.name;
  }
}

TEST(Gallery, EveryModelMeshesAtItsDefaults) {
  constexpr std::size_t n = 24;
  for (const Model& m : gallery()) {
    SCOPED_TRACE(m.name);
    const Fn s = build_model(m);
    ASSERT_EQ(s.dim(), 3u);
    const Mesh mesh = mesh_model(m, s, n);
    if (m.solid) {  // six boundary patches
      EXPECT_EQ(mesh.vertices.size(), 6 * n * n);
      EXPECT_EQ(mesh.triangles.size(), 6 * 2 * (n - 1) * (n - 1));
    } else {
      EXPECT_EQ(mesh.vertices.size(), n * n);
      const std::size_t quads_u = m.periodic_u ? n : n - 1, quads_v = m.periodic_v ? n : n - 1;
      EXPECT_EQ(mesh.triangles.size(), 2 * quads_u * quads_v);
    }
    for (const auto& p : mesh.vertices)
      for (double c : p) ASSERT_TRUE(std::isfinite(c));
  }
}

// Claim 28 / section 7.2: sqrt(S1^2 + S2^2) = delta1(v) for every u, S3 = delta2(v).
TEST(Doorknob, IsASurfaceOfRevolutionOfItsProfile) {
  const Model& m = find_model("doorknob");
  const ParameterValues p = resolve_parameters(m);
  const Fn s = m.build(p);
  const Curve profile = doorknob_profile(p);
  for (double u : kSamples)
    for (double v : kSamples) {
      const auto S = at(s, u, v);
      const auto d = at(profile, v);
      EXPECT_NEAR(std::hypot(S[0], S[1]), std::abs(d[0]), 1e-12) << u << "," << v;
      EXPECT_NEAR(S[2], d[1], 1e-12) << u << "," << v;
    }
  // The authored profile: closed on the axis at both ends, neck narrower than the bulge.
  EXPECT_NEAR(at(profile, 0.0)[0], 0.0, 1e-15);
  EXPECT_NEAR(at(profile, 1.0)[0], 0.0, 1e-15);
  EXPECT_NEAR(at(profile, 0.0)[1], -1.0, 1e-15);
  EXPECT_NEAR(at(profile, 1.0)[1], 1.0, 1e-15);
}

// Section 7.3: the profile product of two polylines is a polyhedron: S = (g1 d1, g2 d1, d2),
// and every patch between polyline vertices is planar.
TEST(PatioTile, IsAPolyhedralProfileProduct) {
  const Model& m = find_model("patio_tile");
  const ParameterValues p = resolve_parameters(m);
  const Fn s = m.build(p);
  const Curve cross = patio_tile_cross(p), profile = patio_tile_profile(p);
  expect_profile_product(s, cross, profile);
  // Planarity: within each (cross edge) x (profile segment) patch, a fifth interior point lies
  // on the plane of three corners.
  const int sides = 8, segments = 5;
  for (int i = 0; i < sides; ++i)
    for (int j = 0; j < segments; ++j) {
      const double u0 = double(i) / sides, u1 = double(i + 1) / sides;
      const double v0 = double(j) / segments, v1 = double(j + 1) / segments;
      const auto a = at(s, u0, v0), b = at(s, u1, v0), c = at(s, u0, v1);
      const auto q = at(s, u0 + 0.3 * (u1 - u0), v0 + 0.7 * (v1 - v0));
      const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
      const double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
      const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
      const double nn = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (nn < 1e-12) continue;  // degenerate patch (the center fans: d1 = 0 at one edge)
      const double dist = (n[0] * (q[0] - a[0]) + n[1] * (q[1] - a[1]) + n[2] * (q[2] - a[2])) / nn;
      EXPECT_NEAR(dist, 0.0, 1e-12) << "patch " << i << "," << j;
    }
}

// Section 7.4: profile product with a star-shaped cross section (polar angle strictly
// increasing around the curve: the sweep does not self-intersect), closed in u.
TEST(LampStand, IsAProfileProductOfAStarShapedClosedCross) {
  const Model& m = find_model("lamp_stand");
  const ParameterValues p = resolve_parameters(m);
  const Fn s = m.build(p);
  const Curve cross = lamp_stand_cross(p), profile = lamp_stand_profile(p);
  expect_profile_product(s, cross, profile);
  const auto g0 = at(cross, 0.0), g1 = at(cross, 1.0);
  EXPECT_NEAR(g0[0], g1[0], 1e-12);
  EXPECT_NEAR(g0[1], g1[1], 1e-12);
  double previous = std::atan2(g0[1], g0[0]), turned = 0.0;
  for (int k = 1; k <= 400; ++k) {
    const auto g = at(cross, k / 400.0);
    double step = std::atan2(g[1], g[0]) - previous;
    if (step < -std::numbers::pi) step += 2 * std::numbers::pi;
    EXPECT_GT(step, 0.0) << "at t = " << k / 400.0;
    turned += step;
    previous = std::atan2(g[1], g[0]);
  }
  EXPECT_NEAR(turned, 2 * std::numbers::pi, 1e-9);
  // Profile: base wider than the stem, top flare wider than the stem.
  EXPECT_GT(p.at("base_radius"), p.at("stem_radius"));
  EXPECT_NEAR(at(profile, 0.5)[0], p.at("stem_radius"), 1e-12);
}

// Each build applies new curve operators; they used to live forever, so about the 33,000th
// build of the patio tile threw "too many custom operators" for the rest of the process. Now
// what a dropped model held is reclaimed.
TEST(Gallery, BuildingAModelSeventyThousandTimesLeavesNothingBehind) {
  const std::size_t nodes = live_nodes(), ops = live_custom_operators();
  const Model& tile = find_model("patio_tile");
  for (int i = 0; i < 70000; ++i) {
    const Fn f = build_model(tile);
    ASSERT_EQ(f.dim(), 3u);
  }
  EXPECT_EQ(live_nodes(), nodes);
  EXPECT_EQ(live_custom_operators(), ops);
}

TEST(Gallery, OverridesChangeTheShape) {
  {
    const Model& m = find_model("doorknob");
    const auto a = at(build_model(m), 0.0, 0.75), b = at(build_model(m, {{"bulge_radius", 1.2}}), 0.0, 0.75);
    EXPECT_NEAR(b[0] / a[0], 1.5, 1e-12);  // bulge control point scales with bulge_radius
  }
  {
    const Model& m = find_model("patio_tile");
    const ParameterValues p = resolve_parameters(m, {{"sides", 6.0}});
    EXPECT_EQ(patio_tile_cross(p).control_points().size(), 7u);
    const auto top = at(build_model(m, {{"thickness", 1.0}}), 0.3, 1.0);
    EXPECT_NEAR(top[2], 0.5, 1e-15);
  }
  {
    const Model& m = find_model("lamp_stand");
    const auto circle = at(lamp_stand_cross(resolve_parameters(m, {{"lobe_depth", 0.0}})), 0.2);
    EXPECT_NEAR(std::hypot(circle[0], circle[1]), 1.0, 1e-2);
    const auto h = at(build_model(m, {{"height", 3.0}}), 0.1, 1.0);
    EXPECT_NEAR(h[2], 3.0, 1e-12);
  }
  {
    const auto s = at(build_model(find_model("sphere"), {{"radius", 2.5}}), 0.3, 0.6);
    EXPECT_NEAR(std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]), 2.5, 1e-12);
  }
}

// The compiled-in curve files parse, and a missing one is named.
TEST(Gallery, CurveFilesParse) {
  const std::vector<std::string> names = gallery_curve_names();
  EXPECT_FALSE(names.empty());
  for (const std::string& name : names) EXPECT_GE(gallery_curve(name).dimension(), 1) << name;
  const std::string msg = error_of([] { gallery_curve("no_such_curve"); });
  EXPECT_NE(msg.find("no_such_curve"), std::string::npos) << msg;
}

TEST(Gallery, UnknownModelNamesItAndListsKnownOnes) {
  const std::string msg = error_of([] { find_model("teapot"); });
  EXPECT_NE(msg.find("teapot"), std::string::npos) << msg;
  for (const Model& m : gallery()) EXPECT_NE(msg.find(m.name), std::string::npos) << msg;
}

TEST(Gallery, BadParametersAreNamed) {
  const Model& m = find_model("torus");
  std::string msg = error_of([&] { build_model(m, {{"radius", 1.0}}); });
  EXPECT_NE(msg.find("'radius'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("torus"), std::string::npos) << msg;
  EXPECT_NE(msg.find("major_radius"), std::string::npos) << msg;
  msg = error_of([&] { build_model(m, {{"minor_radius", -1.0}}); });
  EXPECT_NE(msg.find("minor_radius"), std::string::npos) << msg;
  msg = error_of([] { build_model(find_model("patio_tile"), {{"sides", 2.5}}); });
  EXPECT_NE(msg.find("sides"), std::string::npos) << msg;
  msg = error_of([] { build_model(find_model("doorknob"), {{"height", std::nan("")}}); });
  EXPECT_NE(msg.find("height"), std::string::npos) << msg;
}

}  // namespace
}  // namespace genmod::models
