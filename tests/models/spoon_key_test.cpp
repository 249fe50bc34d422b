// The spoon and the key (research/snyder.md 7.15-7.16): the spoon's sections are closed
// offsets of arcs between (+-shape_y, 0) with sagitta bowl_y and thickness 2 thick_y; the
// key is its unwarped sides plus exactly warp_scale v x^2 + warp_offset v in z (the key's
// shape: key_test.cpp).
#include "genmod/models/gallery.hpp"

#include "models/model_testing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace genmod::models {
namespace {

using namespace testing;  // the shared helpers of models/model_testing.hpp

const std::vector<double> kV{0.0, 0.07, 0.2, 0.33, 0.5, 0.61, 0.75, 0.88, 0.96, 1.0};

TEST(Spoon, EverySectionIsClosed) {
  const Fn s = build_model(find_model("spoon"));
  for (double v : kV) {
    const auto a = at(s, 0.0, v), b = at(s, 1.0, v);
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(a[j], b[j], 1e-12) << "v " << v;
    // The quarters join: the offset sides meet their end caps.
    for (double u : {0.25, 0.5, 0.75}) {
      const auto l = at(s, u - 1e-9, v), r = at(s, u + 1e-9, v);
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(l[j], r[j], 1e-7) << "u " << u << " v " << v;
    }
  }
}

// The mid-surface arc runs from (-shape_y, 0) to (shape_y, 0) (lifted by bend_y), at
// x = shape_x, with its middle bowl_y above the chord (negative: the bowl sags).
TEST(Spoon, ArcEndsAreAtTheHalfWidthAndTheMiddleAtTheBowlDepth) {
  for (double bowl_scale : {1.0, 0.0, 2.0}) {
    const ParameterValues p = resolve_parameters(find_model("spoon"), {{"bowl_scale", bowl_scale}});
    const Fn mid = spoon_mid_surface(p);
    const Curve shape = gallery_curve("spoon_shape"), bend = gallery_curve("spoon_bend"),
                bowl = gallery_curve("spoon_bowl");
    for (double v : kV) {
      const auto sh = at(shape, v), be = at(bend, v), bo = at(bowl, v);
      const auto a = at(mid, 0.0, v), b = at(mid, 1.0, v), c = at(mid, 0.5, v);
      EXPECT_NEAR(a[0], sh[0], 1e-14);
      EXPECT_NEAR(a[1], -sh[1], 1e-14) << v;
      EXPECT_NEAR(b[1], sh[1], 1e-14) << v;
      EXPECT_NEAR(a[2], be[1], 1e-14) << v;
      EXPECT_NEAR(b[2], be[1], 1e-14) << v;
      EXPECT_NEAR(c[1], 0.0, 1e-14) << v;
      EXPECT_NEAR(c[2] - be[1], bowl_scale * bo[1], 1e-14) << v;
      if (bowl_scale > 0) {
        EXPECT_LT(c[2], a[2]) << "the bowl sags below its rim at v " << v;
      }
    }
  }
}

// Offset(-r) forward is u in [0, 1/4] and offset(+r) backward [1/2, 3/4] (operators/offset.hpp),
// so u = 1/8 and 5/8 are the two sides at the arc's middle: 2 thick_y apart, centred on it.
TEST(Spoon, ThicknessIsTwiceTheHalfThickness) {
  for (double scale : {1.0, 2.5}) {
    const ParameterValues p = resolve_parameters(find_model("spoon"), {{"thickness_scale", scale}});
    const Fn s = find_model("spoon").build(p), mid = spoon_mid_surface(p), thick = spoon_half_thickness(p);
    const Curve thick_curve = gallery_curve("spoon_thick");
    for (double v : kV) {
      const auto a = at(s, 0.125, v), b = at(s, 0.625, v), c = at(mid, 0.5, v);
      const double t = at(thick, 0.0, v)[0];
      EXPECT_NEAR(t, scale * at(thick_curve, v)[1], 1e-15);
      EXPECT_NEAR(a[0], b[0], 1e-15);
      EXPECT_NEAR(std::hypot(a[1] - b[1], a[2] - b[2]), 2.0 * t, 1e-13) << v;
      EXPECT_NEAR((a[1] + b[1]) / 2, c[1], 1e-13) << v;
      EXPECT_NEAR((a[2] + b[2]) / 2, c[2], 1e-13) << v;
      // Everywhere on the section (off the caps' joints) the spoon is within thick of the arc's
      // circle; on the sides exactly: |(y, z) - centre| = R -+ thick. Checked at the caps'
      // middles: thick from the arc ends.
      const auto e0 = at(mid, 0.0, v), e1 = at(mid, 1.0, v);
      const auto cap1 = at(s, 0.375, v), cap0 = at(s, 0.875, v);
      EXPECT_NEAR(std::hypot(cap1[1] - e1[1], cap1[2] - e1[2]), t, 1e-13) << v;
      EXPECT_NEAR(std::hypot(cap0[1] - e0[1], cap0[2] - e0[2]), t, 1e-13) << v;
    }
  }
}

// The defaults and the extremes of the parameters: the deepest bowl with the thickest spoon
// (whose tip's end circles nearly touch), and a flat section.
const std::vector<ParameterValues> kCapParameters{
    {}, {{"bowl_scale", 2.0}, {"thickness_scale", 3.0}}, {{"bowl_scale", 0.0}}};

// The end faces (the model's extra patches) close the sweep: each face's four edges are the
// four quarters of its end section, point for point at linearly mapped parameters (so the
// mesher glues them), and the face is planar at x = shape_x(end).
TEST(Spoon, EndFacesHaveTheEndSectionsAsEdges) {
  for (const ParameterValues& overrides : kCapParameters) {
    const ParameterValues p = resolve_parameters(find_model("spoon"), overrides);
    Eval sweep(find_model("spoon").build(p));
    const std::vector<ModelPatch> caps = spoon_caps(p);
    ASSERT_EQ(caps.size(), 2u);
    for (int end = 0; end < 2; ++end) {
      Eval face(caps[end].surface);
      // The handle's face has s and t swapped (its normal points the other way).
      auto F = [&](double s, double t) { return end == 0 ? face({t, s}) : face({s, t}); };
      const double v = end;
      const double x_end = at(gallery_curve("spoon_shape"), v)[0];
      for (int i = 0; i <= 64; ++i) {
        const double a = i / 64.0;
        const std::vector<std::pair<std::vector<double>, std::vector<double>>> pairs{
            {F(a, 0.0), sweep({a / 4, v})}, {F(1.0, a), sweep({(1 + a) / 4, v})},
            {F(a, 1.0), sweep({(3 - a) / 4, v})}, {F(0.0, a), sweep({1 - a / 4, v})}};
        for (const auto& [on_face, on_sweep] : pairs)
          for (int j = 0; j < 3; ++j) EXPECT_NEAR(on_face[j], on_sweep[j], 1e-14) << "end " << end << " a " << a;
        for (double b : {0.1, 0.5, 0.77}) EXPECT_EQ(F(a, b)[0], x_end);
      }
    }
  }
}

// Each face is one-to-one and points out of the spoon: on a dense grid of its inside,
// F_s x F_t (in the face's own (s, t) before the handle's swap) has x component > 0, and the
// patch as given (the handle's swapped) points along -x at the handle's end and +x at the tip,
// the directions away from the spoon (it runs along +x). A positive Jacobian determinant
// inside, with the section as its boundary, makes the face a one-to-one cover of the section.
TEST(Spoon, EndFacesAreOneToOneAndOutward) {
  for (const ParameterValues& overrides : kCapParameters) {
    const ParameterValues p = resolve_parameters(find_model("spoon"), overrides);
    const std::vector<ModelPatch> caps = spoon_caps(p);
    for (int end = 0; end < 2; ++end) {
      const Fn& f = caps[end].surface;
      Eval fu(derivative(f, 0)), fv(derivative(f, 1));
      const double outward = end == 0 ? -1.0 : 1.0;
      constexpr int kN = 120;
      double smallest = 1e300;
      for (int i = 0; i < kN; ++i)
        for (int j = 0; j < kN; ++j) {
          const double a = (i + 0.5) / kN, b = (j + 0.5) / kN;
          const auto du = fu({a, b}), dv = fv({a, b});
          EXPECT_EQ(du[0], 0.0);
          EXPECT_EQ(dv[0], 0.0);
          smallest = std::min(smallest, outward * (du[1] * dv[2] - du[2] * dv[1]));
        }
      EXPECT_GT(smallest, 0.0) << "end " << end;
    }
  }
}

// The sweep and its two end faces bound one solid, oriented outward: the divergence
// theorem's three volumes agree (about 0.00599; the end faces carry the x flux that the
// open sweep misses, 0.00098, all of it through the tip's face at x = 1.62) and are positive.
TEST(Spoon, SweepAndEndFacesBoundAnOutwardSolid) {
  const ParameterValues p = resolve_parameters(find_model("spoon"));
  const std::vector<ModelPatch> caps = spoon_caps(p);
  const auto open = flux_volumes({{find_model("spoon").build(p)}}, 160);
  const auto faces = flux_volumes({{caps[0].surface}, {caps[1].surface}}, 160);
  std::array<double, 3> vol{};
  for (int k = 0; k < 3; ++k) vol[k] = open[k] + faces[k];
  EXPECT_GT(vol[2], 0.0);
  EXPECT_NEAR(vol[0], vol[2], 2e-3 * vol[2]);
  EXPECT_NEAR(vol[1], vol[2], 2e-3 * vol[2]);
  EXPECT_GT(std::abs(open[0] - open[2]), 0.1 * vol[2]) << "the end faces carry x flux";
}

TEST(Spoon, ParametersAreValidated) {
  const Model& m = find_model("spoon");
  EXPECT_NE(error_of([&] { build_model(m, {{"bowl_scale", -1.0}}); }).find("bowl_scale"), std::string::npos);
  EXPECT_NE(error_of([&] { build_model(m, {{"thickness_scale", 0.0}}); }).find("thickness_scale"), std::string::npos);
  EXPECT_NE(error_of([&] { build_model(m, {{"thickness_scale", 9.0}}); }).find("thickness_scale"), std::string::npos);
}

// 7.16: sides = warp(_sides): x and y unchanged, z + warp_scale v x^2 + warp_offset v; no warp
// at v = 0.
TEST(Key, WarpIsExactlyParabolicInXAndProportionalToV) {
  const Model& m = find_model("key");
  for (const ParameterValues& overrides :
       {ParameterValues{}, ParameterValues{{"warp_scale", 3.0}, {"warp_offset", 0.4}}}) {
    const ParameterValues p = resolve_parameters(m, overrides);
    const Fn key = m.build(p), sides = key_unwarped(p);
    const double a = p.at("warp_scale"), b = p.at("warp_offset");
    for (int i = 0; i <= 32; ++i)
      for (double v : kV) {
        const double u = i / 32.0;
        const auto k = at(key, u, v), s = at(sides, u, v);
        EXPECT_EQ(k[0], s[0]);
        EXPECT_EQ(k[1], s[1]);
        EXPECT_NEAR(k[2] - s[2], a * v * s[0] * s[0] + b * v, 1e-15) << u << ", " << v;
        if (v == 0.0) {
          EXPECT_EQ(k[2], s[2]);
        }
      }
  }
  const ParameterValues p = resolve_parameters(m);
  EXPECT_EQ(p.at("warp_scale"), 0.2);
  EXPECT_EQ(p.at("warp_offset"), -0.05);
}

}  // namespace
}  // namespace genmod::models
