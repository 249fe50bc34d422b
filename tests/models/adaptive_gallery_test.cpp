// The gallery meshed by the adaptive mesher, as users get it: every closed model closed,
// 2-manifold, outward and free of self-intersections (validate, CGAL), within the certified
// distance of its surface (checked against surface samples); every open model manifold and
// consistently oriented with its boundary reported.
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/models/gallery.hpp"
#include "genmod/tessellate/validate.hpp"
#include "tessellate/point_triangle_distance.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace genmod::models {
namespace {

class AdaptiveGallery : public ::testing::TestWithParam<std::string> {};

TEST_P(AdaptiveGallery, MeshIsCleanAndWithinItsBound) {
  const Model& model = find_model(GetParam());
  const ParameterValues p = resolve_parameters(model);
  const Fn surface = model.build(p);
  const double tol = 3e-3 * model_extent(model, surface, p);
  // A deterministic limit, not a clock: the largest model needs under 180,000 leaves (phillips
  // screwdriver; bottle 77,490), and a time limit would fail on a slow or loaded machine.
  const AdaptiveMesh m = mesh_model_adaptive(model, surface, p, {.tolerance = tol, .max_leaves = 400'000});
  ASSERT_TRUE(m.limits_hit.empty()) << model.name << ": limit " << m.limits_hit.front();
  EXPECT_LE(m.distance_bound, tol);
  const MeshValidity v = validate(m.mesh);
  EXPECT_TRUE(v.manifold()) << describe(v);
  EXPECT_TRUE(v.oriented()) << describe(v);
  EXPECT_EQ(v.degenerate_triangles, 0u) << describe(v);
  EXPECT_EQ(v.self_intersections, 0u) << describe(v);
  if (model.open) {
    EXPECT_GT(v.boundary_edges, 0u) << model.name << " is listed as open";
  } else {
    EXPECT_TRUE(v.valid()) << describe(v);
  }
  // Surface samples lie within the certified bound of the mesh: 40 per patch, fewer (at
  // least 4) where a model has hundreds of patches (the bear: 5 per hair), since the distance
  // to the mesh is a brute-force search.
  std::mt19937 rng(11);
  PointEvaluator ev;
  const std::vector<SurfacePatch> patches = model_patches(model, surface, p);
  const int samples = std::clamp(static_cast<int>(4000 / patches.size()), 4, 40);
  for (const SurfacePatch& patch : patches) {
    const Tape tape(patch.surface, std::vector<int>{0, 1});
    std::uniform_real_distribution<double> su(patch.u.lo(), patch.u.hi()), sv(patch.v.lo(), patch.v.hi());
    for (int i = 0; i < samples; ++i) {
      const auto s = ev.eval(tape, {su(rng), sv(rng)});
      ASSERT_LE(testing_support::distance_to_mesh({s[0], s[1], s[2]}, m.mesh), m.distance_bound) << model.name;
    }
  }
}

// A solid swept all the way around: its first and last faces coincide inside it and are left
// out, so the beam is one closed ring (the lattice gave thousands of non-manifold edges).
TEST(AdaptiveGallerySolid, FullCircleBeamIsOneClosedRing) {
  const Model& beam = find_model("circular_beam");
  const ParameterValues p = resolve_parameters(beam, {{"angle", 2.0 * 3.141592653589793}});
  const Fn solid = beam.build(p);
  EXPECT_EQ(model_patches(beam, solid, p).size(), 4u);
  const AdaptiveMesh m = mesh_model_adaptive(beam, solid, p, {.tolerance = 3e-3});
  const MeshValidity v = validate(m.mesh);
  EXPECT_TRUE(v.valid()) << describe(v);
  EXPECT_EQ(v.euler_characteristic, 0);
  // Pappus: width x height x radius x angle.
  EXPECT_NEAR(v.volume, 0.2 * 0.1 * 1.0 * 2.0 * 3.141592653589793, 0.01 * v.volume);
}

// The bear and its hairs are one closed surface (issue 14: the tubes used to be separate
// closed surfaces sunk into the scalp, 2 rows^2 + 1 components that intersect): a sphere
// (Euler characteristic 2), valid, and every hair's tip (furry_bear_hair) is a vertex of it.
// Few rows give wide cells near the poles (their folds were cured by the polar caps), more
// rows more hairs. (At hair_rows 14 with the default kappa and hair_length the top row's
// hairs, combed toward the pole, cross each other: a property of the model, not the mesh,
// rejected when the model is built: FurryBear.CrossingHairsAreRejected.)
TEST(FurryBearMesh, ScalpAndHairsAreOneSphere) {
  const Model& bear = find_model("furry_bear");
  for (const double rows : {3.0, 8.0}) {
    const ParameterValues p = resolve_parameters(bear, {{"hair_rows", rows}});
    const Fn scalp = bear.build(p);
    const double tol = 3e-3 * model_extent(bear, scalp, p);
    const AdaptiveMesh m = mesh_model_adaptive(bear, scalp, p, {.tolerance = tol});
    ASSERT_TRUE(m.limits_hit.empty());
    EXPECT_LE(m.distance_bound, tol);
    // The root rings are shared bit for bit; cell sides, caps and tips agree to rounding
    // (measured 2.2e-16).
    EXPECT_LT(m.seam_deviation, 1e-12);
    const MeshValidity v = validate(m.mesh);
    EXPECT_TRUE(v.valid()) << describe(v);
    EXPECT_EQ(v.components, 1u);
    EXPECT_EQ(v.euler_characteristic, 2);
    PointEvaluator ev;
    const Tape field(furry_bear_hair(p), std::vector<int>{0, 1});
    std::size_t tips = 0;
    for (const HairRoot& r : furry_bear_roots(p)) {
      const auto h = ev.eval(field, {r.u, r.v});
      for (const auto& q : m.mesh.vertices)
        if (std::hypot(q[0] - h[3], q[1] - h[4], q[2] - h[5]) < 1e-12) {
          ++tips;
          break;
        }
    }
    EXPECT_EQ(tips, static_cast<std::size_t>(2 * rows * rows));
  }
}

// At coarse tolerances the scalp's pieces about each root, slivers fanning out from the root
// ellipse on the flat bottom, were triangulated into backward triangles within the distance
// bound (tolerance 0.02: 20 intersecting pairs); their leaves are now split until no mesh
// triangle faces against the surface (fold_repair.hpp).
TEST(FurryBearMesh, CoarseTolerancesGiveNoFolds) {
  const Model& bear = find_model("furry_bear");
  const ParameterValues p = resolve_parameters(bear);
  const Fn scalp = bear.build(p);
  for (const double tol : {0.02, 0.05}) {
    const AdaptiveMesh m = mesh_model_adaptive(bear, scalp, p, {.tolerance = tol});
    ASSERT_TRUE(m.limits_hit.empty());
    EXPECT_LE(m.distance_bound, tol);
    const MeshValidity v = validate(m.mesh);
    EXPECT_EQ(v.self_intersections, 0u) << tol << "\n" << describe(v);
    EXPECT_TRUE(v.valid()) << tol << "\n" << describe(v);
  }
}

std::vector<std::string> all_models() {
  std::vector<std::string> names;
  for (const Model& m : gallery()) names.push_back(m.name);
  return names;
}

INSTANTIATE_TEST_SUITE_P(Gallery, AdaptiveGallery, ::testing::ValuesIn(all_models()),
                         [](const auto& test) { return test.param; });

}  // namespace
}  // namespace genmod::models
