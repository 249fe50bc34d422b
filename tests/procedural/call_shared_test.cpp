// ProcedureRegistry::call_shared (issue 12): the read-only call the assembling bodies use. It
// must give the bytes and the hit/miss counts of call(), share a stored hit instead of copying
// it (that is its point), and leave call()'s copies independent (claim 10).
#include "genmod/procedural/procedural.hpp"

#include <gtest/gtest.h>

#include <atomic>

namespace genmod {
namespace {

std::atomic<int> body_runs{0};

// A seeded, level-of-detail dependent part: a column of `segments` boxes (more at higher lod),
// jittered by the seed.
void register_part(ProcedureRegistry& r) {
  ProcedureSpec part;
  part.name = "Part";
  part.mode = Mode::Out;
  part.cacheable = true;
  part.uses_lod = true;
  part.params = {param("length", 2.0), param("segments", 3)};
  part.out_body = [](const Arguments& a, const CallContext& c) {
    ++body_runs;
    PolyMesh m;
    const std::int64_t n = a.integer("segments") + c.lod();
    const double step = a.real("length") / static_cast<double>(n);
    for (std::int64_t i = 0; i < n; ++i) append_mesh(m, make_box(Vec3(0, 0, step * i), Vec3(1, 1, step * (i + 1)), "part"));
    Rng rng(c.seed());
    for (PolyMesh::VertexHandle v : m.vertices()) m.set_point(v, m.point(v) + 0.01 * rng.next_double() * Vec3(1, 0, 0));
    return m;
  };
  r.add(part);
}

TEST(CallShared, SameBytesAndCountsAsCall) {
  ProcedureRegistry shared, copied;
  register_part(shared);
  register_part(copied);
  for (int round = 0; round < 3; ++round) {
    const Context c{.seed = 4};
    EXPECT_EQ(content_hash(*shared.call_shared("Part", {}, c)), content_hash(copied.call("Part", {}, c)));
  }
  EXPECT_EQ(shared.cache_stats("Part").misses, 1u);
  EXPECT_EQ(shared.cache_stats("Part").hits, 2u);
  EXPECT_EQ(copied.cache_stats("Part").misses, 1u);
  EXPECT_EQ(copied.cache_stats("Part").hits, 2u);
  shared.set_caching(false);
  EXPECT_EQ(content_hash(*shared.call_shared("Part", {}, Context{.seed = 4})), content_hash(copied.call("Part", {}, Context{.seed = 4})));
  EXPECT_EQ(shared.cache_stats("Part").misses + shared.cache_stats("Part").hits, 3u);  // off: not counted
}

TEST(CallShared, HitsShareTheStoredMeshAndCallStillCopies) {
  ProcedureRegistry r;
  register_part(r);
  body_runs = 0;
  const auto first = r.call_shared("Part");
  const auto second = r.call_shared("Part");
  EXPECT_EQ(first.get(), second.get());  // the stored mesh, not a copy
  EXPECT_EQ(body_runs.load(), 1);
  const MeshHash original = content_hash(*first);
  PolyMesh edited = r.call("Part");  // a copy the caller may change
  apply_affine(Affine::translation(Vec3(3, 0, 0)), edited);
  set_face_label(edited, edited.face_handle(0), "changed");
  EXPECT_EQ(content_hash(*first), original);
  EXPECT_EQ(content_hash(*r.call_shared("Part")), original);
  EXPECT_EQ(content_hash(r.call("Part")), original);
  // Without caching every call builds its own mesh.
  r.set_caching(false);
  EXPECT_NE(r.call_shared("Part").get(), r.call_shared("Part").get());
}

TEST(CallShared, KeyHoldsArgumentsSeedAndLevelOfDetail) {
  ProcedureRegistry r;
  register_part(r);
  r.call_shared("Part", {}, Context{.seed = 1});
  r.call_shared("Part", {{"length", 2.0}, {"segments", 3}}, Context{.seed = 1});  // defaults explicit: a hit
  EXPECT_EQ(r.cache_stats("Part").hits, 1u);
  r.call_shared("Part", {{"length", 2.5}}, Context{.seed = 1});
  r.call_shared("Part", {{"segments", 4}}, Context{.seed = 1});
  r.call_shared("Part", {}, Context{.seed = 2});
  const auto fine = r.call_shared("Part", {}, Context{.seed = 1, .lod = 2});
  EXPECT_EQ(r.cache_stats("Part").misses, 5u);
  EXPECT_EQ(r.cache_stats("Part").hits, 1u);
  EXPECT_EQ(fine->n_faces(), 6u * 5u);  // the lod changed the mesh, so it had to miss
  // Through a body's context: the same cache.
  ProcedureSpec outer;
  outer.name = "Outer";
  outer.mode = Mode::Out;
  outer.params = {param("n", 2)};
  outer.out_body = [](const Arguments& a, const CallContext& c) {
    PolyMesh m;
    for (std::int64_t i = 0; i < a.integer("n"); ++i) append_mesh(m, *c.call_shared("Part"), Affine::translation(Vec3(2.0 * i, 0, 0)));
    return m;
  };
  r.add(outer);
  r.reset_cache_stats("Part");
  r.call("Outer", {{"n", 3}}, Context{.seed = 1});
  EXPECT_EQ(r.cache_stats("Part").hits, 3u);
  EXPECT_EQ(r.cache_stats("Part").misses, 0u);
}

TEST(CallShared, RefusesAnInOutProcedureAndUnknownNames) {
  ProcedureRegistry r;
  register_part(r);
  ProcedureSpec bump;
  bump.name = "Bump";
  bump.mode = Mode::InOut;
  bump.inout_body = [](PolyMesh&, const Arguments&, const CallContext&) {};
  r.add(bump);
  EXPECT_THROW(r.call_shared("Bump"), std::invalid_argument);
  EXPECT_THROW(r.call_shared("Nope"), std::invalid_argument);
}

}  // namespace
}  // namespace genmod
