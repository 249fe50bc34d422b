// mesh_adaptive: certified distance (mesh samples against the true surface and surface samples
// against the mesh), conforming triangulations of random kd-trees, seams, poles and glued
// patches giving closed outward meshes as written (validate, CGAL), claim 37 of
// research/snyder.md, limits, errors and determinism.
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/tessellate/parametric_mesher.hpp"
#include "genmod/tessellate/validate.hpp"
#include "tessellate/point_triangle_distance.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <array>
#include <bit>
#include <cmath>
#include <map>
#include <numbers>
#include <random>

namespace genmod {
namespace {

constexpr double kPi = std::numbers::pi;
const Fn U = x(0), V = x(1);

using testing_support::distance_to_mesh;
using testing_support::Vec3;

// The largest distance from random surface points to the mesh.
double surface_to_mesh(const SurfacePatch& patch, const Mesh& mesh, int samples, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> su(patch.u.lo(), patch.u.hi()), sv(patch.v.lo(), patch.v.hi());
  const Tape tape(patch.surface, std::vector<int>{0, 1});
  PointEvaluator ev;
  double worst = 0;
  for (int i = 0; i < samples; ++i) {
    const auto s = ev.eval(tape, {su(rng), sv(rng)});
    worst = std::max(worst, distance_to_mesh({s[0], s[1], s[2]}, mesh));
  }
  return worst;
}

SurfacePatch unit_sphere() {
  const Fn theta = 2 * kPi * U, phi = kPi * V;
  return {cat({cos(theta) * sin(phi), sin(theta) * sin(phi), -cos(phi)}), Interval(0, 1), Interval(0, 1), true};
}

SurfacePatch torus(double R, double r) {
  const Fn a = 2 * kPi * U, b = 2 * kPi * V;
  const Fn ring = R + r * cos(b);
  return {cat({ring * cos(a), ring * sin(a), r * sin(b)}), Interval(0, 1), Interval(0, 1), true, true};
}

Tape implicit_sphere() {
  const Fn X = x(0), Y = x(1), Z = x(2);
  return Tape(sqrt(X * X + Y * Y + Z * Z) - 1.0, std::vector<int>{0, 1, 2});
}

TEST(AdaptiveMesh, SphereIsClosedOutwardAndWithinTheCertifiedDistance) {
  const SurfacePatch sphere = unit_sphere();
  const double tol = 2e-3;
  const AdaptiveMesh m = mesh_adaptive({sphere}, {.tolerance = tol});
  EXPECT_TRUE(m.limits_hit.empty());
  EXPECT_LE(m.distance_bound, tol);
  EXPECT_EQ(m.collapsed_edges, 2u);  // the poles
  EXPECT_GT(m.dropped_triangles, 0u);
  EXPECT_TRUE(m.closed());
  const Tape surface = implicit_sphere();
  const MeshValidity v = validate(m.mesh, {.surface = &surface, .face_samples = 4});
  EXPECT_TRUE(v.valid()) << describe(v);
  EXPECT_EQ(v.euler_characteristic, 2);
  EXPECT_GT(v.volume, 0.0);
  // Mesh -> surface (vertices and face samples) and surface -> mesh, both within the bound.
  EXPECT_LE(v.surface.max_vertex_bound, m.distance_bound);
  EXPECT_LE(v.surface.max_face_bound, m.distance_bound);
  EXPECT_LE(surface_to_mesh(sphere, m.mesh, 1500, 7), m.distance_bound);
  // The bound is not loose by orders of magnitude: the true error is a sizeable part of it.
  EXPECT_GT(v.surface.max_face_estimate, 0.05 * m.distance_bound);
}

TEST(AdaptiveMesh, TorusIsAClosedGenusOneMesh) {
  const AdaptiveMesh m = mesh_adaptive({torus(1.0, 0.3)}, {.tolerance = 1e-3});
  EXPECT_TRUE(m.closed());
  EXPECT_EQ(m.glued_edges, 4u);
  const MeshValidity v = validate(m.mesh);
  EXPECT_TRUE(v.valid()) << describe(v);
  EXPECT_EQ(v.euler_characteristic, 0);
  EXPECT_LE(surface_to_mesh(torus(1.0, 0.3), m.mesh, 1000, 3), m.distance_bound);
}

// Claim 37: with Snyder's criterion w(S(X)) <= delta alone, every leaf's samples fit in a box
// of width <= delta (so every triangle's corners do), and the mesh is conforming: every edge
// of the closed torus belongs to exactly two triangles.
TEST(AdaptiveMesh, Claim37BoxWidthCriterionAndConformingMesh) {
  const double delta = 0.05;
  const AdaptiveMesh m = mesh_adaptive({torus(1.0, 0.3)}, {.tolerance = delta, .bound = LeafBound::BoxWidth});
  EXPECT_LE(m.distance_bound, delta);
  for (const auto& t : m.mesh.triangles) {
    double width2 = 0;
    for (int j = 0; j < 3; ++j) {
      const double lo = std::min({m.mesh.vertices[t[0]][j], m.mesh.vertices[t[1]][j], m.mesh.vertices[t[2]][j]});
      const double hi = std::max({m.mesh.vertices[t[0]][j], m.mesh.vertices[t[1]][j], m.mesh.vertices[t[2]][j]});
      width2 += (hi - lo) * (hi - lo);
    }
    ASSERT_LE(std::sqrt(width2), delta);
  }
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const auto& t : m.mesh.triangles)
    for (int k = 0; k < 3; ++k) ++edges[std::minmax(t[k], t[(k + 1) % 3])];
  for (const auto& [e, n] : edges) ASSERT_EQ(n, 2);
  EXPECT_EQ(m.boundary_edges, 0u);
}

// The linear-interpolation bound shrinks with the square of the leaf size, so a 100x smaller
// tolerance costs about 100x the leaves, where the box width alone costs about 10,000x.
TEST(AdaptiveMesh, InterpolationBoundConvergesQuadratically) {
  const SurfacePatch t = torus(1.0, 0.3);
  const AdaptiveMesh coarse = mesh_adaptive({t}, {.tolerance = 1e-2});
  const AdaptiveMesh fine = mesh_adaptive({t}, {.tolerance = 1e-4});
  const double ratio = static_cast<double>(fine.leaves) / static_cast<double>(coarse.leaves);
  EXPECT_GT(ratio, 30.0);
  EXPECT_LT(ratio, 400.0);
  const AdaptiveMesh box = mesh_adaptive({t}, {.tolerance = 1e-2, .bound = LeafBound::BoxWidth});
  EXPECT_LT(coarse.leaves * 3, box.leaves);
}

// The certified bound is on |A(p) - S(p)|, the mesh point against the surface point of the
// same parameters. On a graph S = (u, v, f(u, v)) the mesh interpolates u and v exactly, so a
// mesh point (x, y, z) stands for p = (x, y) and the claim reads |z - f(x, y)| <= bound. The
// second-order bound (from the interval second derivatives) is tight for a quadratic: a
// triangle's edge across a leaf of width a sags by |f_uu| a^2 / 8 at its middle, which is the
// bound, so the sampled error comes close to it (the linear bound alone would
// be twice as far). Convex, saddle and wavy graphs.
TEST(AdaptiveMesh, SecondOrderBoundHoldsOnGraphsAndIsTight) {
  const std::vector<std::pair<const char*, Fn>> graphs{{"convex", 3 * U * U - 2 * U * V + V * V},
                                                       {"saddle", U * U - 2 * V * V + 0.5 * U * V},
                                                       {"wavy", 0.3 * sin(7 * U) * cos(5 * V)}};
  for (const auto& [name, f] : graphs) {
    const double tol = 1e-3;
    const SurfacePatch patch{cat({U, V, f}), Interval(-1, 1), Interval(-1, 1)};
    const AdaptiveMesh m = mesh_adaptive({patch}, {.tolerance = tol});
    ASSERT_LE(m.distance_bound, tol) << name;
    const Tape height(f, std::vector<int>{0, 1});
    PointEvaluator ev;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst = 0.0;
    for (const auto& t : m.mesh.triangles)
      for (int k = 0; k < 4; ++k) {
        double l0 = unit(rng), l1 = unit(rng);
        if (k == 0) l0 = l1 = 0.0;  // a midpoint of an edge: where a chord sags most
        if (l0 + l1 > 1.0) l0 = 1.0 - l0, l1 = 1.0 - l1;
        const double l2 = 1.0 - l0 - l1;
        std::array<double, 3> q{};
        for (int c = 0; c < 3; ++c) {
          const double w0 = k == 0 ? 0.0 : l0, w1 = k == 0 ? 0.5 : l1, w2 = k == 0 ? 0.5 : l2;
          q[static_cast<std::size_t>(c)] = w0 * m.mesh.vertices[t[0]][static_cast<std::size_t>(c)] +
                                           w1 * m.mesh.vertices[t[1]][static_cast<std::size_t>(c)] +
                                           w2 * m.mesh.vertices[t[2]][static_cast<std::size_t>(c)];
        }
        const double z = ev.eval(height, {q[0], q[1]})[0];
        worst = std::max(worst, std::abs(q[2] - z));
      }
    EXPECT_LE(worst, m.distance_bound) << name;
    EXPECT_GT(worst, 0.4 * m.distance_bound) << name;  // 0.82, 0.58, 0.81 measured
  }
}

// Random kd-trees (a pseudo-random refine criterion) over a flat patch: the triangulation
// covers the rectangle exactly once (area), has no T-junction (edges with one triangle lie
// on the rectangle's boundary), no degenerate triangle, and every other edge has two.
TEST(AdaptiveMesh, RandomKdTreesTriangulateConformingly) {
  for (unsigned seed = 1; seed <= 12; ++seed) {
    const SurfacePatch plane{cat({U * 2.0, V, Fn(0.0)}), Interval(0, 1), Interval(0, 1)};
    AdaptiveMeshOptions o{.tolerance = 1.0, .max_depth = 7, .glue_edges = true};
    o.refine = [seed](std::size_t, const Interval& u, const Interval& v) {
      // splitmix64 of the leaf's corner bits: a random tree that is a function of the leaf.
      std::uint64_t h = std::bit_cast<std::uint64_t>(u.lo()) ^ (std::bit_cast<std::uint64_t>(v.lo()) * 3) ^
                        (std::bit_cast<std::uint64_t>(u.hi()) * 5) ^ (std::bit_cast<std::uint64_t>(v.hi()) * 7) ^ seed;
      h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ULL;
      h = (h ^ (h >> 27)) * 0x94D049BB133111EBULL;
      h ^= h >> 31;
      const double size = (u.hi() - u.lo()) * (v.hi() - v.lo());
      return size > 1.0 / 16 || (h % 100 < 45 && size > 1.0 / 4096);
    };
    const AdaptiveMesh m = mesh_adaptive({plane}, o);
    ASSERT_GT(m.leaves, 20u) << "seed " << seed;
    double area = 0;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (const auto& t : m.mesh.triangles) {
      const Vec3 a = m.mesh.vertices[t[0]], b = m.mesh.vertices[t[1]], c = m.mesh.vertices[t[2]];
      const double z = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      ASSERT_GT(std::abs(z), 0.0) << "degenerate triangle, seed " << seed;
      area += 0.5 * std::abs(z);
      for (int k = 0; k < 3; ++k) ++edges[std::minmax(t[k], t[(k + 1) % 3])];
    }
    EXPECT_NEAR(area, 2.0, 1e-12) << "seed " << seed;
    auto on_boundary = [](const Vec3& p) { return p[0] == 0 || p[0] == 2 || p[1] == 0 || p[1] == 1; };
    for (const auto& [e, n] : edges) {
      ASSERT_LE(n, 2);
      if (n == 1) {
        const Vec3 &a = m.mesh.vertices[e.first], &b = m.mesh.vertices[e.second];
        ASSERT_TRUE(on_boundary(a) && on_boundary(b) && (a[0] == b[0] || a[1] == b[1])) << "seed " << seed;
      }
    }
    EXPECT_EQ(m.collapsed_edges, 0u);
    EXPECT_EQ(m.glued_edges, 0u);
  }
}

// A cube as six patches with independent kd-trees: the twelve shared edges are glued by
// geometry, so the mesh is closed as written, and orientation comes from the geometry.
TEST(AdaptiveMesh, SixGluedFacesMakeAClosedOutwardCube) {
  std::vector<SurfacePatch> faces;
  for (int k = 0; k < 3; ++k)
    for (double side : {-1.0, 1.0}) {
      Fn c[3];
      c[k] = Fn(side);
      c[(k + 1) % 3] = U * 2.0 - 1.0;
      c[(k + 2) % 3] = V * 2.0 - 1.0;
      faces.push_back({cat({c[0], c[1], c[2]}), Interval(0, 1), Interval(0, 1)});
    }
  AdaptiveMeshOptions o{.tolerance = 1e-3};
  o.refine = [](std::size_t patch, const Interval& u, const Interval& v) {  // unequal kd-trees
    return u.hi() - u.lo() > 1.0 / (2 + patch) || v.hi() - v.lo() > 1.0 / (3 + patch);
  };
  const AdaptiveMesh m = mesh_adaptive(faces, o);
  EXPECT_EQ(m.glued_edges, 24u);
  EXPECT_TRUE(m.closed());
  const MeshValidity v = validate(m.mesh);
  EXPECT_TRUE(v.valid()) << describe(v);
  EXPECT_EQ(v.euler_characteristic, 2);
  EXPECT_NEAR(v.volume, 8.0, 1e-12);
}

TEST(AdaptiveMesh, UnflaggedCylinderSeamIsFoundByGeometry) {
  const Fn a = 2 * kPi * U;
  const SurfacePatch tube{cat({cos(a), sin(a), V}), Interval(0, 1), Interval(0, 1)};
  const AdaptiveMesh m = mesh_adaptive({tube}, {.tolerance = 1e-3});
  EXPECT_EQ(m.glued_edges, 2u);
  EXPECT_FALSE(m.closed());  // open at both ends
  const MeshValidity v = validate(m.mesh, {.check_self_intersections = false});
  EXPECT_EQ(v.components, 1u);
  EXPECT_EQ(v.euler_characteristic, 0);  // an annulus
  EXPECT_EQ(v.nonmanifold_edges, 0u);
  EXPECT_EQ(v.misoriented_edges, 0u);
}

// A cap filling a wall's rim in pieces is glued to the rim's parts even where mapping a part's
// parameters onto the rim's grid moves them by more than the gluing tolerance (1e-9 of the
// extent): the rim of a flat three-lobed cylinder is fast (its length, about 11, against an
// extent of about 2.6), and one grid step of its parameter is up to 1e-8 of length. Each end
// is closed by two half fans from the centre starting at an angle off the grid, one of them
// running through the wall's seam. Checking the part at its rounded parameters refused all
// four rims here (their seam deviation is 3.5e-9); every edge must be glued and the mesh valid.
TEST(AdaptiveMesh, CapPiecesAreGluedToAFastRim) {
  const double h = 0.05, phase = 0.3141592;  // the half fans start at 2 pi phase
  auto rim = [](const Fn& t) {
    const Fn r = 1.0 + 0.3 * cos(6 * kPi * t);
    return cat({r * cos(2 * kPi * t), r * sin(2 * kPi * t)});
  };
  const Fn wall = rim(U);
  std::vector<SurfacePatch> patches{{cat({wall[0], wall[1], h * V}), Interval(0, 1), Interval(0, 1), true}};
  for (double z : {0.0, h})
    for (double half : {0.0, 0.5}) {
      const Fn e = rim(phase + half + 0.5 * U);  // orientation is the mesher's to make outward
      patches.push_back({cat({V * e[0], V * e[1], Fn(z)}), Interval(0, 1), Interval(0, 1)});
    }
  const AdaptiveMesh m = mesh_adaptive(patches, {.tolerance = 5e-3});
  EXPECT_EQ(m.glued_edges, 4u + 4u * 3u);  // the wall's seam and rims; each half fan's rim and radii
  EXPECT_EQ(m.collapsed_edges, 4u);         // the half fans' centres
  EXPECT_TRUE(m.closed());
  EXPECT_LT(m.seam_deviation, 1e-7);
  const MeshValidity v = validate(m.mesh);
  EXPECT_TRUE(v.valid()) << describe(v);
  EXPECT_EQ(v.euler_characteristic, 2);
  // h times the area inside the rim, pi (1 + 0.3^2 / 2).
  EXPECT_NEAR(v.volume, h * kPi * 1.045, 1e-2 * h * kPi * 1.045);
}

// Leaves at a pole whose edges carry their neighbours' corners: a cone over a disc, both in
// polar coordinates with the pole at v = 1 (straight rays into the apex and the centre), one
// sector refined along v near the pole, so the leaves beside it have many points on one ray.
// Joining the pole to two points of one ray gives a flat triangle and folds over its
// neighbours (the old zipper made 30 such and 66 intersecting pairs here); the mesh must be
// valid.
TEST(AdaptiveMesh, PolesOfStraightRaysGiveNoFlatTriangles) {
  const Fn a = 2 * kPi * U, r = 1.0 - V;
  const std::vector<SurfacePatch> patches{
      {cat({r * cos(a), r * sin(a), 0.5 * V}), Interval(0, 1), Interval(0, 1), true},  // cone, apex at v = 1
      {cat({r * cos(a), r * sin(a), Fn(0.0)}), Interval(0, 1), Interval(0, 1), true}};  // disc, centre at v = 1
  AdaptiveMeshOptions o{.tolerance = 0.05};
  o.refine = [](std::size_t, const Interval& u, const Interval& v) {
    return u.hi() <= 0.125 && v.lo() >= 0.75 && v.hi() - v.lo() > 1.0 / 512;
  };
  const AdaptiveMesh m = mesh_adaptive(patches, o);
  EXPECT_EQ(m.collapsed_edges, 2u);
  EXPECT_TRUE(m.closed());
  const MeshValidity v = validate(m.mesh);
  EXPECT_EQ(v.degenerate_triangles, 0u) << describe(v);
  EXPECT_EQ(v.self_intersections, 0u) << describe(v);
  EXPECT_TRUE(v.valid()) << describe(v);
  EXPECT_NEAR(v.volume, kPi / 6.0, 0.05 * kPi / 6.0);  // a cone of radius 1 and height 1/2
}

// A tube periodic in u closed at each end by two half discs: one half disc's rim is the
// tube's rim for u in [0, 1/2], the other's for u in [1/2, 1]; both touch the tube's seam
// (u = 1 is u = 0). The first starts at angle 2 pi, the tube's point at u = 1 bit for bit
// (sin(2 pi) is not 0), so its start is found at the seam's other end and must be taken as
// u = 0 there. The half discs' straight edges are glued to each other and their centres
// collapse to a point.
TEST(AdaptiveMesh, CapPiecesEndingOnAPeriodicSeamAreGlued) {
  const Fn a = 2 * kPi * U;
  std::vector<SurfacePatch> patches{{cat({cos(a), sin(a), V}), Interval(0, 1), Interval(0, 1), true}};
  for (double z : {0.0, 1.0})
    for (double first : {1.0, 0.5}) {
      // Radius V, angle from first to first + 1/2 of the loop (the rim at V = 1).
      const Fn angle = 2 * kPi * (first + 0.5 * U);
      patches.push_back({cat({V * cos(angle), V * sin(angle), Fn(z)}), Interval(0, 1), Interval(0, 1)});
    }
  const AdaptiveMesh m = mesh_adaptive(patches, {.tolerance = 1e-3});
  EXPECT_EQ(m.collapsed_edges, 4u);
  EXPECT_EQ(m.boundary_edges, 0u);
  EXPECT_TRUE(m.closed());
  const MeshValidity v = validate(m.mesh);
  EXPECT_TRUE(v.valid()) << describe(v);
  EXPECT_EQ(v.euler_characteristic, 2);
  EXPECT_NEAR(v.volume, kPi, 0.02);  // the area (4 pi) times the tolerance
}

TEST(AdaptiveMesh, SameMeshForAnyThreadCount) {
  const AdaptiveMesh one = mesh_adaptive({torus(1.0, 0.4)}, {.tolerance = 1e-3, .threads = 1});
  const AdaptiveMesh two = mesh_adaptive({torus(1.0, 0.4)}, {.tolerance = 1e-3, .threads = 2});
  EXPECT_EQ(one.mesh.vertices, two.mesh.vertices);
  EXPECT_EQ(one.mesh.triangles, two.mesh.triangles);
  EXPECT_EQ(one.distance_bound, two.distance_bound);
}

TEST(AdaptiveMesh, LimitsAreReported) {
  const AdaptiveMesh leaves = mesh_adaptive({unit_sphere()}, {.tolerance = 1e-6, .max_leaves = 500});
  EXPECT_NE(std::find(leaves.limits_hit.begin(), leaves.limits_hit.end(), "leaves"), leaves.limits_hit.end());
  EXPECT_GT(leaves.distance_bound, 1e-6);
  EXPECT_LE(leaves.leaves, 500u);
  EXPECT_TRUE(leaves.closed());  // still a whole mesh, only coarser
  const AdaptiveMesh depth = mesh_adaptive({unit_sphere()}, {.tolerance = 1e-6, .max_depth = 4});
  EXPECT_NE(std::find(depth.limits_hit.begin(), depth.limits_hit.end(), "depth"), depth.limits_hit.end());
  EXPECT_GT(depth.distance_bound, 1e-6);
  // The request comes while the kd-tree is refined (after 200 leaves were looked at).
  std::atomic<bool> stop{false};
  std::atomic<int> looked_at{0};
  AdaptiveMeshOptions o{.tolerance = 1e-6, .cancel = &stop};
  o.refine = [&](std::size_t, const Interval&, const Interval&) {
    if (++looked_at > 200) stop = true;
    return false;
  };
  const AdaptiveMesh cancelled = mesh_adaptive({unit_sphere()}, o);
  EXPECT_NE(std::find(cancelled.limits_hit.begin(), cancelled.limits_hit.end(), "cancelled"), cancelled.limits_hit.end());
  EXPECT_GT(cancelled.distance_bound, 1e-6);
  EXPECT_TRUE(cancelled.closed());
}

TEST(AdaptiveMesh, BadInputIsRejectedWithAMessage) {
  const SurfacePatch s = unit_sphere();
  EXPECT_THROW(mesh_adaptive({}, {}), std::invalid_argument);
  EXPECT_THROW(mesh_adaptive({s}, {.tolerance = 0.0}), std::invalid_argument);
  EXPECT_THROW(mesh_adaptive({s}, {.tolerance = NAN}), std::invalid_argument);
  EXPECT_THROW(mesh_adaptive({s}, {.max_depth = 40}), std::invalid_argument);
  EXPECT_THROW(mesh_adaptive({{cat({U, V})}}, {}), std::invalid_argument);
  EXPECT_THROW(mesh_adaptive({{cat({U, V, x(2)})}}, {}), std::invalid_argument);
  EXPECT_THROW(mesh_adaptive({{cat({U, V, V}), Interval(0, 0)}}, {}), std::invalid_argument);
  try {
    mesh_adaptive({{cat({U, V, sqrt(U - 0.5)})}}, {.tolerance = 0.1, .max_depth = 6});
    FAIL() << "expected std::domain_error";
  } catch (const std::domain_error& e) {
    EXPECT_NE(std::string(e.what()).find("undefined at (u, v)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace genmod
