// mesh_implicit: every mesh is closed, 2-manifold, outward, free of self-intersections and
// degenerate triangles (validate(), CGAL, on the mesh as it is), with vertices within the
// tolerance of the surface; sharp features kept; topology counts (Euler characteristic,
// components) of known shapes; uncertified cells reported; the same mesh for any thread count.
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/vm_format.hpp"
#include "genmod/operators/shapes.hpp"
#include "genmod/operators/transform.hpp"
#include "genmod/tessellate/implicit_mesher.hpp"
#include "genmod/tessellate/validate.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <random>

namespace genmod {
namespace {

const Fn X = x(0), Y = x(1), Z = x(2);

Box3 cube_box(double h) { return {Interval(-h, h), Interval(-h, h), Interval(-h, h)}; }

// The solid as meshed: f intersected with the box (the box's exact distance).
Fn clipped(const Fn& f, const Box3& box) {
  Fn d = -1e300;
  const Fn p[3] = {X, Y, Z};
  for (int k = 0; k < 3; ++k) {
    const double c = 0.5 * (box[k].lo() + box[k].hi()), h = 0.5 * (box[k].hi() - box[k].lo());
    d = max(d, abs(p[k] - c) - h);
  }
  return max(f, d);
}

struct Checked {
  ImplicitMesh result;
  MeshValidity validity;
  double tolerance;
};

// Meshes f and validates the mesh as it is, and its distance to the surface (of the solid
// clipped by the box when it crosses the box; clipping elsewhere would only loosen the
// distance bounds where the box's distance is the larger value inside the solid).
Checked mesh_and_check(const Fn& f, const Box3& box, ImplicitMeshSettings s, bool crosses_box = false) {
  Checked c{mesh_implicit(f, box, s), {}, s.tolerance > 0 ? s.tolerance : s.min_feature};
  const Tape solid(crosses_box ? clipped(f, box) : f, std::vector<int>{0, 1, 2});
  c.validity = validate(c.result.mesh, {.surface = &solid, .face_samples = 2, .search_radius = 8 * c.tolerance});
  return c;
}

std::string summary(const Checked& c) {
  const ImplicitMeshStats& s = c.result.stats;
  std::string limits;
  for (const auto& l : s.limits_hit) limits += " " + l;
  return describe(c.validity) + "surface cells " + std::to_string(s.surface_cells) + ", certified " +
         std::to_string(s.certified_cells) + ", uncertified " + std::to_string(s.uncertified_cells) +
         ", unbounded gradient " + std::to_string(s.unbounded_gradient_cells) + ", several loops " +
         std::to_string(s.multi_loop_cells) + ", inaccurate " + std::to_string(s.inaccurate_cells) + ", rounds " +
         std::to_string(s.rounds) + ", feature points " + std::to_string(s.feature_points) +
         ", uncertified vertices " + std::to_string(s.uncertified_vertices) + ", limits:" + limits + "\n";
}

// Properties 1-3 and 4 (every certified vertex within the tolerance; the stats count the
// others).
void expect_valid(const Checked& c) {
  EXPECT_TRUE(c.validity.valid());
  EXPECT_GT(c.validity.triangles, 0u);
  EXPECT_LE(c.result.stats.max_vertex_error, c.tolerance);
  if (c.result.stats.uncertified_vertices == 0) {
    EXPECT_LE(c.validity.surface.max_vertex_bound, c.tolerance);
  }
}

double sphere_volume(double r) { return 4.0 / 3.0 * M_PI * r * r * r; }

TEST(ImplicitMesher, Sphere) {
  const Fn f = sqrt(square(X) + square(Y) + square(Z)) - 1.0;
  const Checked c = mesh_and_check(f, cube_box(1.5), {.min_feature = 0.02, .tolerance = 0.005});
  SCOPED_TRACE(summary(c));
  expect_valid(c);
  EXPECT_EQ(c.validity.components, 1u);
  EXPECT_EQ(c.validity.euler_characteristic, 2);
  EXPECT_NEAR(c.validity.volume, sphere_volume(1), 4 * M_PI * c.tolerance);  // area x tolerance
  EXPECT_EQ(c.result.stats.uncertified_vertices, 0u);
  EXPECT_EQ(c.result.stats.uncertified_cells, 0u);
  EXPECT_EQ(c.result.stats.certified_cells, c.result.stats.surface_cells);
  EXPECT_LE(c.validity.surface.max_face_bound, 2 * c.tolerance);
}

// Claim 40 of the thesis's Algorithm 5.5: x^2 + y^2 + z^2 - 0.5 on [-1, 1]^3 is closed with
// Euler characteristic 2; a blobby surface of four well separated terms has four closed
// components with Euler characteristic 2 each.
TEST(ImplicitMesher, Claim40SphereAndBlobby) {
  const Checked sphere = mesh_and_check(square(X) + square(Y) + square(Z) - 0.5, cube_box(1.0), {.min_feature = 0.02});
  SCOPED_TRACE(summary(sphere));
  expect_valid(sphere);
  EXPECT_EQ(sphere.validity.euler_characteristic, 2);

  // f = 0.5 - sum exp(-4 |p - q_i|): negative (inside) near each center.
  const double centers[4][3] = {{-1, -1, 0}, {1, -1, 0.2}, {-1, 1, -0.2}, {1, 1, 0}};
  Fn density = 0.0;
  for (const auto& q : centers)
    density = density + exp(-4.0 * sqrt(square(X - q[0]) + square(Y - q[1]) + square(Z - q[2])));
  const Checked blobby = mesh_and_check(0.5 - density, cube_box(2.0), {.min_feature = 0.02});
  SCOPED_TRACE(summary(blobby));
  expect_valid(blobby);
  ASSERT_EQ(blobby.validity.components, 4u);
  for (const ComponentValidity& comp : blobby.validity.component_info) EXPECT_EQ(comp.euler_characteristic, 2);
}

TEST(ImplicitMesher, BoxKeepsItsEdgesAndCorners) {
  const double h[3] = {0.7, 0.5, 0.3};
  const Checked c = mesh_and_check(implicit_box(cat({h[0], h[1], h[2]})), cube_box(1.5), {.min_feature = 0.02, .tolerance = 0.005});
  SCOPED_TRACE(summary(c));
  expect_valid(c);
  EXPECT_EQ(c.validity.euler_characteristic, 2);
  EXPECT_NEAR(c.validity.volume, 8 * h[0] * h[1] * h[2], 1e-4);
  // Flat faces and sharp edges: the faces lie on the box (not cut off at edges).
  EXPECT_LE(c.validity.surface.max_face_estimate, 1e-4);
  for (int corner = 0; corner < 8; ++corner) {
    const std::array<double, 3> p{corner & 1 ? h[0] : -h[0], corner & 2 ? h[1] : -h[1], corner & 4 ? h[2] : -h[2]};
    double nearest = 1e300;
    for (const auto& v : c.result.mesh.vertices)
      nearest = std::min(nearest, std::hypot(v[0] - p[0], v[1] - p[1], v[2] - p[2]));
    EXPECT_LE(nearest, c.tolerance) << "corner " << corner;
  }
  // Adaptive: a flat box needs few triangles, far fewer than cells of min_feature would make.
  EXPECT_LT(c.result.mesh.triangles.size(), 2000u);
}

TEST(ImplicitMesher, Torus) {
  const Checked c = mesh_and_check(implicit_torus(1.0, 0.3), cube_box(1.5), {.min_feature = 0.02, .tolerance = 0.005});
  SCOPED_TRACE(summary(c));
  expect_valid(c);
  EXPECT_EQ(c.validity.components, 1u);
  EXPECT_EQ(c.validity.euler_characteristic, 0);
  // An inscribed mesh loses at most area x tolerance of the volume.
  const double area = 4 * M_PI * M_PI * 1.0 * 0.3;
  EXPECT_NEAR(c.validity.volume, 2 * M_PI * M_PI * 1.0 * 0.09, area * c.tolerance);
}

TEST(ImplicitMesher, BoxMinusCylinderHasGenusOne) {
  const Fn f = csg_difference(implicit_box(cat({1.0, 1.0, 1.0})), implicit_cylinder(0.5, 2.0));
  const Checked c = mesh_and_check(f, cube_box(1.5), {.min_feature = 0.02, .tolerance = 0.005});
  SCOPED_TRACE(summary(c));
  expect_valid(c);
  EXPECT_EQ(c.validity.euler_characteristic, 0);
  EXPECT_NEAR(c.validity.volume, 8.0 - M_PI * 0.25 * 2.0, 0.01);
  EXPECT_GT(c.result.stats.feature_points, 0u);
  EXPECT_LE(c.validity.surface.max_face_estimate, 2 * c.tolerance);
}

TEST(ImplicitMesher, SphereGyroidBenchmarkShape) {
  const Fn f = load_vm(std::string(GENMOD_DATA_DIR) + "/sphere_gyroid.vm");
  const Checked c = mesh_and_check(f, cube_box(5.0), {.min_feature = 0.05, .tolerance = 0.05});
  SCOPED_TRACE(summary(c));
  expect_valid(c);
  // Vertices without a sign-change bracket within the tolerance are counted, never hidden.
  EXPECT_EQ(c.validity.surface.uncertified_vertices == 0, c.result.stats.uncertified_vertices == 0);
}

TEST(ImplicitMesher, SphereGyroidCreaseVerticesAreCertified) {
  // Where the sphere cuts the gyroid, a cell's quadric point lies on the crease, often farther
  // than the tolerance from the surface, and the gradient of the active piece leads out of
  // the solid's wedge, so moving it along the gradient found no root: before nearest_root()
  // 51 vertices here had no sign-change bracket within the tolerance.
  const Fn f = load_vm(std::string(GENMOD_DATA_DIR) + "/sphere_gyroid.vm");
  const double tolerance = 0.00337;
  const Checked c = mesh_and_check(f, cube_box(5.0), {.min_feature = 0.025, .tolerance = tolerance});
  SCOPED_TRACE(summary(c));
  expect_valid(c);
  EXPECT_EQ(c.result.stats.uncertified_vertices, 0u);
  EXPECT_LE(c.result.stats.max_vertex_error, tolerance);
  // Independently of the mesher's brackets: every vertex has a sign change of f within the
  // tolerance in one of 400 directions.
  PointEvaluator pe;
  const Tape tape(f, {0, 1, 2});
  std::size_t checked = 0, missed = 0;
  for (const auto& v : c.result.mesh.vertices) {
    const double p[3] = {v[0], v[1], v[2]};
    const double fv = pe.eval(tape, p)[0];
    if (fv == 0.0) continue;
    bool found = false;
    for (int k = 0; k < 400 && !found; ++k) {   // a Fibonacci sphere of directions
      const double z = 1.0 - (k + 0.5) / 200.0, r = std::sqrt(1.0 - z * z), phi = k * 2.399963229728653;
      for (double t : {0.25, 0.5, 0.75, 0.999}) {
        const double q[3] = {p[0] + t * tolerance * r * std::cos(phi), p[1] + t * tolerance * r * std::sin(phi),
                             p[2] + t * tolerance * z};
        const double fq = pe.eval(tape, q)[0];
        if (fq == 0.0 || (fq < 0) != (fv < 0)) {
          found = true;
          break;
        }
      }
    }
    ++checked;
    if (!found) ++missed;
  }
  EXPECT_EQ(missed, 0u) << "of " << checked << " vertices";
}

TEST(ImplicitMesher, TanglecubeHasGenusFive) {
  const Fn f = load_vm(std::string(GENMOD_DATA_DIR) + "/tanglecube.vm");
  const Checked c = mesh_and_check(f, cube_box(2.5), {.min_feature = 0.05});
  SCOPED_TRACE(summary(c));
  expect_valid(c);
  EXPECT_EQ(c.validity.components, 1u);
  EXPECT_EQ(c.validity.euler_characteristic, -8);  // 2 - 2 * 5
}

TEST(ImplicitMesher, TouchingSpheresAreReportedUncertified) {
  const Fn f = csg_union(implicit_sphere(1.0, cat({-1.0, 0.0, 0.0})), implicit_sphere(1.0, cat({1.0, 0.0, 0.0})));
  const Checked c = mesh_and_check(f, {Interval(-2.5, 2.5), Interval(-1.5, 1.5), Interval(-1.5, 1.5)}, {.min_feature = 0.02});
  SCOPED_TRACE(summary(c));
  expect_valid(c);
  // The touching point is singular: the cells around it cannot be certified.
  EXPECT_GT(c.result.stats.uncertified_cells, 0u);
}

TEST(ImplicitMesher, PlateThinnerThanMinFeatureIsReported) {
  const Fn f = abs(Z) - 0.004;
  const ImplicitMesh m = mesh_implicit(f, cube_box(1.0), {.min_feature = 0.02});
  // Whatever the samples saw, the mesh is closed and manifold, and the cells where the plate
  // may be are reported.
  const MeshValidity v = validate(m.mesh);
  EXPECT_TRUE(v.closed() && v.manifold() && v.oriented() && v.self_intersections == 0);
  EXPECT_GT(m.stats.uncertified_cells, 0u);
}

TEST(ImplicitMesher, ShapeCrossingTheBoxIsClosedByItsFaces) {
  const Fn f = sqrt(square(X) + square(Y) + square(Z)) - 1.3;
  const Checked c = mesh_and_check(f, cube_box(1.0), {.min_feature = 0.02, .tolerance = 0.005}, true);
  SCOPED_TRACE(summary(c));
  expect_valid(c);
  EXPECT_EQ(c.validity.euler_characteristic, 2);
  // The sphere of radius 1.3 covers the cube's faces but not its corners.
  EXPECT_LT(c.validity.volume, 8.0);
  EXPECT_GT(c.validity.volume, 7.0);
  double max_coordinate = 0;
  for (const auto& v : c.result.mesh.vertices)
    for (double x : v) max_coordinate = std::max(max_coordinate, std::fabs(x));
  EXPECT_LE(max_coordinate, 1.0 + c.tolerance);  // vertices within the tolerance of the box faces
}

// Random CSG trees of the standard implicit shapes, rotated and translated.
Fn random_shape(std::mt19937& rng, int depth) {
  std::uniform_real_distribution<double> u(-0.6, 0.6), r(0.2, 0.6), angle(0, 3.0);
  if (depth == 0) {
    Fn s;
    switch (std::uniform_int_distribution<int>(0, 3)(rng)) {
      case 0: s = implicit_sphere(r(rng)); break;
      case 1: s = implicit_box(cat({r(rng), r(rng), r(rng)})); break;
      case 2: s = implicit_cylinder(r(rng), r(rng)); break;
      default: s = implicit_torus(0.45, 0.15); break;
    }
    s = transform_implicit(s, rotate_x(angle(rng)) * rotate_z(angle(rng)));
    return translate_implicit(s, cat({u(rng), u(rng), u(rng)}));
  }
  const Fn a = random_shape(rng, depth - 1), b = random_shape(rng, depth - 1);
  switch (std::uniform_int_distribution<int>(0, 3)(rng)) {
    case 0: return csg_union(a, b);
    case 1: return csg_intersection(a, b);
    case 2: return csg_difference(a, b);
    default: return smooth_union(a, b, 0.2);
  }
}

TEST(ImplicitMesher, RandomCsgTrees) {
  std::mt19937 rng(20261201);
  for (int trial = 0; trial < 10; ++trial) {
    const Fn f = random_shape(rng, 1 + trial % 2);
    const Checked c = mesh_and_check(f, cube_box(1.5), {.min_feature = 0.05}, true);
    SCOPED_TRACE("trial " + std::to_string(trial) + "\n" + summary(c));
    if (c.validity.triangles == 0) continue;  // an empty intersection
    EXPECT_TRUE(c.validity.valid());
    EXPECT_LE(c.result.stats.max_vertex_error, c.tolerance);
  }
}

TEST(ImplicitMesher, SameMeshForAnyThreadCount) {
  const Fn f = load_vm(std::string(GENMOD_DATA_DIR) + "/tanglecube.vm");
  const ImplicitSurface s(f);
  const ImplicitMesh one = mesh_implicit(s, cube_box(2.5), {.min_feature = 0.08, .threads = 1});
  const ImplicitMesh two = mesh_implicit(s, cube_box(2.5), {.min_feature = 0.08, .threads = 2});
  ASSERT_GT(one.mesh.triangles.size(), 0u);
  EXPECT_EQ(one.mesh.vertices, two.mesh.vertices);
  EXPECT_EQ(one.mesh.triangles, two.mesh.triangles);
}

TEST(ImplicitMesher, LimitsAreReported) {
  const Fn f = load_vm(std::string(GENMOD_DATA_DIR) + "/tanglecube.vm");
  const ImplicitMesh m = mesh_implicit(f, cube_box(2.5), {.min_feature = 0.01, .max_cells = 2000});
  ASSERT_FALSE(m.stats.limits_hit.empty());
  EXPECT_EQ(m.stats.limits_hit[0], "cells");
  const MeshValidity v = validate(m.mesh);
  EXPECT_TRUE(v.valid()) << describe(v);  // coarser, still a valid mesh
  // The memory limit (bytes of cells and pruned tapes) stops refinement the same way.
  const ImplicitMesh small = mesh_implicit(f, cube_box(2.5), {.min_feature = 0.01, .max_memory = 1 << 20});
  ASSERT_FALSE(small.stats.limits_hit.empty());
  EXPECT_EQ(small.stats.limits_hit[0], "memory");
  const MeshValidity w = validate(small.mesh);
  EXPECT_TRUE(w.valid()) << describe(w);
  EXPECT_LT(small.mesh.triangles.size(), mesh_implicit(f, cube_box(2.5), {.min_feature = 0.025}).mesh.triangles.size());
}

// A stop request (Python's Ctrl-C) stops refinement like a time limit: reported, and the mesh
// made so far is still closed and valid.
TEST(ImplicitMesher, CancellationIsReportedAndLeavesAValidMesh) {
  const Fn f = load_vm(std::string(GENMOD_DATA_DIR) + "/tanglecube.vm");
  std::atomic<bool> stop{false};
  ImplicitMeshSettings s{.min_feature = 0.01, .cancel = &stop};
  s.progress = [&](double done) {
    if (done > 0.1) stop = true;  // the request comes while the octree is being refined
  };
  const ImplicitMesh m = mesh_implicit(f, cube_box(2.5), s);
  ASSERT_FALSE(m.stats.limits_hit.empty());
  EXPECT_EQ(m.stats.limits_hit[0], "cancelled");
  const MeshValidity v = validate(m.mesh);
  EXPECT_TRUE(v.valid()) << describe(v);
  EXPECT_LT(m.mesh.triangles.size(), mesh_implicit(f, cube_box(2.5), {.min_feature = 0.025}).mesh.triangles.size());
}

TEST(ImplicitMesher, RejectsBadInput) {
  const Fn f = sqrt(square(X) + square(Y) + square(Z)) - 1.0;
  EXPECT_THROW(mesh_implicit(f, cube_box(1.5), {}), std::invalid_argument);  // no min_feature
  EXPECT_THROW(mesh_implicit(f, cube_box(1.5), {.min_feature = -1}), std::invalid_argument);
  EXPECT_THROW(mesh_implicit(f, cube_box(1.5), {.min_feature = 1e-9}), std::invalid_argument);
  EXPECT_THROW(mesh_implicit(f, cube_box(1.5), {.min_feature = 0.1, .tolerance = NAN}), std::invalid_argument);
  EXPECT_THROW(mesh_implicit(f, {Interval(0, 1), Interval(0, 0), Interval(0, 1)}, {.min_feature = 0.1}),
               std::invalid_argument);
  EXPECT_THROW(mesh_implicit(f, {Interval(0, 1), Interval::entire(), Interval(0, 1)}, {.min_feature = 0.1}),
               std::invalid_argument);
  EXPECT_THROW(ImplicitSurface(cat({X, Y})), std::invalid_argument);
  EXPECT_THROW(ImplicitSurface(X + x(3)), std::invalid_argument);
}

}  // namespace
}  // namespace genmod
