// Meshing a culled field of many Gaussian segments (operators/culled_field.hpp, issue 11): the
// mesher's point evaluations walk the element hierarchy, and the mesh is still valid, with
// the culled field's values at its vertices equal to the exact sum within the tolerance.
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/convolution.hpp"
#include "genmod/operators/culled_field.hpp"
#include "genmod/tessellate/implicit_mesher.hpp"
#include "genmod/tessellate/validate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace genmod {
namespace {

// A random walk of n segments of length 0.12, radius 0.05 to 0.07, in [-0.6, 0.6]^3.
std::vector<FieldElement> walk(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1), w(0, 1);
  Point3 a = {0, 0, 0}, dir = {1, 0, 0};
  std::vector<FieldElement> es;
  for (int i = 0; i < n; ++i) {
    double len = 0;
    for (int k = 0; k < 3; ++k) dir[k] += 0.6 * u(rng), len += dir[k] * dir[k];
    Point3 b;
    for (int k = 0; k < 3; ++k) {
      dir[k] /= std::sqrt(len);
      b[k] = a[k] + 0.12 * dir[k];
      if (std::abs(b[k]) > 0.6) dir[k] = -dir[k], b[k] = a[k] + 0.12 * dir[k];
    }
    const double r = 0.05 + 0.02 * w(rng);
    es.push_back(gaussian_segment_element(a, b, r, r));
    a = b;
  }
  return es;
}

TEST(CulledFieldMesh, IsValidAndItsVerticesAreOnTheExactSurface) {
  const std::vector<FieldElement> es = walk(60, 31);
  const ImplicitSurface s(density_to_implicit(culled_field(es)));
  const Box3 box = {Interval(-0.8, 0.8), Interval(-0.8, 0.8), Interval(-0.8, 0.8)};
  const ImplicitMesh m = mesh_implicit(s, box, {.min_feature = 0.05});
  const MeshValidity v = validate(m.mesh);
  EXPECT_TRUE(v.valid()) << v.triangles << " triangles, " << v.boundary_edges << " boundary edges";
  EXPECT_GT(v.triangles, 500u);
  // At the vertices (points where the mesher evaluated the field), the culled value is the
  // exact sum within the point tolerance (2^-60 max(sum, cull_below), plus rounding).
  const int xyz[3] = {0, 1, 2};
  std::vector<Tape> terms;
  for (const FieldElement& e : es) terms.emplace_back(e.density, xyz);
  const Tape culled(culled_field(es), xyz);
  PointEvaluator pv;
  for (std::size_t i = 0; i < m.mesh.vertices.size(); i += 7) {
    const auto& p = m.mesh.vertices[i];
    double sum = 0;
    for (const Tape& t : terms) sum += pv.eval(t, p)[0];
    ASSERT_NEAR(pv.eval(culled, p)[0], sum, 0x1p-60 * std::max(sum, 1e-6) + 0x1p-50 * sum);
  }
}

}  // namespace
}  // namespace genmod
