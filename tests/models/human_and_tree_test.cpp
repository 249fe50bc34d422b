// Morkel's human figure (foot, leg, arm, torso, head, human) and the L-system tree (branch,
// tree) as registered procedures (procedural_models.hpp): valid closed meshes, parameters that
// act, reproducible bytes, the cache counts of claim 12 and the testable parts of claims 13,
// 14, 29 and 30 of research/morkel.md (the speed parts are measured in
// bench/procedural/luggage_bench.cpp).
#include "genmod/models/procedural_models.hpp"

#include "genmod/procedural/mesh_hash.hpp"
#include "genmod/procedural/rng.hpp"
#include "genmod/tessellate/validate.hpp"
#include "procedural/mesh_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod::models {
namespace {

using genmod::test::expect_valid_closed;
using genmod::test::mesh_difference;
using genmod::test::refusal;

Context seeded(std::int64_t seed) {
  Context c;
  c.seed = seed;
  return c;
}

PolyMesh build(const std::string& name, const NamedArgs& args = {}, std::int64_t seed = 0) {
  return procedural_registry().call(name, args, seeded(seed));
}

std::array<Vec3, 2> box_of(const PolyMesh& mesh) { return bounds(mesh, all_faces(mesh)); }

// A registry of its own (cache counters start at zero), optionally with some procedures'
// cacheable flag switched off.
struct OwnRegistry {
  ProcedureRegistry registry;
  explicit OwnRegistry(std::set<std::string> uncached = {}) {
    register_procedural_models(registry, [&](ProcedureSpec& spec) {
      if (uncached.count(spec.name)) spec.cacheable = false;
    });
  }
};

TEST(HumanAndTree, EveryNewModelMeshesClosedManifoldOutwardWithoutSelfIntersections) {
  const std::vector<std::pair<std::string, NamedArgs>> cases = {
      {"foot", {}},
      {"foot", {{"side", "right"}}},
      {"foot", {{"numToes", 1}}},
      {"foot", {{"numToes", 3}, {"subdivisions", 0}}},
      {"leg", {}},
      {"leg", {{"side", "right"}, {"subdivisions", 0}}},
      {"arm", {}},
      {"torso", {}},
      {"torso", {{"cubical", false}}},
      {"torso", {{"tummy", 0.1}, {"butt", 0.1}}},
      {"head", {}},
      {"human", {}},
      {"human", {{"cubical", false}}},
      {"human", {{"tummy", 0.15}, {"butt", 0.1}}},
      {"human", {{"height", 5.0}, {"tummy", -0.02}}},
      {"human", {{"subdivisions", 0}}},
      {"branch", {}},
      {"tree", {}},
      {"tree", {{"angle", 45.0}, {"levels", 4}}},
      {"tree", {{"angle", 15.0}, {"jitter", 0.5}}},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE(cases[i].first + ", case " + std::to_string(i));
    expect_valid_closed(build(cases[i].first, cases[i].second));
  }
}

// Experiment 4's trees (levels 3-6) and several seeds: valid, one closed component per branch,
// 2^levels - 1 branches, the polygon count growing with the level.
TEST(HumanAndTree, TreesAtLevelsThreeToSixAreValidWithOneComponentPerBranch) {
  std::size_t previous = 0;
  for (int levels = 3; levels <= 6; ++levels)
    for (std::int64_t seed : {0, 1, 12345}) {
      SCOPED_TRACE("levels " + std::to_string(levels) + ", seed " + std::to_string(seed));
      const PolyMesh tree = build("tree", {{"levels", levels}}, seed);
      EXPECT_TRUE(is_closed_manifold(tree));
      const MeshValidity v = validate(to_triangle_mesh(tree));
      EXPECT_TRUE(v.valid()) << describe(v);
      const std::size_t branches = (std::size_t{1} << levels) - 1;
      EXPECT_EQ(v.components, branches);
      EXPECT_EQ(tree.n_faces(), branches * (8 * 2 + 2));
      if (seed == 0) {
        EXPECT_GT(tree.n_faces(), previous);
        previous = tree.n_faces();
      }
    }
}

TEST(HumanAndTree, HeightScalesTheFigure) {
  // Claim 29 (with the section 7 items 2-3 fixes): two heights give the same mesh scaled by
  // their ratio, the same topology. A power-of-two ratio scales every operation exactly.
  const PolyMesh six = build("human"), twelve = build("human", {{"height", 12.0}});
  ASSERT_EQ(six.n_vertices(), twelve.n_vertices());
  ASSERT_EQ(six.n_faces(), twelve.n_faces());
  for (auto v : six.vertices()) ASSERT_EQ(twelve.point(v), 2.0 * six.point(v)) << v.idx();
  for (double h : {5.5, 6.5, 3.0}) {
    SCOPED_TRACE("height " + std::to_string(h));
    const PolyMesh other = build("human", {{"height", h}});
    ASSERT_EQ(other.n_vertices(), six.n_vertices());
    ASSERT_EQ(other.n_faces(), six.n_faces());
    const double ratio = h / 6.0;
    const double scale = (box_of(six)[1] - box_of(six)[0]).norm();
    double worst = 0;
    for (auto v : six.vertices()) worst = std::max(worst, (other.point(v) - ratio * six.point(v)).norm());
    EXPECT_LE(worst, 1e-9 * ratio * scale);
    for (auto f : six.faces()) {
      std::vector<int> a, b;
      for (auto v : six.fv_range(f)) a.push_back(v.idx());
      for (auto v : other.fv_range(f)) b.push_back(v.idx());
      ASSERT_EQ(a, b) << "face " << f.idx();
    }
  }
  // Loomis: about 8 heads tall (head = height / 8), soles on the ground, arms spanning about
  // the height (T pose).
  const double metres = 6.0 * 0.3048, head = metres / 8.0;
  const auto b = box_of(six);
  EXPECT_NEAR(b[0][1], 0.0, 1e-12);
  EXPECT_NEAR(b[1][1], metres, 0.3 * head);
  EXPECT_NEAR(b[1][0] - b[0][0], metres, 0.5 * head);
}

// The belly's extent: the furthest forward point of the torso's lower half.
double belly(const PolyMesh& human) {
  const double head = 6.0 * 0.3048 / 8.0, lo = 4.0 * head, hi = lo + 0.5 * (61.5 / 23.0) * head;
  double front = -HUGE_VAL;
  for (auto f : faces_labelled(human, "torso"))
    for (auto v : human.fv_range(f))
      if (human.point(v)[1] > lo && human.point(v)[1] < hi) front = std::max(front, human.point(v)[2]);
  return front;
}
double seat(const PolyMesh& human) {
  double back = HUGE_VAL;
  for (auto f : faces_labelled(human, "torso"))
    for (auto v : human.fv_range(f)) back = std::min(back, human.point(v)[2]);
  return back;
}

TEST(HumanAndTree, TummyAndButtChangeTheBellyAndTheBack) {
  const PolyMesh plain = build("human"), fat = build("human", {{"tummy", 0.1}}), thin = build("human", {{"tummy", -0.02}});
  EXPECT_GT(belly(fat), belly(plain) + 0.01);
  EXPECT_LT(belly(thin), belly(plain));
  // The tummy moves the front only.
  EXPECT_EQ(seat(fat), seat(plain));
  const PolyMesh round = build("human", {{"butt", 0.1}});
  EXPECT_LT(seat(round), seat(plain) - 0.01);
  EXPECT_EQ(belly(round), belly(plain));
  // Same topology: the parameters move vertices only.
  EXPECT_EQ(fat.n_faces(), plain.n_faces());
  EXPECT_EQ(round.n_vertices(), plain.n_vertices());
}

// Claim 29: 50 humans with distinct (height, tummy, butt) from a seeded generator are pairwise
// distinct meshes.
TEST(HumanAndTree, FiftyParameterisedHumansAreDistinct) {
  Rng rng(2006);
  std::set<std::pair<std::uint64_t, std::uint64_t>> hashes;
  for (int i = 0; i < 50; ++i) {
    const double height = 5.0 + 1.5 * rng.next_double(), tummy = 0.1 * rng.next_double(), butt = 0.1 * rng.next_double();
    const MeshHash h = content_hash(build("human", {{"height", height}, {"tummy", tummy}, {"butt", butt}, {"subdivisions", 1}}));
    hashes.insert({h.a, h.b});
  }
  EXPECT_EQ(hashes.size(), 50u);
}

// Claim 30: the egg torso (cubical = false) completes with two arms and two legs attached:
// exactly the faces of two arm calls besides the torso's, legs with feet, and the bridges at
// the shoulders and hips. The cubical figure has a head; the egg has none (Experiment 3's
// Humpty-Dumpty), its neck faces left on the egg.
TEST(HumanAndTree, EggTorsoHumanHasTwoArmsTwoLegsAndOnlyTheCubicalOneAHead) {
  for (bool cubical : {true, false}) {
    SCOPED_TRACE(cubical ? "cubical" : "egg");
    const PolyMesh human = build("human", {{"cubical", cubical}});
    expect_valid_closed(human);
    const PolyMesh arm = build("arm", {{"length", 3.0 * 0.2286}, {"thickness", (9.0 / 23.0) * 0.2286}});
    EXPECT_EQ(faces_labelled(human, "arm").size(), 2 * faces_labelled(arm, "arm").size());
    for (const char* part : {"leg", "foot", "toe0", "toe4", "ankle", "neck"})
      EXPECT_FALSE(faces_labelled(human, part).empty()) << part;
    for (const char* part : {"head", "nose"}) EXPECT_EQ(faces_labelled(human, part).empty(), !cubical) << part;
    for (const char* joint : {"shoulder_l", "shoulder_r", "hip_l", "hip_r"})
      EXPECT_FALSE(faces_labelled(human, joint).empty()) << joint;
    EXPECT_EQ(validate(to_triangle_mesh(human)).components, 1u);
  }
}

// Experiment 3's egg: the egg torso lies in the ellipsoid inscribed in the cubical torso's
// block, its unsubdivided attachment faces on it, and its smoothed rest close to it (the
// default torso: 0.611 x 0.398 x 0.288 m about (0, height / 2, 0)).
TEST(HumanAndTree, EggTorsoIsAnEllipsoid) {
  const PolyMesh egg = build("torso", {{"cubical", false}});
  expect_valid_closed(egg);
  const double a = 0.39756521739130435 / 2, b = 0.6112565217391304 / 2, c = 0.28823478260869567 / 2;
  double lowest = HUGE_VAL, highest = 0;
  for (auto v : egg.vertices()) {
    const Vec3 p = egg.point(v);
    const double r = std::sqrt(std::pow(p[0] / a, 2) + std::pow((p[1] - b) / b, 2) + std::pow(p[2] / c, 2));
    lowest = std::min(lowest, r);
    highest = std::max(highest, r);
  }
  EXPECT_LE(highest, 1.0 + 1e-12);  // smoothing only moves points inwards (claim 24)
  EXPECT_GE(highest, 1.0 - 1e-12);  // the limbs' faces are not smoothed
  EXPECT_GT(lowest, 0.9);
  for (const char* joint : {"neck", "shoulder_l", "shoulder_r", "hip_l", "hip_r"}) {
    for (auto f : faces_labelled(egg, joint))
      for (auto v : egg.fv_range(f)) {
        const Vec3 p = egg.point(v);
        EXPECT_NEAR(std::pow(p[0] / a, 2) + std::pow((p[1] - b) / b, 2) + std::pow(p[2] / c, 2), 1.0, 1e-12) << joint;
      }
  }
}

TEST(HumanAndTree, FeetAreMirroredWithTheBigToeInside) {
  const PolyMesh left = build("foot"), right = build("foot", {{"side", "right"}});
  const auto tip_x = [](const PolyMesh& m) {
    double z = -HUGE_VAL, x = 0;
    for (auto v : m.vertices())
      if (m.point(v)[2] > z) z = m.point(v)[2], x = m.point(v)[0];
    return x;
  };
  EXPECT_LT(tip_x(left), 0.0);
  EXPECT_GT(tip_x(right), 0.0);
  EXPECT_NEAR(tip_x(left), -tip_x(right), 1e-12);
  EXPECT_EQ(left.n_faces(), right.n_faces());
  const PolyMesh sharp = build("foot", {{"smoothing", 0.0}});
  EXPECT_NEAR(box_of(sharp)[1][2], 0.3, 1e-12);  // the big toe's tip at z = length
  EXPECT_NEAR(box_of(sharp)[0][1], -0.07, 1e-12);  // the sole at y = -height
  EXPECT_NEAR(box_of(sharp)[1][1], 0.0, 1e-12);
  EXPECT_EQ(faces_labelled(build("foot", {{"numToes", 3}}), "toe2").size() > 0, true);
  EXPECT_TRUE(faces_labelled(build("foot", {{"numToes", 3}}), "toe3").empty());
}

TEST(HumanAndTree, SameArgumentsAndSeedGiveByteIdenticalMeshes) {
  for (const char* name : {"foot", "leg", "arm", "torso", "head", "human", "branch", "tree"}) {
    SCOPED_TRACE(name);
    EXPECT_EQ(mesh_difference(build(name, {}, 12345), build(name, {}, 12345)), "");
  }
  // The seed places a tree's branches (jittered angles), not their shapes.
  const PolyMesh a = build("tree", {}, 1), b = build("tree", {}, 2);
  EXPECT_NE(content_hash(a), content_hash(b));
  EXPECT_EQ(a.n_faces(), b.n_faces());
  EXPECT_EQ(mesh_difference(build("tree", {{"jitter", 0.0}}, 1), build("tree", {{"jitter", 0.0}}, 2)), "");
  // The human uses no random numbers.
  EXPECT_EQ(mesh_difference(build("human", {}, 1), build("human", {}, 2)), "");
}

// Claim 12 for the human (left and right feet differ in arguments: 2 misses) and claim 9 (the
// cache is transparent).
TEST(HumanAndTree, HumanCacheCounts) {
  OwnRegistry own;
  ProcedureRegistry& r = own.registry;
  const PolyMesh first = r.call("human");
  EXPECT_EQ(r.cache_stats("leg").misses, 2u);
  EXPECT_EQ(r.cache_stats("leg").hits, 0u);
  EXPECT_EQ(r.cache_stats("foot").misses, 2u);
  EXPECT_EQ(r.cache_stats("foot").hits, 0u);
  for (const char* part : {"arm", "torso", "head"}) {  // one call each per human
    EXPECT_EQ(r.cache_stats(part).misses, 1u) << part;
    EXPECT_EQ(r.cache_stats(part).hits, 0u) << part;
  }
  const PolyMesh second = r.call("human");
  EXPECT_EQ(r.cache_stats("leg").hits, 2u);
  EXPECT_EQ(r.cache_stats("foot").misses, 2u);  // a leg hit does not call foot
  for (const char* part : {"arm", "torso", "head"}) {
    EXPECT_EQ(r.cache_stats(part).misses, 1u) << part;
    EXPECT_EQ(r.cache_stats(part).hits, 1u) << part;
  }
  EXPECT_EQ(mesh_difference(first, second), "");
  r.set_caching(false);
  EXPECT_EQ(mesh_difference(r.call("human"), first), "");

  // Claim 14's setting: only the feet cached. Two feet per human, two distinct keys: the cache
  // gives nothing on the first human (2 misses, 0 hits) and both feet on a second.
  OwnRegistry feet_only({"leg", "arm", "torso", "head"});
  ProcedureRegistry& f = feet_only.registry;
  EXPECT_EQ(mesh_difference(f.call("human"), first), "");
  EXPECT_EQ(f.cache_stats("foot").misses, 2u);
  EXPECT_EQ(f.cache_stats("foot").hits, 0u);
  EXPECT_EQ(f.cache_stats("leg").misses + f.cache_stats("leg").hits, 0u);
  f.call("human");
  EXPECT_EQ(f.cache_stats("foot").hits, 2u);
}

// Claim 12 for the tree: `levels` distinct branch tuples, so levels misses and 2^levels - 1 -
// levels hits; a cached whole tree called again: a tree hit and no new branch calls. With only
// the branches cacheable (Experiment 6's "cylinders") a second tree is all branch hits.
TEST(HumanAndTree, TreeCacheCounts) {
  for (int levels = 3; levels <= 6; ++levels) {
    SCOPED_TRACE("levels " + std::to_string(levels));
    const std::uint64_t branches = (std::uint64_t{1} << levels) - 1;
    const NamedArgs args{{"levels", levels}};
    OwnRegistry own;
    ProcedureRegistry& r = own.registry;
    const PolyMesh first = r.call("tree", args, seeded(5));
    EXPECT_EQ(r.cache_stats("tree").misses, 1u);
    EXPECT_EQ(r.cache_stats("branch").misses, static_cast<std::uint64_t>(levels));
    EXPECT_EQ(r.cache_stats("branch").hits, branches - levels);
    const PolyMesh again = r.call("tree", args, seeded(5));
    EXPECT_EQ(r.cache_stats("tree").hits, 1u);
    EXPECT_EQ(r.cache_stats("branch").misses + r.cache_stats("branch").hits, branches);
    EXPECT_EQ(mesh_difference(first, again), "");
    // Another seed: another tree, the same branches.
    r.call("tree", args, seeded(6));
    EXPECT_EQ(r.cache_stats("tree").misses, 2u);
    EXPECT_EQ(r.cache_stats("branch").misses, static_cast<std::uint64_t>(levels));
    EXPECT_EQ(r.cache_stats("branch").hits, 2 * branches - levels);

    OwnRegistry branches_only({"tree"});
    ProcedureRegistry& b = branches_only.registry;
    b.call("tree", args, seeded(5));
    b.call("tree", args, seeded(5));
    EXPECT_EQ(b.cache_stats("branch").misses, static_cast<std::uint64_t>(levels));
    EXPECT_EQ(b.cache_stats("branch").hits, 2 * branches - levels);
    b.set_caching(false);
    EXPECT_EQ(mesh_difference(b.call("tree", args, seeded(5)), first), "");
  }
}

// Claim 13's structure (its speed is in the bench): a warm 30-leg luggage builds no leg, and
// the luggage on human legs keeps claim 30's roughly constant faces per leg. The thesis's
// setting, only the parts cached (the luggage's own cacheable flag off): the warm luggage is
// assembled from 30 leg hits.
TEST(HumanAndTree, WarmLuggageOnHumanLegsBuildsNoLeg) {
  OwnRegistry own({"luggage"});
  ProcedureRegistry& r = own.registry;
  const PolyMesh cold = r.call("luggage", {{"numLegs", 30}});
  EXPECT_EQ(r.cache_stats("leg").misses, 1u);
  EXPECT_EQ(r.cache_stats("foot").misses, 1u);
  r.reset_cache_stats("leg");
  r.reset_cache_stats("foot");
  const PolyMesh warm = r.call("luggage", {{"numLegs", 30}});
  EXPECT_EQ(r.cache_stats("leg").hits, 30u);
  EXPECT_EQ(r.cache_stats("leg").misses, 0u);
  EXPECT_EQ(r.cache_stats("foot").misses + r.cache_stats("foot").hits, 0u);
  EXPECT_EQ(mesh_difference(cold, warm), "");
  // The luggage's legs are the human leg: toes and ankles.
  EXPECT_EQ(faces_labelled(warm, "toe0").size(), 30 * faces_labelled(build("leg", {{"subdivisions", 3}}), "toe0").size());
}

TEST(HumanAndTree, BadParametersAreRefusedNamingProcedureAndParameter) {
  struct Case {
    std::string procedure;
    NamedArgs args;
    std::string parameter;
  };
  const std::vector<Case> cases = {
      {"human", {{"height", -1.0}}, "height"},     {"human", {{"height", 1e6}}, "height"},
      {"human", {{"tummy", 5.0}}, "tummy"},        {"human", {{"butt", std::nan("")}}, "butt"},
      {"human", {{"subdivisions", 9}}, "subdivisions"},
      {"foot", {{"side", "middle"}}, "side"},      {"foot", {{"numToes", 0}}, "numToes"},
      {"foot", {{"heel", 0.5}}, "heel"},           {"leg", {{"side", "up"}}, "side"},
      {"leg", {{"footHeight", 2.0}}, "footHeight"}, {"arm", {{"length", 0.0}}, "length"},
      {"torso", {{"width", -0.2}}, "width"},       {"head", {{"head", 0.0}}, "head"},
      {"tree", {{"levels", 0}}, "levels"},         {"tree", {{"angle", 90.0}}, "angle"},
      {"tree", {{"lengthRatio", 0.9}}, "lengthRatio"}, {"tree", {{"trunkRadius", 0.5}}, "trunkRadius"},
      {"branch", {{"sides", 2}}, "sides"},
  };
  for (const Case& c : cases) {
    const std::string message = refusal([&] { build(c.procedure, c.args); });
    EXPECT_NE(message.find("'" + c.procedure + "'"), std::string::npos) << c.procedure << ": " << message;
    EXPECT_NE(message.find("'" + c.parameter + "'"), std::string::npos) << c.procedure << ": " << message;
  }
}

}  // namespace
}  // namespace genmod::models
