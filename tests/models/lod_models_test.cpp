// Level of detail in the procedural models (issue 12; camera.hpp): the tree and the human use the
// context's lod as a refinement offset (fewer tree levels, fewer sqrt(2) subdivision levels),
// declare it for the cache key, and declare bounding boxes that hold their meshes; with a camera
// a far tree is coarser and a tree out of view is not built.
#include "genmod/models/procedural_models.hpp"

#include "genmod/procedural/mesh_hash.hpp"
#include "procedural/mesh_test_support.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <set>
#include <string>

namespace genmod::models {
namespace {

using genmod::test::mesh_difference;

Context at_lod(int lod, std::int64_t seed = 0) {
  Context c;
  c.lod = lod;
  c.seed = seed;
  return c;
}

// Every vertex of `mesh` lies in `box`.
void expect_inside(const PolyMesh& mesh, const std::array<Vec3, 2>& box) {
  const auto b = bounds(mesh, all_faces(mesh));
  for (int a = 0; a < 3; ++a) {
    EXPECT_GE(b[0][a], box[0][a]) << "axis " << a;
    EXPECT_LE(b[1][a], box[1][a]) << "axis " << a;
  }
}

TEST(ModelLevelOfDetail, TreeFacesGrowWithLodAndEveryLevelIsClosed) {
  ProcedureRegistry r;
  register_procedural_models(r);
  std::size_t previous = 0;
  for (int lod = -5; lod <= 1; ++lod) {
    SCOPED_TRACE("lod " + std::to_string(lod));
    const PolyMesh tree = r.call("tree", {}, at_lod(lod));
    // levels = clamp(5 + lod, 1, 10): lods -4 and -5 are both the trunk alone.
    const int levels = std::max(5 + lod, 1);
    EXPECT_EQ(tree.n_faces(), ((std::size_t{1} << levels) - 1) * (8 * 2 + 2));
    if (lod > -4) {
      EXPECT_GT(tree.n_faces(), previous);
    }
    previous = tree.n_faces();
    genmod::test::expect_valid_closed(tree);
  }
  // lod 0 is the tree of the parameters: the same bytes as the default call.
  EXPECT_EQ(mesh_difference(r.call("tree", {}, at_lod(0)), r.call("tree")), "");
  // A coarser tree is the finer one without its finest branches: every point of lod -2 (seed 7)
  // is, bitwise, a point of lod 0 (no branch moves between levels).
  const PolyMesh coarse = r.call("tree", {}, at_lod(-2, 7)), fine = r.call("tree", {}, at_lod(0, 7));
  std::set<std::array<double, 3>> points;
  for (auto v : fine.vertices()) points.insert({fine.point(v)[0], fine.point(v)[1], fine.point(v)[2]});
  for (auto v : coarse.vertices())
    EXPECT_TRUE(points.count({coarse.point(v)[0], coarse.point(v)[1], coarse.point(v)[2]})) << v.idx();
}

TEST(ModelLevelOfDetail, TreeLodIsInTheCacheKey) {
  ProcedureRegistry r, uncached;
  register_procedural_models(r);
  register_procedural_models(uncached);
  uncached.set_caching(false);
  const PolyMesh fine = r.call("tree", {}, at_lod(0)), coarse = r.call("tree", {}, at_lod(-2));
  EXPECT_EQ(r.cache_stats("tree").misses, 2u);
  const PolyMesh coarse_again = r.call("tree", {}, at_lod(-2));
  EXPECT_EQ(r.cache_stats("tree").hits, 1u);
  EXPECT_EQ(mesh_difference(coarse, coarse_again), "");
  EXPECT_EQ(mesh_difference(fine, uncached.call("tree", {}, at_lod(0))), "");
  EXPECT_EQ(mesh_difference(coarse, uncached.call("tree", {}, at_lod(-2))), "");
  EXPECT_LT(coarse.n_faces(), fine.n_faces());
}

TEST(ModelLevelOfDetail, BoundsHoldTheMeshes) {
  const ProcedureRegistry& r = procedural_registry();
  for (const NamedArgs& args : {NamedArgs{}, NamedArgs{{"angle", 80.0}, {"jitter", 0.5}, {"lengthRatio", 0.8}},
                                NamedArgs{{"radiusRatio", 1.0}, {"angle", 5.0}, {"trunkRadius", 0.2}}})
    for (int lod : {0, 2})
      for (std::int64_t seed : {0, 3}) expect_inside(r.call("tree", args, at_lod(lod, seed)), *r.bounds("tree", args));
  for (const NamedArgs& args : {NamedArgs{}, NamedArgs{{"tummy", 0.25}, {"butt", 0.25}}, NamedArgs{{"cubical", false}}})
    expect_inside(r.call("human", args), *r.bounds("human", args));
}

TEST(ModelLevelOfDetail, HumanSubdivisionFollowsTheLod) {
  ProcedureRegistry r;
  register_procedural_models(r);
  // The default 2 levels: lod -1 is 1 level, lod -2 and below 0 levels, each the figure built with
  // that many subdivisions, closed and valid.
  std::size_t previous = 0;
  for (int lod = -2; lod <= 0; ++lod) {
    SCOPED_TRACE("lod " + std::to_string(lod));
    const PolyMesh human = r.call("human", {}, at_lod(lod));
    EXPECT_EQ(mesh_difference(human, r.call("human", {{"subdivisions", 2 + lod}})), "");
    EXPECT_GT(human.n_faces(), previous);
    previous = human.n_faces();
    genmod::test::expect_valid_closed(human);
  }
  EXPECT_EQ(mesh_difference(r.call("human", {}, at_lod(-3)), r.call("human", {}, at_lod(-2))), "");
}

TEST(ModelLevelOfDetail, CameraCoarsensFarTreesAndSkipsHiddenOnes) {
  ProcedureRegistry r;
  register_procedural_models(r);
  // Looking along -z at the tree's middle (it stands along +y from the origin, about 2.3 tall).
  const auto camera_at = [](double distance) {
    Camera c;
    c.position = Vec3(0, 1.2, distance);
    c.direction = Vec3(0, 0, -1);
    return c;
  };
  std::size_t previous = std::numeric_limits<std::size_t>::max();
  int coarser = 0;
  for (double distance : {4.0, 16.0, 64.0, 256.0}) {
    Context c;
    c.camera = camera_at(distance);
    const PolyMesh tree = r.call("tree", {}, c);
    EXPECT_GT(tree.n_faces(), 0u);
    EXPECT_LE(tree.n_faces(), previous);
    coarser += tree.n_faces() < previous && previous != std::numeric_limits<std::size_t>::max();
    previous = tree.n_faces();
    genmod::test::expect_valid_closed(tree);
  }
  EXPECT_GE(coarser, 2);
  // Turned away: not built at all.
  Context away;
  away.camera = camera_at(8);
  away.camera->direction = Vec3(0, 0, 1);
  r.reset_cache_stats("branch");
  EXPECT_EQ(r.call("tree", {}, away).n_faces(), 0u);
  EXPECT_EQ(r.culled_calls("tree"), 1u);
  EXPECT_EQ(r.cache_stats("branch").misses + r.cache_stats("branch").hits, 0u);  // the body never ran
}

}  // namespace
}  // namespace genmod::models
