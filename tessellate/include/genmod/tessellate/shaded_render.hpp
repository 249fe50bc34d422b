// Shaded 3-D pictures of implicit solids (solid where f < 0): a heightmap by interval
// subdivision in x, y and z, shaded with normals from the gradient.
//
// The view is orthographic along -z: pixel column i covers x, row j covers y (row 0 at the
// top, as in raster2d.hpp), and z points toward the viewer. The box is cut into
// size x size x depth voxels; the height of a pixel is one plus the index k (counted upward
// from box.z.lo) of the highest voxel whose center has f < 0, or 0 when the ray meets no
// solid. Voxel centers sit at lo + (k + 0.5) * h on every axis, computed once.
//
// Example:
//   Tape tape(implicit_sphere(2.0));                // or Tape tape(load_vm("tanglecube.vm"))
//   using I = Interval;
//   ShadedImage shot = render_shaded(tape, {.size = 128, .box = {I(-2.5, 2.5), I(-2.5, 2.5), I(-2.5, 2.5)}});
//   // write_png("ball.png", shot.image) saves it
//
// render_shaded subdivides the voxel block into cubes of tile_sizes[0], tile_sizes[1], ...
// voxels. Each cube is evaluated with interval arithmetic over the hull of its voxel centers,
// with the tape its parent pruned: a cube certainly inside raises the height of its pixels to
// its top voxel, a cube certainly outside is dropped, and an ambiguous cube is pruned and split.
// Cubes are visited from the top down, and a cube whose pixels all have a height at or above
// its top is never evaluated (it is hidden). Ambiguous cubes of the last level are evaluated
// voxel by voxel. Pruning keeps point values bit for bit, so the heights equal
// render_shaded_brute_force's (a per-pixel ray march) exactly, for any thread count.
//
// Shading: the surface is bisected between the hit voxel's center and the one above it, and the
// gradient of f there (GradientEvaluator, full tape) gives the normal n; the pixel is
// 40 + 215 max(0, n . l) with the light l from the upper left, in front. A pixel whose hit is on
// the box's top layer shows the box's cut face (n = +z). Background 0.
#pragma once

#include "genmod/kernel/interval.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/tessellate/box3.hpp"
#include "genmod/tessellate/image.hpp"

#include <cstdint>
#include <vector>

namespace genmod {

inline constexpr int kMaxShadedSize = 1 << 14;

struct ShadedOptions {
  int size = 512;  // image width and height in pixels, 1 <= size <= kMaxShadedSize
  Box3 box{Interval(-1, 1), Interval(-1, 1), Interval(-1, 1)};  // bounded, nonzero widths
  // Voxels along z, 1 <= depth <= kMaxShadedSize; 0 = cubes as wide as the pixels in x.
  int depth = 0;
  // Cube edges in voxels below the whole block, strictly decreasing, >= 1, at most
  // kMaxTileLevels (raster2d.hpp) of them.
  std::vector<int> tile_sizes{64, 16, 4};
  int threads = 0;  // worker threads; 0 = all cores
};

struct ShadedStats {
  std::uint64_t full_tape = 0;         // clauses of the given tape
  std::uint64_t cubes = 0;             // cubes evaluated with intervals
  std::uint64_t inside = 0;            // ... certainly inside
  std::uint64_t outside = 0;           // ... certainly outside
  std::uint64_t ambiguous = 0;         // ... pruned and split (or evaluated per voxel)
  std::uint64_t hidden = 0;            // cubes skipped because their pixels were already higher
  std::uint64_t voxels_evaluated = 0;  // voxel centers evaluated one by one
  std::uint64_t tape_clauses = 0;      // sum over cubes of the tape length they were evaluated with
};

struct ShadedImage {
  Image image;                         // the shaded picture
  int depth = 0;                       // voxels along z that were used
  std::vector<std::uint32_t> heights;  // per pixel (row-major like image): 0 or k + 1
};

// Renders the implicit solid of `tape` (one output; inputs any subset of x(0), x(1), x(2)).
// Throws std::invalid_argument naming the problem for a bad tape or bad options.
ShadedImage render_shaded(const Tape& tape, const ShadedOptions& options = {}, ShadedStats* stats = nullptr);

// The same image by marching down every pixel's column of voxel centers with the full tape
// until the first f < 0 (BatchEvaluator, a column block at a time). The reference for tests
// and benchmarks; tile_sizes is ignored.
ShadedImage render_shaded_brute_force(const Tape& tape, const ShadedOptions& options = {});

}  // namespace genmod
