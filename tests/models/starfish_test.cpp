// Bloomenthal's starfish joint (models/starfish.hpp): the claims 12-17 of
// research/bloomenthal.md §11 and a valid closed mesh of the combination surface.
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/models/implicit_gallery.hpp"
#include "genmod/models/starfish.hpp"
#include "genmod/tessellate/validate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

namespace genmod::models {
namespace {

const int kXyz[3] = {0, 1, 2};

struct Field {
  explicit Field(const Fn& f) : tape(f, kXyz) {}
  double operator()(double x, double y, double z) const {
    const double p[3] = {x, y, z};
    return PointEvaluator().eval(tape, p)[0];
  }
  Tape tape;
};

// The crossing D = 1/2 along p(t) = o + t dir, t in [lo, hi], D(lo) > 1/2 > D(hi).
double crossing(const Field& d, const Point3& o, const Point3& dir, double lo, double hi) {
  auto at = [&](double t) { return d(o[0] + t * dir[0], o[1] + t * dir[1], o[2] + t * dir[2]); };
  EXPECT_GT(at(lo), 0.5);
  EXPECT_LT(at(hi), 0.5);
  for (int i = 0; i < 100; ++i) {
    const double m = (lo + hi) / 2;
    (at(m) > 0.5 ? lo : hi) = m;
  }
  return (lo + hi) / 2;
}

Point3 unit(const Point3& v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / n, v[1] / n, v[2] / n};
}

TEST(BloomenthalClaims, Claim12StarfishUnionEndpoints) {
  const std::vector<StarfishLimb> limbs = starfish_limbs();
  ASSERT_EQ(limbs.size(), 5u);
  EXPECT_NEAR(limbs[0].union1[0], -0.407802, 1e-6);
  EXPECT_NEAR(limbs[0].union1[1], -0.171277, 1e-6);
  EXPECT_EQ(limbs[0].union1[2], 0);
  EXPECT_EQ(limbs[0].union2, limbs[0].e2);  // internal end unchanged
  for (std::size_t i = 1; i < 5; ++i) {
    const StarfishLimb& l = limbs[i];
    EXPECT_EQ(l.union1, l.e1);
    const Point3 u = unit({l.e2[0] - l.e1[0], l.e2[1] - l.e1[1], l.e2[2] - l.e1[2]});
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(l.union2[k], l.e2[k] - 0.1 * u[k], 1e-15);
  }
  for (const StarfishLimb& l : limbs)
    for (const Point3* n : {&l.n1, &l.n2}) {
      EXPECT_NEAR(std::abs((*n)[2]), 1, 1e-15);
      EXPECT_EQ((*n)[0], 0);
      EXPECT_EQ((*n)[1], 0);
    }
  EXPECT_NEAR(limbs[3].union2[0], 0.60385, 1e-5);  // the spec's table, child C
  EXPECT_NEAR(limbs[3].union2[1], -0.17253, 1e-5);
}

TEST(BloomenthalClaims, Claim13StarfishHeights) {
  const StarfishFields f = starfish_fields();
  const double conv = crossing(Field(f.convolution), {0, 0, 0}, {0, 0, 1}, 0, 0.3);
  const double uni = crossing(Field(f.union_density), {0, 0, 0}, {0, 0, 1}, 0, 0.3);
  const double comb = crossing(Field(f.combination), {0, 0, 0}, {0, 0, 1}, 0, 0.3);
  EXPECT_NEAR(conv, 0.1524, 0.001);
  EXPECT_NEAR(uni, 0.1000, 1e-6);
  EXPECT_NEAR(comb, 0.1026, 0.002);
  EXPECT_LT(comb, 0.105);
  std::printf("starfish heights above the joint: convolution %.5f union %.5f combination %.5f\n", conv, uni, comb);
}

TEST(BloomenthalClaims, Claim14StarfishWebbingKeepsTheFillet) {
  const StarfishFields f = starfish_fields();
  const Point3 a = unit({.06, .6, 0}), b = unit({.6, .4, 0});
  const Point3 dir = unit({a[0] + b[0], a[1] + b[1], 0});
  const double conv = crossing(Field(f.convolution), {0, 0, 0}, dir, 0, 0.6);
  const double uni = crossing(Field(f.union_density), {0, 0, 0}, dir, 0, 0.6);
  const double comb = crossing(Field(f.combination), {0, 0, 0}, dir, 0, 0.6);
  EXPECT_NEAR(conv, 0.3311, 0.001);
  EXPECT_NEAR(comb, 0.3311, 0.001);
  EXPECT_NEAR(uni, 0.2340, 0.001);
  std::printf("starfish webbing extent: convolution %.5f union %.5f combination %.5f\n", conv, uni, comb);
}

TEST(BloomenthalClaims, Claim15StarfishFreeEndsAgree) {
  const StarfishFields f = starfish_fields();
  const Field conv(f.convolution), uni(f.union_density), comb(f.combination);
  const std::vector<StarfishLimb> limbs = starfish_limbs();
  std::vector<std::pair<Point3, Point3>> ends;  // (end, outward axis direction)
  ends.push_back({limbs[0].e1, unit({limbs[0].e1[0] - limbs[0].e2[0], limbs[0].e1[1] - limbs[0].e2[1], 0})});
  for (std::size_t i = 1; i < 5; ++i) ends.push_back({limbs[i].e2, unit({limbs[i].e2[0], limbs[i].e2[1], 0})});
  for (const auto& [end, dir] : ends) {
    EXPECT_LT(std::abs(crossing(uni, end, dir, -0.05, 0.05)), 1e-12);
    EXPECT_LT(std::abs(crossing(conv, end, dir, -0.05, 0.05)), 1e-4);
    EXPECT_LT(std::abs(crossing(comb, end, dir, -0.05, 0.05)), 1e-4);
  }
}

TEST(BloomenthalClaims, Claim16StarfishConvexCombinationBound) {
  const StarfishFields f = starfish_fields();
  const Field conv(f.convolution), uni(f.union_density), comb(f.combination);
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> ux(-0.65, 0.85), uy(-0.55, 0.75), uz(-0.3, 0.3);
  for (int i = 0; i < 10000; ++i) {
    const double x = ux(rng), y = uy(rng), z = uz(rng);
    const double c = conv(x, y, z), u = uni(x, y, z), j = comb(x, y, z);
    ASSERT_LE(std::min(c, u) - 1e-12, j);
    ASSERT_LE(j, std::max(c, u) + 1e-12);
  }
  // the operator's inclusion is the hull bound: random boxes contain the sampled values
  const Tape t(f.combination, kXyz);
  IntervalEvaluator iv;
  std::uniform_real_distribution<double> w(0, 1);
  for (int b = 0; b < 300; ++b) {
    const double s = 0.2 * std::pow(w(rng), 2), lo[3] = {ux(rng), uy(rng), uz(rng)};
    const std::vector<Interval> box = {Interval(lo[0], lo[0] + s), Interval(lo[1], lo[1] + s), Interval(lo[2], lo[2] + s)};
    const Interval y = iv.eval(t, box)[0];
    EXPECT_EQ(iv.errors()[0], 0);
    for (int k = 0; k < 10; ++k) {
      const double v = comb(lo[0] + w(rng) * s, lo[1] + w(rng) * s, lo[2] + w(rng) * s);
      ASSERT_TRUE(y.contains(v)) << v << " outside " << y;
    }
  }
}

TEST(BloomenthalClaims, Claim17StarfishConvexityRange) {
  const StarfishFields f = starfish_fields();
  const Field cx(f.convexity);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> ux(-0.6, 0.8), uy(-0.5, 0.7), uz(-0.25, 0.25);
  for (int i = 0; i < 2000; ++i) {
    const double v = cx(ux(rng), uy(rng), uz(rng));
    ASSERT_GE(v, 0);
    ASSERT_LE(v, 1);
  }
  // in the skeleton's plane the gradient is in-plane (perpendicular to the normal): 0
  EXPECT_NEAR(cx(0.2, 0.35, 0), 0, 1e-9);
  // above the middle of arm C the gradient is nearly parallel to the normal: about 1
  EXPECT_GT(cx(0.35, -0.1, 0.1), 0.99);
  // independent of the normal's sign
  std::vector<StarfishLimb> flipped = starfish_limbs();
  for (StarfishLimb& l : flipped) l.n1[2] = -l.n1[2], l.n2[2] = -l.n2[2];
  const Field cf(starfish_fields(flipped).convexity);
  for (int i = 0; i < 200; ++i) {
    const double x = ux(rng), y = uy(rng), z = uz(rng);
    EXPECT_EQ(cx(x, y, z), cf(x, y, z));
  }
}

TEST(Starfish, CombinationMeshIsClosedWithTheExpectedExtent) {
  const ImplicitModel* m = find_implicit_model("starfish");
  ASSERT_NE(m, nullptr);
  const ImplicitMesh mesh = mesh_implicit(build_implicit_model(*m), m->box, {.min_feature = 0.05});
  const MeshValidity v = validate(mesh.mesh);
  EXPECT_TRUE(v.valid()) << describe(v);
  EXPECT_EQ(v.components, 1u);
  EXPECT_EQ(v.euler_characteristic, 2);
  double lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9};
  for (const auto& p : mesh.mesh.vertices)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  // spec §7.1: x in [-0.51, 0.71], y in [-0.41, 0.61], |z| <~ 0.11 for the combination
  EXPECT_NEAR(lo[0], -0.51, 0.02);
  EXPECT_NEAR(hi[0], 0.71, 0.02);
  EXPECT_NEAR(lo[1], -0.41, 0.02);
  EXPECT_NEAR(hi[1], 0.61, 0.02);
  EXPECT_LT(hi[2], 0.115);
  EXPECT_GT(lo[2], -0.115);
  std::printf("starfish mesh: %zu triangles, box [%.3f %.3f] [%.3f %.3f] [%.3f %.3f]\n", mesh.mesh.triangles.size(), lo[0], hi[0],
              lo[1], hi[1], lo[2], hi[2]);
}

}  // namespace
}  // namespace genmod::models
