#include "shaded_common.hpp"

#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/kernel/gradient_evaluator.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace genmod::shaded_detail {
namespace {

void check_range(const Interval& r, const char* axis, const char* who) {
  if (r.is_empty() || !r.is_bounded() || !(r.lo() < r.hi())) {
    std::ostringstream os;
    os << "genmod: " << who << ": the box's " << axis << " range must be bounded with nonzero width, got " << r;
    throw std::invalid_argument(os.str());
  }
}

void check_count(int n, const char* what, const char* who) {
  if (n < 1 || n > kMaxShadedSize)
    throw std::invalid_argument(std::string("genmod: ") + who + ": " + what + " must be in [1, " +
                                std::to_string(kMaxShadedSize) + "], got " + std::to_string(n));
}

std::vector<double> centers(const Interval& r, int n, bool descending) {
  std::vector<double> c(static_cast<std::size_t>(n));
  const double h = (r.hi() - r.lo()) / n;
  for (int i = 0; i < n; ++i) c[static_cast<std::size_t>(i)] = descending ? r.hi() - (i + 0.5) * h : r.lo() + (i + 0.5) * h;
  return c;
}

// 40 + 215 max(0, cos(normal, light)); a zero or non-finite gradient counts as facing the light.
std::uint8_t lambert_value(double gx, double gy, double gz, double lx, double ly, double lz, double ln) {
  const double norm = std::sqrt(gx * gx + gy * gy + gz * gz);
  const double c = norm > 0 && std::isfinite(norm) ? (gx * lx + gy * ly + gz * lz) / (norm * ln) : 1.0;
  return static_cast<std::uint8_t>(std::lround(40.0 + 215.0 * std::clamp(c, 0.0, 1.0)));
}

// Bisection steps from the hit voxel's center toward the one above: 1/256 of a voxel.
constexpr int kBisections = 8;

}  // namespace

VoxelGrid::VoxelGrid(const ShadedOptions& options, const char* who) {
  check_count(options.size, "size", who);
  check_range(options.box[0], "x", who);
  check_range(options.box[1], "y", who);
  check_range(options.box[2], "z", who);
  int depth = options.depth;
  if (depth == 0) {
    const double cubes = options.size * (options.box[2].hi() - options.box[2].lo()) / (options.box[0].hi() - options.box[0].lo());
    depth = static_cast<int>(std::clamp(std::ceil(cubes), 1.0, static_cast<double>(kMaxShadedSize)));
  }
  check_count(depth, "depth", who);
  xs_ = centers(options.box[0], options.size, false);
  ys_ = centers(options.box[1], options.size, true);
  zs_ = centers(options.box[2], depth, false);
}

SpaceInputs space_inputs(const Tape& tape, const char* who) {
  if (tape.num_outputs() != 1)
    throw std::invalid_argument(std::string("genmod: ") + who + ": the function must be scalar, it has " +
                                std::to_string(tape.num_outputs()) + " outputs");
  SpaceInputs s;
  for (int coordinate : tape.inputs()) {
    if (coordinate < 0 || coordinate > 2)
      throw std::invalid_argument(std::string("genmod: ") + who + ": the function depends on x(" +
                                  std::to_string(coordinate) + "); a 3-D render takes only x(0), x(1) and x(2)");
    s.axis[s.count++] = coordinate;
  }
  return s;
}

Image shade(const Tape& tape, const SpaceInputs& in, const VoxelGrid& grid, const std::vector<std::uint32_t>& heights) {
  const int n = grid.size();
  Image image(n, n);
  // Light from the upper left, in front of the picture.
  const double lx = -0.4, ly = 0.5, lz = 0.77;
  const double ln = std::sqrt(lx * lx + ly * ly + lz * lz);
  struct Scratch {
    GradientEvaluator gradients;
    BatchEvaluator points;
    std::array<std::vector<double>, 3> coordinates;
    std::vector<double> below, above, values;
    std::vector<int> columns;
  };
  tbb::enumerable_thread_specific<Scratch> scratch;
  tbb::parallel_for(tbb::blocked_range<int>(0, n), [&](const tbb::blocked_range<int>& rows) {
    Scratch& s = scratch.local();
    for (int row = rows.begin(); row < rows.end(); ++row) {
      // The hit voxel's center has f < 0 and the center above it not: bisect between them (a
      // whole row at once) so that the normal is taken at the surface, not somewhere inside
      // (where a field like 2 sqrt|s| - 1 turns its gradient around).
      s.columns.clear();
      s.below.clear();
      s.above.clear();
      const std::uint32_t* row_heights = heights.data() + static_cast<std::size_t>(row) * static_cast<std::size_t>(n);
      for (int column = 0; column < n; ++column) {
        const std::uint32_t h = row_heights[column];
        if (h == 0) continue;
        if (h == static_cast<std::uint32_t>(grid.depth())) {
          image.at(column, row) = lambert_value(0, 0, 1, lx, ly, lz, ln);  // the box's cut face
          continue;
        }
        s.columns.push_back(column);
        s.below.push_back(grid.z(static_cast<int>(h) - 1));
        s.above.push_back(grid.z(static_cast<int>(h)));
      }
      const std::size_t m = s.columns.size();
      if (m == 0) continue;
      for (auto& c : s.coordinates) c.resize(m);
      s.values.resize(m);
      for (std::size_t i = 0; i < m; ++i) {
        s.coordinates[0][i] = grid.x(s.columns[i]);
        s.coordinates[1][i] = grid.y(row);
      }
      std::array<const double*, 3> inputs{};
      for (std::size_t k = 0; k < in.count; ++k) inputs[k] = s.coordinates[static_cast<std::size_t>(in.axis[k])].data();
      for (int step = 0; step < kBisections; ++step) {
        for (std::size_t i = 0; i < m; ++i) s.coordinates[2][i] = 0.5 * (s.below[i] + s.above[i]);
        double* out = s.values.data();
        s.points.eval(tape, std::span(inputs.data(), in.count), m, std::span(&out, 1));
        for (std::size_t i = 0; i < m; ++i) (s.values[i] < 0.0 ? s.below[i] : s.above[i]) = s.coordinates[2][i];
      }
      for (std::size_t i = 0; i < m; ++i) {
        const std::array<double, 3> p{s.coordinates[0][i], s.coordinates[1][i], s.below[i]};
        std::array<double, 3> point{};
        for (std::size_t k = 0; k < in.count; ++k) point[k] = p[static_cast<std::size_t>(in.axis[k])];
        s.gradients.eval(tape, std::span<const double>(point.data(), in.count));
        std::array<double, 3> g{0.0, 0.0, 0.0};
        for (std::size_t k = 0; k < in.count; ++k) g[static_cast<std::size_t>(in.axis[k])] = s.gradients.jacobian()[k];
        image.at(s.columns[i], row) = lambert_value(g[0], g[1], g[2], lx, ly, lz, ln);
      }
    }
  });
  return image;
}

}  // namespace genmod::shaded_detail
