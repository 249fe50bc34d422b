// preview: a sphere is a filled disk of the framed radius, an inside-out mesh is darker, a cube
// seen along an axis covers its square exactly (no gaps or double draws on shared edges), and
// bad input is refused.
#include "genmod/tessellate/implicit_mesher.hpp"
#include "genmod/tessellate/preview.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace genmod {
namespace {

const Mesh& sphere_mesh() {
  static const Mesh mesh = [] {
    const Fn X = x(0), Y = x(1), Z = x(2);
    return mesh_implicit(sqrt(square(X) + square(Y) + square(Z)) - 0.8,
                         {Interval(-1, 1), Interval(-1, 1), Interval(-1, 1)}, {.min_feature = 0.03})
        .mesh;
  }();
  return mesh;
}

std::size_t covered(const Image& image) {
  std::size_t n = 0;
  for (std::uint8_t p : image.pixels) n += p != 255;
  return n;
}

// An axis-aligned cube [0, 1]^3 with outward triangles.
Mesh unit_cube() {
  Mesh m;
  for (int k = 0; k < 8; ++k) m.vertices.push_back({double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)});
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

TEST(Preview, SphereIsAFilledDiskOfTheFramedRadius) {
  const PreviewOptions o{.width = 200, .height = 200};
  const Image image = preview(sphere_mesh(), o);
  ASSERT_EQ(image.width, 200);
  ASSERT_EQ(image.height, 200);
  // Framed on the projected extent with a 5% margin: radius 0.9 * 200 / 2 = 90 pixels.
  const double radius = 90, centre = 100;
  const double area = std::numbers::pi * radius * radius;
  EXPECT_NEAR(double(covered(image)), area, 0.02 * area);
  std::size_t holes = 0, outside = 0;
  for (int j = 0; j < 200; ++j)
    for (int i = 0; i < 200; ++i) {
      const double r = std::hypot(i + 0.5 - centre, j + 0.5 - centre);
      if (r < radius - 2) holes += image.at(i, j) == 255;
      if (r > radius + 1) outside += image.at(i, j) != 255;
    }
  EXPECT_EQ(holes, 0u);
  EXPECT_EQ(outside, 0u);
}

TEST(Preview, InsideOutMeshIsDarker) {
  Mesh flipped = sphere_mesh();
  for (auto& t : flipped.triangles) std::swap(t[1], t[2]);
  const PreviewOptions o{.width = 160, .height = 160};
  const Image out = preview(sphere_mesh(), o), in = preview(flipped, o);
  EXPECT_NEAR(double(covered(in)), double(covered(out)), 0.01 * double(covered(out)));
  std::size_t bright_out = 0, dark_in = 0, n = 0;
  double sum_out = 0, sum_in = 0;
  for (std::size_t k = 0; k < out.pixels.size(); ++k) {
    if (out.pixels[k] == 255 || in.pixels[k] == 255) continue;
    ++n;
    bright_out += out.pixels[k] >= 60;
    dark_in += in.pixels[k] <= 80;
    sum_out += out.pixels[k];
    sum_in += in.pixels[k];
  }
  ASSERT_GT(n, 10000u);
  EXPECT_EQ(bright_out, n);  // the outside of a closed outward mesh: front faces only
  EXPECT_EQ(dark_in, n);     // the inside: back faces only
  EXPECT_LT(sum_in, 0.6 * sum_out);
}

TEST(Preview, CubeAlongAnAxisCoversItsSquareExactly) {
  // Seen from +z: the top face's two triangles fill the framed square, pixel centres on their
  // shared diagonal drawn once, and all at the same level.
  const Image image = preview(unit_cube(), {.width = 100, .height = 100, .view = {0, 0, 1}, .margin = 0.1});
  std::size_t inside = 0;
  for (int j = 0; j < 100; ++j)
    for (int i = 0; i < 100; ++i) {
      const bool in_square = i >= 10 && i < 90 && j >= 10 && j < 90;
      if (in_square) {
        inside += image.at(i, j) == image.at(10, 10);
      } else {
        EXPECT_EQ(image.at(i, j), 255) << i << " " << j;
      }
    }
  EXPECT_EQ(inside, 80u * 80u);
  EXPECT_LT(image.at(10, 10), 255);
  EXPECT_GE(image.at(10, 10), 60);
}

TEST(Preview, BadInputIsRefused) {
  EXPECT_THROW((void)preview(Mesh{}), std::invalid_argument);
  const Mesh cube = unit_cube();
  EXPECT_THROW((void)preview(cube, {.width = 0}), std::invalid_argument);
  EXPECT_THROW((void)preview(cube, {.height = 9000}), std::invalid_argument);
  EXPECT_THROW((void)preview(cube, {.view = {0, 0, 0}}), std::invalid_argument);
  EXPECT_THROW((void)preview(cube, {.margin = 0.5}), std::invalid_argument);
  Mesh bad = cube;
  bad.triangles.push_back({0, 1, 8});
  EXPECT_THROW((void)preview(bad), std::invalid_argument);
  bad = cube;
  bad.vertices[3][0] = INFINITY;
  EXPECT_THROW((void)preview(bad), std::invalid_argument);
  const Image one = preview(cube, {.width = 1, .height = 1});
  EXPECT_EQ(one.pixels.size(), 1u);
}

}  // namespace
}  // namespace genmod
