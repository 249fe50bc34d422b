#include "pixel_grid.hpp"

#include <sstream>
#include <stdexcept>
#include <string>

namespace genmod::raster_detail {
namespace {

void check_range(const Interval& r, const char* name) {
  if (r.is_empty() || !r.is_bounded() || !(r.lo() < r.hi())) {
    std::ostringstream os;
    os << "genmod: render: " << name << " must be a bounded interval of nonzero width, got " << r;
    throw std::invalid_argument(os.str());
  }
}

}  // namespace

PixelGrid::PixelGrid(const RasterOptions& options) {
  if (options.size < 1 || options.size > kMaxRasterSize)
    throw std::invalid_argument("genmod: render: size must be in [1, " + std::to_string(kMaxRasterSize) + "], got " +
                                std::to_string(options.size));
  check_range(options.x_range, "x_range");
  check_range(options.y_range, "y_range");
  const int n = options.size;
  const double hx = (options.x_range.hi() - options.x_range.lo()) / n;
  const double hy = (options.y_range.hi() - options.y_range.lo()) / n;
  xs_.resize(static_cast<std::size_t>(n));
  ys_.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    xs_[static_cast<std::size_t>(i)] = options.x_range.lo() + (i + 0.5) * hx;
    ys_[static_cast<std::size_t>(i)] = options.y_range.hi() - (i + 0.5) * hy;
  }
}

PlaneInputs plane_inputs(const Tape& tape, const char* who) {
  if (tape.num_outputs() != 1)
    throw std::invalid_argument(std::string("genmod: ") + who + ": the function must be scalar, it has " +
                                std::to_string(tape.num_outputs()) + " outputs");
  PlaneInputs p;
  for (int coordinate : tape.inputs()) {
    if (coordinate != 0 && coordinate != 1)
      throw std::invalid_argument(std::string("genmod: ") + who + ": the function depends on x(" +
                                  std::to_string(coordinate) + "); a 2-D render takes only x(0) and x(1)");
    p.axis[p.count++] = coordinate == 0 ? kAxisX : kAxisY;
  }
  return p;
}

}  // namespace genmod::raster_detail
