#include "genmod/procedural/procedural.hpp"

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace genmod {
namespace {

// Moves every vertex by a random offset of size <= amount: the seed shows in the output.
void jitter(PolyMesh& mesh, Rng& rng, double amount) {
  for (PolyMesh::VertexHandle v : mesh.vertices())
    mesh.set_point(v, mesh.point(v) + amount * Vec3(rng.next_double() - 0.5, rng.next_double() - 0.5, rng.next_double() - 0.5));
}

std::atomic<int> leg_body_runs{0};

// Torso (claim 5's header), Leg (cacheable), Luggage (N legs), Outer (calls Leg, optionally
// with a seed override), Bump (cacheable in-out noise displacement).
void register_examples(ProcedureRegistry& r, bool torso_cacheable = true) {
  ProcedureSpec torso;
  torso.name = "Torso";
  torso.mode = Mode::Out;
  torso.cacheable = torso_cacheable;
  torso.params = {param("ratio", 0.6), param("arms", 2), param("name", "torso")};
  torso.out_body = [](const Arguments& a, const CallContext& c) {
    double h = a.real("ratio");
    PolyMesh m = make_box(Vec3(-0.5, -0.5, 0), Vec3(0.5, 0.5, h * 3), a.string("name"));
    for (std::int64_t i = 0; i < a.integer("arms"); ++i)
      append_mesh(m, make_box(Vec3(0.5 + i, -0.1, 1), Vec3(1.5 + i, 0.1, 1.2), a.string("name") + ":arm"));
    Rng rng(c.seed());
    jitter(m, rng, 0.05);
    return m;
  };
  r.add(torso);

  ProcedureSpec leg;
  leg.name = "Leg";
  leg.mode = Mode::Out;
  leg.cacheable = true;
  leg.params = {param("length", 2.0), param("segments", 4)};
  leg.out_body = [](const Arguments& a, const CallContext& c) {
    ++leg_body_runs;
    PolyMesh m;
    double step = a.real("length") / static_cast<double>(a.integer("segments"));
    for (std::int64_t i = 0; i < a.integer("segments"); ++i)
      append_mesh(m, make_box(Vec3(-0.1, -0.1, -step * (i + 1)), Vec3(0.1, 0.1, -step * i), "leg"));
    Rng rng(c.seed(), 17);
    jitter(m, rng, 0.02);
    return m;
  };
  r.add(leg);

  ProcedureSpec luggage;
  luggage.name = "Luggage";
  luggage.mode = Mode::Out;
  luggage.params = {param("numLegs", 4), param("legLength", 1.0)};
  luggage.out_body = [](const Arguments& a, const CallContext& c) {
    PolyMesh m = make_box(Vec3(0, 0, 0), Vec3(4, 2, 1), "luggage");
    for (std::int64_t i = 0; i < a.integer("numLegs"); ++i)
      append_mesh(m, c.call("Leg", {{"length", a.real("legLength")}}), Affine::translation(Vec3(0.2 + 0.3 * i, 0.2, 0)));
    return m;
  };
  r.add(luggage);

  ProcedureSpec outer;
  outer.name = "Outer";
  outer.mode = Mode::Out;
  outer.params = {param("override", false), param("legSeed", 0)};
  outer.out_body = [](const Arguments& a, const CallContext& c) {
    CallOptions o;
    if (a.boolean("override")) o.seed = a.integer("legSeed");
    return c.call("Leg", {}, o);
  };
  r.add(outer);

  ProcedureSpec bump;
  bump.name = "Bump";
  bump.mode = Mode::InOut;
  bump.cacheable = true;
  bump.params = {param("amount", 0.1), param("direction", Vec3(0, 0, 1))};
  bump.inout_body = [](PolyMesh& m, const Arguments& a, const CallContext&) {
    for (PolyMesh::VertexHandle v : m.vertices()) {
      Vec3 p = m.point(v);
      m.set_point(v, p + a.real("amount") * improved_noise(p[0] * 1.7, p[1] * 1.3, p[2] * 1.1) * a.vector("direction"));
    }
  };
  r.add(bump);
}

TEST(Procedure, SignatureStringMatchesTheThesis) {  // claim 5
  ProcedureRegistry r;
  register_examples(r);
  EXPECT_EQ(r.signature("Torso"), "OUT:Double,ratio:Integer,arms:String,name");
  EXPECT_EQ(r.signature("Bump"), "INOUT:Double,amount:Vector,direction");
}

TEST(Procedure, DefaultsFillMissingArguments) {  // claim 2
  ProcedureRegistry r;
  register_examples(r, false);
  Arguments partial = r.resolve("Torso", {{"ratio", 0.6}});
  EXPECT_EQ(partial.integer("arms"), 2);
  EXPECT_EQ(partial.string("name"), "torso");
  Context c{.seed = 31};
  EXPECT_EQ(content_hash(r.call("Torso", {}, c)),
            content_hash(r.call("Torso", {{"ratio", 0.6}, {"arms", 2}, {"name", "torso"}}, c)));
  EXPECT_NE(content_hash(r.call("Torso", {}, c)), content_hash(r.call("Torso", {{"arms", 3}}, c)));
}

TEST(Procedure, NamedArgumentsInAnyOrder) {  // claim 3
  ProcedureRegistry r;
  register_examples(r, false);
  EXPECT_EQ(content_hash(r.call("Torso", {{"ratio", 0.7}, {"arms", 3}, {"name", "t"}})),
            content_hash(r.call("Torso", {{"name", "t"}, {"arms", 3}, {"ratio", 0.7}})));
}

TEST(Procedure, IntegerConvertsToDoubleOnlyThere) {
  ProcedureRegistry r;
  register_examples(r);
  EXPECT_EQ(r.resolve("Torso", {{"ratio", 1}}).real("ratio"), 1.0);
  EXPECT_THROW(r.resolve("Torso", {{"arms", 2.0}}), std::invalid_argument);
  EXPECT_THROW(r.resolve("Torso", {{"ratio", std::int64_t{1} << 60}}), std::invalid_argument);
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no exception)";
}

TEST(Procedure, StandardisationErrorsNameTheProblem) {  // claim 4
  ProcedureRegistry r;
  register_examples(r);
  ProcedureSpec no_default;
  no_default.name = "Chair";
  no_default.mode = Mode::Out;
  no_default.out_body = [](const Arguments&, const CallContext&) { return PolyMesh(); };
  no_default.params = {ParamDecl{"legs", ParamType::Integer, std::nullopt}};
  std::string m = message_of([&] { r.add(no_default); });
  EXPECT_NE(m.find("Chair"), std::string::npos) << m;
  EXPECT_NE(m.find("legs"), std::string::npos) << m;

  ProcedureSpec no_mode = no_default;
  no_mode.params = {param("legs", 4)};
  no_mode.mode = Mode::Unset;
  m = message_of([&] { r.add(no_mode); });
  EXPECT_NE(m.find("mode"), std::string::npos) << m;

  ProcedureSpec wrong_default = no_mode;
  wrong_default.mode = Mode::Out;
  wrong_default.params = {ParamDecl{"legs", ParamType::Integer, ParamValue(4.0)}};
  EXPECT_THROW(r.add(wrong_default), std::invalid_argument);

  ProcedureSpec twice = no_mode;
  twice.mode = Mode::Out;
  twice.params = {param("legs", 4), param("legs", 3)};
  m = message_of([&] { r.add(twice); });
  EXPECT_NE(m.find("legs"), std::string::npos) << m;

  ProcedureSpec duplicate = twice;
  duplicate.name = "Torso";
  duplicate.params = {};
  m = message_of([&] { r.add(duplicate); });
  EXPECT_NE(m.find("Torso"), std::string::npos) << m;
  EXPECT_FALSE(r.contains("Chair"));

  m = message_of([&] { r.call("Torso", {{"legs", 2}}); });
  EXPECT_NE(m.find("Torso"), std::string::npos) << m;
  EXPECT_NE(m.find("legs"), std::string::npos) << m;
  m = message_of([&] { r.call("Torso", {{"name", 5}}); });
  EXPECT_NE(m.find("name"), std::string::npos) << m;
  EXPECT_NE(m.find("String"), std::string::npos) << m;
  EXPECT_THROW(r.call("Torso", {{"arms", 1}, {"arms", 2}}), std::invalid_argument);
  EXPECT_THROW(r.call("Nobody"), std::invalid_argument);
  PolyMesh box = make_box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  EXPECT_THROW(r.call("Bump"), std::invalid_argument);
  EXPECT_THROW(r.call_inout("Torso", box), std::invalid_argument);
}

TEST(Procedure, SeedIsInheritedByCallees) {  // claim 6
  ProcedureRegistry r;
  register_examples(r);
  r.set_caching(false);
  Context c{.seed = 1234};
  MeshHash direct = content_hash(r.call("Leg", {}, c));
  EXPECT_EQ(content_hash(r.call("Outer", {}, c)), direct);
  EXPECT_NE(content_hash(r.call("Outer", {}, Context{.seed = 1235})), direct);
  // An override replaces the inherited seed.
  EXPECT_EQ(content_hash(r.call("Outer", {{"override", true}, {"legSeed", 1234}}, Context{.seed = 9})), direct);
  EXPECT_NE(content_hash(r.call("Outer", {{"override", true}, {"legSeed", 5}}, c)), direct);
}

// The hash of one fixed call, from a registry built afresh.
MeshHash reference_hash() {
  ProcedureRegistry r;
  register_examples(r);
  return content_hash(r.call("Luggage", {{"numLegs", 5}, {"legLength", 1.5}}, Context{.seed = 777}));
}

TEST(Procedure, ReproducibleInProcessAndAcrossProcesses) {  // claim 1
  const char* out = std::getenv("GENMOD_PROC_HASH_OUT");
  if (out) {  // the child: write the hash and stop
    std::ofstream(out) << reference_hash().hex();
    return;
  }
  MeshHash here = reference_hash();
  EXPECT_EQ(reference_hash(), here);
  {
    ProcedureRegistry r;
    register_examples(r);
    r.set_caching(false);
    EXPECT_EQ(content_hash(r.call("Luggage", {{"numLegs", 5}, {"legLength", 1.5}}, Context{.seed = 777})), here);
  }
  std::string file = ::testing::TempDir() + "genmod_proc_hash.txt";
  std::remove(file.c_str());
  // std::system runs a shell, whose /proc/self/exe is the shell: resolve this binary first.
  std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  std::string command = "GENMOD_PROC_HASH_OUT=" + file + " '" + self +
                        "' --gtest_filter=Procedure.ReproducibleInProcessAndAcrossProcesses > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0);
  std::string child;
  std::ifstream(file) >> child;
  EXPECT_EQ(child, here.hex());
}

TEST(ProcedureCache, TransparentOnAndOff) {  // claim 9
  ProcedureRegistry on, off;
  register_examples(on);
  register_examples(off);
  off.set_caching(false);
  for (int round = 0; round < 3; ++round)
    for (std::int64_t seed : {1, 2}) {
      Context c{.seed = seed};
      EXPECT_EQ(content_hash(on.call("Luggage", {{"numLegs", 6}}, c)), content_hash(off.call("Luggage", {{"numLegs", 6}}, c)));
      EXPECT_EQ(content_hash(on.call("Torso", {}, c)), content_hash(off.call("Torso", {}, c)));
    }
  EXPECT_GT(on.cache_stats("Leg").hits, 0u);
  EXPECT_EQ(off.cache_stats("Leg").hits + off.cache_stats("Leg").misses, 0u);
}

TEST(ProcedureCache, HitsAreIndependentCopies) {  // claim 10
  ProcedureRegistry r;
  register_examples(r);
  PolyMesh first = r.call("Torso");
  MeshHash original = content_hash(first);
  PolyMesh a = r.call("Torso"), b = r.call("Torso");
  EXPECT_EQ(r.cache_stats("Torso").hits, 2u);
  EXPECT_NE(&a, &b);
  apply_affine(Affine::translation(Vec3(1, 0, 0)), a);
  set_face_label(a, a.face_handle(0), "changed");
  EXPECT_EQ(content_hash(b), original);
  EXPECT_EQ(content_hash(r.call("Torso")), original);
  EXPECT_EQ(content_hash(first), original);
}

TEST(ProcedureCache, KeyUsesResolvedArgumentsAndSeed) {  // claim 11
  ProcedureRegistry r;
  register_examples(r);
  auto misses = [&] { return r.cache_stats("Torso").misses; };
  auto hits = [&] { return r.cache_stats("Torso").hits; };
  r.call("Torso", {}, Context{.seed = 5});
  EXPECT_EQ(misses(), 1u);
  r.call("Torso", {{"ratio", 0.6}, {"arms", 2}, {"name", "torso"}}, Context{.seed = 5});  // defaults explicit
  EXPECT_EQ(hits(), 1u);
  r.call("Torso", {{"arms", 2}}, Context{.seed = 5});
  EXPECT_EQ(hits(), 2u);
  r.call("Torso", {{"arms", 3}}, Context{.seed = 5});
  r.call("Torso", {{"ratio", 0.61}}, Context{.seed = 5});
  r.call("Torso", {{"name", "torsa"}}, Context{.seed = 5});
  r.call("Torso", {}, Context{.seed = 6});
  EXPECT_EQ(misses(), 5u);
  EXPECT_EQ(hits(), 2u);
  // The lod is not in the key of a procedure that does not use it.
  r.call("Torso", {}, Context{.seed = 5, .lod = 3});
  EXPECT_EQ(hits(), 3u);
  r.reset_cache_stats("Torso");
  EXPECT_EQ(hits() + misses(), 0u);
  EXPECT_EQ(r.cache_stats("Torso").entries, 5u);
  r.clear_caches();
  EXPECT_EQ(r.cache_stats("Torso").entries, 0u);
  r.call("Torso", {}, Context{.seed = 5});
  EXPECT_EQ(misses(), 1u);
}

TEST(ProcedureCache, RepeatedLegsGiveOneMissAndNMinusOneHits) {  // claim 12
  ProcedureRegistry r;
  register_examples(r);
  const int legs = 30;
  leg_body_runs = 0;
  PolyMesh m = r.call("Luggage", {{"numLegs", legs}}, Context{.seed = 3});
  EXPECT_EQ(r.cache_stats("Leg").misses, 1u);
  EXPECT_EQ(r.cache_stats("Leg").hits, static_cast<std::uint64_t>(legs - 1));
  EXPECT_EQ(leg_body_runs.load(), 1);
  EXPECT_EQ(counts(m).faces, 6u + legs * 4u * 6u);
  r.call("Luggage", {{"numLegs", legs}}, Context{.seed = 3});
  EXPECT_EQ(r.cache_stats("Leg").misses, 1u);
}

TEST(ProcedureCache, EntryLimitEvictsLeastRecentlyUsed) {
  ProcedureRegistry r;
  register_examples(r);
  r.set_cache_limit("Torso", 2);
  r.call("Torso", {{"arms", 1}});
  r.call("Torso", {{"arms", 2}});
  r.call("Torso", {{"arms", 1}});  // hit: arms=1 is now the most recent
  r.call("Torso", {{"arms", 3}});  // evicts arms=2
  CacheStats s = r.cache_stats("Torso");
  EXPECT_EQ(s.entries, 2u);
  EXPECT_EQ(s.evictions, 1u);
  r.call("Torso", {{"arms", 1}});
  EXPECT_EQ(r.cache_stats("Torso").hits, 2u);
  r.call("Torso", {{"arms", 2}});
  EXPECT_EQ(r.cache_stats("Torso").misses, 4u);
  r.set_cache_limit("Torso", 0);
  EXPECT_EQ(r.cache_stats("Torso").entries, 0u);
  r.call("Torso");
  EXPECT_EQ(r.cache_stats("Torso").entries, 0u);
}

TEST(ProcedureCache, InOutKeyIncludesTheInputMesh) {
  ProcedureRegistry on, off;
  register_examples(on);
  register_examples(off);
  off.set_caching(false);
  for (double shift : {0.0, 0.25, 0.0}) {
    PolyMesh a = make_box(Vec3(shift, 0, 0), Vec3(1.3, 1.1, 0.9), "b"), b = a;
    on.call_inout("Bump", a, {{"amount", 0.3}});
    off.call_inout("Bump", b, {{"amount", 0.3}});
    EXPECT_EQ(content_hash(a), content_hash(b));
    EXPECT_NE(content_hash(a), content_hash(make_box(Vec3(shift, 0, 0), Vec3(1.3, 1.1, 0.9), "b")));
  }
  EXPECT_EQ(on.cache_stats("Bump").misses, 2u);
  EXPECT_EQ(on.cache_stats("Bump").hits, 1u);
  // A different label is a different input.
  PolyMesh c = make_box(Vec3(0, 0, 0), Vec3(1.3, 1.1, 0.9), "c");
  on.call_inout("Bump", c, {{"amount", 0.3}});
  EXPECT_EQ(on.cache_stats("Bump").misses, 3u);
}

TEST(ProcedureCache, ParallelCallsMatchSerialCalls) {
  ProcedureRegistry r, serial;
  register_examples(r);
  register_examples(serial);
  serial.set_caching(false);
  const int calls = 200, keys = 5;
  std::vector<MeshHash> expected(keys);
  for (int k = 0; k < keys; ++k)
    expected[k] = content_hash(serial.call("Luggage", {{"numLegs", 3}, {"legLength", 1.0 + k}}, Context{.seed = k}));
  std::vector<MeshHash> got(calls);
  tbb::parallel_for(0, calls, [&](int i) {
    int k = i % keys;
    got[i] = content_hash(r.call("Luggage", {{"numLegs", 3}, {"legLength", 1.0 + k}}, Context{.seed = k}));
  });
  for (int i = 0; i < calls; ++i) EXPECT_EQ(got[i], expected[i % keys]) << i;
  CacheStats s = r.cache_stats("Leg");
  EXPECT_EQ(s.hits + s.misses, static_cast<std::uint64_t>(3 * calls));
  EXPECT_GE(s.misses, static_cast<std::uint64_t>(keys));
  EXPECT_EQ(s.entries, static_cast<std::size_t>(keys));
}

TEST(Procedure, BoundsAndTransformKey) {
  ProcedureRegistry r;
  ProcedureSpec placed;
  placed.name = "Placed";
  placed.mode = Mode::Out;
  placed.cacheable = true;
  placed.uses_transform = true;
  placed.params = {param("size", 1.0)};
  placed.bounds = [](const Arguments& a) { return std::array<Vec3, 2>{Vec3(0, 0, 0), Vec3(a.real("size"), a.real("size"), a.real("size"))}; };
  placed.out_body = [](const Arguments& a, const CallContext& c) {
    PolyMesh m = make_box(Vec3(0, 0, 0), Vec3(a.real("size"), a.real("size"), a.real("size")));
    apply_affine(c.transform(), m);
    return m;
  };
  r.add(placed);
  EXPECT_EQ((*r.bounds("Placed", {{"size", 2.0}}))[1], Vec3(2, 2, 2));
  PolyMesh a = r.call("Placed");
  PolyMesh b = r.call("Placed", {}, Context{.transform = Affine::translation(Vec3(5, 0, 0))});
  EXPECT_EQ(r.cache_stats("Placed").misses, 2u);
  EXPECT_EQ(b.point(b.vertex_handle(0)), a.point(a.vertex_handle(0)) + Vec3(5, 0, 0));
}

}  // namespace
}  // namespace genmod
