// CSG of trimmed surfaces (Algorithm 5.4, trimmed_csg.hpp): claim 38 (the drilled bumpy sphere)
// and the union / intersection of two spheres against their exact volumes.
#include "genmod/models/trimmed_csg.hpp"
#include "genmod/tessellate/validate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

namespace genmod::models {
namespace {

const TrimmedCsgResult& drilled() {
  static const TrimmedCsgResult r = mesh_csg_model("drilled_sphere");
  return r;
}

// Claim 38: one closed, manifold, outward mesh without self-intersections, genus 1.
TEST(TrimmedCsg, DrilledSphereIsValidGenusOne) {
  const TrimmedCsgResult& r = drilled();
  EXPECT_TRUE(r.curve_complete);
  EXPECT_EQ(r.curve_components, 2u);
  const MeshValidity v = validate(r.mesh);
  EXPECT_TRUE(v.valid()) << describe(v);
  EXPECT_EQ(v.components, 1u);
  EXPECT_EQ(v.euler_characteristic, 0);
  EXPECT_EQ(v.coincident_vertices, 0u);
  EXPECT_GT(r.triangles_first, 0u);
  EXPECT_GT(r.triangles_second, 0u);
  // Every sampling leaf met the box-size criterion (none stopped at max_depth).
  EXPECT_EQ(r.capped_leaves, 0u);
  // No intersection leaf was subdivided by the merge with the sampling trees.
  EXPECT_EQ(r.samples_inside_curve_leaves, 0u);
  // Smaller than the bumpy sphere's volume bound and larger than the sphere minus the
  // cylinder's bounding box would leave.
  EXPECT_GT(v.volume, 3.0);
  EXPECT_LT(v.volume, 4.0 / 3.0 * std::numbers::pi * 1.1 * 1.1 * 1.1);
}

// Claim 38: the seam vertices are the same vertices (bitwise the same samples) in both trimmed
// pieces: each is used by triangles of the sphere and of the cylinder.
TEST(TrimmedCsg, SeamVerticesAreShared) {
  const TrimmedCsgResult& r = drilled();
  ASSERT_GT(r.seam.size(), 20u);
  EXPECT_EQ(r.seam_vertices_in_both, r.seam.size());
  // The sphere piece's triangles come first.
  std::set<std::uint32_t> a, b;
  for (std::size_t i = 0; i < r.mesh.triangles.size(); ++i)
    for (std::uint32_t k : r.mesh.triangles[i]) (i < r.triangles_first ? a : b).insert(k);
  for (std::uint32_t s : r.seam) {
    EXPECT_TRUE(a.count(s) && b.count(s)) << s;
  }
  // No two vertices share a position: the pieces are welded, not duplicated.
  std::set<std::array<double, 3>> positions(r.mesh.vertices.begin(), r.mesh.vertices.end());
  EXPECT_EQ(positions.size(), r.mesh.vertices.size());
}

// Vertices on the true surfaces: cylinder-piece vertices on the cylinder (the seam within the
// curve's tolerance), and every vertex inside the bumpy sphere's shell (1 +- 0.1)^2.
TEST(TrimmedCsg, VerticesOnTheSurfaces) {
  const TrimmedCsgResult& r = drilled();
  std::set<std::uint32_t> seam(r.seam.begin(), r.seam.end());
  std::set<std::uint32_t> b;
  for (std::size_t i = r.triangles_first; i < r.mesh.triangles.size(); ++i)
    for (std::uint32_t k : r.mesh.triangles[i]) b.insert(k);
  double worst_seam = 0.0;
  for (std::uint32_t k : b) {
    const auto& p = r.mesh.vertices[k];
    const double d = std::abs(std::hypot(p[1], p[2]) - 0.3);
    if (seam.count(k))
      worst_seam = std::max(worst_seam, d);
    else
      EXPECT_LT(d, 1e-12);
    EXPECT_LT(std::abs(p[0]), 1.1 * 1.1 + 1e-9);
  }
  EXPECT_LT(worst_seam, 1e-4);
  for (const auto& p : r.mesh.vertices) {
    const double n = std::hypot(p[0], p[1], p[2]);
    EXPECT_LT(n, 1.1 * 1.1 + 1e-9);
  }
}

// Two unit spheres with centres 1 apart: the lens has volume 5π/12, the union 8π/3 - 5π/12.
TEST(TrimmedCsg, UnionAndIntersectionOfSpheres) {
  const ClosedSurface a = sphere_surface(1.0, 0.0, 0.0, 0.0), b = sphere_surface(1.0, 1.0, 0.0, 0.0);
  const double lens = 5.0 * std::numbers::pi / 12.0;
  const double both = 8.0 * std::numbers::pi / 3.0 - lens;
  const TrimmedCsgResult i = trimmed_csg(a, b, CsgOperation::Intersection);
  // Vertices on the spheres: samples exactly (to rounding), seam vertices on both.
  auto off = [](const std::array<double, 3>& p, double cx) { return std::abs(std::hypot(p[0] - cx, p[1], p[2]) - 1.0); };
  for (const auto& p : i.mesh.vertices) EXPECT_LT(std::min(off(p, 0.0), off(p, 1.0)), 1e-12);
  for (std::uint32_t k : i.seam) EXPECT_LT(std::max(off(i.mesh.vertices[k], 0.0), off(i.mesh.vertices[k], 1.0)), 1e-6);
  // Triangle centroids within the sampling's chord error of a sphere.
  double worst = 0.0;
  for (const auto& t : i.mesh.triangles) {
    std::array<double, 3> c{};
    for (std::uint32_t k : t)
      for (int j = 0; j < 3; ++j) c[j] += i.mesh.vertices[k][j] / 3.0;
    worst = std::max(worst, std::min(off(c, 0.0), off(c, 1.0)));
  }
  EXPECT_LT(worst, 0.01);
  EXPECT_EQ(i.samples_inside_curve_leaves, 0u);
  const MeshValidity vi = validate(i.mesh);
  EXPECT_TRUE(vi.valid()) << describe(vi);
  EXPECT_EQ(vi.euler_characteristic, 2);
  EXPECT_NEAR(vi.volume, lens, 0.02 * lens);
  EXPECT_EQ(i.seam_vertices_in_both, i.seam.size());
  const TrimmedCsgResult u = trimmed_csg(a, b, CsgOperation::Union);
  const MeshValidity vu = validate(u.mesh);
  EXPECT_TRUE(vu.valid()) << describe(vu);
  EXPECT_EQ(vu.euler_characteristic, 2);
  EXPECT_NEAR(vu.volume, both, 0.02 * both);
  EXPECT_EQ(u.seam_vertices_in_both, u.seam.size());
  const TrimmedCsgResult d = trimmed_csg(a, b, CsgOperation::Difference);
  const MeshValidity vd = validate(d.mesh);
  EXPECT_TRUE(vd.valid()) << describe(vd);
  EXPECT_NEAR(vd.volume, 4.0 * std::numbers::pi / 3.0 - lens, 0.02 * lens * 4);
}

}  // namespace
}  // namespace genmod::models

namespace genmod::models {
namespace {

// (A - B) - C (§5.5): the drilled sphere minus a second bore that does not meet the first:
// one closed, valid mesh of genus 2, every seam vertex shared by two pieces, and less volume
// than the drilled sphere.
TEST(TrimmedCsg, DrilledTwiceIsValidGenusTwo) {
  const TrimmedCsgResult r = mesh_csg_model("drilled_sphere_twice");
  const MeshValidity v = validate(r.mesh);
  EXPECT_TRUE(v.valid()) << describe(v);
  EXPECT_EQ(v.components, 1u);
  EXPECT_EQ(v.euler_characteristic, -2);
  EXPECT_EQ(r.curve_components, 4u);
  ASSERT_EQ(r.triangles_per_surface.size(), 3u);
  for (std::size_t t : r.triangles_per_surface) EXPECT_GT(t, 0u);
  EXPECT_EQ(r.seam_vertices_in_both, r.seam.size());
  const MeshValidity once = validate(drilled().mesh);
  EXPECT_LT(v.volume, once.volume);
  // The second bore removes about pi r^2 times its length inside the sphere (r = 0.2).
  EXPECT_NEAR(once.volume - v.volume, std::numbers::pi * 0.04 * 1.6, 0.05);
}

}  // namespace
}  // namespace genmod::models
