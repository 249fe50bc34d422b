// Image: an 8-bit grayscale raster, the output of the 2-D renderers.
#pragma once

#include <cstdint>
#include <vector>

namespace genmod {

struct Image {
  int width = 0;
  int height = 0;
  // Row-major, row 0 at the top: pixel (column, row) is pixels[row * width + column].
  std::vector<std::uint8_t> pixels;

  Image() = default;
  // A width x height image filled with `value`. Throws std::invalid_argument for a negative
  // dimension.
  Image(int w, int h, std::uint8_t value = 0);

  std::uint8_t& at(int column, int row) { return pixels[static_cast<std::size_t>(row) * width + column]; }
  std::uint8_t at(int column, int row) const { return pixels[static_cast<std::size_t>(row) * width + column]; }

  friend bool operator==(const Image&, const Image&) = default;
};

}  // namespace genmod
