#include "genmod/procedural/poly_mesh.hpp"
#include "genmod/tessellate/validate.hpp"

#include <gtest/gtest.h>

namespace genmod {
namespace {

TEST(PolyMesh, BoxIsAClosedOutwardCubeWithLabels) {
  PolyMesh box = make_box(Vec3(-1, -1, -1), Vec3(1, 1, 1), "body");
  EXPECT_EQ(counts(box), (MeshCounts{8, 12, 6}));
  EXPECT_TRUE(is_closed_manifold(box));
  EXPECT_EQ(faces_labelled(box, "body").size(), 6u);
  EXPECT_TRUE(faces_labelled(box, "leg").empty());
  // The triangulation is a valid closed mesh, oriented outward (CGAL's validator).
  Mesh tri = to_triangle_mesh(box);
  EXPECT_EQ(tri.triangles.size(), 12u);
  MeshValidity report = validate(tri);
  EXPECT_TRUE(report.valid()) << describe(report);
  // Copies carry the labels.
  PolyMesh copy = box;
  set_face_label(copy, copy.face_handle(0), "lid");
  EXPECT_EQ(face_label(copy, copy.face_handle(0)), "lid");
  EXPECT_EQ(face_label(box, box.face_handle(0)), "body");
}

TEST(PolyMesh, BadBoxIsRefused) {
  EXPECT_THROW(make_box(Vec3(0, 0, 0), Vec3(1, 0, 1)), std::invalid_argument);
  EXPECT_THROW(make_box(Vec3(0, 0, 0), Vec3(1, NAN, 1)), std::invalid_argument);
}

}  // namespace
}  // namespace genmod
