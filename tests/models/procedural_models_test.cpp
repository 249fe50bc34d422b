// Morkel's furniture models as registered procedures (procedural_models.hpp): valid closed
// meshes, parameters that act, reproducible bytes, refused bad values, and the luggage's leg
// cache counts of research/morkel.md claim 12.
#include "genmod/models/gallery.hpp"
#include "genmod/models/implicit_gallery.hpp"
#include "genmod/models/procedural_models.hpp"

#include "genmod/procedural/mesh_hash.hpp"
#include "procedural/mesh_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod::models {
namespace {

using genmod::test::expect_valid_closed;
using genmod::test::mesh_difference;
using genmod::test::refusal;

PolyMesh build(const std::string& name, const NamedArgs& args = {}, std::int64_t seed = 0) {
  Context c;
  c.seed = seed;
  return procedural_registry().call(name, args, c);
}

Context seeded(std::int64_t seed) {
  Context c;
  c.seed = seed;
  return c;
}

std::array<Vec3, 2> box_of(const PolyMesh& mesh) { return bounds(mesh, all_faces(mesh)); }
double extent(const PolyMesh& mesh, int axis) {
  const auto b = box_of(mesh);
  return b[1][axis] - b[0][axis];
}

// `genmod mesh NAME` finds one model: no name is used by two of the three galleries.
TEST(ProceduralModels, NoTwoModelsShareAName) {
  std::map<std::string, int> uses;
  for (const Model& m : gallery()) ++uses[m.name];
  for (const ImplicitModel& m : implicit_gallery()) ++uses[m.name];
  for (const ProceduralModel& m : procedural_gallery()) ++uses[m.name];
  for (const auto& [name, count] : uses) EXPECT_EQ(count, 1) << name;
}

TEST(ProceduralModels, GalleryListsTheProceduresWithTheirParameters) {
  std::vector<std::string> names;
  for (const ProceduralModel& m : procedural_gallery()) {
    names.push_back(m.name);
    ASSERT_TRUE(procedural_registry().contains(m.name));
    const ProcedureSpec& spec = procedural_registry().spec(m.name);
    ASSERT_EQ(spec.params.size(), m.parameter_docs.size()) << m.name;
    for (std::size_t i = 0; i < spec.params.size(); ++i) EXPECT_EQ(spec.params[i].name, m.parameter_docs[i].first);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"leg", "chair", "couch", "table", "luggage", "luggage_chest", "foot", "arm",
                                             "torso", "head", "human", "branch", "tree"}));
  EXPECT_EQ(find_procedural_model("doorknob"), nullptr);
  ASSERT_NE(find_procedural_model("luggage"), nullptr);
  // The thesis's Luggage signature begins height, width, length, numLegs with its defaults.
  EXPECT_EQ(procedural_registry().signature("luggage").rfind("OUT:Double,height:Double,width:Double,length:Integer,numLegs", 0),
            0u);
  for (const char* name : {"leg", "luggage", "luggage_chest", "foot", "arm", "torso", "head", "branch", "tree"})
    EXPECT_TRUE(procedural_registry().spec(name).cacheable) << name;
  for (const char* name : {"human", "chair", "couch", "table"}) EXPECT_FALSE(procedural_registry().spec(name).cacheable) << name;
}

TEST(ProceduralModels, DefaultsMeshClosedManifoldOutwardWithoutSelfIntersections) {
  for (const ProceduralModel& m : procedural_gallery()) {
    SCOPED_TRACE(m.name);
    const PolyMesh mesh = build(m.name);
    EXPECT_GT(mesh.n_faces(), 10u);  // the branch, the smallest, has 18
    expect_valid_closed(mesh);
  }
}

TEST(ProceduralModels, VariantsMeshValid) {
  const std::vector<std::pair<std::string, NamedArgs>> variants = {
      {"chair", {{"arms", true}}},
      {"chair", {{"arms", true}, {"bottomArms", false}}},
      {"chair", {{"shape", true}}},
      {"chair", {{"arms", true}, {"shape", true}, {"offSet", -1.0}, {"length", 3.0}, {"depth", 1.5}}},
      {"chair", {{"feet", true}}},
      {"chair", {{"feet", true}, {"arms", true}, {"segments", 3}}},
      {"chair", {{"feet", true}, {"segments", 2}}},  // too few cells: extruded legs
      {"couch", {{"numCushions", 1}}},
      {"couch", {{"numCushions", 2}, {"shape", true}, {"backCushions", false}}},
      {"table", {{"roundTable", true}}},
      {"table", {{"roundTable", true}, {"smoothingFactor", 0.0}}},
      {"table", {{"roundTable", true}, {"segments", 4}}},
      {"table", {{"segments", 3}, {"length", 1.0}}},
      {"luggage", {{"numLegs", 0}}},
      {"luggage", {{"numLegs", 1}}},
      {"luggage", {{"numLegs", 7}, {"legColumns", 3}, {"lidHeight", 0.0}}},
      {"leg", {{"subdivisions", 0}}},
  };
  for (std::size_t i = 0; i < variants.size(); ++i) {
    SCOPED_TRACE(variants[i].first + ", variant " + std::to_string(i));
    expect_valid_closed(build(variants[i].first, variants[i].second));
  }
}

// The pieces of the faces labelled `label`: groups of faces joined through shared edges.
std::size_t labelled_pieces(const PolyMesh& mesh, const std::string& label) {
  const FaceList faces = faces_labelled(mesh, label);
  std::set<int> left;
  for (auto f : faces) left.insert(f.idx());
  std::size_t pieces = 0;
  while (!left.empty()) {
    ++pieces;
    std::vector<int> stack{*left.begin()};
    left.erase(left.begin());
    while (!stack.empty()) {
      const PolyMesh::FaceHandle f(stack.back());
      stack.pop_back();
      for (auto g : mesh.ff_range(f))
        if (left.erase(g.idx())) stack.push_back(g.idx());
    }
  }
  return pieces;
}

// Claim 30: the chair completes at every segments value; from 5 on it has every part (the
// thesis's complete chairs).
TEST(ProceduralModels, ChairAtEveryDetailLevel) {
  for (int segments = 1; segments <= 10; ++segments) {
    SCOPED_TRACE("segments " + std::to_string(segments));
    const PolyMesh chair = build("chair", {{"segments", segments}, {"arms", true}});
    expect_valid_closed(chair);
    if (segments >= 5) {
      for (const char* part : {"back", "cushion1", "legs", "armrest_l", "armrest_r", "seat"})
        EXPECT_FALSE(faces_labelled(chair, part).empty()) << part;
      // Four legs: the "legs" faces fall into four pieces joined by edges (one per corner).
      EXPECT_EQ(labelled_pieces(chair, "legs"), 4u);
    }
  }
}

// Experiment 3's chair from a disc (cubic = false): at every detail level and with arms, feet
// and a shaped back it meshes valid and closed, with the square chair's counts (the same
// construction drawn onto a round seat); without feet every vertex lies in the ellipse
// inscribed in the seat rectangle and the rectangle's corners are on it.
TEST(ProceduralModels, ChairOnADiscBase) {
  std::vector<NamedArgs> variants;
  for (int segments = 1; segments <= 10; ++segments) variants.push_back({{"segments", segments}});
  variants.push_back({{"arms", true}, {"shape", true}});
  variants.push_back({{"arms", true}, {"bottomArms", false}, {"segments", 9}, {"length", 3.0}});
  variants.push_back({{"feet", true}, {"arms", true}});
  for (NamedArgs args : variants) {
    const bool feet = std::any_of(args.begin(), args.end(), [](const auto& a) { return a.first == "feet"; });
    const PolyMesh square = build("chair", args);
    args.emplace_back("cubic", false);
    SCOPED_TRACE("variant with " + std::to_string(args.size()) + " arguments, first " + args[0].first);
    const PolyMesh disc = build("chair", args);
    expect_valid_closed(disc);
    EXPECT_EQ(disc.n_vertices(), square.n_vertices());
    EXPECT_EQ(disc.n_faces(), square.n_faces());
    double length = 2.0;
    for (const auto& [k, v] : args)
      if (k == "length") length = v.as_double();
    const double cx = 0.5 * length, cz = 1.0;  // depth 2
    double largest = 0;
    for (auto v : disc.vertices()) {
      const Vec3 p = disc.point(v);
      largest = std::max(largest, std::hypot((p[0] - cx) / cx, (p[2] - cz) / cz));
    }
    if (!feet) {
      EXPECT_NEAR(largest, 1.0, 1e-12);  // on the ellipse, never beyond it
    }
  }
  // The listing's default, cubic = true, is the square chair.
  EXPECT_EQ(mesh_difference(build("chair", {{"cubic", true}}), build("chair")), "");
}

// Claim 30: the luggage's face count grows by a constant amount per leg (same leg, same
// layout rule; the base grid grows with the rows).
TEST(ProceduralModels, LuggageWithExperimentLegCounts) {
  std::vector<std::size_t> faces;
  for (int legs : {6, 12, 18, 24, 30}) {
    SCOPED_TRACE("numLegs " + std::to_string(legs));
    const PolyMesh mesh = build("luggage", {{"numLegs", legs}});
    expect_valid_closed(mesh);
    faces.push_back(mesh.n_faces());
  }
  double least = HUGE_VAL, most = 0;
  for (std::size_t i = 1; i < faces.size(); ++i) {
    EXPECT_GT(faces[i], faces[i - 1]);
    const double step = static_cast<double>(faces[i]) - static_cast<double>(faces[i - 1]);
    least = std::min(least, step);
    most = std::max(most, step);
  }
  // Six more legs add about the same number of faces each time (within 20%).
  EXPECT_LE(most, 1.2 * least);
}

TEST(ProceduralModels, ParametersChangeTheResult) {
  // The chair's height is legLength + seat + backLength: changing the back by 1 changes it by 1.
  const PolyMesh chair = build("chair"), tall = build("chair", {{"backLength", 2.5}});
  EXPECT_NEAR(extent(tall, 1) - extent(chair, 1), 1.0, 1e-12);
  EXPECT_NEAR(extent(chair, 1), 2.0 + 1.0 / 3.0 + 1.5, 1e-12);
  const PolyMesh long_legs = build("chair", {{"legLength", 3.0}});
  EXPECT_NEAR(box_of(long_legs)[0][1], -3.0, 1e-12);
  EXPECT_NEAR(extent(build("chair", {{"length", 3.0}}), 0), 3.0, 1e-12);
  EXPECT_NEAR(extent(build("chair", {{"depth", 1.2}}), 2), 1.2, 1e-12);
  // Arms add faces, a shaped back rises above the flat one.
  EXPECT_GT(build("chair", {{"arms", true}}).n_faces(), chair.n_faces());
  EXPECT_GT(box_of(build("chair", {{"shape", true}}))[1][1], box_of(chair)[1][1]);
  // The couch grows with its cushions.
  EXPECT_NEAR(extent(build("couch", {{"numCushions", 4}}), 0), 8.0, 1e-12);
  // The table's top has the given size; the round one is inside the box one's footprint.
  const PolyMesh table = build("table", {{"length", 4.0}, {"width", 1.5}});
  EXPECT_NEAR(extent(table, 0), 4.0, 1e-12);
  EXPECT_NEAR(extent(table, 2), 1.5, 1e-12);
  // The round top's corners are rounded off by the smoothing; with smoothing 0 they stay.
  const auto corner_distance = [](const PolyMesh& m) {
    double d = HUGE_VAL;
    for (auto v : m.vertices()) d = std::min(d, (m.point(v) - Vec3(1.5, 0.2, 1.0)).norm());
    return d;
  };
  const PolyMesh round = build("table", {{"roundTable", true}});
  EXPECT_GT(corner_distance(round), 0.05);
  EXPECT_EQ(corner_distance(build("table", {{"roundTable", true}, {"smoothingFactor", 0.0}})), 0.0);
  EXPECT_LE(extent(round, 0), 3.0);
  EXPECT_NE(content_hash(round), content_hash(build("table", {{"roundTable", true}, {"smoothingFactor", 0.5}})));
  // The luggage: width and length are the chest's; more legs, more faces.
  const PolyMesh luggage = build("luggage", {{"width", 1.5}, {"length", 3.0}});
  EXPECT_NEAR(extent(luggage, 0), 1.5, 1e-12);
  EXPECT_NEAR(extent(luggage, 2), 3.0, 1e-12);
  EXPECT_GT(build("luggage", {{"numLegs", 5}}).n_faces(), build("luggage").n_faces());
  EXPECT_GT(box_of(build("luggage", {{"lidHeight", 1.0}}))[1][1], box_of(build("luggage"))[1][1]);
  // The leg's top is the flat quad the luggage bridges to.
  const PolyMesh leg = build("leg", {{"height", 2.0}, {"smoothing", 0.0}});
  EXPECT_NEAR(box_of(leg)[0][1], -2.0, 1e-12);
  EXPECT_NEAR(box_of(leg)[1][2], 0.125 + 0.2, 1e-12);  // the foot reaches footLength forward
  EXPECT_EQ(faces_labelled(leg, "legtop").size(), 1u);
}

TEST(ProceduralModels, SameArgumentsAndSeedGiveByteIdenticalMeshes) {
  for (const ProceduralModel& m : procedural_gallery()) {
    SCOPED_TRACE(m.name);
    const PolyMesh a = build(m.name, {}, 12345), b = build(m.name, {}, 12345);
    EXPECT_EQ(mesh_difference(a, b), "");
    EXPECT_EQ(content_hash(a), content_hash(b));
    const Mesh ta = mesh_procedural_model(m.name, {}, 12345), tb = mesh_procedural_model(m.name, {}, 12345);
    ASSERT_EQ(ta.vertices.size(), tb.vertices.size());
    ASSERT_EQ(ta.triangles.size(), tb.triangles.size());
    EXPECT_EQ(std::memcmp(ta.vertices.data(), tb.vertices.data(), ta.vertices.size() * sizeof(ta.vertices[0])), 0);
    EXPECT_EQ(std::memcmp(ta.triangles.data(), tb.triangles.data(), ta.triangles.size() * sizeof(ta.triangles[0])),
              0);
  }
  // Named arguments in any order and explicit defaults give the same mesh (claims 2, 3).
  EXPECT_EQ(mesh_difference(build("chair", {{"arms", true}, {"length", 2.5}}),
                            build("chair", {{"length", 2.5}, {"arms", true}, {"segments", 6}})),
            "");
}

TEST(ProceduralModels, BadParametersAreRefusedNamingProcedureAndParameter) {
  struct Case {
    std::string procedure;
    NamedArgs args;
    std::string parameter;
  };
  const std::vector<Case> cases = {
      {"chair", {{"length", -1.0}}, "length"},
      {"chair", {{"backLength", 0.0}}, "backLength"},
      {"chair", {{"segments", 0}}, "segments"},
      {"chair", {{"offSet", -3.0}}, "offSet"},
      {"chair", {{"depth", std::nan("")}}, "depth"},
      {"chair", {{"colour", 1.0}}, "colour"},       // not in the signature (the registry refuses)
      {"chair", {{"arms", 1}}, "arms"},             // wrong type
      {"couch", {{"numCushions", 0}}, "numCushions"},
      {"table", {{"smoothingFactor", 2.0}}, "smoothingFactor"},
      {"table", {{"roundTable", true}, {"segments", 2}}, "segments"},
      {"luggage", {{"numLegs", -1}}, "numLegs"},
      {"luggage", {{"numLegs", 2}, {"legColumns", 3}}, "legColumns"},
      {"luggage", {{"width", HUGE_VAL}}, "width"},
      {"leg", {{"smoothing", 1.5}}, "smoothing"},
  };
  for (const Case& c : cases) {
    const std::string message = refusal([&] { build(c.procedure, c.args); });
    EXPECT_NE(message.find("'" + c.procedure + "'"), std::string::npos) << c.procedure << ": " << message;
    EXPECT_NE(message.find("'" + c.parameter + "'"), std::string::npos) << c.procedure << ": " << message;
  }
}

// Claim 12: N identical cacheable leg calls (same arguments, inherited seed) record exactly 1
// miss and N - 1 hits; claim 9: the mesh is the same bytes with the cache on and off. The
// luggage is cacheable itself, so a repeated luggage is one luggage hit and calls no leg (as a
// repeated tree: "0 new misses"); with its own flag off (the thesis's Experiment 6, only the
// parts cached) the repeated luggage is assembled from N leg hits and a chest hit.
TEST(ProceduralModels, LuggageLegsCostOneMissAndNumLegsMinusOneHits) {
  for (bool whole : {true, false}) {
    ProcedureRegistry registry;
    register_procedural_models(registry, [&](ProcedureSpec& spec) {
      if (spec.name == "luggage") spec.cacheable = whole;
    });
    for (int legs : {4, 12, 30}) {
      SCOPED_TRACE("numLegs " + std::to_string(legs) + (whole ? ", luggage cacheable" : ", parts only"));
      const NamedArgs args{{"numLegs", legs}};
      registry.set_caching(false);
      registry.clear_caches();
      for (const char* name : {"leg", "luggage", "luggage_chest"}) registry.reset_cache_stats(name);
      const PolyMesh uncached = registry.call("luggage", args, seeded(7));
      EXPECT_EQ(registry.cache_stats("leg").misses, 0u);
      EXPECT_EQ(registry.cache_stats("leg").hits, 0u);

      registry.set_caching(true);
      const PolyMesh cold = registry.call("luggage", args, seeded(7));
      EXPECT_EQ(registry.cache_stats("leg").misses, 1u);
      EXPECT_EQ(registry.cache_stats("leg").hits, static_cast<std::uint64_t>(legs - 1));
      EXPECT_EQ(registry.cache_stats("luggage_chest").misses, 1u);
      EXPECT_EQ(registry.cache_stats("luggage").misses, whole ? 1u : 0u);
      EXPECT_EQ(mesh_difference(cold, uncached), "");

      // A second luggage with the same arguments.
      const PolyMesh warm = registry.call("luggage", args, seeded(7));
      EXPECT_EQ(registry.cache_stats("leg").misses, 1u);
      EXPECT_EQ(registry.cache_stats("leg").hits, static_cast<std::uint64_t>(whole ? legs - 1 : 2 * legs - 1));
      EXPECT_EQ(registry.cache_stats("luggage").hits, whole ? 1u : 0u);
      EXPECT_EQ(registry.cache_stats("luggage_chest").hits, whole ? 0u : 1u);
      EXPECT_EQ(mesh_difference(warm, uncached), "");

      // Another seed is another key: one more leg miss (and luggage miss); the chest, built
      // with seed 0, is shared.
      const PolyMesh other = registry.call("luggage", args, seeded(8));
      EXPECT_EQ(registry.cache_stats("leg").misses, 2u);
      EXPECT_EQ(registry.cache_stats("luggage").misses, whole ? 2u : 0u);
      EXPECT_EQ(registry.cache_stats("luggage_chest").misses, 1u);
      EXPECT_EQ(mesh_difference(other, uncached), "");  // the luggage draws no random numbers
    }
  }
}

// The chair's feet reuse the luggage's cacheable leg (thesis: the chair's #Leg): four calls,
// one build.
TEST(ProceduralModels, ChairFeetAreOneLegBuildAndThreeHits) {
  ProcedureRegistry registry;
  register_procedural_models(registry);
  const PolyMesh chair = registry.call("chair", {{"feet", true}});
  EXPECT_EQ(registry.cache_stats("leg").misses, 1u);
  EXPECT_EQ(registry.cache_stats("leg").hits, 3u);
  EXPECT_EQ(faces_labelled(chair, "legs").size(), 0u);
  EXPECT_GT(faces_labelled(chair, "ankle").size(), 0u);
  registry.set_caching(false);
  EXPECT_EQ(mesh_difference(registry.call("chair", {{"feet", true}}), chair), "");
}

}  // namespace
}  // namespace genmod::models
