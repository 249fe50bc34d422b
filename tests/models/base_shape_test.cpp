// Base-shape independence (research/morkel.md section 4.3, Experiment 3; issue 12: "base shapes
// may come from genmod's own parametric and implicit shapes meshed by the tessellators"). The
// procedural tools do not need the boxes the models start from: an ellipsoid meshed by the
// implicit octree mesher (irregular triangles, not a grid) is grown like a Humpty-Dumpty torso,
// a neck and two arms extruded from ratio-box selections, the arms rounded by sqrt(2)
// subdivision and the neck's top shaped onto a curve, and the result is closed, manifold,
// valid and the same bytes every time.
#include "genmod/operators/shapes.hpp"
#include "genmod/procedural/curve_shaping.hpp"
#include "genmod/procedural/extrusion.hpp"
#include "genmod/procedural/mesh_hash.hpp"
#include "genmod/procedural/selection.hpp"
#include "genmod/procedural/sqrt2_subdivision.hpp"
#include "genmod/tessellate/implicit_mesher.hpp"
#include "genmod/tessellate/validate.hpp"
#include "procedural/mesh_test_support.hpp"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace genmod {
namespace {

// The triangle mesh as a PolyMesh (same vertex order, one face per triangle), labelled `label`.
PolyMesh poly_mesh_of(const Mesh& m, const std::string& label) {
  PolyMesh p;
  std::vector<PolyMesh::VertexHandle> v;
  for (const auto& x : m.vertices) v.push_back(p.add_vertex(Vec3(x[0], x[1], x[2])));
  for (const auto& t : m.triangles) set_face_label(p, p.add_face(v[t[0]], v[t[1]], v[t[2]]), label);
  return p;
}

// Edges of `faces` with a face outside them: the b of the extrusion's (+b, +2b, +b).
std::size_t boundary_edges(const PolyMesh& mesh, const FaceList& faces) {
  const std::set<int> in = [&] {
    std::set<int> s;
    for (auto f : faces) s.insert(f.idx());
    return s;
  }();
  std::size_t b = 0;
  for (auto f : faces)
    for (auto h : mesh.fh_range(f)) b += !in.count(mesh.face_handle(mesh.opposite_halfedge_handle(h)).idx());
  return b;
}

PolyMesh humpty(std::vector<std::pair<MeshCounts, MeshCounts>>* steps = nullptr) {
  // The unit ball meshed by the octree mesher, stretched into an egg 1.5 wide and 2 tall.
  const ImplicitSurface ball(implicit_sphere(1.0));
  ImplicitMeshSettings settings;
  settings.min_feature = 0.1;
  settings.tolerance = 0.01;
  const Box3 box{Interval(-1.5, 1.5), Interval(-1.5, 1.5), Interval(-1.5, 1.5)};
  PolyMesh egg = poly_mesh_of(mesh_implicit(ball, box, settings).mesh, "egg");
  for (auto v : egg.vertices()) {
    Vec3 p = egg.point(v);
    p[0] *= 0.75;
    p[1] *= 0.75;
    egg.set_point(v, p);
  }
  const auto extrude_counted = [&](const FaceList& faces, const Vec3& by) {
    const MeshCounts before = counts(egg);
    const std::size_t b = boundary_edges(egg, faces);
    FaceList caps = extrude(egg, faces, by);
    // (expected, got) for the test; an empty selection would be a test that tests nothing.
    if (b == 0) throw std::logic_error("empty selection");
    if (steps) steps->push_back({MeshCounts{before.vertices + b, before.edges + 2 * b, before.faces + b}, counts(egg)});
    return caps;
  };
  // The neck: the faces in the top 6% of the egg, raised twice (the thesis's chained extrusions).
  FaceList neck = select_faces(egg, all_faces(egg), RatioBox{0, 1, 0, 1, 0.94, 1});
  neck = extrude_counted(neck, Vec3(0, 0, 0.15));
  neck = extrude_counted(neck, Vec3(0, 0, 0.15));
  // Its top onto an arch across x (seen along y), moving along z: the apex 0.1 up.
  const auto [lo, hi] = bounds(egg, neck);
  shape_to_curve(egg, neck, BezierCurve({Vec3(lo[0], 0, hi[2]), Vec3(0, 0, hi[2] + 0.2), Vec3(hi[0], 0, hi[2])}),
                 Vec3(0, 0, 1), Vec3(0, 1, 0));
  // The arms: a patch on each side at mid height, pushed out along x, then rounded.
  for (const double side : {-1.0, 1.0}) {
    const RatioBox patch = side < 0 ? RatioBox{0, 0.04, 0.4, 0.6, 0.45, 0.6} : RatioBox{0.96, 1, 0.4, 0.6, 0.45, 0.6};
    FaceList arm = select_faces(egg, all_faces(egg), patch);
    arm = extrude_counted(arm, Vec3(0.6 * side, 0, 0));
    sqrt2_subdivide(egg, arm, 1, 0.5);
  }
  egg.garbage_collection();
  return egg;
}

TEST(BaseShape, ToolsGrowATessellatedEllipsoidLikeATorso) {
  std::vector<std::pair<MeshCounts, MeshCounts>> steps;
  const PolyMesh egg = humpty(&steps);
  // Each extrusion changed (V, E, F) by exactly (+b, +2b, +b) on the irregular triangle mesh.
  ASSERT_EQ(steps.size(), 4u);
  for (std::size_t i = 0; i < steps.size(); ++i) {
    EXPECT_EQ(steps[i].second, steps[i].first) << "extrusion " << i;
  }
  EXPECT_TRUE(is_closed_manifold(egg));
  const MeshValidity v = validate(to_triangle_mesh(egg));
  EXPECT_TRUE(v.valid()) << describe(v);
  EXPECT_EQ(v.components, 1u);
  EXPECT_EQ(v.euler_characteristic, 2);
  // The neck and arms reach out of the egg (half-widths 0.75, half-height 1).
  const auto [lo, hi] = bounds(egg, all_faces(egg));
  EXPECT_GT(hi[2], 1.25);
  EXPECT_LT(lo[0], -1.2);
  EXPECT_GT(hi[0], 1.2);
  // Deterministic: the same bytes from a second build.
  EXPECT_EQ(test::mesh_difference(egg, humpty()), "");
}

}  // namespace
}  // namespace genmod
