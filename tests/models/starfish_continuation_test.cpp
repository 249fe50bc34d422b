// research/bloomenthal.md §11 claim 27 for the starfish: the tetrahedral continuation
// polygonizer's mesh of the combination surface is a closed 2-manifold of Euler
// characteristic 2 (the sphere and torus parts are in tests/tessellate).
#include "genmod/models/starfish.hpp"
#include "genmod/tessellate/continuation_polygonizer.hpp"
#include "genmod/tessellate/validate.hpp"

#include <gtest/gtest.h>

namespace genmod::models {
namespace {

TEST(BloomenthalClaims, Claim27StarfishContinuationIsAClosedManifold) {
  // Start above the joint centre, where the combination surface is at z ~ 0.1026 (claim 13).
  const ContinuationMesh m =
      polygonize_continuation(starfish_implicit(StarfishVariant::combination), {.cube_size = 0.02, .starts = {{0, 0, 0.1}}});
  const MeshValidity v = validate(m.mesh);
  EXPECT_TRUE(v.valid()) << describe(v);
  EXPECT_TRUE(v.closed() && v.manifold() && v.oriented());
  EXPECT_EQ(v.components, 1u);
  EXPECT_EQ(v.euler_characteristic, 2);
  EXPECT_EQ(2 * v.edges, 3 * v.triangles);  // every edge in exactly two triangles
  EXPECT_TRUE(m.stats.limits_hit.empty());
  // It reaches the free ends of the limbs (spec §7.1: x in [-0.51, 0.71]).
  double lo = 1e9, hi = -1e9;
  for (const auto& p : m.mesh.vertices) lo = std::min(lo, p[0]), hi = std::max(hi, p[0]);
  EXPECT_NEAR(lo, -0.51, 0.02);
  EXPECT_NEAR(hi, 0.71, 0.02);
}

}  // namespace
}  // namespace genmod::models
