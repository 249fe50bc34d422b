// The reference shaded renderer: every pixel marches down its column of voxel centers with
// the full tape until the first f < 0.
#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/tessellate/shaded_render.hpp"
#include "shaded_common.hpp"
#include "thread_arena.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <vector>

namespace genmod {

ShadedImage render_shaded_brute_force(const Tape& tape, const ShadedOptions& options) {
  const shaded_detail::SpaceInputs in = shaded_detail::space_inputs(tape, "render_shaded_brute_force");
  const shaded_detail::VoxelGrid grid(options, "render_shaded_brute_force");
  const int n = grid.size(), depth = grid.depth();
  ShadedImage out;
  out.depth = depth;
  out.heights.assign(static_cast<std::size_t>(n) * static_cast<std::size_t>(n), 0);

  // A ray evaluates its voxels in blocks of kStep, from the top, and stops at the first hit.
  constexpr int kStep = 32;
  struct Scratch {
    BatchEvaluator points;
    std::array<std::vector<double>, 3> coordinates;
    std::vector<double> values;
  };
  tbb::enumerable_thread_specific<Scratch> scratch;
  raster_detail::run_with_threads(options.threads, "render_shaded_brute_force", [&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, n), [&](const tbb::blocked_range<int>& rows) {
      Scratch& s = scratch.local();
      for (auto& c : s.coordinates) c.resize(kStep);
      s.values.resize(kStep);
      for (int row = rows.begin(); row < rows.end(); ++row)
        for (int column = 0; column < n; ++column) {
          std::uint32_t& h = out.heights[static_cast<std::size_t>(row) * static_cast<std::size_t>(n) + static_cast<std::size_t>(column)];
          for (int top = depth; top > 0 && h == 0; top -= kStep) {
            const int count = std::min(kStep, top);
            for (int i = 0; i < count; ++i) {
              s.coordinates[0][static_cast<std::size_t>(i)] = grid.x(column);
              s.coordinates[1][static_cast<std::size_t>(i)] = grid.y(row);
              s.coordinates[2][static_cast<std::size_t>(i)] = grid.z(top - 1 - i);
            }
            std::array<const double*, 3> inputs{};
            for (std::size_t k = 0; k < in.count; ++k) inputs[k] = s.coordinates[static_cast<std::size_t>(in.axis[k])].data();
            double* values = s.values.data();
            s.points.eval(tape, std::span(inputs.data(), in.count), static_cast<std::size_t>(count), std::span(&values, 1));
            for (int i = 0; i < count; ++i)
              if (s.values[static_cast<std::size_t>(i)] < 0.0) {
                h = static_cast<std::uint32_t>(top - i);
                break;
              }
          }
        }
    });
    out.image = shaded_detail::shade(tape, in, grid, out.heights);
  });
  return out;
}

}  // namespace genmod
