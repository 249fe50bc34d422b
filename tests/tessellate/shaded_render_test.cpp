// render_shaded: the interval subdivision finds exactly the heights of the per-pixel ray march,
// for any thread count; heights of a sphere against the exact ones; the shading follows the
// normal; bad input is refused with a message.
#include "genmod/kernel/vm_format.hpp"
#include "genmod/tessellate/shaded_render.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace genmod {
namespace {

const Fn X = x(0), Y = x(1), Z = x(2);

Fn sphere(double r) { return sqrt(square(X) + square(Y) + square(Z)) - r; }

Box3 cube_box(double h) { return {Interval(-h, h), Interval(-h, h), Interval(-h, h)}; }

TEST(ShadedRender, SphereHeightsAreTheExactOnesAndEqualTheRayMarch) {
  const double r = 0.6;
  const Tape tape(sphere(r));
  ShadedOptions o{.size = 96, .box = cube_box(1)};
  ShadedStats stats;
  const ShadedImage shot = render_shaded(tape, o, &stats);
  EXPECT_EQ(shot.heights, render_shaded_brute_force(tape, o).heights);
  ASSERT_EQ(shot.depth, 96);
  const double h = 2.0 / 96;
  int mismatched = 0, covered = 0;
  for (int row = 0; row < 96; ++row)
    for (int column = 0; column < 96; ++column) {
      const double x = -1 + (column + 0.5) * h, y = 1 - (row + 0.5) * h;
      // The highest voxel center z_k = -1 + (k + 0.5) h below the sphere's top at (x, y).
      const double top2 = r * r - x * x - y * y;
      std::uint32_t expected = 0;
      if (top2 > 0) {
        const double k = std::floor((std::sqrt(top2) + 1) / h - 0.5);
        expected = k >= 0 ? static_cast<std::uint32_t>(k) + 1 : 0;
      }
      const std::uint32_t got = shot.heights[static_cast<std::size_t>(row) * 96 + column];
      covered += got > 0;
      // Rounding may move a center that sits on the sphere by one layer.
      if (got != expected) ++mismatched;
      EXPECT_LE(std::abs(static_cast<int>(got) - static_cast<int>(expected)), 1) << column << "," << row;
      EXPECT_EQ(got == 0, shot.image.at(column, row) == 0);
    }
  EXPECT_LT(mismatched, 20);
  EXPECT_NEAR(covered, M_PI * r * r / (h * h), 0.03 * M_PI * r * r / (h * h));
  // Most of the block is decided by intervals, not voxel by voxel.
  EXPECT_GT(stats.inside + stats.outside + stats.hidden, 0u);
  EXPECT_LT(stats.voxels_evaluated, 96u * 96u * 96u / 8);
}

TEST(ShadedRender, ShadingFollowsTheNormal) {
  const Tape tape(sphere(0.8));
  const ShadedImage shot = render_shaded(tape, {.size = 65, .box = cube_box(1)});
  // Facing the viewer: n = +z.
  const double ln = std::sqrt(0.4 * 0.4 + 0.5 * 0.5 + 0.77 * 0.77);
  EXPECT_NEAR(shot.image.at(32, 32), 40 + 215 * 0.77 / ln, 3);
  // The light comes from the upper left: that side of the sphere is brighter than the lower right.
  EXPECT_GT(shot.image.at(18, 18), shot.image.at(46, 46) + 60);
  EXPECT_EQ(shot.image.at(0, 0), 0);  // background
}

TEST(ShadedRender, SolidFillingTheBoxShowsTheCutFace) {
  const Tape tape(sphere(10));
  const ShadedImage shot = render_shaded(tape, {.size = 16, .box = cube_box(1), .depth = 8});
  const double ln = std::sqrt(0.4 * 0.4 + 0.5 * 0.5 + 0.77 * 0.77);
  for (std::uint32_t h : shot.heights) EXPECT_EQ(h, 8u);
  for (std::uint8_t v : shot.image.pixels) EXPECT_EQ(v, std::lround(40 + 215 * 0.77 / ln));
}

TEST(ShadedRender, TanglecubeEqualsTheRayMarchForAnyThreadCount) {
  const Tape tape(load_vm(std::string(GENMOD_DATA_DIR) + "/tanglecube.vm"));
  ShadedOptions o{.size = 128, .box = cube_box(2.5), .threads = 1};
  ShadedStats stats;
  const ShadedImage one = render_shaded(tape, o, &stats);
  o.threads = 2;
  const ShadedImage two = render_shaded(tape, o);
  EXPECT_EQ(one.heights, two.heights);
  EXPECT_EQ(one.image, two.image);
  const ShadedImage reference = render_shaded_brute_force(tape, o);
  EXPECT_EQ(one.heights, reference.heights);
  EXPECT_EQ(one.image, reference.image);
  EXPECT_GT(stats.hidden, 0u);
  // Other tile hierarchies find the same heights.
  o.tile_sizes = {32, 8, 2};
  EXPECT_EQ(render_shaded(tape, o).heights, one.heights);
  o.tile_sizes = {};
  EXPECT_EQ(render_shaded(tape, o).heights, one.heights);
}

TEST(ShadedRender, NonCubicBoxAndMissingInputs) {
  // f of z alone: a slab below z = 0.25, seen from above at layer k with z_k < 0.25.
  const Tape tape(Z - 0.25);
  const ShadedImage shot = render_shaded(tape, {.size = 8, .box = {Interval(0, 1), Interval(0, 2), Interval(-1, 1)}});
  EXPECT_EQ(shot.depth, 16);  // voxels as wide as the pixels in x: 2 / (1 / 8)
  for (std::uint32_t h : shot.heights) EXPECT_EQ(h, 10u);  // z_9 = -1 + 9.5 / 8 = 0.1875
}

TEST(ShadedRender, BadInputIsRefusedWithAMessage) {
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  EXPECT_NE(message([] { render_shaded(Tape(X + x(3))); }).find("x(3)"), std::string::npos);
  EXPECT_NE(message([] { render_shaded(Tape(sphere(1)), {.size = 0}); }).find("size"), std::string::npos);
  EXPECT_NE(message([] { render_shaded(Tape(sphere(1)), {.size = 8, .box = {Interval(1, 1), Interval(0, 1), Interval(0, 1)}}); })
                .find("x range"),
            std::string::npos);
  EXPECT_NE(message([] { render_shaded(Tape(sphere(1)), {.size = 8, .tile_sizes = {4, 8}}); }).find("tile_sizes"),
            std::string::npos);
  EXPECT_NE(message([] {
              std::vector<int> many(40);
              for (int k = 0; k < 40; ++k) many[static_cast<std::size_t>(k)] = 40 - k;
              render_shaded(Tape(sphere(1)), {.size = 8, .tile_sizes = many});
            }).find("at most 16 tile levels"),
            std::string::npos);
  EXPECT_NE(message([] { render_shaded_brute_force(Tape(sphere(1)), {.size = 8, .depth = -1}); }).find("depth"),
            std::string::npos);
}

}  // namespace
}  // namespace genmod
