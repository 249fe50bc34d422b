// Level of detail and lazy evaluation (camera.hpp, procedure.hpp; research/morkel.md section
// 1.8, issue 12): a procedure with bounds is not run when the camera does not see its box, gets
// a higher lod the nearer (larger on screen) the box is, has the lod in its cache key, and a bad
// camera is refused by the field's name.
#include "genmod/procedural/procedural.hpp"
#include "mesh_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <thread>
#include <vector>

namespace genmod {
namespace {

using test::refusal;

std::atomic<int> runs{0};

// A cube of side `size` about the origin, declared as its bounds, built as a column of 9 + lod
// boxes (more at a higher lod); counts its runs; cacheable and lod dependent.
void register_lodded(ProcedureRegistry& r, bool cacheable = true) {
  ProcedureSpec s;
  s.name = "Lodded";
  s.mode = Mode::Out;
  s.cacheable = cacheable;
  s.uses_lod = true;
  s.params = {param("size", 1.0)};
  s.bounds = [](const Arguments& a) {
    const double h = 0.5 * a.real("size");
    return std::array<Vec3, 2>{Vec3(-h, -h, -h), Vec3(h, h, h)};
  };
  s.out_body = [](const Arguments& a, const CallContext& c) {
    ++runs;
    PolyMesh m;
    const int n = 9 + c.lod();  // lods down to -8 keep at least one box
    const double h = 0.5 * a.real("size"), step = 2.0 * h / n;
    for (int i = 0; i < n; ++i) append_mesh(m, make_box(Vec3(-h, -h + step * i, -h), Vec3(h, -h + step * (i + 1), h), "part"));
    return m;
  };
  r.add(s);
}

// An InOut procedure with bounds that adds a box to the model.
void register_grower(ProcedureRegistry& r) {
  ProcedureSpec s;
  s.name = "Grow";
  s.mode = Mode::InOut;
  s.bounds = [](const Arguments&) { return std::array<Vec3, 2>{Vec3(0, 0, 0), Vec3(1, 1, 1)}; };
  s.inout_body = [](PolyMesh& m, const Arguments&, const CallContext&) {
    ++runs;
    append_mesh(m, make_box(Vec3(0, 0, 0), Vec3(1, 1, 1), "grown"));
  };
  r.add(s);
}

// Looking down -z from z = `distance` at the origin.
Camera looking_at_origin(double distance) {
  Camera c;
  c.position = Vec3(0, 0, distance);
  c.direction = Vec3(0, 0, -1);
  return c;
}

Context at_lod(int lod) {
  Context c;
  c.lod = lod;
  return c;
}

Context with(const Camera& camera, const Affine& xf = {}) {
  Context c;
  c.camera = camera;
  c.transform = xf;
  return c;
}

TEST(LevelOfDetail, BoxOutsideTheFrustumIsNotEvaluated) {
  ProcedureRegistry r;
  register_lodded(r);
  register_grower(r);
  runs = 0;
  const Camera camera = looking_at_origin(10);
  // Behind the camera, far to the side, and far above (beyond the vertical field of view).
  for (const Vec3& at : {Vec3(0, 0, 20), Vec3(100, 0, 0), Vec3(0, 50, 0)}) {
    const PolyMesh m = r.call("Lodded", {}, with(camera, Affine::translation(at)));
    EXPECT_EQ(m.n_faces(), 0u) << at;
  }
  EXPECT_EQ(r.call_shared("Lodded", {}, with(camera, Affine::translation(Vec3(0, 0, 20))))->n_faces(), 0u);
  EXPECT_EQ(r.call_shared("Lodded", {}, with(camera, Affine::translation(Vec3(0, 0, 20))))->n_faces(), 0u);
  EXPECT_EQ(runs.load(), 0);
  EXPECT_EQ(r.culled_calls("Lodded"), 5u);
  // Culled calls neither look up nor fill the cache.
  EXPECT_EQ(r.cache_stats("Lodded").misses + r.cache_stats("Lodded").hits, 0u);
  // InOut: the model is left as it was.
  PolyMesh model = make_box(Vec3(5, 5, 5), Vec3(6, 6, 6), "kept");
  r.call_inout("Grow", model, {}, with(camera, Affine::translation(Vec3(-100, 0, 0))));
  EXPECT_EQ(model.n_faces(), 6u);
  EXPECT_EQ(r.culled_calls("Grow"), 1u);
  EXPECT_EQ(runs.load(), 0);
  // In view: run.
  r.call_inout("Grow", model, {}, with(camera));
  EXPECT_EQ(model.n_faces(), 12u);
  EXPECT_GT(r.call("Lodded", {}, with(camera)).n_faces(), 0u);
  EXPECT_EQ(runs.load(), 2);
  EXPECT_EQ(r.culled_calls("Lodded"), 5u);
}

TEST(LevelOfDetail, FrustumEdgeKeepsBoxesPartlyInView) {
  const Camera camera = looking_at_origin(10);
  const std::array<Vec3, 2> unit{Vec3(-0.5, -0.5, -0.5), Vec3(0.5, 0.5, 0.5)};
  // The view's half width at depth d is d tan(0.4) 640 / 480 (5.64 at the box's centre, 5.92 at
  // its far face, depth 10.5): a unit box centred on the right plane straddles it and is kept; one
  // whose left face is at 5.64 + 0.5 = 6.14 is outside at every depth it reaches.
  const double half_width = 10.0 * std::tan(0.4) * 640.0 / 480.0;
  EXPECT_TRUE(view_of_box(camera, unit, Affine::translation(Vec3(half_width, 0, 0))).visible);
  EXPECT_FALSE(view_of_box(camera, unit, Affine::translation(Vec3(half_width + 1.0, 0, 0))).visible);
  // The box is placed by the transform: scaled by 4 at the same spot, it reaches back in.
  const Affine grown = Affine::translation(Vec3(half_width + 1.0, 0, 0)) * Affine::scaling(4.0);
  EXPECT_TRUE(view_of_box(camera, unit, grown).visible);
  // A box around the camera covers the whole view and gets the top level.
  const BoxView around = view_of_box(camera, unit, Affine::translation(Vec3(0, 0, 10)));
  EXPECT_TRUE(around.visible);
  EXPECT_EQ(around.pixels, 640.0 * 480.0);
  EXPECT_EQ(around.lod, camera.max_lod);
}

TEST(LevelOfDetail, NearerBoxGetsAHigherLod) {
  ProcedureRegistry r;
  register_lodded(r);
  const std::array<Vec3, 2> unit{Vec3(-0.5, -0.5, -0.5), Vec3(0.5, 0.5, 0.5)};
  int previous = std::numeric_limits<int>::max();
  double previous_pixels = std::numeric_limits<double>::infinity();
  std::size_t previous_faces = std::numeric_limits<std::size_t>::max();
  for (double distance : {2.0, 8.0, 32.0, 128.0, 512.0}) {
    const Camera camera = looking_at_origin(distance);
    const BoxView view = view_of_box(camera, unit);
    ASSERT_TRUE(view.visible);
    EXPECT_LT(view.pixels, previous_pixels);
    EXPECT_LT(view.lod, previous);  // each distance 4 times the last: about two levels down
    // The formula, from the measured area.
    EXPECT_EQ(view.lod, std::clamp(static_cast<int>(std::floor(0.5 * std::log2(std::max(view.pixels, 1.0)))) +
                                       camera.lod_bias,
                                   camera.min_lod, camera.max_lod));
    // The body sees that lod: fewer boxes farther away.
    const PolyMesh m = r.call("Lodded", {}, with(camera));
    EXPECT_EQ(m.n_faces(), 6u * static_cast<std::size_t>(9 + view.lod));
    EXPECT_LE(m.n_faces(), previous_faces);
    previous = view.lod, previous_pixels = view.pixels, previous_faces = m.n_faces();
  }
}

TEST(LevelOfDetail, NoCameraKeepsTheContextLod) {
  ProcedureRegistry r;
  register_lodded(r);
  runs = 0;
  EXPECT_EQ(r.call("Lodded").n_faces(), 6u * 9u);
  EXPECT_EQ(r.call("Lodded", {}, at_lod(-3)).n_faces(), 6u * 6u);
  // Far away, but without a camera nothing is culled.
  Context far;
  far.transform = Affine::translation(Vec3(1e6, 0, 0));
  EXPECT_EQ(r.call("Lodded", {}, far).n_faces(), 6u * 9u);
  EXPECT_EQ(r.culled_calls("Lodded"), 0u);
}

TEST(LevelOfDetail, CalleesInheritTheCameraAndTheLod) {
  ProcedureRegistry r;
  register_lodded(r);
  // A procedure without bounds calling Lodded at two places: one in view, one behind.
  ProcedureSpec scene;
  scene.name = "Scene";
  scene.mode = Mode::Out;
  scene.out_body = [](const Arguments&, const CallContext& c) {
    PolyMesh m;
    for (double z : {0.0, 50.0}) {
      CallOptions o;
      o.transform = Affine::translation(Vec3(0, 0, z));
      append_mesh(m, c.call("Lodded", {}, o));
    }
    return m;
  };
  r.add(scene);
  Camera camera = looking_at_origin(8);
  const int lod = view_of_box(camera, {Vec3(-0.5, -0.5, -0.5), Vec3(0.5, 0.5, 0.5)}).lod;
  ASSERT_LT(lod, 0);
  EXPECT_EQ(r.call("Scene", {}, with(camera)).n_faces(), 6u * static_cast<std::size_t>(9 + lod));
  EXPECT_EQ(r.culled_calls("Lodded"), 1u);
}

TEST(LevelOfDetail, LodIsInTheCacheKey) {
  ProcedureRegistry r;
  register_lodded(r);
  ProcedureRegistry uncached;
  register_lodded(uncached);
  uncached.set_caching(false);
  const Camera near = looking_at_origin(4), far = looking_at_origin(64);
  const int near_lod = view_of_box(near, {Vec3(-0.5, -0.5, -0.5), Vec3(0.5, 0.5, 0.5)}).lod;
  const int far_lod = view_of_box(far, {Vec3(-0.5, -0.5, -0.5), Vec3(0.5, 0.5, 0.5)}).lod;
  ASSERT_NE(near_lod, far_lod);
  runs = 0;
  const PolyMesh a = r.call("Lodded", {}, with(near)), b = r.call("Lodded", {}, with(far));
  EXPECT_EQ(r.cache_stats("Lodded").misses, 2u);  // two lods: two misses
  EXPECT_EQ(runs.load(), 2);
  const PolyMesh a2 = r.call("Lodded", {}, with(near));
  // The same lod from another camera (a step aside, same distance): a hit.
  Camera aside = near;
  aside.position = Vec3(0.01, 0, 4);
  const PolyMesh a3 = r.call("Lodded", {}, with(aside));
  ASSERT_EQ(view_of_box(aside, {Vec3(-0.5, -0.5, -0.5), Vec3(0.5, 0.5, 0.5)}).lod, near_lod);
  // And the lod given directly, without a camera: the same key.
  const PolyMesh a4 = r.call("Lodded", {}, at_lod(near_lod));
  EXPECT_EQ(r.cache_stats("Lodded").hits, 3u);
  EXPECT_EQ(runs.load(), 2);
  for (const PolyMesh* m : {&a2, &a3, &a4}) EXPECT_EQ(test::mesh_difference(a, *m), "");
  // Caching off: the same bytes.
  EXPECT_EQ(test::mesh_difference(a, uncached.call("Lodded", {}, with(near))), "");
  EXPECT_EQ(test::mesh_difference(b, uncached.call("Lodded", {}, with(far))), "");
  EXPECT_NE(test::mesh_difference(a, b), "");
}

TEST(LevelOfDetail, BadCamerasAreRefusedByField) {
  ProcedureRegistry r;
  register_lodded(r);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const auto refused = [&](auto change) {
    Camera c = looking_at_origin(5);
    change(c);
    return refusal([&] { r.call("Lodded", {}, with(c)); });
  };
  const auto names = [](const std::string& message, const std::string& field) {
    return message.find("'" + field + "'") != std::string::npos && message.find("'Lodded'") != std::string::npos;
  };
  EXPECT_PRED2(names, refused([&](Camera& c) { c.position[1] = nan; }), "position");
  EXPECT_PRED2(names, refused([&](Camera& c) { c.direction[0] = inf; }), "direction");
  EXPECT_PRED2(names, refused([&](Camera& c) { c.direction = Vec3(0, 0, 0); }), "direction");
  EXPECT_PRED2(names, refused([&](Camera& c) { c.up = Vec3(0, 0, 2); }), "up");  // parallel to the view
  EXPECT_PRED2(names, refused([&](Camera& c) { c.up[2] = nan; }), "up");
  EXPECT_PRED2(names, refused([&](Camera& c) { c.fov_y = 0; }), "fov_y");
  EXPECT_PRED2(names, refused([&](Camera& c) { c.fov_y = std::numbers::pi; }), "fov_y");
  EXPECT_PRED2(names, refused([&](Camera& c) { c.fov_y = nan; }), "fov_y");
  EXPECT_PRED2(names, refused([&](Camera& c) { c.image_width = 0; }), "image_width");
  EXPECT_PRED2(names, refused([&](Camera& c) { c.image_height = 0; }), "image_height");
  EXPECT_PRED2(names, refused([&](Camera& c) { c.near = 0; }), "near");
  EXPECT_PRED2(names, refused([&](Camera& c) { c.min_lod = 1; }), "min_lod");
  EXPECT_EQ(refused([](Camera&) {}), "");
  // Checked even for a procedure without bounds (the camera would reach its callees).
  ProcedureSpec plain;
  plain.name = "Plain";
  plain.mode = Mode::Out;
  plain.out_body = [](const Arguments&, const CallContext&) { return PolyMesh(); };
  r.add(plain);
  Camera bad = looking_at_origin(5);
  bad.image_height = 0;
  EXPECT_NE(refusal([&] { r.call("Plain", {}, with(bad)); }).find("'image_height'"), std::string::npos);
}

TEST(LevelOfDetail, BadBoundsAreRefused) {
  ProcedureRegistry r;
  ProcedureSpec s;
  s.name = "Inverted";
  s.mode = Mode::Out;
  s.bounds = [](const Arguments&) { return std::array<Vec3, 2>{Vec3(1, 0, 0), Vec3(0, 1, 1)}; };
  s.out_body = [](const Arguments&, const CallContext&) { return PolyMesh(); };
  r.add(s);
  EXPECT_NE(refusal([&] { r.call("Inverted", {}, with(looking_at_origin(5))); }).find("bounds"), std::string::npos);
  EXPECT_EQ(refusal([&] { r.call("Inverted"); }), "");  // no camera: the bounds are not read
  // A non-finite placement is refused rather than culled.
  register_lodded(r);
  Affine nowhere = Affine::translation(Vec3(std::numeric_limits<double>::quiet_NaN(), 0, 0));
  EXPECT_NE(refusal([&] { r.call("Lodded", {}, with(looking_at_origin(5), nowhere)); }).find("transform"), std::string::npos);
  EXPECT_EQ(r.culled_calls("Lodded"), 0u);
}

// Calls with cameras from several threads: the culled counter and the cache agree with a
// sequential count (each thread alternates a visible and a culled call).
TEST(LevelOfDetail, ThreadsCountCulledCalls) {
  ProcedureRegistry r;
  register_lodded(r);
  const int threads = 4, calls = 50;
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([&] {
      for (int i = 0; i < calls; ++i) {
        r.call_shared("Lodded", {}, with(looking_at_origin(4)));
        r.call_shared("Lodded", {}, with(looking_at_origin(4), Affine::translation(Vec3(0, 0, 9))));
      }
    });
  for (auto& th : pool) th.join();
  EXPECT_EQ(r.culled_calls("Lodded"), static_cast<std::uint64_t>(threads * calls));
  const CacheStats s = r.cache_stats("Lodded");
  EXPECT_EQ(s.hits + s.misses, static_cast<std::uint64_t>(threads * calls));
  EXPECT_EQ(s.entries, 1u);
}

}  // namespace
}  // namespace genmod
