// Folds of the adaptive parametric mesher in flat regions: the distance bound allows in-plane
// distortion up to the tolerance, so a leaf much narrower than that may be triangulated into
// a backward triangle that overlaps its neighbours (fold_repair.hpp). The furry bear's scalp
// pieces, fanning out from a small root ellipse to a long cell side on its flat bottom, folded
// at tolerance 0.02 (20 intersecting pairs); this is that piece, alone and in the plane.
#include "genmod/tessellate/parametric_mesher.hpp"
#include "genmod/tessellate/validate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace genmod {
namespace {

// The piece between a small ellipse about (uc, vc) (radii a, b, its quarter from -45 to 45
// degrees) and the right side of the cell [ul, uh] x [vl, vh], (t, r) -> (1 - r) ellipse +
// r side, mapped to the plane by polar coordinates (angle 2 pi u, radius 4.63 v): the bear's
// flat bottom in the cell [12, 13] / 24 x [0.2 / 12, 1 / 12] near its 12-row root ring at (u, v) = (12.5 / 24, 1 / 24), hair radius 0.004.
SurfacePatch flat_fan_piece() {
  constexpr double pi = std::numbers::pi;
  const double uh = 13.0 / 24, vl = 0.2 / 12, vh = 1.0 / 12, uc = 12.5 / 24, vc = 1.0 / 24;
  const double slope = 4.63, a = 0.004 / (2 * pi * slope * vc), b = 0.004 / slope;
  const Fn t = x(0), r = x(1), phi = (t - 0.5) * (pi / 2);
  const Fn u = uc + ((1.0 - r) * (a * cos(phi)) + r * (uh - uc));
  const Fn v = vc + ((1.0 - r) * (b * sin(phi)) + r * ((vl - vc) + t * (vh - vl)));
  const Fn angle = u * (2 * pi), radius = v * slope;
  return {cat({radius * cos(angle), radius * sin(angle), Fn(0.0)})};
}

// Every triangle of the flat piece faces the same way (+z, as (t, r) is counter-clockwise in
// the plane) and no two overlap, at coarse and fine tolerances.
TEST(AdaptiveMeshFolds, FlatFanPieceNeverFolds) {
  for (const double tolerance : {0.005, 0.01, 0.02, 0.03, 0.05}) {
    const AdaptiveMesh m = mesh_adaptive({flat_fan_piece()}, {.tolerance = tolerance});
    ASSERT_FALSE(m.mesh.triangles.empty());
    std::size_t backward = 0;
    for (const auto& tri : m.mesh.triangles) {
      const auto& p = m.mesh.vertices[tri[0]];
      const auto& q = m.mesh.vertices[tri[1]];
      const auto& s = m.mesh.vertices[tri[2]];
      const double z = (q[0] - p[0]) * (s[1] - p[1]) - (q[1] - p[1]) * (s[0] - p[0]);
      backward += z <= 0.0 ? 1 : 0;
    }
    EXPECT_EQ(backward, 0u) << "tolerance " << tolerance << ": " << m.mesh.triangles.size() << " triangles";
    const MeshValidity v = validate(m.mesh);
    EXPECT_EQ(v.self_intersections, 0u) << "tolerance " << tolerance << "\n" << describe(v);
    EXPECT_LE(m.distance_bound, tolerance);
  }
}

}  // namespace
}  // namespace genmod
