// PNG I/O through libpng's simplified API (png_image), which reports errors through a message
// in the png_image instead of longjmp, so no C++ frame is ever skipped.
#include "genmod/tessellate/png_io.hpp"

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

namespace genmod {
namespace {

struct FileCloser {
  void operator()(std::FILE* f) const noexcept { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

File open_file(const std::string& path, const char* mode, const char* verb) {
  std::FILE* f = std::fopen(path.c_str(), mode);
  if (f == nullptr) throw PngError("genmod: cannot " + std::string(verb) + " '" + path + "': " + std::strerror(errno));
  return File(f);
}

png_image gray_image_header(png_uint_32 width, png_uint_32 height) {
  png_image header;
  std::memset(&header, 0, sizeof header);
  header.version = PNG_IMAGE_VERSION;
  header.width = width;
  header.height = height;
  header.format = PNG_FORMAT_GRAY;
  return header;
}

}  // namespace

namespace {

// std::invalid_argument for an image without pixels or with a buffer of the wrong size.
void check_image(const Image& image, const std::string& what) {
  if (image.width <= 0 || image.height <= 0)
    throw std::invalid_argument("genmod: " + what + ": the image is empty (" + std::to_string(image.width) + " x " +
                                std::to_string(image.height) + ")");
  if (image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
    throw std::invalid_argument("genmod: " + what + ": " + std::to_string(image.pixels.size()) + " pixels for a " +
                                std::to_string(image.width) + " x " + std::to_string(image.height) + " image");
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image) {
  check_image(image, "encode_png");
  png_image header = gray_image_header(static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height));
  header.flags = PNG_IMAGE_FLAG_FAST;
  png_alloc_size_t size = 0;  // first call: the size needed
  if (png_image_write_to_memory(&header, nullptr, &size, 0, image.pixels.data(), 0, nullptr) == 0)
    throw PngError(std::string("genmod: cannot encode PNG: ") + header.message);
  std::vector<std::uint8_t> bytes(size);
  if (png_image_write_to_memory(&header, bytes.data(), &size, 0, image.pixels.data(), 0, nullptr) == 0)
    throw PngError(std::string("genmod: cannot encode PNG: ") + header.message);
  bytes.resize(size);
  return bytes;
}

void write_png(const std::string& path, const Image& image) {
  check_image(image, "write_png '" + path + "'");
  File file = open_file(path, "wb", "create");
  png_image header = gray_image_header(static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height));
  // Binary sign images compress well even at zlib's fast setting.
  header.flags = PNG_IMAGE_FLAG_FAST;
  const bool written = png_image_write_to_stdio(&header, file.get(), 0, image.pixels.data(), 0, nullptr) != 0;
  // fclose flushes: a full disk shows up here, not in libpng.
  const bool closed = std::fclose(file.release()) == 0;
  if (!written || !closed) {
    const std::string why = !written ? std::string(header.message) : std::strerror(errno);
    // No truncated file left behind; but never remove what is not a regular file (/dev/full).
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) std::filesystem::remove(path, ec);
    throw PngError("genmod: cannot write PNG '" + path + "': " + why);
  }
}

Image read_png(const std::string& path) {
  File file = open_file(path, "rb", "open");
  png_image header;
  std::memset(&header, 0, sizeof header);
  header.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_stdio(&header, file.get()) == 0)
    throw PngError("genmod: cannot read PNG '" + path + "': " + header.message);
  header.format = PNG_FORMAT_GRAY;
  Image image;
  try {
    image = Image(static_cast<int>(header.width), static_cast<int>(header.height));
  } catch (...) {
    png_image_free(&header);
    throw;
  }
  if (png_image_finish_read(&header, nullptr, image.pixels.data(), 0, nullptr) == 0)
    throw PngError("genmod: cannot read PNG '" + path + "': " + header.message);
  return image;
}

}  // namespace genmod
