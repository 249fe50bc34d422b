// Rendering the sign of a 2-D implicit function f(x, y) into an image (the Prospero
// challenge).
//
// Convention: the image is size x size pixels over the region x_range x y_range. Pixel column
// i covers x in [x.lo + i*hx, x.lo + (i+1)*hx] with hx = width(x_range) / size, row j covers
// y in [y.hi - (j+1)*hy, y.hi - j*hy]: row 0 is the TOP of the image. Each pixel is decided by
// the value of f at its center: kInside (255, white) where f < 0, kOutside (0, black) where
// f >= 0 or where f is an error (NaN).
//
// Example:
//   Tape tape(square(x(0)) + square(x(1)) - 0.5);   // or Tape tape(load_vm("prospero.vm"))
//   RasterStats stats;
//   Image img = render_sign(tape, {.size = 256}, &stats);
//   // write_png("disk.png", img) saves it
//
// render_sign subdivides the image into a hierarchy of square tiles: the whole image (level 0),
// then tiles of tile_sizes[0] pixels (level 1), tile_sizes[1] (level 2), ... Tiles at the
// right and bottom edges are clipped to the image, and a level whose tiles are no smaller than
// their parent is skipped for that parent. Each tile is evaluated with interval arithmetic over
// the box of its pixel centers, using the tape pruned by its parent: a tile whose interval is
// certainly < 0 (or certainly >= 0) without possible error is filled; otherwise the tape is
// pruned for the tile and its sub-tiles are visited, and the pixels of an ambiguous tile that
// no level splits further are evaluated one by one (BatchEvaluator). Pruning keeps the point
// values bit for bit, so the image equals render_sign_brute_force pixel for pixel, and is the
// same for any thread count (tiles run as nested TBB tasks).
#pragma once

#include "genmod/kernel/interval.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/tessellate/image.hpp"

#include <cstdint>
#include <vector>

namespace genmod {

inline constexpr std::uint8_t kInside = 255;
inline constexpr std::uint8_t kOutside = 0;
inline constexpr int kMaxRasterSize = 1 << 15;
// At most this many tile levels below the whole image (the subdivision nests one parallel
// task level per tile level, so the list's length bounds the depth of the worker stacks).
inline constexpr std::size_t kMaxTileLevels = 16;

struct RasterOptions {
  int size = 1024;                      // the image is size x size pixels, 1 <= size <= kMaxRasterSize
  Interval x_range{-1.0, 1.0};          // region covered by the image (bounded, nonzero width)
  Interval y_range{-1.0, 1.0};
  // Tile widths in pixels below the whole image, strictly decreasing, >= 1, at most
  // kMaxTileLevels of them. The default halves the tile at every level down to 16 pixels
  // (levels not smaller than the image are skipped): each level prunes the tape a little
  // further, so its children are evaluated with shorter tapes, and four children per tile
  // waste less work on tiles that turn out empty. For Prospero this costs 9% fewer
  // instructions than 256, 64, 16 at 256 x 256 and 1024 x 1024, and 24% fewer at 4096 x 4096.
  // Tiles of 16 pixels stay the last level: interval evaluation plus pruning costs about as
  // much per clause as 100 batch point evaluations, so smaller tiles do not pay.
  std::vector<int> tile_sizes{2048, 1024, 512, 256, 128, 64, 32, 16};
  int threads = 0;                      // worker threads; 0 = all cores
};

// What the interval subdivision did at one level of the tile hierarchy.
struct RasterLevelStats {
  int tile_size = 0;               // nominal tile width in pixels (level 0: the image size)
  std::uint64_t tiles = 0;         // tiles evaluated with intervals
  std::uint64_t inside = 0;        // ... filled as inside
  std::uint64_t outside = 0;       // ... filled as outside
  std::uint64_t ambiguous = 0;     // ... pruned and subdivided (or evaluated per pixel)
  std::uint64_t tape_clauses = 0;  // sum over tiles of the length of the tape they were evaluated with
  std::uint64_t min_tape = 0;      // shortest such tape (0 when no tile was evaluated)

  double mean_tape() const noexcept {
    return tiles ? static_cast<double>(tape_clauses) / static_cast<double>(tiles) : 0.0;
  }
};

struct RasterStats {
  std::uint64_t full_tape = 0;              // clauses of the tape given to the renderer
  std::vector<RasterLevelStats> levels;     // levels[0] is the whole image (a skipped level has no tiles)
  // Ambiguous tiles that no level splits further (normally those of the last level) are
  // evaluated per pixel with their pruned tape:
  std::uint64_t pixel_tiles = 0;            // number of such tiles
  std::uint64_t pixels_evaluated = 0;       // pixels in them
  std::uint64_t pixel_tape_clauses = 0;     // sum of their pruned tape lengths
  std::uint64_t min_pixel_tape = 0;         // shortest of those tapes (0 when there were none)

  double mean_pixel_tape() const noexcept {
    return pixel_tiles ? static_cast<double>(pixel_tape_clauses) / static_cast<double>(pixel_tiles) : 0.0;
  }
};

// Renders the sign of `tape` (one output; inputs only x(0) and x(1), any subset) by interval
// subdivision with tape pruning, in parallel. `stats` (optional) receives the counts. Throws
// std::invalid_argument naming the problem for a bad tape or bad options.
Image render_sign(const Tape& tape, const RasterOptions& options = {}, RasterStats* stats = nullptr);

// The same image computed by evaluating every pixel center (BatchEvaluator, full tape, no
// intervals). The reference for tests and benchmarks; tile_sizes is ignored.
Image render_sign_brute_force(const Tape& tape, const RasterOptions& options = {});

}  // namespace genmod
