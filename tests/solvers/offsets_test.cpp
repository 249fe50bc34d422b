// s- and b-offsets by nested search (snyder.md section 5.1, claim 39).
#include "genmod/solvers/offsets.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace genmod {
namespace {

// Distance from (px, py) to the segment [(-1, 0), (1, 0)].
double segment_distance(double px, double py) {
  const double cx = std::clamp(px, -1.0, 1.0);
  return std::hypot(px - cx, py);
}

bool covered(const OffsetResult& r, double px, double py) {
  for (const OffsetBox& b : r.boxes)
    if (b.box[0].contains(px) && b.box[1].contains(py)) return true;
  return false;
}

const Fn kSegment = cat({2 * x(0) - 1, Fn(0.0)});

// Claim 39: the b-offset of a segment is the stadium boundary: two segments y = +-r and two
// semicircles. Every sampled boundary point is covered, every box lies near the boundary.
TEST(Offsets, BOffsetOfASegmentIsTheStadium) {
  const double r = 0.25;
  const Box region = {Interval(-1.5, 1.5), Interval(-0.5, 0.5)};
  OffsetOptions opt;
  opt.epsilon = 0.02;
  const OffsetResult res = b_offset(kSegment, r, region, {}, opt);
  ASSERT_EQ(res.report.limit, LimitHit::None);
  ASSERT_FALSE(res.boxes.empty());
  // Boundary samples: straight parts and the two caps.
  for (int i = 0; i <= 200; ++i) {
    const double s = -1 + 2.0 * i / 200;
    EXPECT_TRUE(covered(res, s, r)) << s;
    EXPECT_TRUE(covered(res, s, -r)) << s;
    const double a = std::numbers::pi * i / 200 - std::numbers::pi / 2;
    EXPECT_TRUE(covered(res, 1 + r * std::cos(a), r * std::sin(a))) << a;
    EXPECT_TRUE(covered(res, -1 - r * std::cos(a), r * std::sin(a))) << a;
  }
  // Every box lies within C w of the boundary (C = 3: the box itself plus the inner tolerance).
  for (const OffsetBox& b : res.boxes) {
    EXPECT_EQ(b.status, OffsetBoxStatus::Boundary);
    const double w = width(b.box);
    EXPECT_LE(std::abs(segment_distance(b.box[0].mid(), b.box[1].mid()) - r), 3 * w);
  }
}

TEST(Offsets, SOffsetOfASegmentIsTheFilledStadium) {
  const double r = 0.25;
  const Box region = {Interval(-1.5, 1.5), Interval(-0.5, 0.5)};
  OffsetOptions opt;
  opt.epsilon = 0.05;
  const OffsetResult res = s_offset(kSegment, r, region, {}, opt);
  ASSERT_EQ(res.report.limit, LimitHit::None);
  std::size_t inside = 0;
  for (const OffsetBox& b : res.boxes) {
    if (b.status != OffsetBoxStatus::Inside) continue;
    ++inside;
    for (double px : {b.box[0].lo(), b.box[0].hi()})
      for (double py : {b.box[1].lo(), b.box[1].hi()}) EXPECT_LE(segment_distance(px, py), r + 1e-12);
  }
  EXPECT_GT(inside, 0u);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> ux(-1.5, 1.5), uy(-0.5, 0.5);
  for (int i = 0; i < 2000; ++i) {
    const double px = ux(rng), py = uy(rng);
    if (segment_distance(px, py) <= r) {
      EXPECT_TRUE(covered(res, px, py)) << px << ", " << py;
    }
  }
}

TEST(Offsets, BOffsetOfACircleIsTwoCircles) {
  const Fn a = 2 * std::numbers::pi * x(0);
  const Fn circle = cat({cos(a), sin(a)});
  OffsetOptions opt;
  opt.epsilon = 0.05;
  const OffsetResult res = b_offset(circle, 0.25, std::vector<Interval>{Interval(-1.5, 1.5), Interval(-1.5, 1.5)}, {}, opt);
  ASSERT_EQ(res.report.limit, LimitHit::None);
  for (int i = 0; i < 100; ++i) {
    const double t = 2 * std::numbers::pi * i / 100;
    EXPECT_TRUE(covered(res, 0.75 * std::cos(t), 0.75 * std::sin(t)));
    EXPECT_TRUE(covered(res, 1.25 * std::cos(t), 1.25 * std::sin(t)));
  }
  for (const OffsetBox& b : res.boxes) {
    const double d = std::abs(std::hypot(b.box[0].mid(), b.box[1].mid()) - 1.0);
    EXPECT_LE(std::abs(d - 0.25), 3 * width(b.box));
  }
}

TEST(Offsets, BadInputIsNamed) {
  const Box region = {Interval(-1, 1), Interval(-1, 1)};
  EXPECT_THROW(b_offset(kSegment, 0.0, region), std::invalid_argument);
  EXPECT_THROW(b_offset(kSegment, 0.1, std::vector<Interval>{Interval(-1, 1)}), std::invalid_argument);
  EXPECT_THROW(b_offset(Fn(cat({Fn(1.0), Fn(2.0)})), 0.1, region), std::invalid_argument);
}

}  // namespace
}  // namespace genmod
