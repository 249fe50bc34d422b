// Level of detail in the procedural models (issue 12; camera.hpp): the tree, the human, the
// chair, the couch, the table and the luggage use the context's lod as a refinement offset
// (fewer tree levels, fewer sqrt(2) subdivision levels, fewer leg steps), declare it for the
// cache key, and declare bounding boxes that hold their meshes; with a camera a far model is
// coarser and a model out of view is not built.
#include "genmod/models/procedural_models.hpp"

#include "genmod/procedural/mesh_hash.hpp"
#include "procedural/mesh_test_support.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <set>
#include <string>
#include <vector>

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


// The furniture: each lod step up gives strictly more faces (sqrt(2) rounds of the cushions,
// the round top, the luggage's legs; below 0 also fewer leg steps), every lod meshes closed,
// manifold and valid, and lod 0 is the default call's bytes.
struct LodCase {
  const char* name;
  NamedArgs args;
  int lowest, highest;  // the lods over which the faces grow strictly
};

const std::vector<LodCase>& furniture_cases() {
  static const std::vector<LodCase> cases{
      {"chair", {}, -2, 2},
      {"chair", {{"feet", true}, {"arms", true}}, -2, 2},
      {"couch", {{"numCushions", 2}}, -2, 1},
      {"table", {{"roundTable", true}}, -3, 3},
      {"table", {}, -2, 0},  // the box table: only its legs' steps (below 0)
      {"luggage", {{"numLegs", 6}}, -3, 2},
  };
  return cases;
}

TEST(ModelLevelOfDetail, FurnitureFacesGrowWithLodAndEveryLevelIsClosed) {
  ProcedureRegistry r;
  register_procedural_models(r);
  for (const LodCase& c : furniture_cases()) {
    std::size_t previous = 0;
    for (int lod = c.lowest; lod <= c.highest; ++lod) {
      SCOPED_TRACE(std::string(c.name) + " (" + std::to_string(c.args.size()) + " arguments) lod " + std::to_string(lod));
      const PolyMesh mesh = r.call(c.name, c.args, at_lod(lod));
      EXPECT_GT(mesh.n_faces(), previous);
      previous = mesh.n_faces();
      genmod::test::expect_valid_closed(mesh);
    }
    EXPECT_EQ(mesh_difference(r.call(c.name, c.args, at_lod(0)), r.call(c.name, c.args)), "") << c.name;
  }
  // The box table has nothing curved: above lod 0 it stays the lod 0 table.
  EXPECT_EQ(mesh_difference(r.call("table", {}, at_lod(2)), r.call("table")), "");
  // Far below: the coarsest chair still has every part (the lod never changes the cells).
  const PolyMesh coarse = r.call("chair", {{"arms", true}}, at_lod(-64));
  genmod::test::expect_valid_closed(coarse);
  for (const char* part : {"back", "cushion1", "legs", "armrest_l", "armrest_r", "seat"})
    EXPECT_FALSE(faces_labelled(coarse, part).empty()) << part;
  EXPECT_EQ(mesh_difference(coarse, r.call("chair", {{"arms", true}}, at_lod(std::numeric_limits<int>::min()))), "");
}

// The round table's and the luggage's lod is their subdivisions parameter moved by the lod, and
// the chair's is the cushions' rounds: a coarser call equals a call of coarser arguments where
// the model has such a parameter.
TEST(ModelLevelOfDetail, FurnitureLodIsTheSubdivisionParameterMoved) {
  ProcedureRegistry r;
  register_procedural_models(r);
  for (int lod = -3; lod <= 3; ++lod) {
    SCOPED_TRACE("lod " + std::to_string(lod));
    EXPECT_EQ(mesh_difference(r.call("luggage", {}, at_lod(lod)),
                              r.call("luggage", {{"legSubdivisions", std::clamp(3 + lod, 0, 6)}})),
              "");
    // The round table's legs keep their steps at lod >= 0 only.
    if (lod >= 0) {
      EXPECT_EQ(mesh_difference(r.call("table", {{"roundTable", true}}, at_lod(lod)),
                                r.call("table", {{"roundTable", true}, {"subdivisions", 3 + lod}})),
                "");
    }
  }
  // A far round table is still rounded: its top keeps one sqrt(2) round at any lod (more faces
  // than the flat grid box it starts from), unless its subdivisions parameter is 0.
  const auto top_faces = [](const PolyMesh& m) { return faces_labelled(m, "top").size(); };
  const PolyMesh far = r.call("table", {{"roundTable", true}}, at_lod(-20));
  EXPECT_EQ(top_faces(far), top_faces(r.call("table", {{"roundTable", true}, {"subdivisions", 1}}, at_lod(-20))));
  EXPECT_GT(top_faces(far), top_faces(r.call("table", {{"roundTable", true}, {"subdivisions", 0}})));
  EXPECT_EQ(mesh_difference(r.call("table", {{"roundTable", true}, {"subdivisions", 0}}, at_lod(-20)),
                            r.call("table", {{"roundTable", true}, {"subdivisions", 0}}, at_lod(-3))),
            "");
  genmod::test::expect_valid_closed(far);
}

TEST(ModelLevelOfDetail, LuggageAndChairFeetLodIsInTheCacheKey) {
  ProcedureRegistry r, uncached;
  register_procedural_models(r);
  register_procedural_models(uncached);
  uncached.set_caching(false);
  const PolyMesh fine = r.call("luggage", {}, at_lod(0)), coarse = r.call("luggage", {}, at_lod(-1));
  EXPECT_EQ(r.cache_stats("luggage").misses, 2u);
  EXPECT_EQ(r.cache_stats("leg").misses, 2u);  // one leg build per lod, the other legs hits
  EXPECT_EQ(r.cache_stats("luggage_chest").misses, 1u);  // the chest is the same at every lod
  const PolyMesh coarse_again = r.call("luggage", {}, at_lod(-1));
  EXPECT_EQ(r.cache_stats("luggage").hits, 1u);
  EXPECT_EQ(r.cache_stats("luggage").misses, 2u);
  EXPECT_EQ(mesh_difference(coarse, coarse_again), "");
  EXPECT_EQ(mesh_difference(fine, uncached.call("luggage", {}, at_lod(0))), "");
  EXPECT_EQ(mesh_difference(coarse, uncached.call("luggage", {}, at_lod(-1))), "");
  EXPECT_LT(coarse.n_faces(), fine.n_faces());
  // The chair's feet: four leg calls per chair, one build per lod.
  r.reset_cache_stats("leg");
  const PolyMesh chair_fine = r.call("chair", {{"feet", true}}, at_lod(0));
  const PolyMesh chair_coarse = r.call("chair", {{"feet", true}}, at_lod(-1));
  EXPECT_EQ(r.cache_stats("leg").misses, 2u);
  EXPECT_EQ(r.cache_stats("leg").hits, 6u);
  EXPECT_EQ(mesh_difference(chair_coarse, uncached.call("chair", {{"feet", true}}, at_lod(-1))), "");
  EXPECT_LT(chair_coarse.n_faces(), chair_fine.n_faces());
}

TEST(ModelLevelOfDetail, FurnitureBoundsHoldTheMeshes) {
  const ProcedureRegistry& r = procedural_registry();
  const std::vector<std::pair<const char*, NamedArgs>> cases{
      {"chair", {}},
      {"chair", {{"arms", true}, {"shape", true}, {"offSet", 16.0}}},
      {"chair", {{"feet", true}, {"segments", 3}, {"length", 0.5}}},
      {"chair", {{"backLength", 0.1}, {"depth", 4.0}, {"segments", 10}}},
      {"chair", {{"cubic", false}, {"feet", true}, {"arms", true}}},
      {"couch", {}},
      {"couch", {{"numCushions", 1}, {"shape", true}, {"offSet", -1.0}}},
      {"table", {}},
      {"table", {{"segments", 3}, {"width", 5.0}}},
      {"table", {{"roundTable", true}, {"smoothingFactor", 0.0}}},
      {"table", {{"roundTable", true}, {"segments", 3}}},
      {"luggage", {}},
      {"luggage", {{"numLegs", 30}, {"lidHeight", 2.0}}},
      {"luggage", {{"numLegs", 1}, {"width", 3.0}, {"lidHeight", 0.0}}},
  };
  for (const auto& [name, args] : cases)
    for (int lod : {-2, 0, 2}) {
      SCOPED_TRACE(std::string(name) + " with " + std::to_string(args.size()) + " arguments, lod " + std::to_string(lod));
      expect_inside(r.call(name, args, at_lod(lod)), *r.bounds(name, args));
    }
}

TEST(ModelLevelOfDetail, CameraCoarsensFarFurnitureAndSkipsHiddenFurniture) {
  ProcedureRegistry r;
  register_procedural_models(r);
  // In front of the chair (its front faces +z), looking back at its middle.
  const auto camera_at = [](double distance) {
    Camera c;
    c.position = Vec3(1, 1, 2 + distance);
    c.direction = Vec3(0, 0, -1);
    return c;
  };
  std::size_t previous = std::numeric_limits<std::size_t>::max();
  int coarser = 0;
  for (double distance : {2.0, 16.0, 128.0}) {
    Context c;
    c.camera = camera_at(distance);
    const PolyMesh chair = r.call("chair", {}, c);
    // The camera's lod for the chair's box, applied as the context's lod.
    const BoxView view = view_of_box(*c.camera, *r.bounds("chair", {}));
    ASSERT_TRUE(view.visible);
    EXPECT_EQ(mesh_difference(chair, r.call("chair", {}, at_lod(view.lod))), "") << distance;
    EXPECT_LT(chair.n_faces(), previous);
    coarser += previous != std::numeric_limits<std::size_t>::max();
    previous = chair.n_faces();
  }
  EXPECT_EQ(coarser, 2);
  for (const char* name : {"chair", "couch", "table", "luggage"}) {
    Context away;
    away.camera = camera_at(8);
    away.camera->direction = Vec3(0, 0, 1);
    EXPECT_EQ(r.call(name, {}, away).n_faces(), 0u) << name;
    EXPECT_EQ(r.culled_calls(name), 1u) << name;
  }
}

// mesh_procedural_model's camera is in the z-up frame of its meshes: a camera in front of the
// chair there (the front faces -y) sees it, the same camera turned round does not, and the mesh
// is the chair at the camera's lod.
TEST(ModelLevelOfDetail, MeshWithACameraInTheZUpFrame) {
  Camera front;
  front.position = Vec3(1, -40, 1);
  front.direction = Vec3(0, 1, 0);
  front.up = Vec3(0, 0, 1);
  const std::optional<BoxView> view = procedural_model_view("chair", {}, front);
  ASSERT_TRUE(view.has_value());
  ASSERT_TRUE(view->visible);
  EXPECT_LT(view->lod, 0);
  const Mesh seen = mesh_procedural_model("chair", {}, 0, front);
  const Mesh at_that_lod = mesh_procedural_model("chair", {}, 0, view->lod);
  EXPECT_EQ(seen.vertices, at_that_lod.vertices);
  EXPECT_EQ(seen.triangles, at_that_lod.triangles);
  EXPECT_LT(seen.triangles.size(), mesh_procedural_model("chair").triangles.size());
  Camera behind = front;
  behind.direction = Vec3(0, -1, 0);
  EXPECT_FALSE(procedural_model_view("chair", {}, behind)->visible);
  EXPECT_TRUE(mesh_procedural_model("chair", {}, 0, behind).triangles.empty());
  // Above the chair looking down at it along z: seen as well (the frame's z is the chair's up).
  Camera above;
  above.position = Vec3(1, -1, 30);
  above.direction = Vec3(0, 0, -1);
  above.up = Vec3(0, 1, 0);
  EXPECT_TRUE(procedural_model_view("chair", {}, above)->visible);
  // Models without bounds have no view; a bad camera is refused by its field.
  EXPECT_FALSE(procedural_model_view("leg", {}, front).has_value());
  Camera bad = front;
  bad.fov_y = 4.0;
  EXPECT_NE(genmod::test::refusal([&] { procedural_model_view("chair", {}, bad); }).find("fov_y"), std::string::npos);
}

}  // namespace
}  // namespace genmod::models
