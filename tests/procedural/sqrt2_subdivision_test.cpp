#include "genmod/procedural/grid_box.hpp"
#include "genmod/procedural/selection.hpp"
#include "genmod/procedural/sqrt2_subdivision.hpp"
#include "genmod/tessellate/validate.hpp"
#include "mesh_test_support.hpp"

#include "tool_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace genmod {
namespace {

using test::expect_valid_closed;

bool all_quads(const PolyMesh& mesh) {
  for (auto f : mesh.faces())
    if (mesh.valence(f) != 4) return false;
  return true;
}

double max_abs_coordinate(const PolyMesh& mesh) {
  double m = 0;
  for (auto v : mesh.vertices())
    for (int a = 0; a < 3; ++a) m = std::max(m, std::abs(mesh.point(v)[a]));
  return m;
}

PolyMesh unit_cube() { return make_box(Vec3(-1, -1, -1), Vec3(1, 1, 1)); }

// Claim 22.
TEST(Sqrt2Subdivision, CubeCountsDoubleAndEveryFaceIsAQuad) {
  PolyMesh cube = unit_cube();
  const MeshCounts expected[] = {{14, 24, 12}, {26, 48, 24}, {50, 96, 48}};
  for (const MeshCounts& c : expected) {
    const MeshCounts before = counts(cube);
    sqrt2_subdivide_all(cube, 1, 1.0);
    EXPECT_EQ(counts(cube), c);
    EXPECT_EQ(counts(cube), (MeshCounts{before.vertices + before.faces, 2 * before.edges, before.edges}));
    EXPECT_TRUE(all_quads(cube));
    expect_valid_closed(cube);
  }
}

TEST(Sqrt2Subdivision, TetrahedronBecomesSixQuads) {
  PolyMesh tet = test::make_tetrahedron();
  expect_valid_closed(tet);
  sqrt2_subdivide_all(tet, 1, 1.0);
  EXPECT_EQ(counts(tet), (MeshCounts{8, 12, 6}));
  EXPECT_TRUE(all_quads(tet));
  expect_valid_closed(tet);
}

// Claim 23.
TEST(Sqrt2Subdivision, SmoothingFactorZeroKeepsOldVerticesBitwise) {
  PolyMesh mesh = make_grid_box(Vec3(-1, -2, 0.5), Vec3(3, 1, 2), 2);
  const test::Snapshot before = test::snapshot(mesh);
  sqrt2_subdivide_all(mesh, 1, 0.0);
  for (std::size_t i = 0; i < before.points.size(); ++i)
    EXPECT_EQ(mesh.point(PolyMesh::VertexHandle(static_cast<int>(i))), before.points[i]);
}

TEST(Sqrt2Subdivision, OldVerticesAreAffineInTheSmoothingFactor) {
  // One level: the face points do not depend on s, so the old vertices are affine in it.
  PolyMesh a0 = make_grid_box(Vec3(-1, -2, 0.5), Vec3(3, 1, 2), 2), a1 = a0, ah = a0;
  sqrt2_subdivide_all(a0, 1, 0.0);
  sqrt2_subdivide_all(a1, 1, 1.0);
  sqrt2_subdivide_all(ah, 1, 0.5);
  for (auto v : a0.vertices()) {
    const Vec3 mid = (a0.point(v) + a1.point(v)) * 0.5;
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(ah.point(v)[a], mid[a], 1e-15 * 4);
  }
}

TEST(Sqrt2Subdivision, CubeCornerUnderTheRule) {
  const struct { double s, expected; } cases[] = {{1.0, 1.0 / 3}, {2.0, -1.0 / 3}, {-2.0, 7.0 / 3}, {0.0, 1.0}};
  for (const auto& c : cases) {
    PolyMesh cube = unit_cube();
    ASSERT_EQ(cube.point(PolyMesh::VertexHandle(7)), Vec3(1, 1, 1));
    sqrt2_subdivide_all(cube, 1, c.s);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(cube.point(PolyMesh::VertexHandle(7))[a], c.expected, 1e-15) << "s = " << c.s;
    EXPECT_TRUE(is_closed_manifold(cube));
  }
  PolyMesh star = unit_cube();
  sqrt2_subdivide_all(star, 2, 2.0);  // Fig. 5.7's star runs without error
  EXPECT_EQ(counts(star), (MeshCounts{26, 48, 24}));
}

// Claim 24.
TEST(Sqrt2Subdivision, RepeatedSmoothingShrinksTheCube) {
  PolyMesh cube = unit_cube();
  const double expected[] = {1.0, 1.0, 0.41667, 0.38194};
  EXPECT_EQ(max_abs_coordinate(cube), expected[0]);
  for (int step = 1; step <= 3; ++step) {
    sqrt2_subdivide_all(cube, 1, 1.0);
    EXPECT_NEAR(max_abs_coordinate(cube), expected[step], 5e-6) << "step " << step;
  }
}

TEST(Sqrt2Subdivision, SmoothingInZeroOneStaysInTheInputBox) {
  for (double s : {0.0, 0.3, 1.0}) {
    PolyMesh mesh = make_grid_box(Vec3(-1, -2, 0.5), Vec3(3, 1, 2), 2);
    sqrt2_subdivide_all(mesh, 3, s);
    const auto [lo, hi] = bounds(mesh, all_faces(mesh));
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(lo[a], (Vec3(-1, -2, 0.5))[a]);
      EXPECT_LE(hi[a], (Vec3(3, 1, 2))[a]);
    }
  }
}

TEST(Sqrt2Subdivision, PlanarRegionStaysPlanarForAnySmoothing) {
  for (double s : {-2.0, 0.5, 2.0}) {
    PolyMesh mesh = make_grid_box(Vec3(0, 0, 0), Vec3(4, 4, 4), 4);
    FaceList top = select_faces(mesh, all_faces(mesh), RatioBox{0, 1, 0, 1, 1, 1});
    FaceList created = sqrt2_subdivide(mesh, top, 2, s);
    ASSERT_FALSE(created.empty());
    for (auto f : created)
      for (auto v : mesh.fv_range(f)) EXPECT_NEAR(mesh.point(v)[2], 4.0, 1e-12) << "s = " << s;
    EXPECT_TRUE(is_closed_manifold(mesh));
  }
}

// Claim 25.
TEST(Sqrt2Subdivision, AdaptiveOneCubeFace) {
  PolyMesh cube = make_box(Vec3(-1, -1, -1), Vec3(1, 1, 1), "body");
  FaceList top = select_faces(cube, all_faces(cube), RatioBox{0, 1, 0, 1, 1, 1});
  set_face_label(cube, top[0], "lid");
  std::vector<std::vector<Vec3>> outside;
  for (auto f : cube.faces())
    if (f != top[0]) outside.push_back(test::position_ring(cube, f));
  const test::Snapshot before = test::snapshot(cube);
  ASSERT_EQ(top[0].idx(), 1);  // so the outside faces 0, 2..5 become 0..4
  FaceList created = sqrt2_subdivide(cube, top, 1, 1.0);
  EXPECT_EQ(counts(cube), (MeshCounts{9, 16, 9}));
  ASSERT_EQ(created.size(), 4u);
  for (auto f : created) {
    EXPECT_EQ(cube.valence(f), 3u);
    EXPECT_EQ(face_label(cube, f), "lid");
  }
  // The five faces outside come first, with their vertex lists and positions bitwise.
  for (int i = 0; i < 5; ++i) {
    const auto f = PolyMesh::FaceHandle(i);
    EXPECT_EQ(test::position_ring(cube, f), outside[i]);
    EXPECT_EQ(test::snapshot(cube).faces[i], before.faces[i < 1 ? i : i + 1]) << i;
    EXPECT_EQ(face_label(cube, f), "body");
  }
  expect_valid_closed(cube);
}

TEST(Sqrt2Subdivision, AdaptivePatchMakesOneTrianglePerBoundaryEdge) {
  PolyMesh mesh = make_grid_box(Vec3(0, 0, 0), Vec3(4, 4, 4), 4);
  FaceList patch = select_faces(mesh, all_faces(mesh), RatioBox{0.25, 0.75, 0.25, 0.75, 1, 1});
  ASSERT_EQ(patch.size(), 4u);
  FaceList created = sqrt2_subdivide(mesh, patch, 1, 1.0);
  // 12 edges touch the patch: 4 inside (quads) and 8 on its boundary (triangles).
  std::size_t triangles = 0;
  for (auto f : created) triangles += mesh.valence(f) == 3;
  EXPECT_EQ(created.size(), 12u);
  EXPECT_EQ(triangles, 8u);
  expect_valid_closed(mesh);
  // A second level refines the created faces; the mesh stays closed.
  FaceList again = sqrt2_subdivide(mesh, created, 2, 0.5);
  EXPECT_FALSE(again.empty());
  expect_valid_closed(mesh);
}

// Claim 18.
TEST(Sqrt2Subdivision, EmptySetOrZeroLevelsLeaveTheMeshBitwiseUnchanged) {
  PolyMesh mesh = make_grid_box(Vec3(0, 0, 0), Vec3(1, 2, 3), 2, "a");
  const test::Snapshot before = test::snapshot(mesh);
  EXPECT_TRUE(sqrt2_subdivide(mesh, {}, 2, 1.0).empty());
  EXPECT_TRUE(sqrt2_subdivide(mesh, all_faces(mesh), 0, 1.0).empty());
  EXPECT_EQ(test::snapshot(mesh), before);
}

TEST(Sqrt2Subdivision, BadInputIsRefused) {
  PolyMesh cube = unit_cube();
  EXPECT_THROW(sqrt2_subdivide(cube, {PolyMesh::FaceHandle(6)}, 1, 1.0), std::invalid_argument);
  EXPECT_THROW(sqrt2_subdivide(cube, all_faces(cube), -1, 1.0), std::invalid_argument);
  try {
    sqrt2_subdivide(cube, all_faces(cube), 1, NAN);
    ADD_FAILURE() << "a NaN smoothing factor was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("sqrt2_subdivide"), std::string::npos);
  }
}

}  // namespace
}  // namespace genmod

namespace genmod {
namespace {

// On an open mesh the boundary vertices stay and each boundary edge gives a triangle.
TEST(Sqrt2Subdivision, LoneQuadOnAnOpenMesh) {
  PolyMesh quad = test::unit_quad();
  FaceList created = sqrt2_subdivide(quad, all_faces(quad), 1, 1.0);
  EXPECT_EQ(counts(quad), (MeshCounts{5, 8, 4}));
  EXPECT_EQ(created.size(), 4u);
  EXPECT_EQ(quad.point(PolyMesh::VertexHandle(0)), Vec3(0, 0, 0));
  EXPECT_EQ(quad.point(PolyMesh::VertexHandle(4)), Vec3(0.5, 0.5, 0));
}

TEST(Sqrt2Subdivision, SameInputGivesTheSameMesh) {
  PolyMesh a = make_grid_box(Vec3(0, 0, 0), Vec3(4, 4, 4), 3, "x"), b = a;
  FaceList half = select_faces(a, all_faces(a), RatioBox{0, 1, 0, 1, 0.5, 1});
  sqrt2_subdivide(a, half, 2, 0.7);
  sqrt2_subdivide(b, half, 2, 0.7);
  EXPECT_EQ(test::snapshot(a), test::snapshot(b));
  expect_valid_closed(a);
}

}  // namespace
}  // namespace genmod
