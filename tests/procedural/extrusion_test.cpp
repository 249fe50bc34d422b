#include "genmod/procedural/extrusion.hpp"
#include "genmod/procedural/grid_box.hpp"
#include "genmod/procedural/selection.hpp"
#include "genmod/tessellate/validate.hpp"
#include "mesh_test_support.hpp"

#include "tool_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace genmod {
namespace {

using test::expect_valid_closed;

MeshCounts plus(MeshCounts c, std::size_t dv, std::size_t de, std::size_t df) {
  return {c.vertices + dv, c.edges + de, c.faces + df};
}

// Claim 19.
TEST(Extrusion, OneCubeFace) {
  PolyMesh cube = make_box(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  FaceList top = select_faces(cube, all_faces(cube), RatioBox{0, 1, 0, 1, 1, 1});
  ASSERT_EQ(top.size(), 1u);
  FaceList caps = extrude(cube, top, Vec3(0, 0, 0.5));
  EXPECT_EQ(counts(cube), (MeshCounts{12, 20, 10}));
  EXPECT_EQ(caps.size(), 1u);
  expect_valid_closed(cube);
}

TEST(Extrusion, TwoAdjacentCubeFacesHaveNoInternalWall) {
  PolyMesh cube = make_box(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  // +z and +x share the edge x = z = 1.
  FaceList faces = select_faces(cube, all_faces(cube), RatioBox{0, 1, 0, 1, 1, 1});
  FaceList side = select_faces(cube, all_faces(cube), RatioBox{1, 1, 0, 1, 0, 1});
  faces.insert(faces.end(), side.begin(), side.end());
  ASSERT_EQ(faces.size(), 2u);
  extrude(cube, faces, Vec3(0.5, 0, 0.5));
  EXPECT_EQ(counts(cube), (MeshCounts{14, 24, 12}));
  expect_valid_closed(cube);
  // No face lies in the old shared edge's wall: every face has a vertex off the plane x = z.
  for (auto f : cube.faces()) {
    bool off = false;
    for (auto v : cube.fv_range(f)) off |= cube.point(v)[0] != cube.point(v)[2];
    EXPECT_TRUE(off) << "face " << f.idx() << " is an internal wall";
  }
}

TEST(Extrusion, TwoByTwoPatchWithAnInteriorVertex) {
  PolyMesh mesh = make_grid_box(Vec3(0, 0, 0), Vec3(4, 4, 4), 4);
  const MeshCounts before = counts(mesh);
  FaceList patch = select_faces(mesh, all_faces(mesh), RatioBox{0.25, 0.75, 0.25, 0.75, 1, 1});
  ASSERT_EQ(patch.size(), 4u);
  extrude(mesh, patch, Vec3(0, 0, 1));
  EXPECT_EQ(counts(mesh), plus(before, 8, 16, 8));
  expect_valid_closed(mesh);
}

// Claim 20.
TEST(Extrusion, CapsAreTheFacesMovedBitwiseWithTheirWinding) {
  PolyMesh mesh = make_grid_box(Vec3(-1.3, 0.2, -0.7), Vec3(2.9, 1.1, 0.3), 3);
  FaceList faces = select_faces(mesh, all_faces(mesh), RatioBox{0, 0.7, 1, 1, 0, 0.7});
  ASSERT_EQ(faces.size(), 4u);
  const Vec3 by(0.1, 0.37, -0.05);
  std::vector<std::vector<Vec3>> expected;
  for (auto f : faces) {
    std::vector<Vec3> ring;
    for (auto v : mesh.fv_range(f)) ring.push_back(mesh.point(v) + by);
    expected.push_back(ring);
  }
  FaceList caps = extrude(mesh, faces, by);
  ASSERT_EQ(caps.size(), faces.size());
  for (std::size_t i = 0; i < caps.size(); ++i) {
    PolyMesh ring_mesh;  // rotate the expected ring the same way as position_ring does
    std::vector<PolyMesh::VertexHandle> vs;
    for (const Vec3& p : expected[i]) vs.push_back(ring_mesh.add_vertex(p));
    auto f = ring_mesh.add_face(vs);
    EXPECT_EQ(test::position_ring(mesh, caps[i]), test::position_ring(ring_mesh, f));
  }
  expect_valid_closed(mesh);
}

TEST(Extrusion, ChainedExtrusionsOfOneCubeFace) {
  PolyMesh cube = make_box(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  FaceList cap = select_faces(cube, all_faces(cube), RatioBox{0, 1, 0, 1, 1, 1});
  const Vec3 by(0.05, -0.02, 0.3);
  const int k = 7;
  for (int i = 1; i <= k; ++i) {
    cap = extrude(cube, cap, by);
    EXPECT_EQ(counts(cube), (MeshCounts{8u + 4u * i, 12u + 8u * i, 6u + 4u * i}));
  }
  ASSERT_EQ(cap.size(), 1u);
  const double ulp = std::numeric_limits<double>::epsilon() * 4;  // magnitudes below 4
  for (auto v : cube.fv_range(cap[0])) {
    const Vec3& p = cube.point(v);
    const double x0 = p[0] - k * by[0] > 0 ? 1 : -1, y0 = p[1] - k * by[1] > 0 ? 1 : -1;
    EXPECT_NEAR(p[0], x0 + k * by[0], k * ulp);
    EXPECT_NEAR(p[1], y0 + k * by[1], k * ulp);
    EXPECT_NEAR(p[2], 1 + k * by[2], k * ulp);
  }
  expect_valid_closed(cube);
}

// Claim 21.
TEST(Extrusion, SideAndCapFacesInheritTheLabel) {
  PolyMesh mesh = make_grid_box(Vec3(0, 0, 0), Vec3(4, 4, 4), 4, "body");
  FaceList patch = select_faces(mesh, all_faces(mesh), RatioBox{0.25, 0.75, 0.25, 0.75, 1, 1});
  for (auto f : patch) set_face_label(mesh, f, "chimney");
  FaceList caps = extrude(mesh, patch, Vec3(0, 0, 2));
  for (auto f : caps) EXPECT_EQ(face_label(mesh, f), "chimney");
  EXPECT_EQ(faces_labelled(mesh, "chimney").size(), 4u + 8u);
  EXPECT_EQ(faces_labelled(mesh, "body").size(), 96u - 4u);
}

// Claim 18.
TEST(Extrusion, EmptySetLeavesTheMeshBitwiseUnchanged) {
  PolyMesh mesh = make_grid_box(Vec3(0, 0, 0), Vec3(1, 2, 3), 2, "a");
  const test::Snapshot before = test::snapshot(mesh);
  EXPECT_TRUE(extrude(mesh, {}, Vec3(1, 0, 0)).empty());
  EXPECT_EQ(test::snapshot(mesh), before);
}

TEST(Extrusion, BadInputIsRefused) {
  PolyMesh cube = make_box(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  EXPECT_THROW(extrude(cube, {PolyMesh::FaceHandle(9)}, Vec3(1, 0, 0)), std::invalid_argument);
  EXPECT_THROW(extrude(cube, {cube.face_handle(0), cube.face_handle(0)}, Vec3(1, 0, 0)), std::invalid_argument);
  try {
    extrude(cube, {cube.face_handle(0)}, Vec3(1, INFINITY, 0));
    ADD_FAILURE() << "an infinite vector was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("extrude"), std::string::npos);
  }
  cube.request_face_status();
  cube.request_edge_status();
  cube.request_vertex_status();
  cube.delete_face(cube.face_handle(3), false);
  EXPECT_THROW(extrude(cube, {cube.face_handle(3)}, Vec3(1, 0, 0)), std::invalid_argument);
}

}  // namespace
}  // namespace genmod

namespace genmod {
namespace {

// On an open mesh the set's edges on the mesh boundary also get side quads (the thesis's
// occurrence rule), so one lone quad becomes an open box: 4 walls and the cap.
TEST(Extrusion, LoneQuadOnAnOpenMeshBecomesAnOpenBox) {
  PolyMesh quad = test::unit_quad();
  FaceList caps = extrude(quad, all_faces(quad), Vec3(0, 0, 1));
  EXPECT_EQ(counts(quad), (MeshCounts{8, 12, 5}));
  ASSERT_EQ(caps.size(), 1u);
  for (auto u : quad.fv_range(caps[0])) EXPECT_EQ(quad.point(u)[2], 1.0);
}

TEST(Extrusion, SameInputGivesTheSameMesh) {
  PolyMesh a = make_grid_box(Vec3(0, 0, 0), Vec3(4, 4, 4), 4, "x"), b = a;
  FaceList patch = select_faces(a, all_faces(a), RatioBox{0, 0.75, 0, 1, 0.5, 1});
  extrude(a, patch, Vec3(0.3, 0, 1));
  extrude(b, patch, Vec3(0.3, 0, 1));
  EXPECT_EQ(test::snapshot(a), test::snapshot(b));
  // The set wraps round the box, so one vector pushes its -x faces into the body: the result
  // is self-intersecting (legal, as in the thesis) but still a closed manifold.
  EXPECT_TRUE(is_closed_manifold(a));
}

}  // namespace
}  // namespace genmod

namespace genmod {
namespace {

// Two faces that touch only at a vertex would share the wall edge through it four times: the
// result is not a manifold, so the tool refuses and leaves the mesh as it was.
TEST(Extrusion, FacesTouchingAtAVertexOnlyAreRefusedWithoutChange) {
  PolyMesh mesh = make_grid_box(Vec3(0, 0, 0), Vec3(2, 2, 2), 2);
  FaceList a = select_faces(mesh, all_faces(mesh), RatioBox{0, 0.5, 0, 0.5, 1, 1});
  FaceList b = select_faces(mesh, all_faces(mesh), RatioBox{0.5, 1, 0.5, 1, 1, 1});
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  const test::Snapshot before = test::snapshot(mesh);
  FaceList both{a[0], b[0]};
  std::sort(both.begin(), both.end());
  EXPECT_THROW(extrude(mesh, both, Vec3(0, 0, 1)), std::invalid_argument);
  EXPECT_EQ(test::snapshot(mesh), before);
}

}  // namespace
}  // namespace genmod
