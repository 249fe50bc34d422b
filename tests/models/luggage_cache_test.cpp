// The luggage and its chest as cacheable procedures (issue 12; research/morkel.md claims 9-12):
// transparent (the same bytes with the cache on and off, first and later calls), independent
// copies, and keys that hold every argument and the seed (the level of detail is left out
// because neither procedure uses it: a changed lod gives the same bytes and hits).
#include "genmod/models/procedural_models.hpp"
#include "genmod/procedural/extrusion.hpp"
#include "genmod/procedural/mesh_hash.hpp"
#include "procedural/mesh_test_support.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace genmod::models {
namespace {

using genmod::test::mesh_difference;

Context at(std::int64_t seed, int lod = 0) {
  Context c;
  c.seed = seed;
  c.lod = lod;
  return c;
}

struct Registries {
  ProcedureRegistry on, off;
  Registries() {
    register_procedural_models(on);
    register_procedural_models(off);
    off.set_caching(false);
  }
};

TEST(LuggageCache, ChestAndLuggageAreTransparent) {  // claim 9
  Registries r;
  const std::vector<std::pair<std::string, NamedArgs>> calls = {
      {"luggage_chest", {}},
      {"luggage_chest", {{"legColumns", 4}, {"legRows", 8}, {"lidHeight", 0.0}}},
      {"luggage", {{"numLegs", 6}}},
      {"luggage", {{"numLegs", 3}, {"legSubdivisions", 1}}},
  };
  for (int round = 0; round < 3; ++round)
    for (const auto& [name, args] : calls) {
      SCOPED_TRACE(name + " round " + std::to_string(round));
      EXPECT_EQ(mesh_difference(r.on.call(name, args, at(3)), r.off.call(name, args, at(3))), "");
    }
  EXPECT_EQ(r.on.cache_stats("luggage").hits, 4u);
  EXPECT_EQ(r.on.cache_stats("luggage").misses, 2u);
  EXPECT_EQ(r.on.cache_stats("luggage_chest").misses, 4u);  // two of its own, two the luggages' layouts
}

TEST(LuggageCache, HitsAreIndependentCopies) {  // claim 10
  ProcedureRegistry r;
  register_procedural_models(r);
  for (const char* name : {"luggage", "luggage_chest"}) {
    SCOPED_TRACE(name);
    const PolyMesh first = r.call(name);
    const MeshHash original = content_hash(first);
    PolyMesh a = r.call(name), b = r.call(name);
    EXPECT_NE(&a, &b);
    extrude(a, {PolyMesh::FaceHandle(0)}, Vec3(0, -0.1, 0));
    set_face_label(a, a.face_handle(1), "changed");
    EXPECT_NE(content_hash(a), original);
    EXPECT_EQ(content_hash(b), original);
    EXPECT_EQ(content_hash(r.call(name)), original);
    EXPECT_EQ(content_hash(first), original);
  }
}

TEST(LuggageCache, ChestKeyHoldsEveryArgumentAndTheSeed) {  // claim 11
  ProcedureRegistry r;
  register_procedural_models(r);
  const auto misses = [&] { return r.cache_stats("luggage_chest").misses; };
  const auto hits = [&] { return r.cache_stats("luggage_chest").hits; };
  const PolyMesh base = r.call("luggage_chest", {}, at(0));
  r.call("luggage_chest",
         {{"height", 2.0}, {"width", 1.0}, {"length", 2.0}, {"lidHeight", 0.4}, {"legColumns", 2}, {"legRows", 2}},
         at(0));
  EXPECT_EQ(hits(), 1u);  // the defaults given explicitly: the same resolved key
  const std::vector<NamedArgs> changed = {{{"height", 2.5}},  {{"width", 1.25}},   {{"length", 2.5}},
                                          {{"lidHeight", 0.2}}, {{"legColumns", 3}}, {{"legRows", 3}}};
  for (const NamedArgs& args : changed) {
    SCOPED_TRACE(args.front().first);
    const std::uint64_t before = misses();
    const PolyMesh other = r.call("luggage_chest", args, at(0));
    EXPECT_EQ(misses(), before + 1);
    EXPECT_NE(content_hash(other), content_hash(base));  // each argument changes the mesh
  }
  r.call("luggage_chest", {}, at(1));  // another seed: another key
  EXPECT_EQ(misses(), 1u + changed.size() + 1u);
  const PolyMesh coarse = r.call("luggage_chest", {}, at(0, 3));  // lod unused: a hit, same bytes
  EXPECT_EQ(hits(), 2u);
  EXPECT_EQ(mesh_difference(coarse, base), "");
}

TEST(LuggageCache, LuggageKeyHoldsEveryArgumentAndTheSeed) {  // claims 11-12
  ProcedureRegistry r;
  register_procedural_models(r);
  const auto misses = [&] { return r.cache_stats("luggage").misses; };
  const NamedArgs base{{"numLegs", 2}, {"legSubdivisions", 1}};
  const PolyMesh first = r.call("luggage", base, at(5));
  const std::vector<NamedArgs> changed = {
      {{"numLegs", 3}, {"legSubdivisions", 1}},
      {{"numLegs", 2}, {"legSubdivisions", 2}},
      {{"numLegs", 2}, {"legSubdivisions", 1}, {"height", 2.5}},
      {{"numLegs", 2}, {"legSubdivisions", 1}, {"width", 1.5}},
      {{"numLegs", 2}, {"legSubdivisions", 1}, {"length", 2.5}},
      {{"numLegs", 2}, {"legSubdivisions", 1}, {"legColumns", 1}},
      {{"numLegs", 2}, {"legSubdivisions", 1}, {"lidHeight", 0.1}},
  };
  for (const NamedArgs& args : changed) {
    SCOPED_TRACE(args.back().first);
    const std::uint64_t before = misses();
    EXPECT_NE(content_hash(r.call("luggage", args, at(5))), content_hash(first));
    EXPECT_EQ(misses(), before + 1);
  }
  // Another seed misses (the legs inherit it, so it is in their keys as well).
  const std::uint64_t leg_misses = r.cache_stats("leg").misses;
  r.call("luggage", base, at(6));
  EXPECT_EQ(misses(), 1u + changed.size() + 1u);
  EXPECT_EQ(r.cache_stats("leg").misses, leg_misses + 1);
  // Called again: a hit and no sub-call at all.
  const std::uint64_t leg_calls = r.cache_stats("leg").misses + r.cache_stats("leg").hits;
  EXPECT_EQ(mesh_difference(r.call("luggage", base, at(5)), first), "");
  EXPECT_EQ(r.cache_stats("luggage").hits, 1u);
  EXPECT_EQ(r.cache_stats("leg").misses + r.cache_stats("leg").hits, leg_calls);
  // Another lod is another luggage (legs with legSubdivisions + lod rounds): a miss, and a luggage
  // equal to the one whose legSubdivisions is moved by that lod (the lod 0 call of it is a
  // third key).
  const PolyMesh finer = r.call("luggage", base, at(5, 2));
  EXPECT_EQ(misses(), 1u + changed.size() + 2u);
  EXPECT_EQ(mesh_difference(finer, r.call("luggage", {{"numLegs", 2}, {"legSubdivisions", 3}}, at(5))), "");
  EXPECT_EQ(misses(), 1u + changed.size() + 3u);
  EXPECT_GT(finer.n_faces(), first.n_faces());
}

TEST(LuggageCache, ChestArgumentsAreCheckedByName) {
  ProcedureRegistry r;
  register_procedural_models(r);
  const std::string message = test::refusal([&] { r.call("luggage_chest", {{"legColumns", 0}}); });
  EXPECT_NE(message.find("'luggage_chest'"), std::string::npos) << message;
  EXPECT_NE(message.find("'legColumns'"), std::string::npos) << message;
}

}  // namespace
}  // namespace genmod::models
