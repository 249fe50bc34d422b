// Parameter limits where a model's surface starts to intersect itself (banana bend, bottle
// tangent_length): the limits follow the geometry (banana.cpp, bottle.cpp derive them), values
// beyond are rejected naming the parameter and its range, and just inside the surface has no
// self-intersecting triangles (CGAL, on a fine lattice mesh with the degenerate tips cut off).
#include "genmod/models/gallery.hpp"
#include "genmod/tessellate/mesh.hpp"
#include "genmod/tessellate/validate.hpp"

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

// Self-intersecting triangle pairs of the model's lattice mesh over v in [cut, 1 - cut].
std::size_t self_intersections(const Model& m, const ParameterValues& overrides, std::size_t n, double cut) {
  const Fn s = build_model(m, overrides);
  ParametricMeshOptions options;
  options.periodic_u = m.periodic_u;
  const Mesh mesh = mesh_parametric(s, {0, 0.0, 1.0, n}, {1, cut, 1.0 - cut, n}, options);
  const MeshValidity v = validate(mesh);
  EXPECT_TRUE(v.self_intersections_checked);
  return v.self_intersections;
}

double curve_extreme(const Curve& c, int k, double sign) {
  Eval e(c(x(0)));
  double best = -1e300;
  for (int i = 0; i <= 20000; ++i) best = std::max(best, sign * e({i / 20000.0})[static_cast<std::size_t>(k)]);
  return best;
}

// |bend| < min(pi, L / thickness), L = 2 / (max banscale max |cross_x|): the tips meet at pi,
// the inside of the bend folds at L.
TEST(Banana, BendLimitIsTheFoldOrTheTipsMeeting) {
  const Curve cross = gallery_curve("banana_cross");
  const double extent = std::max(curve_extreme(cross, 0, 1.0), curve_extreme(cross, 0, -1.0));
  const double fold = 2.0 / (curve_extreme(gallery_curve("banana_scale"), 1, 1.0) * extent);
  EXPECT_GT(fold, 6.0);
  EXPECT_LT(fold, 7.5);
  EXPECT_NEAR(banana_max_bend(1.0), std::numbers::pi, 1e-15);
  EXPECT_NEAR(banana_max_bend(4.0), fold / 4.0, 1e-5);
  const Model& m = find_model("banana");
  for (const auto& [bend, thickness] : std::vector<std::pair<double, double>>{{10.0, 1.0}, {-3.2, 1.0}, {1.8, 4.0}}) {
    const std::string msg = error_of([&] { build_model(m, {{"bend", bend}, {"thickness", thickness}}); });
    EXPECT_NE(msg.find("'bend'"), std::string::npos) << msg;
    EXPECT_NE(msg.find(std::to_string(banana_max_bend(thickness))), std::string::npos) << msg;
  }
}

TEST(Banana, JustInsideTheLimitTheSurfaceDoesNotIntersectItself) {
  const Model& m = find_model("banana");
  EXPECT_EQ(self_intersections(m, {}, 128, 0.002), 0u);
  EXPECT_EQ(self_intersections(m, {{"bend", 0.99 * std::numbers::pi}}, 160, 0.002), 0u);
  EXPECT_EQ(self_intersections(m, {{"bend", -0.99 * std::numbers::pi}}, 160, 0.002), 0u);
  EXPECT_EQ(self_intersections(m, {{"bend", 0.97 * banana_max_bend(4.0)}, {"thickness", 4.0}}, 160, 0.002), 0u);
}

// tangent_length < 3 sqrt 2 min over v of min(q, 1 - q), q the rounding schedule: the
// Hermite corners loop beyond (about 1.616 for the authored schedule).
TEST(Bottle, TangentLengthLimitIsWhereTheCornersLoop) {
  const double limit = bottle_max_tangent_length();
  EXPECT_GT(limit, 1.5);
  EXPECT_LT(limit, 1.7);
  const Model& m = find_model("bottle");
  for (double t : {2.0, limit, 1.0001 * limit}) {
    const std::string msg = error_of([&] { build_model(m, {{"tangent_length", t}}); });
    EXPECT_NE(msg.find("'tangent_length'"), std::string::npos) << msg;
    EXPECT_NE(msg.find(std::to_string(limit)), std::string::npos) << msg;
  }
  // The section at every height stays a simple closed curve just inside the limit: a point
  // of the half section on the mirror line (y = 0) only at its two ends.
  const Fn half = bottle_half_cross(resolve_parameters(m, {{"tangent_length", 0.99 * limit}}));
  Eval h(half);
  for (double v : {0.0, 0.2, 0.5, 0.8, 1.0}) {
    int sign_changes = 0;
    double prev = h({1e-6, v})[1];
    for (int i = 1; i <= 2000; ++i) {
      const double y = h({i / 2000.0 * (1 - 2e-6) + 1e-6, v})[1];
      if ((y > 0) != (prev > 0)) ++sign_changes;
      prev = y;
    }
    EXPECT_EQ(sign_changes, 0) << v;
    EXPECT_NEAR(h({0.0, v})[1], 0.0, 1e-12);
  }
}

TEST(Bottle, JustInsideTheLimitTheSurfaceDoesNotIntersectItself) {
  const Model& m = find_model("bottle");
  EXPECT_EQ(self_intersections(m, {{"tangent_length", 0.995 * bottle_max_tangent_length()}}, 200, 0.003), 0u);
}

}  // namespace
}  // namespace genmod::models
