// PNG files: what is written reads back unchanged; failures name the path.
#include "genmod/tessellate/png_io.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace genmod {
namespace {

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("genmod_png_io_test_" + name)).string();
}

TEST(PngIo, RoundTripsEveryGrayLevel) {
  Image image(37, 11);
  for (int row = 0; row < image.height; ++row)
    for (int column = 0; column < image.width; ++column)
      image.at(column, row) = static_cast<std::uint8_t>((column * 7 + row * 31) % 256);
  const std::string path = temp_path("round_trip.png");
  write_png(path, image);
  const Image back = read_png(path);
  EXPECT_EQ(back.width, 37);
  EXPECT_EQ(back.height, 11);
  EXPECT_TRUE(back == image);
  std::remove(path.c_str());
}

TEST(PngIo, UnwritablePathFailsNamingIt) {
  const std::string path = "/nonexistent-genmod-dir/out.png";
  try {
    write_png(path, Image(4, 4));
    FAIL() << "no exception";
  } catch (const PngError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

TEST(PngIo, FullDeviceFailsAndIsNotRemoved) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  for (int size : {4, 600}) {  // within stdio's buffer (fails at the close) and beyond it
    Image noise(size, size);
    for (std::size_t k = 0; k < noise.pixels.size(); ++k) noise.pixels[k] = static_cast<std::uint8_t>(k * 2654435761u >> 13);
    EXPECT_THROW(write_png("/dev/full", noise), PngError) << size;
    EXPECT_TRUE(std::filesystem::exists("/dev/full"));
  }
}

TEST(PngIo, ReadingANonPngFailsNamingIt) {
  const std::string path = temp_path("not_a_png.png");
  {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fputs("definitely not a PNG file", f);
    std::fclose(f);
  }
  try {
    read_png(path);
    FAIL() << "no exception";
  } catch (const PngError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
  EXPECT_THROW(read_png(temp_path("missing.png")), PngError);
}

TEST(PngIo, RejectsAnEmptyImage) { EXPECT_THROW(write_png(temp_path("empty.png"), Image()), std::invalid_argument); }

}  // namespace
}  // namespace genmod
