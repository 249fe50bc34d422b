// The reference renderer: every pixel center evaluated with the full tape.
#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/tessellate/raster2d.hpp"
#include "pixel_grid.hpp"
#include "thread_arena.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <array>
#include <vector>

namespace genmod {

using raster_detail::kAxisX;

Image render_sign_brute_force(const Tape& tape, const RasterOptions& options) {
  const raster_detail::PlaneInputs in = raster_detail::plane_inputs(tape, "render_sign_brute_force");
  const raster_detail::PixelGrid grid(options);
  const int n = grid.size();
  Image image(n, n);

  // One row per batch: the row's x values are the grid's, its y value is repeated.
  struct Scratch {
    BatchEvaluator points;
    std::vector<double> ys, values;
  };
  tbb::enumerable_thread_specific<Scratch> scratch;
  raster_detail::run_with_threads(options.threads, "render_sign_brute_force", [&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, n), [&](const tbb::blocked_range<int>& rows) {
      Scratch& s = scratch.local();
      s.values.resize(static_cast<std::size_t>(n));
      for (int row = rows.begin(); row < rows.end(); ++row) {
        s.ys.assign(static_cast<std::size_t>(n), grid.y(row));
        std::array<const double*, 2> inputs{};
        for (std::size_t k = 0; k < in.count; ++k) inputs[k] = in.axis[k] == kAxisX ? grid.xs() : s.ys.data();
        double* out = s.values.data();
        s.points.eval(tape, std::span(inputs.data(), in.count), static_cast<std::size_t>(n), std::span(&out, 1));
        for (int column = 0; column < n; ++column)
          image.at(column, row) = raster_detail::pixel_value(s.values[static_cast<std::size_t>(column)]);
      }
    });
  });
  return image;
}

}  // namespace genmod
