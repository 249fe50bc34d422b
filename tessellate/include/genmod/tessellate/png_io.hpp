// 8-bit grayscale PNG files (libpng).
//
// Reading is here so that callers and tests can check a written file without depending on
// libpng themselves.
#pragma once

#include "genmod/tessellate/image.hpp"

#include <stdexcept>
#include <cstdint>
#include <string>
#include <vector>

namespace genmod {

// A PNG file could not be written or read; what() names the path and the problem.
class PngError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes `image` as an 8-bit grayscale PNG. Throws PngError (the file cannot be created, libpng
// fails) or std::invalid_argument (an empty image or a pixel buffer of the wrong size).
void write_png(const std::string& path, const Image& image);

// The bytes of `image` as an 8-bit grayscale PNG file (for a notebook or a network answer).
// Throws like write_png.
std::vector<std::uint8_t> encode_png(const Image& image);

// Reads a PNG, converting any colour type and bit depth to 8-bit grayscale (colour images
// become luminance; alpha is dropped). Throws PngError.
Image read_png(const std::string& path);

}  // namespace genmod
