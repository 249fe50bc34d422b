// The pixel-center convention and input checks shared by both sign renderers, so that the
// subdividing renderer and the brute-force reference sample exactly the same points.
#pragma once

#include "genmod/kernel/interval.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/tessellate/raster2d.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace genmod::raster_detail {

// The sample point of every pixel: column i at x.lo + (i + 0.5) * hx, row j at
// y.hi - (j + 0.5) * hy. The coordinates are computed once, in round-to-nearest, and both
// renderers read them from here.
class PixelGrid {
 public:
  // Throws std::invalid_argument for a bad size or region.
  explicit PixelGrid(const RasterOptions& options);

  int size() const noexcept { return static_cast<int>(xs_.size()); }
  const double* xs() const noexcept { return xs_.data(); }
  double x(int column) const noexcept { return xs_[static_cast<std::size_t>(column)]; }
  double y(int row) const noexcept { return ys_[static_cast<std::size_t>(row)]; }

  // The hull of the centers of columns [c0, c1) (c0 < c1); x(i) is nondecreasing in i
  // (rounding is monotone), so the hull is [x(c0), x(c1 - 1)] and holds every center exactly.
  Interval column_hull(int c0, int c1) const noexcept { return Interval::unchecked(x(c0), x(c1 - 1)); }
  // The hull of the centers of rows [r0, r1) (r0 < r1); y decreases with the row.
  Interval row_hull(int r0, int r1) const noexcept { return Interval::unchecked(y(r1 - 1), y(r0)); }

 private:
  std::vector<double> xs_, ys_;
};

// The pixel value for a function value at the pixel's center (NaN compares false: outside).
inline std::uint8_t pixel_value(double f) noexcept { return f < 0.0 ? kInside : kOutside; }

// Which image axis feeds each tape input: kAxisX for x(0), kAxisY for x(1).
enum Axis : std::uint8_t { kAxisX = 0, kAxisY = 1 };
struct PlaneInputs {
  std::array<Axis, 2> axis{};
  std::size_t count = 0;
};

// Checks that the tape is a scalar function of x(0) and x(1) only (std::invalid_argument
// naming the problem) and says which input is which.
PlaneInputs plane_inputs(const Tape& tape, const char* who);

}  // namespace genmod::raster_detail
