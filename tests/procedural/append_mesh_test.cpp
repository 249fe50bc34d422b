// append_mesh copies a part's half-edge arrays (issue 12) instead of adding it face by face; the
// result must be the mesh the face-by-face loop gives (vertices, faces, each face's vertex ring
// from the same corner, labels) and a consistent half-edge structure the tools can edit.
#include "genmod/procedural/affine.hpp"
#include "genmod/procedural/extrusion.hpp"
#include "genmod/procedural/grid_box.hpp"
#include "genmod/procedural/stitching.hpp"
#include "mesh_test_support.hpp"
#include "tool_test_support.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace genmod {
namespace {

// The reference: the face-by-face loop append_mesh used before.
void append_by_faces(PolyMesh& mesh, const PolyMesh& part, const Affine& xf) {
  std::vector<PolyMesh::VertexHandle> map(part.n_vertices());
  for (PolyMesh::VertexHandle v : part.vertices()) map[v.idx()] = mesh.add_vertex(xf.apply(part.point(v)));
  for (PolyMesh::FaceHandle f : part.faces()) {
    std::vector<PolyMesh::VertexHandle> corners;
    for (PolyMesh::VertexHandle v : part.fv_range(f)) corners.push_back(map[v.idx()]);
    set_face_label(mesh, mesh.add_face(corners), face_label(part, f));
  }
}

// Every half-edge's links agree: next/prev inverse, the face of a ring is the face, opposite
// half-edges run between the same vertices, a vertex's outgoing half-edge starts at it.
void expect_consistent(const PolyMesh& m) {
  for (auto h : m.halfedges()) {
    EXPECT_EQ(m.prev_halfedge_handle(m.next_halfedge_handle(h)), h);
    EXPECT_EQ(m.to_vertex_handle(h), m.from_vertex_handle(m.next_halfedge_handle(h)));
    EXPECT_EQ(m.face_handle(m.next_halfedge_handle(h)), m.face_handle(h));
    EXPECT_EQ(m.to_vertex_handle(m.opposite_halfedge_handle(h)), m.from_vertex_handle(h));
  }
  for (auto v : m.vertices())
    if (!m.is_isolated(v)) EXPECT_EQ(m.from_vertex_handle(m.halfedge_handle(v)), v);
  for (auto f : m.faces()) EXPECT_EQ(m.face_handle(m.halfedge_handle(f)), f);
}

TEST(AppendMesh, SameMeshAsFaceByFace) {
  PolyMesh part = make_grid_box(Vec3(0, 0, 0), Vec3(1, 2, 3), 3, "part");
  extrude(part, {PolyMesh::FaceHandle(0), PolyMesh::FaceHandle(1)}, Vec3(-0.5, 0, 0));
  const Affine xf = Affine::translation(Vec3(5, 0, 0)) * Affine::scaling(0.5);
  PolyMesh fast = make_box(Vec3(-1, -1, -1), Vec3(0, 0, 0), "base"), slow = fast;
  append_mesh(fast, part, xf);
  append_by_faces(slow, part, xf);
  append_mesh(fast, part);
  append_by_faces(slow, part, {});
  EXPECT_EQ(test::snapshot(fast), test::snapshot(slow));
  EXPECT_EQ(counts(fast), counts(slow));
  EXPECT_TRUE(is_closed_manifold(fast));
  expect_consistent(fast);
}

TEST(AppendMesh, OpenPartsAndUnlabelledParts) {
  PolyMesh quad;
  const auto a = quad.add_vertex(Vec3(0, 0, 0)), b = quad.add_vertex(Vec3(1, 0, 0)), c = quad.add_vertex(Vec3(1, 1, 0)),
             d = quad.add_vertex(Vec3(0, 1, 0));
  quad.add_face(a, b, c, d);  // no label property at all
  PolyMesh fast, slow;
  append_mesh(fast, quad);
  append_by_faces(slow, quad, {});
  append_mesh(fast, quad, Affine::translation(Vec3(0, 0, 1)));
  append_by_faces(slow, quad, Affine::translation(Vec3(0, 0, 1)));
  EXPECT_EQ(test::snapshot(fast), test::snapshot(slow));
  expect_consistent(fast);
  for (auto v : fast.vertices()) EXPECT_TRUE(fast.is_boundary(v));
}

TEST(AppendMesh, PartWithDeletedElementsSkipsThem) {
  PolyMesh part = make_grid_box(Vec3(0, 0, 0), Vec3(1, 1, 1), 2, "p");
  PolyMesh other = make_box(Vec3(3, 0, 0), Vec3(4, 1, 1), "q");
  append_mesh(part, other);
  // Bridge a quad of the grid box's +x side (faces 4..7) to the box's -x face (24 + 4): deletes
  // them and leaves garbage in `part`.
  bridge(part, {PolyMesh::FaceHandle(4)}, {PolyMesh::FaceHandle(24 + 4)}, "bridge");
  PolyMesh fast = make_box(Vec3(-2, 0, 0), Vec3(-1, 1, 1)), slow = fast;
  append_mesh(fast, part);
  append_by_faces(slow, part, {});
  EXPECT_EQ(test::snapshot(fast), test::snapshot(slow));
  EXPECT_EQ(counts(fast).faces, 6 + counts(part).faces);
  EXPECT_TRUE(is_closed_manifold(fast));
}

TEST(AppendMesh, AppendedPartsCanBeBridgedAndCollected) {
  PolyMesh fast = make_grid_box(Vec3(0, 0, 0), Vec3(4, 1, 1), 2, "body"), slow = fast;
  const PolyMesh leg = make_box(Vec3(0, -2, 0), Vec3(0.5, -1, 0.5), "leg");
  for (PolyMesh* m : {&fast, &slow}) {
    const int first = static_cast<int>(m->n_faces());
    if (m == &fast)
      append_mesh(*m, leg);
    else
      append_by_faces(*m, leg, {});
    // The leg's top (+y, face 3 of make_box) to a bottom face of the body (-y side, faces 8..11).
    bridge(*m, {PolyMesh::FaceHandle(first + 3)}, {PolyMesh::FaceHandle(8)}, "ankle");
    m->garbage_collection();
  }
  EXPECT_EQ(test::snapshot(fast), test::snapshot(slow));
  EXPECT_TRUE(is_closed_manifold(fast));
  expect_consistent(fast);
}

}  // namespace
}  // namespace genmod
