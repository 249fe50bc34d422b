// Meshing polygon-convolution shapes (operators/polygon_convolution.hpp, issue 11): the
// implicit mesher's interval classification, gradient and Hessian bounds run through the
// image lookup operator and its pyramid; the meshes are closed, manifold, oriented and free
// of self-intersections, and their vertices lie on the surface.
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/polygon_convolution.hpp"
#include "genmod/tessellate/implicit_mesher.hpp"
#include "genmod/tessellate/validate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace genmod {
namespace {

void expect_valid_mesh(const Fn& f, const Box3& box, double min_feature, std::size_t min_triangles) {
  const ImplicitMesh m = mesh_implicit(f, box, {.min_feature = min_feature, .tolerance = min_feature / 4});
  const MeshValidity v = validate(m.mesh);
  EXPECT_TRUE(v.valid()) << v.triangles << " triangles, " << v.boundary_edges << " boundary edges";
  EXPECT_GT(v.triangles, min_triangles);
  // Every vertex is certified within the tolerance (default: min_feature) of the surface by a
  // sign change of f, and f is small there against its slope (about 0.7 / r across the slab).
  EXPECT_EQ(m.stats.uncertified_vertices, 0u);
  EXPECT_LE(m.stats.max_vertex_error, min_feature / 4);
  const int xyz[3] = {0, 1, 2};
  const Tape tape(f, xyz);
  PointEvaluator pv;
  double worst = 0;
  for (const auto& p : m.mesh.vertices) worst = std::max(worst, std::abs(pv.eval(tape, p)[0]));
  std::printf("%zu triangles, max vertex error bound %.4f, max |f| at vertices %.4f\n", v.triangles,
              m.stats.max_vertex_error, worst);
  EXPECT_LT(worst, 0.1);
}

TEST(PolygonConvolutionMesh, SquareSlabIsValid) {
  const std::vector<SkeletalPolygon> slab = {
      {{{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0.5, 0.5, 0}, {-0.5, 0.5, 0}}, {}}};
  const Fn f = polygon_convolution_surface(slab, 0.1, {.resolution = 80});
  const Box3 box = {Interval(-0.8, 0.8), Interval(-0.8, 0.8), Interval(-0.4, 0.4)};
  expect_valid_mesh(f, box, 0.05, 300);
}

TEST(PolygonConvolutionMesh, TiltedLShapeWithWeightsIsValid) {
  // An L in the plane x = z (tilted 45 degrees), thinner toward one arm by its weights.
  const double s = std::sqrt(0.5);
  const double uv[6][2] = {{0, 0}, {1, 0}, {1, 0.4}, {0.4, 0.4}, {0.4, 1}, {0, 1}};
  SkeletalPolygon l;
  for (const auto& c : uv) l.vertices.push_back({(c[0] - 0.5) * s, c[1] - 0.5, (c[0] - 0.5) * s});
  l.weights = {1.0, 0.7, 0.7, 1.0, 1.0, 1.0};
  const Fn f = polygon_convolution_surface(std::vector<SkeletalPolygon>{l}, 0.08, {.resolution = 80});
  const Box3 box = {Interval(-0.7, 0.7), Interval(-0.8, 0.8), Interval(-0.7, 0.7)};
  expect_valid_mesh(f, box, 0.04, 300);
}

}  // namespace
}  // namespace genmod
