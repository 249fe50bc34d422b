#include "genmod/procedural/extrusion.hpp"
#include "genmod/procedural/grid_box.hpp"
#include "genmod/procedural/selection.hpp"

#include "tool_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace genmod {
namespace {

PolyMesh transformed(PolyMesh mesh, double scale, const Vec3& shift) {
  for (auto v : mesh.vertices()) mesh.set_point(v, mesh.point(v) * scale + shift);
  return mesh;
}

// Claim 15.
TEST(Selection, UnitBoxReturnsTheParentInItsOrder) {
  PolyMesh mesh = make_grid_box(Vec3(-1, -2, 0), Vec3(3, 1, 5), 3);
  FaceList parent = all_faces(mesh);
  EXPECT_EQ(select_faces(mesh, parent, RatioBox{}), parent);
  FaceList some{parent[40], parent[3], parent[17], parent[9]};
  EXPECT_EQ(select_faces(mesh, some, RatioBox{}), some);
}

TEST(Selection, UpperHalfOfACubeIsOnlyTheTopFace) {
  PolyMesh cube = make_box(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  FaceList top = select_faces(cube, all_faces(cube), RatioBox{0, 1, 0, 1, 0.5, 1});
  ASSERT_EQ(top.size(), 1u);
  for (auto v : cube.fv_range(top[0])) EXPECT_EQ(cube.point(v)[2], 1.0);
}

// Claim 16.
TEST(Selection, PowerOfTwoScaleSelectsTheSameFaces) {
  PolyMesh mesh = make_grid_box(Vec3(-0.7, 0.1, 2.3), Vec3(1.9, 3.3, 4.1), 4);
  const double ratios[] = {-0.1, 0.0, 0.25, 0.3, 0.5, 0.6, 0.75, 0.9, 1.0, 1.2};
  int nonempty = 0;
  for (double scale : {0.125, 2.0, 1024.0})
    for (double a : ratios)
      for (double b : ratios) {
        if (b < a) continue;
        RatioBox box{a, b, 0, 1, a, b};
        PolyMesh scaled = transformed(mesh, scale, Vec3(0, 0, 0));
        FaceList before = select_faces(mesh, all_faces(mesh), box);
        EXPECT_EQ(select_faces(scaled, all_faces(scaled), box), before);
        nonempty += !before.empty();
      }
  EXPECT_GT(nonempty, 20);
}

TEST(Selection, ScaleAndShiftSelectTheSameFacesAwayFromRatioBoundaries) {
  PolyMesh mesh = make_grid_box(Vec3(0, 0, 0), Vec3(1, 1, 1), 4);
  PolyMesh moved = transformed(mesh, 3.7, Vec3(-12.1, 5.3, 0.9));
  const double ratios[] = {0.1, 0.3, 0.6, 0.9};  // not multiples of 1/4
  for (double a : ratios)
    for (double b : ratios) {
      RatioBox box{a, b, 0.1, 0.9, 0, 1};
      EXPECT_EQ(select_faces(moved, all_faces(moved), box), select_faces(mesh, all_faces(mesh), box));
    }
}

// Claim 17: a child of a named parent equals the matching absolute selection.
TEST(Selection, HierarchicalSelectionUsesTheParentsBounds) {
  PolyMesh mesh = make_grid_box(Vec3(0, 0, 0), Vec3(10, 10, 10), 20);
  FaceSets sets;
  FaceSet lower = sets.select(mesh, "", RatioBox{0, 1, 0, 0.5, 0, 1}, "lower");
  EXPECT_EQ(lower.parent, "");
  sets.add(mesh, lower);
  FaceSet top = sets.select(mesh, "lower", RatioBox{0, 1, 0.9, 1, 0, 1}, "top");
  EXPECT_EQ(top.parent, "lower");
  EXPECT_EQ(top.id, "top");
  FaceList absolute = select_faces(mesh, all_faces(mesh), RatioBox{0, 1, 0.45, 0.5, 0, 1});
  EXPECT_EQ(absolute.size(), 80u);  // a ring of 0.5-wide faces around the four sides
  EXPECT_EQ(top.faces, absolute);
  EXPECT_THROW(sets.select(mesh, "arm", RatioBox{}, "hand"), std::invalid_argument);
}

// Claim 18.
TEST(Selection, EmptyAndFlatParents) {
  PolyMesh cube = make_box(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  EXPECT_TRUE(select_faces(cube, {}, RatioBox{}).empty());
  FaceList cap{cube.face_handle(1)};
  EXPECT_EQ(select_faces(cube, cap, RatioBox{}), cap);
  // A flat side of a grid box: the flat axis passes, the others still select.
  PolyMesh grid = make_grid_box(Vec3(0, 0, 0), Vec3(4, 4, 4), 4);
  FaceList side = select_faces(grid, all_faces(grid), RatioBox{0, 1, 0, 1, 1, 1});
  ASSERT_EQ(side.size(), 16u);
  EXPECT_EQ(select_faces(grid, side, RatioBox{}), side);
  EXPECT_EQ(select_faces(grid, side, RatioBox{0, 0.5, 0, 0.5, 0, 0}).size(), 4u);
}

TEST(Selection, BadInputIsRefused) {
  PolyMesh cube = make_box(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  EXPECT_THROW(select_faces(cube, {PolyMesh::FaceHandle(6)}, RatioBox{}), std::invalid_argument);
  EXPECT_THROW(select_faces(cube, {PolyMesh::FaceHandle()}, RatioBox{}), std::invalid_argument);
  EXPECT_THROW(select_faces(cube, all_faces(cube), RatioBox{0, NAN, 0, 1, 0, 1}), std::invalid_argument);
  cube.request_face_status();
  cube.request_edge_status();
  cube.request_vertex_status();
  cube.delete_face(cube.face_handle(2), false);
  try {
    select_faces(cube, {cube.face_handle(2)}, RatioBox{});
    ADD_FAILURE() << "a deleted face was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("select"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("deleted"), std::string::npos);
  }
}

// Claim 21 (second half): named sets follow the labels through a topology change.
TEST(Selection, NamedSetsAreRecomputedFromLabels) {
  PolyMesh cube = make_box(Vec3(-1, -1, -1), Vec3(1, 1, 1), "body");
  FaceSets sets;
  sets.add(cube, sets.select(cube, "", RatioBox{0, 1, 0, 1, 0.5, 1}, "lid"));
  ASSERT_EQ(sets.get("lid").faces.size(), 1u);
  FaceList caps = extrude(cube, sets.get("lid").faces, Vec3(0, 0, 1));
  sets.update(cube);
  FaceList lid = sets.get("lid").faces;
  EXPECT_EQ(lid.size(), 5u);  // four sides and the cap; the original top is gone
  EXPECT_NE(std::find(lid.begin(), lid.end(), caps[0]), lid.end());
  for (auto f : lid)
    for (auto v : cube.fv_range(f)) EXPECT_GE(cube.point(v)[2], 1.0);
  EXPECT_EQ(faces_labelled(cube, "body").size(), 5u);
  EXPECT_THROW(sets.add(cube, FaceSet{"", "", {}}), std::invalid_argument);
  EXPECT_THROW(sets.get("arm"), std::invalid_argument);
}

}  // namespace
}  // namespace genmod
