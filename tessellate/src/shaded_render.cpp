// The subdividing shaded renderer: interval evaluation of a cube hierarchy over the voxel
// block, top down, with tape pruning and occlusion (see shaded_render.hpp).
#include "genmod/tessellate/shaded_render.hpp"

#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/tessellate/raster2d.hpp"
#include "shaded_common.hpp"
#include "thread_arena.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod {
namespace {

using shaded_detail::SpaceInputs;
using shaded_detail::VoxelGrid;

// Pixel columns [c0, c1) x rows [r0, r1) x voxel layers [k0, k1).
struct Block {
  int c0, r0, k0, c1, r1, k1;
};

struct Worker {
  IntervalEvaluator intervals;
  TapeSimplifier simplifier;
  BatchEvaluator points;
  std::array<std::vector<double>, 3> coordinates;
  std::vector<double> values;
  std::vector<std::size_t> owner;  // per batched point: its pixel
  std::vector<std::uint32_t> layer;  // per batched point: its voxel layer
  ShadedStats stats;
};

class CubeRenderer {
 public:
  CubeRenderer(const Tape& tape, const ShadedOptions& options)
      : tape_(tape),
        in_(shaded_detail::space_inputs(tape, "render_shaded")),
        grid_(options, "render_shaded"),
        tile_sizes_(options.tile_sizes),
        heights_(static_cast<std::size_t>(grid_.size()) * static_cast<std::size_t>(grid_.size()), 0) {
    if (tile_sizes_.size() > kMaxTileLevels)
      throw std::invalid_argument("genmod: render_shaded: at most " + std::to_string(kMaxTileLevels) +
                                  " tile levels, got " + std::to_string(tile_sizes_.size()));
    for (std::size_t k = 0; k < tile_sizes_.size(); ++k)
      if (tile_sizes_[k] < 1 || (k > 0 && tile_sizes_[k] >= tile_sizes_[k - 1]))
        throw std::invalid_argument("genmod: render_shaded: tile_sizes must be positive and strictly decreasing; entry " +
                                    std::to_string(k) + " is " + std::to_string(tile_sizes_[k]));
  }

  ShadedImage run(int threads, ShadedStats* stats) {
    ShadedImage out;
    raster_detail::run_with_threads(threads, "render_shaded", [&] {
      visit(tape_, Block{0, 0, 0, grid_.size(), grid_.size(), grid_.depth()}, 0);
      out.image = shaded_detail::shade(tape_, in_, grid_, heights_);
    });
    out.depth = grid_.depth();
    out.heights = std::move(heights_);
    if (stats != nullptr) {
      *stats = ShadedStats{};
      stats->full_tape = tape_.size();
      for (const Worker& w : workers_) {
        stats->cubes += w.stats.cubes;
        stats->inside += w.stats.inside;
        stats->outside += w.stats.outside;
        stats->ambiguous += w.stats.ambiguous;
        stats->hidden += w.stats.hidden;
        stats->voxels_evaluated += w.stats.voxels_evaluated;
        stats->tape_clauses += w.stats.tape_clauses;
      }
    }
    return out;
  }

 private:
  std::uint32_t& height(int column, int row) noexcept {
    return heights_[static_cast<std::size_t>(row) * static_cast<std::size_t>(grid_.size()) + static_cast<std::size_t>(column)];
  }

  // True when every pixel of the block already sees a voxel at or above its top layer.
  bool hidden(const Block& b) {
    for (int row = b.r0; row < b.r1; ++row)
      for (int column = b.c0; column < b.c1; ++column)
        if (height(column, row) < static_cast<std::uint32_t>(b.k1)) return false;
    return true;
  }

  // Decides block b with the tape its parent pruned: raises, drops, or splits it. Only pixels of
  // b are written, and blocks over the same pixels run one after the other (top down), so the
  // heights need no locks.
  void visit(const Tape& tape, const Block& b, int level) {
    Worker& w = workers_.local();
    if (hidden(b)) {
      ++w.stats.hidden;
      return;
    }
    const std::array<Interval, 3> hull{grid_.x_hull(b.c0, b.c1), grid_.y_hull(b.r0, b.r1), grid_.z_hull(b.k0, b.k1)};
    std::array<Interval, 3> box;
    for (std::size_t k = 0; k < in_.count; ++k) box[k] = hull[static_cast<std::size_t>(in_.axis[k])];
    const Interval f = w.intervals.eval(tape, std::span(box.data(), in_.count))[0];
    const bool exact = w.intervals.errors()[0] == kNoError;
    ++w.stats.cubes;
    w.stats.tape_clauses += tape.size();
    if (exact && f.hi() < 0.0) {
      ++w.stats.inside;
      for (int row = b.r0; row < b.r1; ++row)
        for (int column = b.c0; column < b.c1; ++column)
          height(column, row) = std::max(height(column, row), static_cast<std::uint32_t>(b.k1));
      return;
    }
    if (exact && f.lo() >= 0.0) {
      ++w.stats.outside;
      return;
    }
    ++w.stats.ambiguous;
    const Tape pruned = tape.simplify(w.intervals.choices(), w.simplifier);

    // Levels whose cubes are no smaller than this block would evaluate the same box again.
    const int extent = std::max({b.c1 - b.c0, b.r1 - b.r0, b.k1 - b.k0});
    int next = level;
    while (next < static_cast<int>(tile_sizes_.size()) && tile_sizes_[static_cast<std::size_t>(next)] >= extent) ++next;
    if (next == static_cast<int>(tile_sizes_.size())) {
      evaluate_voxels(w, pruned, b);
      return;
    }
    const int step = tile_sizes_[static_cast<std::size_t>(next)];
    std::vector<Block> columns;  // the child footprints; each is walked down its layers in order
    for (int r0 = b.r0; r0 < b.r1; r0 += step)
      for (int c0 = b.c0; c0 < b.c1; c0 += step)
        columns.push_back(Block{c0, r0, b.k0, std::min(c0 + step, b.c1), std::min(r0 + step, b.r1), b.k1});
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, columns.size(), 1),
        [&](const tbb::blocked_range<std::size_t>& range) {
          for (std::size_t i = range.begin(); i < range.end(); ++i) {
            Block child = columns[i];
            for (int top = b.k1; top > b.k0; top -= step) {
              child.k1 = top;
              child.k0 = std::max(top - step, b.k0);
              visit(pruned, child, next + 1);
            }
          }
        },
        tbb::simple_partitioner());
  }

  // Every voxel of b above its pixel's current height, in one batch.
  void evaluate_voxels(Worker& w, const Tape& tape, const Block& b) {
    for (auto& c : w.coordinates) c.clear();
    w.owner.clear();
    w.layer.clear();
    for (int row = b.r0; row < b.r1; ++row)
      for (int column = b.c0; column < b.c1; ++column) {
        const std::uint32_t seen = height(column, row);
        for (int k = b.k1 - 1; k >= b.k0 && static_cast<std::uint32_t>(k) >= seen; --k) {
          w.coordinates[0].push_back(grid_.x(column));
          w.coordinates[1].push_back(grid_.y(row));
          w.coordinates[2].push_back(grid_.z(k));
          w.owner.push_back(static_cast<std::size_t>(row) * static_cast<std::size_t>(grid_.size()) + static_cast<std::size_t>(column));
          w.layer.push_back(static_cast<std::uint32_t>(k));
        }
      }
    const std::size_t n = w.owner.size();
    if (n == 0) return;
    w.values.resize(n);
    std::array<const double*, 3> inputs{};
    for (std::size_t k = 0; k < in_.count; ++k) inputs[k] = w.coordinates[static_cast<std::size_t>(in_.axis[k])].data();
    double* out = w.values.data();
    w.points.eval(tape, std::span(inputs.data(), in_.count), n, std::span(&out, 1));
    for (std::size_t p = 0; p < n; ++p)
      if (w.values[p] < 0.0) heights_[w.owner[p]] = std::max(heights_[w.owner[p]], w.layer[p] + 1);
    w.stats.voxels_evaluated += n;
  }

  const Tape& tape_;
  SpaceInputs in_;
  VoxelGrid grid_;
  std::vector<int> tile_sizes_;
  std::vector<std::uint32_t> heights_;
  tbb::enumerable_thread_specific<Worker> workers_;
};

}  // namespace

ShadedImage render_shaded(const Tape& tape, const ShadedOptions& options, ShadedStats* stats) {
  return CubeRenderer(tape, options).run(options.threads, stats);
}

}  // namespace genmod
