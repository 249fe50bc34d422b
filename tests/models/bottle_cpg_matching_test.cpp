// Models built on the solver layer's operators: the bottle (matched schedules and warps,
// thesis App. B.3), CPG with and without fillets (Fig 3.16, 3.18) and cross-section
// matching (Fig 3.10).
#include "genmod/models/gallery.hpp"

#include "models/model_testing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace genmod::models {
namespace {

using namespace testing;  // the shared helpers of models/model_testing.hpp

// Winding number of the closed curve c (a function of x(0) on [0, 1]) around q, from a
// dense polygon: exact for points not too close to the curve.
int winding(const Fn& c, double qx, double qy, int n = 4000) {
  double turned = 0.0;
  auto angle = [&](double t) {
    const auto p = at(c, t);
    return std::atan2(p[1] - qy, p[0] - qx);
  };
  double previous = angle(0.0);
  for (int k = 1; k <= n; ++k) {
    const double a = angle(static_cast<double>(k) / n);
    double d = a - previous;
    if (d > std::numbers::pi) d -= 2 * std::numbers::pi;
    if (d < -std::numbers::pi) d += 2 * std::numbers::pi;
    turned += d;
    previous = a;
  }
  return static_cast<int>(std::lround(turned / (2 * std::numbers::pi)));
}

// Distance from q to the closed curve c, by dense sampling refined by golden sections.
double distance_to(const Fn& c, double qx, double qy, int n = 4000) {
  auto d2 = [&](double t) {
    const auto p = at(c, t);
    return (p[0] - qx) * (p[0] - qx) + (p[1] - qy) * (p[1] - qy);
  };
  int best = 0;
  double best_d = d2(0.0);
  for (int k = 1; k <= n; ++k)
    if (const double d = d2(static_cast<double>(k) / n); d < best_d) best_d = d, best = k;
  double a = std::max(0.0, (best - 1.0) / n), b = std::min(1.0, (best + 1.0) / n);
  for (int it = 0; it < 80; ++it) {
    const double m1 = a + 0.382 * (b - a), m2 = a + 0.618 * (b - a);
    (d2(m1) < d2(m2) ? b : a) = (d2(m1) < d2(m2) ? m2 : m1);
  }
  return std::sqrt(std::min(best_d, d2(0.5 * (a + b))));
}

// ---- bottle ----

TEST(Bottle, PiecesMeetAndTheSurfaceCloses) {
  const Model& m = find_model("bottle");
  const Fn s = build_model(m);
  for (double u : {0.0, 0.1, 0.3, 0.45, 0.6, 0.77, 0.9}) {
    for (double joint : {0.25, 0.5, 0.75}) {  // v joints of nozzle | shoulders | body | bottom
      const auto below = at(s, u, joint - 1e-10), above = at(s, u, joint + 1e-10);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(below[k], above[k], 1e-6) << "u " << u << " joint " << joint;
    }
    const auto a = at(s, 0.0, u), b = at(s, 1.0, u);  // closed in u
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-12);
    // The bottom closes on the axis; the nozzle opening is the ring of radius
    // nozzle_radius * 1.25 (the nozzle profile's scale at the opening).
    const auto bottom = at(s, u, 1.0), opening = at(s, u, 0.0);
    EXPECT_NEAR(std::hypot(bottom[0], bottom[1]), 0.0, 1e-12);
    EXPECT_NEAR(std::hypot(opening[0], opening[1]), 0.1 * 1.25, 1e-9) << u;
  }
}

TEST(Bottle, IsMirrorSymmetricAboutTheXzPlane) {
  const Fn s = build_model(find_model("bottle"));
  for (double u : {0.05, 0.2, 0.33, 0.49})
    for (double v : {0.1, 0.4, 0.6, 0.9}) {
      const auto a = at(s, u, v), b = at(s, 1.0 - u, v);
      EXPECT_NEAR(a[0], b[0], 1e-9);
      EXPECT_NEAR(a[1], -b[1], 1e-9);
      EXPECT_NEAR(a[2], b[2], 1e-9);
    }
}

// The body's warp: each point's height is top_y(t) + prof_y(w) - 1 where top_x(t) is the
// point's distance from the axis (m_warp), w the body's local parameter.
TEST(Bottle, BodyHeightIsTheWarpOfTheDistanceFromTheAxis) {
  const Fn s = build_model(find_model("bottle"));
  const Fn top = gallery_curve("bottle_top")(x(0)), prof = gallery_curve("bottle_prof")(x(0));
  for (double w : {0.1, 0.35, 0.6, 0.85})
    for (double u : {0.07, 0.25, 0.4}) {
      const auto p = at(s, u, 0.5 + 0.25 * w);
      const double d = std::hypot(p[0], p[1]);
      double lo = 0.0, hi = 1.0;  // top_x is increasing
      for (int it = 0; it < 100; ++it) {
        const double mid = 0.5 * (lo + hi);
        (at(top, mid)[0] < d ? lo : hi) = mid;
      }
      EXPECT_NEAR(p[2], at(top, lo)[1] + at(prof, w)[1] - 1.0, 1e-9) << u << ", " << w;
    }
}

// ---- CPG ----

TEST(Cpg, DifferenceBoundaryIsTheCircleOutsideTheBeanAndTheBeanInsideTheCircle) {
  const Model& m = find_model("cpg");
  const ParameterValues p = resolve_parameters(m);
  const Fn boundary = cpg_boundary(p), circle = cpg_circle(p), bean = cpg_bean(p);
  int on_circle = 0, on_bean = 0;
  for (int k = 0; k < 200; ++k) {
    const auto q = at(boundary, (k + 0.5) / 200.0);
    const double dc = std::abs(std::hypot(q[0], q[1]) - p.at("radius"));
    const double db = distance_to(bean, q[0], q[1]);
    ASSERT_LT(std::min(dc, db), 1e-7) << "sample " << k << " is on neither boundary";
    if (dc < 1e-7 && db > 1e-3) {
      ++on_circle;
      EXPECT_EQ(winding(bean, q[0], q[1]), 0) << "circle piece inside the bean at " << k;
    }
    if (db < 1e-7 && dc > 1e-3) {
      ++on_bean;
      EXPECT_LT(std::hypot(q[0], q[1]), p.at("radius")) << "bean piece outside the circle at " << k;
    }
  }
  EXPECT_GT(on_circle, 0);
  EXPECT_GT(on_bean, 0);
  const auto a = at(boundary, 0.0), b = at(boundary, 1.0);
  EXPECT_NEAR(a[0], b[0], 1e-9);
  EXPECT_NEAR(a[1], b[1], 1e-9);
}

TEST(Cpg, UnionAndIntersectionKeepTheRightPieces) {
  const Model& m = find_model("cpg");
  for (double op : {0.0, 1.0}) {
    const ParameterValues p = resolve_parameters(m, {{"operation", op}});
    const Fn boundary = cpg_boundary(p), bean = cpg_bean(p);
    for (int k = 0; k < 100; ++k) {
      const auto q = at(boundary, (k + 0.5) / 100.0);
      const double r = std::hypot(q[0], q[1]);
      const bool on_circle = std::abs(r - p.at("radius")) < 1e-7;
      if (on_circle && distance_to(bean, q[0], q[1]) > 1e-3) {
        EXPECT_EQ(winding(bean, q[0], q[1]), op == 0.0 ? 0 : 1) << "op " << op << " sample " << k;
      } else if (!on_circle) {
        EXPECT_EQ(r > p.at("radius"), op == 0.0) << "op " << op << " sample " << k;
      }
    }
  }
}

// The largest turn of the tangent between consecutive samples of a closed curve: a corner
// shows up as a turn that does not shrink with the sampling step.
double largest_turn(const Fn& c, int n) {
  double worst = 0.0;
  auto direction = [&](int k) {
    const auto a = at(c, static_cast<double>(k) / n), b = at(c, static_cast<double>(k + 1) / n);
    return std::atan2(b[1] - a[1], b[0] - a[0]);
  };
  for (int k = 0; k + 1 < n; ++k) {
    double d = std::abs(direction(k + 1) - direction(k));
    if (d > std::numbers::pi) d = 2 * std::numbers::pi - d;
    worst = std::max(worst, d);
  }
  return worst;
}

TEST(CpgFillet, FilletedUnionHasNoCornersAndStaysNearTheSharpOne) {
  const Model& fm = find_model("cpg_fillet");
  const ParameterValues p = resolve_parameters(fm);
  const Fn filleted = cpg_boundary(p);
  ParameterValues sharp_p = p;
  sharp_p.erase("fillet_radius");
  const Fn sharp = cpg_boundary(sharp_p);
  EXPECT_LT(largest_turn(filleted, 8000), 0.02);  // smooth: turns shrink with the step
  EXPECT_GT(largest_turn(sharp, 8000), 0.3);      // the union has two corners
  for (int k = 0; k < 100; ++k) {
    const auto q = at(filleted, (k + 0.5) / 100.0);
    EXPECT_LT(distance_to(sharp, q[0], q[1]), p.at("fillet_radius")) << k;
  }
}

// ---- cross-section matching (claim 29's remedy on authored curves) ----

TEST(CrossSectionMatching, WithoutMatchingTheSectionsCollapseWithMatchingTheyStayBetween) {
  const Model& m = find_model("cross_section_matching");
  const Fn inner = gallery_curve("matching_inner")(x(0)), outer = gallery_curve("matching_outer")(x(0));
  {
    const Fn s = build_model(m, {{"method", 0.0}});
    int inside_inner = 0;
    for (int k = 0; k < 50; ++k) {
      const auto q = at(s, (k + 0.5) / 50.0, 0.5);
      inside_inner += winding(inner, q[0], q[1]) != 0;
    }
    EXPECT_GT(inside_inner, 0) << "the mismatched sections should pass inside the inner curve";
  }
  for (double method : {1.0, 2.0}) {
    const Fn s = build_model(m, {{"method", method}});
    for (int k = 0; k < 40; ++k)
      for (double v : {0.25, 0.5, 0.75}) {
        const auto q = at(s, (k + 0.5) / 40.0, v);
        EXPECT_EQ(winding(inner, q[0], q[1], 1500), 0) << "method " << method << " u " << (k + 0.5) / 40 << " v " << v;
        EXPECT_EQ(winding(outer, q[0], q[1], 1500), 1) << "method " << method << " u " << (k + 0.5) / 40 << " v " << v;
      }
  }
}

TEST(CrossSectionMatching, MinimumDistanceMatchesEachOuterPointToItsClosestInnerPoint) {
  const ParameterValues p = resolve_parameters(find_model("cross_section_matching"), {{"method", 2.0}});
  const Fn matched = matching_inner(p);
  const Fn inner = gallery_curve("matching_inner")(x(0)), outer = gallery_curve("matching_outer")(x(0));
  for (int k = 0; k < 12; ++k) {
    const double u = (k + 0.3) / 12.0;
    const auto o = at(outer, u), q = at(matched, u);
    EXPECT_NEAR(std::hypot(q[0] - o[0], q[1] - o[1]), distance_to(inner, o[0], o[1]), 1e-6) << u;
    EXPECT_LT(distance_to(inner, q[0], q[1]), 1e-9) << "matched point off the inner curve at " << u;
  }
}

}  // namespace
}  // namespace genmod::models
