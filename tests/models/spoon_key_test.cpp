// The spoon and the key (research/snyder.md 7.15-7.16): the spoon's sections are closed
// offsets of arcs between (+-shape_y, 0) with sagitta bowl_y and thickness 2 thick_y; the
// key is its unwarped sides plus exactly warp_scale v x^2 + warp_offset v in z (the key's
// shape: key_test.cpp).
#include "genmod/models/gallery.hpp"

#include "models/model_testing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
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
