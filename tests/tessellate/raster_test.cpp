// The subdividing sign renderer against the brute-force reference, pixel for pixel.
#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/kernel/vm_format.hpp"
#include "genmod/tessellate/raster2d.hpp"
#include "kernel/random_functions.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

namespace genmod {
namespace {

const std::array<int, 2> kXY{0, 1};

Tape model(const std::string& name) { return Tape(load_vm(std::string(GENMOD_DATA_DIR) + "/" + name), kXY); }

std::size_t count_inside(const Image& image) {
  return static_cast<std::size_t>(std::count(image.pixels.begin(), image.pixels.end(), kInside));
}

// The first differing pixel, for a readable failure.
std::string first_difference(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) return "different sizes";
  for (int row = 0; row < a.height; ++row)
    for (int column = 0; column < a.width; ++column)
      if (a.at(column, row) != b.at(column, row))
        return "pixel (" + std::to_string(column) + ", " + std::to_string(row) + "): " +
               std::to_string(a.at(column, row)) + " vs " + std::to_string(b.at(column, row));
  return "none";
}

void expect_matches_brute_force(const Tape& tape, const RasterOptions& options) {
  const Image fast = render_sign(tape, options);
  const Image reference = render_sign_brute_force(tape, options);
  ASSERT_EQ(fast.width, options.size);
  ASSERT_EQ(fast.height, options.size);
  EXPECT_TRUE(fast == reference) << "size " << options.size
                                 << ", first difference: " << first_difference(fast, reference);
}

TEST(RenderSign, ProsperoEqualsBruteForce) {
  const Tape tape = model("prospero.vm");
  // 1024 is the challenge itself; 257 clips tiles at the right and bottom edges.
  for (int size : {256, 257, 1024}) {
    RasterOptions options;
    options.size = size;
    expect_matches_brute_force(tape, options);
  }
}

TEST(RenderSign, SmallModelsEqualBruteForceAtOddSizes) {
  for (const char* name : {"quarter.vm", "hi.vm"}) {
    const Tape tape = model(name);
    for (int size : {1, 2, 7, 100, 256, 257}) {
      SCOPED_TRACE(std::string(name) + " at " + std::to_string(size));
      RasterOptions options;
      options.size = size;
      expect_matches_brute_force(tape, options);
    }
  }
}

TEST(RenderSign, EveryTileChainGivesTheSameImage) {
  const Tape tape = model("hi.vm");
  RasterOptions options;
  options.size = 200;
  const Image reference = render_sign_brute_force(tape, options);
  for (const std::vector<int>& chain : std::vector<std::vector<int>>{{}, {1}, {3}, {64, 8}, {50, 7, 2, 1}, {512, 16}}) {
    options.tile_sizes = chain;
    EXPECT_TRUE(render_sign(tape, options) == reference) << "chain of " << chain.size() << " levels";
  }
}

TEST(RenderSign, OtherRegionsFollowThePixelConvention) {
  // quarter.vm is the quarter disc x, y <= 0, x^2 + y^2 < 0.5: over [-1,0] x [-1,0] it fills
  // the lower-left corner of the region; over [0,1]^2 nothing.
  const Tape tape = model("quarter.vm");
  RasterOptions options;
  options.size = 101;
  options.x_range = Interval(-1.0, 0.0);
  options.y_range = Interval(-1.0, 0.0);
  const Image image = render_sign(tape, options);
  EXPECT_TRUE(image == render_sign_brute_force(tape, options));
  EXPECT_EQ(image.at(0, 100), kOutside);   // (-1, -1): r^2 = 2
  EXPECT_EQ(image.at(100, 0), kInside);    // (0, 0) corner, just inside
  EXPECT_EQ(image.at(100, 100), kOutside); // (0, -1)
  options.x_range = options.y_range = Interval(0.0, 1.0);
  EXPECT_EQ(count_inside(render_sign(tape, options)), 0u);
}

TEST(RenderSign, ThreadCountDoesNotChangeTheImageOrStatistics) {
  const Tape tape = model("prospero.vm");
  RasterOptions options;
  options.size = 300;
  RasterStats one_stats, two_stats;
  options.threads = 1;
  const Image one = render_sign(tape, options, &one_stats);
  options.threads = 2;
  const Image two = render_sign(tape, options, &two_stats);
  EXPECT_TRUE(one == two) << first_difference(one, two);
  EXPECT_EQ(one_stats.pixels_evaluated, two_stats.pixels_evaluated);
  EXPECT_EQ(one_stats.pixel_tape_clauses, two_stats.pixel_tape_clauses);
  ASSERT_EQ(one_stats.levels.size(), two_stats.levels.size());
  for (std::size_t l = 0; l < one_stats.levels.size(); ++l) {
    EXPECT_EQ(one_stats.levels[l].inside, two_stats.levels[l].inside);
    EXPECT_EQ(one_stats.levels[l].tape_clauses, two_stats.levels[l].tape_clauses);
  }
}

TEST(RenderSign, CircleAreaMatches) {
  const double radius = 0.6;
  const Fn circle = sqrt(square(x(0)) + square(x(1))) - radius;
  RasterOptions options;
  options.size = 512;
  const Image image = render_sign(Tape(circle), options);
  // Pixels are (2/512)^2 each; the boundary error is of the order of the perimeter in pixels.
  const double expected = std::numbers::pi * radius * radius / (2.0 / 512) / (2.0 / 512);
  const double perimeter_pixels = 2 * std::numbers::pi * radius / (2.0 / 512);
  EXPECT_NEAR(static_cast<double>(count_inside(image)), expected, perimeter_pixels);
  EXPECT_EQ(image.at(256, 256), kInside);
  EXPECT_EQ(image.at(0, 0), kOutside);
}

TEST(RenderSign, RandomFunctionsEqualBruteForce) {
  // Every opcode, errors (NaN pixels) and discontinuities included.
  testing::RandomFunctions random(20240611, 2);
  RasterOptions options;
  options.size = 64;
  options.tile_sizes = {16, 4};
  int mixed = 0;  // images with both inside and outside pixels: the interesting ones
  for (int trial = 0; trial < 1000; ++trial) {
    const Fn f = random.function(6);
    const Tape tape(f, kXY);
    const Image fast = render_sign(tape, options);
    const Image reference = render_sign_brute_force(tape, options);
    ASSERT_TRUE(fast == reference) << "trial " << trial << ", first difference " << first_difference(fast, reference)
                                   << "\n" << tape.disassemble();
    const std::size_t inside = count_inside(fast);
    if (inside > 0 && inside < fast.pixels.size()) ++mixed;
  }
  EXPECT_GT(mixed, 100);
}

TEST(RenderSign, PruningShortensProsperoTapes) {
  const Tape tape = model("prospero.vm");
  RasterOptions options;
  options.size = 512;
  options.tile_sizes = {128, 32, 8};
  RasterStats stats;
  const Image image = render_sign(tape, options, &stats);
  EXPECT_EQ(stats.full_tape, tape.size());
  ASSERT_EQ(stats.levels.size(), 4u);
  EXPECT_EQ(stats.levels[0].tiles, 1u);
  EXPECT_EQ(stats.levels[0].tape_clauses, tape.size());
  std::uint64_t pixels_filled = 0;
  for (std::size_t l = 0; l < stats.levels.size(); ++l) {
    const RasterLevelStats& s = stats.levels[l];
    EXPECT_EQ(s.tile_size, l == 0 ? 512 : options.tile_sizes[l - 1]);
    EXPECT_EQ(s.inside + s.outside + s.ambiguous, s.tiles) << "level " << l;
    EXPECT_GT(s.tiles, 0u) << "level " << l;
    EXPECT_LE(s.min_tape, tape.size());
    if (l > 0) {
      EXPECT_EQ(s.tiles, stats.levels[l - 1].ambiguous * 16u) << "4 x 4 children per tile";
      EXPECT_LE(s.mean_tape(), stats.levels[l - 1].mean_tape()) << "level " << l;
    }
    const std::uint64_t area = static_cast<std::uint64_t>(s.tile_size) * static_cast<std::uint64_t>(s.tile_size);
    pixels_filled += (s.inside + s.outside) * area;  // 512 is a multiple of every tile size
  }
  EXPECT_EQ(pixels_filled + stats.pixels_evaluated, 512u * 512u);
  EXPECT_EQ(stats.pixel_tiles, stats.levels.back().ambiguous);
  EXPECT_EQ(stats.pixels_evaluated, stats.pixel_tiles * 64u);
  EXPECT_GT(stats.pixel_tiles, 0u);
  // The deepest tapes are far shorter than the full one.
  EXPECT_LT(stats.levels.back().mean_tape(), static_cast<double>(tape.size()) / 10);
  EXPECT_LT(stats.mean_pixel_tape(), stats.levels.back().mean_tape());
  EXPECT_LT(stats.min_pixel_tape, stats.levels.back().min_tape);
  EXPECT_GT(count_inside(image), 0u);
}

TEST(RenderSign, LevelsNoSmallerThanTheTileAreSkipped) {
  const Tape tape = model("quarter.vm");
  RasterOptions options;
  options.size = 100;
  options.tile_sizes = {256, 128, 10};
  RasterStats stats;
  EXPECT_TRUE(render_sign(tape, options, &stats) == render_sign_brute_force(tape, options));
  EXPECT_EQ(stats.levels[1].tiles, 0u);
  EXPECT_EQ(stats.levels[2].tiles, 0u);
  EXPECT_EQ(stats.levels[3].tiles, 100u);
}

TEST(RenderSign, RejectsBadInputNamingTheProblem) {
  const Tape tape = model("quarter.vm");
  auto message = [&](const RasterOptions& options) {
    try {
      render_sign(tape, options);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  RasterOptions bad;
  bad.size = 0;
  EXPECT_NE(message(bad).find("size"), std::string::npos);
  bad = {};
  bad.tile_sizes = {8, 16};
  EXPECT_NE(message(bad).find("tile_sizes"), std::string::npos);
  bad = {};
  bad.threads = -1;
  EXPECT_NE(message(bad).find("threads"), std::string::npos);
  // A long tile list (each level nests parallel tasks) is refused, not run to a stack overflow.
  bad = {};
  bad.tile_sizes.clear();
  for (int w = 1000; w >= 1; --w) bad.tile_sizes.push_back(w);
  EXPECT_NE(message(bad).find("at most 16 tile levels, got 1000"), std::string::npos);
  bad.tile_sizes.resize(kMaxTileLevels);
  EXPECT_EQ(message(bad), "no exception");
  bad = {};
  bad.x_range = Interval(0.5, 0.5);
  EXPECT_NE(message(bad).find("x_range"), std::string::npos);

  const std::array<int, 3> xyz{0, 1, 2};
  EXPECT_THROW(render_sign(Tape(x(0) + x(2), xyz)), std::invalid_argument);
  EXPECT_THROW(render_sign_brute_force(Tape(cat({x(0), x(1)}))), std::invalid_argument);
}

}  // namespace
}  // namespace genmod
