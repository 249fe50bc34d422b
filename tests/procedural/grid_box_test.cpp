#include "genmod/procedural/grid_box.hpp"
#include "genmod/tessellate/validate.hpp"

#include <gtest/gtest.h>

namespace genmod {
namespace {

TEST(GridBox, CountsClosednessAndExactPlanes) {
  for (int n : {1, 2, 3, 5}) {
    const PolyMesh box = make_grid_box(Vec3(-1, 0, 2), Vec3(0.5, 3, 2.7), n, "body");
    const std::size_t nn = static_cast<std::size_t>(n) * n;
    EXPECT_EQ(counts(box), (MeshCounts{6 * nn + 2, 12 * nn, 6 * nn})) << n;
    EXPECT_TRUE(is_closed_manifold(box));
    EXPECT_EQ(faces_labelled(box, "body").size(), 6 * nn);
    // Every vertex lies on the surface: some coordinate equals lo or hi exactly.
    for (auto v : box.vertices()) {
      const Vec3& p = box.point(v);
      EXPECT_TRUE(p[0] == -1 || p[0] == 0.5 || p[1] == 0 || p[1] == 3 || p[2] == 2 || p[2] == 2.7);
    }
    const MeshValidity report = validate(to_triangle_mesh(box));
    EXPECT_TRUE(report.valid()) << describe(report);
    EXPECT_EQ(report.euler_characteristic, 2);
    EXPECT_NEAR(report.volume, 1.5 * 3 * 0.7, 1e-12);
  }
}

TEST(GridBox, BadInputIsRefused) {
  EXPECT_THROW(make_grid_box(Vec3(0, 0, 0), Vec3(1, 1, 1), 0), std::invalid_argument);
  EXPECT_THROW(make_grid_box(Vec3(0, 0, 0), Vec3(1, 1, 0), 2), std::invalid_argument);
  EXPECT_THROW(make_grid_box(Vec3(0, 0, 0), Vec3(INFINITY, 1, 1), 2), std::invalid_argument);
}

}  // namespace
}  // namespace genmod
