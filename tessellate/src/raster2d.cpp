// The subdividing sign renderer: interval evaluation of a tile hierarchy with tape pruning.
#include "genmod/tessellate/raster2d.hpp"

#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "pixel_grid.hpp"
#include "thread_arena.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace genmod {
namespace {

using raster_detail::kAxisX;
using raster_detail::PixelGrid;
using raster_detail::PlaneInputs;

// Pixel columns [c0, c1) x rows [r0, r1).
struct Rect {
  int c0, r0, c1, r1;
  int width() const noexcept { return c1 - c0; }
  int height() const noexcept { return r1 - r0; }
};

// Per-thread evaluators, scratch buffers and counts. Counts are summed at the end, so the
// statistics do not depend on which thread did what.
struct Worker {
  IntervalEvaluator intervals;
  TapeSimplifier simplifier;
  BatchEvaluator points;
  std::vector<double> xs, ys, values;
  RasterStats stats;
};

// Minimum of two tape lengths where 0 means "none yet".
std::uint64_t min_length(std::uint64_t a, std::uint64_t b) noexcept { return a == 0 ? b : b == 0 ? a : std::min(a, b); }

void add_level(RasterLevelStats& total, const RasterLevelStats& part) {
  total.tiles += part.tiles;
  total.inside += part.inside;
  total.outside += part.outside;
  total.ambiguous += part.ambiguous;
  total.tape_clauses += part.tape_clauses;
  total.min_tape = min_length(total.min_tape, part.min_tape);
}

class TileRenderer {
 public:
  TileRenderer(const Tape& tape, const RasterOptions& options)
      : tape_(tape),
        in_(raster_detail::plane_inputs(tape, "render_sign")),
        grid_(options),
        tile_sizes_(options.tile_sizes),
        workers_([this] {
          Worker w;
          w.stats.levels.resize(tile_sizes_.size() + 1);
          return w;
        }) {
    if (tile_sizes_.size() > kMaxTileLevels)
      throw std::invalid_argument("genmod: render_sign: at most " + std::to_string(kMaxTileLevels) +
                                  " tile levels, got " + std::to_string(tile_sizes_.size()));
    for (std::size_t k = 0; k < tile_sizes_.size(); ++k) {
      const bool decreasing = k == 0 || tile_sizes_[k] < tile_sizes_[k - 1];
      if (tile_sizes_[k] < 1 || !decreasing)
        throw std::invalid_argument("genmod: render_sign: tile_sizes must be positive and strictly decreasing; entry " +
                                    std::to_string(k) + " is " + std::to_string(tile_sizes_[k]));
    }
    image_ = Image(grid_.size(), grid_.size());
  }

  Image run(int threads, RasterStats* stats) {
    raster_detail::run_with_threads(threads, "render_sign",
                                    [&] { visit(tape_, Rect{0, 0, grid_.size(), grid_.size()}, 0); });
    if (stats != nullptr) *stats = combine();
    return std::move(image_);
  }

 private:
  // Level 0 is the whole image, level l >= 1 has tiles of tile_sizes[l - 1] pixels.
  int last_level() const noexcept { return static_cast<int>(tile_sizes_.size()); }
  int tile_size(int level) const noexcept { return tile_sizes_[static_cast<std::size_t>(level - 1)]; }

  // Decides tile `r` of `level` with the tape its parent pruned; fills it or goes deeper.
  void visit(const Tape& tape, Rect r, int level) {
    Worker& w = workers_.local();
    std::array<Interval, 2> box;
    for (std::size_t k = 0; k < in_.count; ++k)
      box[k] = in_.axis[k] == kAxisX ? grid_.column_hull(r.c0, r.c1) : grid_.row_hull(r.r0, r.r1);
    const Interval f = w.intervals.eval(tape, std::span(box.data(), in_.count))[0];
    const bool exact = w.intervals.errors()[0] == kNoError;

    RasterLevelStats& ls = w.stats.levels[static_cast<std::size_t>(level)];
    ++ls.tiles;
    ls.tape_clauses += tape.size();
    ls.min_tape = min_length(ls.min_tape, tape.size());
    if (exact && f.hi() < 0.0) {
      ++ls.inside;
      fill(r, kInside);
      return;
    }
    if (exact && f.lo() >= 0.0) {
      ++ls.outside;
      fill(r, kOutside);
      return;
    }
    ++ls.ambiguous;
    const Tape pruned = tape.simplify(w.intervals.choices(), w.simplifier);

    // Levels whose tiles are no smaller than this one would only evaluate the same box again.
    int next = level + 1;
    while (next <= last_level() && tile_size(next) >= std::max(r.width(), r.height())) ++next;
    if (next > last_level()) {
      evaluate_pixels(w, pruned, r);
      return;
    }
    const int step = tile_size(next);
    std::vector<Rect> children;
    for (int r0 = r.r0; r0 < r.r1; r0 += step)
      for (int c0 = r.c0; c0 < r.c1; c0 += step)
        children.push_back(Rect{c0, r0, std::min(c0 + step, r.c1), std::min(r0 + step, r.r1)});
    // Nested parallelism: the cost of tiles is very uneven (most are filled at once, a few
    // hold the detail), so every level offers its children as tasks, one tile per task.
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, children.size(), 1),
        [&](const tbb::blocked_range<std::size_t>& range) {
          for (std::size_t i = range.begin(); i < range.end(); ++i) visit(pruned, children[i], next);
        },
        tbb::simple_partitioner());
  }

  void fill(Rect r, std::uint8_t value) {
    for (int row = r.r0; row < r.r1; ++row)
      std::memset(&image_.at(r.c0, row), value, static_cast<std::size_t>(r.width()));
  }

  // Point evaluation of every pixel of an ambiguous tile that no level splits, in one batch.
  void evaluate_pixels(Worker& w, const Tape& tape, Rect r) {
    const std::size_t n = static_cast<std::size_t>(r.width()) * static_cast<std::size_t>(r.height());
    w.xs.resize(n);
    w.ys.resize(n);
    w.values.resize(n);
    std::size_t p = 0;
    for (int row = r.r0; row < r.r1; ++row)
      for (int column = r.c0; column < r.c1; ++column, ++p) {
        w.xs[p] = grid_.x(column);
        w.ys[p] = grid_.y(row);
      }
    std::array<const double*, 2> inputs{};
    for (std::size_t k = 0; k < in_.count; ++k) inputs[k] = in_.axis[k] == kAxisX ? w.xs.data() : w.ys.data();
    double* out = w.values.data();
    w.points.eval(tape, std::span(inputs.data(), in_.count), n, std::span(&out, 1));
    p = 0;
    for (int row = r.r0; row < r.r1; ++row)
      for (int column = r.c0; column < r.c1; ++column, ++p)
        image_.at(column, row) = raster_detail::pixel_value(w.values[p]);

    w.stats.pixels_evaluated += n;
    ++w.stats.pixel_tiles;
    w.stats.pixel_tape_clauses += tape.size();
    w.stats.min_pixel_tape = min_length(w.stats.min_pixel_tape, tape.size());
  }

  RasterStats combine() const {
    RasterStats total;
    total.full_tape = tape_.size();
    total.levels.resize(tile_sizes_.size() + 1);
    for (std::size_t l = 0; l < total.levels.size(); ++l)
      total.levels[l].tile_size = l == 0 ? grid_.size() : tile_sizes_[l - 1];
    for (const Worker& w : workers_) {
      for (std::size_t l = 0; l < total.levels.size(); ++l) add_level(total.levels[l], w.stats.levels[l]);
      total.pixel_tiles += w.stats.pixel_tiles;
      total.pixels_evaluated += w.stats.pixels_evaluated;
      total.pixel_tape_clauses += w.stats.pixel_tape_clauses;
      total.min_pixel_tape = min_length(total.min_pixel_tape, w.stats.min_pixel_tape);
    }
    return total;
  }

  const Tape& tape_;
  PlaneInputs in_;
  PixelGrid grid_;
  std::vector<int> tile_sizes_;
  Image image_;
  tbb::enumerable_thread_specific<Worker> workers_;
};

}  // namespace

Image render_sign(const Tape& tape, const RasterOptions& options, RasterStats* stats) {
  return TileRenderer(tape, options).run(options.threads, stats);
}

}  // namespace genmod
