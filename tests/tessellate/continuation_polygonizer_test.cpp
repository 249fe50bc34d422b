// polygonize_continuation: research/bloomenthal.md §11 claims 27-31 (watertightness, vertex
// accuracy, normals, the case tables, continuation completeness), then closed 2-manifold
// meshes of a sphere and a torus under validate(), one component per start, bitwise
// determinism, limits and rejected input.
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/vm_format.hpp"
#include "genmod/operators/shapes.hpp"
#include "genmod/tessellate/continuation_polygonizer.hpp"
#include "genmod/tessellate/validate.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <map>
#include <random>
#include <set>

namespace genmod {
namespace {

const Fn X = x(0), Y = x(1), Z = x(2);
constexpr int kXyz[3] = {0, 1, 2};

Fn sphere(double r, double cx = 0.0) { return sqrt(square(X - cx) + square(Y) + square(Z)) - r; }
Fn torus() { return implicit_torus(1.0, 0.3); }

struct Checked {
  ContinuationMesh result;
  MeshValidity validity;
};

Checked polygonize_and_check(const Fn& f, const ContinuationSettings& s) {
  Checked c{polygonize_continuation(f, s), {}};
  const Tape tape(f, kXyz);
  c.validity = validate(c.result.mesh, {.surface = &tape, .face_samples = 1, .search_radius = 4 * s.cube_size});
  return c;
}

std::string summary(const Checked& c) {
  std::string limits;
  for (const auto& l : c.result.stats.limits_hit) limits += " " + l;
  return describe(c.validity) + "cubes " + std::to_string(c.result.stats.cubes) + ", evaluations " +
         std::to_string(c.result.stats.evaluations()) + ", limits:" + limits + "\n";
}

void expect_closed_manifold(const Checked& c, long euler) {
  EXPECT_TRUE(c.validity.valid());
  EXPECT_TRUE(c.validity.closed());
  EXPECT_TRUE(c.validity.manifold());
  EXPECT_TRUE(c.validity.oriented());
  EXPECT_EQ(c.validity.coincident_vertices, 0u);
  EXPECT_EQ(c.validity.unused_vertices, 0u);
  EXPECT_EQ(c.validity.components, 1u);
  EXPECT_EQ(c.validity.euler_characteristic, euler);
  EXPECT_TRUE(c.result.stats.limits_hit.empty());
  // Every edge in exactly two triangles: E = 3F / 2.
  EXPECT_EQ(2 * c.validity.edges, 3 * c.validity.triangles);
}

const CellDecomposition kBoth[2] = {CellDecomposition::tetrahedra, CellDecomposition::cubes};
const char* name(CellDecomposition d) { return d == CellDecomposition::tetrahedra ? "tetrahedra" : "cubes"; }

// Claim 27: the tetrahedral (and the cube) polygonizer's sphere and torus are closed,
// 2-manifold, consistently and outwardly oriented, with Euler characteristic 2 and 0. (The
// starfish is in tests/models/starfish_continuation_test.cpp.)
TEST(ContinuationPolygonizer, Claim27SphereAndTorusAreClosedManifolds) {
  for (CellDecomposition d : kBoth) {
    SCOPED_TRACE(name(d));
    const Checked s = polygonize_and_check(sphere(1.0), {.cube_size = 0.1, .starts = {{1, 0, 0}}, .decomposition = d});
    SCOPED_TRACE(summary(s));
    expect_closed_manifold(s, 2);
    EXPECT_NEAR(s.validity.volume, 4.0 / 3.0 * M_PI, 0.05);
    const Checked t = polygonize_and_check(torus(), {.cube_size = 0.05, .starts = {{1.3, 0, 0}}, .decomposition = d});
    SCOPED_TRACE(summary(t));
    expect_closed_manifold(t, 0);
    EXPECT_NEAR(t.validity.volume, 2 * M_PI * M_PI * 0.09, 0.03);
  }
}

// Claim 28: after 10 bisections every vertex is within size 2^-10 sqrt(3) of the zero set, and
// on a sphere | |v| - R | <= size / 1000.
TEST(ContinuationPolygonizer, Claim28VertexAccuracy) {
  const double size = 0.1, R = 1.0;
  for (CellDecomposition d : kBoth) {
    SCOPED_TRACE(name(d));
    const Checked c = polygonize_and_check(sphere(R), {.cube_size = size, .starts = {{0, 0, R}}, .decomposition = d});
    ASSERT_GT(c.result.mesh.vertices.size(), 100u);
    double worst = 0;
    for (const auto& v : c.result.mesh.vertices) worst = std::max(worst, std::abs(std::hypot(v[0], v[1], v[2]) - R));
    EXPECT_LE(worst, size / 1000);
    EXPECT_LE(worst, size * std::sqrt(3.0) / 1024);
    // The bracket is the edge over 2^10; the vertex is its midpoint.
    EXPECT_LE(c.result.stats.max_bracket, size * std::sqrt(3.0) / 1024 * (1 + 1e-12));
    // On the torus (an exact distance too) and by validate()'s certified sign-change bound.
    const Checked t = polygonize_and_check(torus(), {.cube_size = 0.05, .starts = {{1.3, 0, 0}}, .decomposition = d});
    ASSERT_EQ(t.validity.surface.uncertified, 0u);
    EXPECT_LE(t.validity.surface.max_vertex_bound, 0.05 * std::sqrt(3.0) / 1024);
    PointEvaluator ev;
    const Tape tape(torus(), kXyz);
    for (const auto& v : t.result.mesh.vertices)
      ASSERT_LE(std::abs(ev.eval(tape, {v[0], v[1], v[2]})[0]), 0.05 * std::sqrt(3.0) / 2048);
  }
}

// Claim 29: the forward-difference normal with delta = size / 100 points outward, and on a
// sphere of radius 10 sizes it is within 0.1 degree of the true normal.
TEST(ContinuationPolygonizer, Claim29Normals) {
  const double size = 0.1, R = 10 * size;
  const ContinuationMesh m = polygonize_continuation(sphere(R), {.cube_size = size, .starts = {{R, 0, 0}}});
  ASSERT_EQ(m.normals.size(), m.mesh.vertices.size());
  double worst = 0;
  for (std::size_t i = 0; i < m.normals.size(); ++i) {
    const auto& v = m.mesh.vertices[i];
    const auto& n = m.normals[i];
    const double r = std::hypot(v[0], v[1], v[2]);
    const double cosine = (n[0] * v[0] + n[1] * v[1] + n[2] * v[2]) / r;
    EXPECT_GT(cosine, 0.0);  // outward
    worst = std::max(worst, std::acos(std::min(1.0, cosine)) * 180 / M_PI);
  }
  EXPECT_LT(worst, 0.1);
  // A density field (positive inside, Gaussian 2^-|p|^2 at iso 1/2, the unit sphere) wrapped
  // to f = 1/2 - D: Unit(D(p) - D(p + delta e_i)) is the normal computed, and points outward.
  const ContinuationMesh g =
      polygonize_continuation(0.5 - exp(-M_LN2 * (square(X) + square(Y) + square(Z))), {.cube_size = size, .starts = {{R, 0, 0}}});
  ASSERT_GT(g.normals.size(), 100u);
  double worst_density = 0;
  for (std::size_t i = 0; i < g.normals.size(); ++i) {
    const auto& v = g.mesh.vertices[i];
    const auto& n = g.normals[i];
    const double cosine = (n[0] * v[0] + n[1] * v[1] + n[2] * v[2]) / std::hypot(v[0], v[1], v[2]);
    EXPECT_GT(cosine, 0.0);
    worst_density = std::max(worst_density, std::acos(std::min(1.0, cosine)) * 180 / M_PI);
  }
  EXPECT_LT(worst_density, 0.1);
  // Off: no normals, and four evaluations fewer per vertex.
  ContinuationSettings off{.cube_size = size, .starts = {{R, 0, 0}}, .normals = false};
  const ContinuationMesh m2 = polygonize_continuation(sphere(R), off);
  EXPECT_TRUE(m2.normals.empty());
  EXPECT_EQ(m2.stats.normal_evaluations, 0u);
  EXPECT_EQ(m.stats.normal_evaluations, 4 * m.mesh.vertices.size());
  EXPECT_EQ(m2.mesh.vertices, m.mesh.vertices);
}

bool is_tet_edge(const std::array<std::uint8_t, 4>& tet, const CornerPair& e) {
  int found = 0;
  for (auto c : tet) found += (c == e[0]) + (c == e[1]);
  return found == 2 && e[0] != e[1];
}

// Per-cube meshing of a lattice of corner signs with the tables alone (vertices at the edge
// midpoints, shared by their lattice edge).
Mesh lattice_mesh(const std::vector<bool>& inside, int n, CellDecomposition d) {
  auto at = [&](int i, int j, int k) { return inside[(static_cast<std::size_t>(k) * n + j) * n + i]; };
  Mesh mesh;
  std::map<std::array<int, 6>, std::uint32_t> vertex;
  for (int k = 0; k + 1 < n; ++k)
    for (int j = 0; j + 1 < n; ++j)
      for (int i = 0; i + 1 < n; ++i) {
        auto corner = [&](int c) { return std::array<int, 3>{i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1)}; };
        unsigned mask = 0;
        for (int c = 0; c < 8; ++c) {
          const auto p = corner(c);
          if (at(p[0], p[1], p[2])) mask |= 1u << c;
        }
        std::vector<CaseTriangle> tris;
        if (d == CellDecomposition::cubes) {
          for (const auto& t : cube_case(mask)) tris.push_back(t);
        } else {
          for (int t = 0; t < 6; ++t) {
            unsigned m = 0;
            for (int q = 0; q < 4; ++q)
              if (mask >> cube_tetrahedra()[t][q] & 1) m |= 1u << q;
            for (const auto& tri : tetrahedron_case(t, m)) tris.push_back(tri);
          }
        }
        for (const auto& tri : tris) {
          std::array<std::uint32_t, 3> out;
          for (int v = 0; v < 3; ++v) {
            auto a = corner(tri[v][0]), b = corner(tri[v][1]);
            if (b < a) std::swap(a, b);
            const std::array<int, 6> key{a[0], a[1], a[2], b[0], b[1], b[2]};
            auto [it, added] = vertex.emplace(key, static_cast<std::uint32_t>(mesh.vertices.size()));
            if (added) mesh.vertices.push_back({0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])});
            out[v] = it->second;
          }
          mesh.triangles.push_back(out);
        }
      }
  return mesh;
}

// Claim 30: the 16-case tetrahedral table emits 0, 1 or 2 triangles per tetrahedron on 0, 3 or
// 4 edge vertices; the 256-case cube table (and the tetrahedra) on a lattice of random corner
// signs leave no holes: every mesh edge has degree 2.
TEST(ContinuationPolygonizer, Claim30CaseTablesAreWatertight) {
  ASSERT_EQ(cube_tetrahedra().size(), 6u);
  for (int t = 0; t < 6; ++t) {
    const auto& tet = cube_tetrahedra()[t];
    for (unsigned mask = 0; mask < 16; ++mask) {
      const auto tris = tetrahedron_case(t, mask);
      const int inside = std::popcount(mask);
      std::set<std::pair<int, int>> edges;
      for (const auto& tri : tris)
        for (const auto& e : tri) {
          EXPECT_TRUE(is_tet_edge(tet, e));
          int i0 = -1, i1 = -1;
          for (int q = 0; q < 4; ++q) {
            if (tet[q] == e[0]) i0 = q;
            if (tet[q] == e[1]) i1 = q;
          }
          EXPECT_TRUE((mask >> i0 & 1) && !(mask >> i1 & 1)) << "inside corner first";
          edges.insert({e[0], e[1]});
        }
      const std::size_t expect_tris = inside == 0 || inside == 4 ? 0 : inside == 2 ? 2 : 1;
      const std::size_t expect_vertices = inside == 0 || inside == 4 ? 0 : inside == 2 ? 4 : 3;
      EXPECT_EQ(tris.size(), expect_tris) << "tet " << t << " mask " << mask;
      EXPECT_EQ(edges.size(), expect_vertices) << "tet " << t << " mask " << mask;
    }
  }
  for (unsigned mask = 0; mask < 256; ++mask) {
    std::set<std::pair<int, int>> used, crossed;
    for (const auto& tri : cube_case(mask))
      for (const auto& e : tri) {
        EXPECT_EQ(std::popcount(static_cast<unsigned>(e[0] ^ e[1])), 1) << "a cube edge";
        EXPECT_TRUE((mask >> e[0] & 1) && !(mask >> e[1] & 1));
        used.insert({e[0], e[1]});
      }
    for (int a = 0; a < 8; ++a)
      for (int axis = 0; axis < 3; ++axis) {
        const int b = a ^ (1 << axis);
        if ((mask >> a & 1) && !(mask >> b & 1)) crossed.insert({a, b});
      }
    EXPECT_EQ(used, crossed) << "every crossed cube edge has a vertex, mask " << mask;
  }
  std::mt19937 rng(30);
  const int n = 10;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<bool> inside(static_cast<std::size_t>(n) * n * n);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const bool border = i == 0 || j == 0 || k == 0 || i == n - 1 || j == n - 1 || k == n - 1;
          inside[(static_cast<std::size_t>(k) * n + j) * n + i] = !border && (rng() & 1);
        }
    for (CellDecomposition d : kBoth) {
      SCOPED_TRACE(name(d));
      const Mesh mesh = lattice_mesh(inside, n, d);
      const MeshValidity v = validate(mesh, {.check_self_intersections = false});
      ASSERT_GT(v.triangles, 0u);
      EXPECT_EQ(v.boundary_edges, 0u);
      EXPECT_EQ(v.nonmanifold_edges, 0u);
      EXPECT_EQ(v.misoriented_edges, 0u);
      EXPECT_EQ(v.nonmanifold_vertices, 0u);
      EXPECT_EQ(2 * v.edges, 3 * v.triangles);
    }
  }
}

Fn two_spheres() { return csg_union(sphere(1.0, -2.0), sphere(1.0, 2.0)); }

// Claim 31: continuation from one start point yields exactly one connected component; on two
// disjoint spheres it returns only the one near the start, and with two starts both.
TEST(ContinuationPolygonizer, Claim31OneComponentPerStart) {
  for (CellDecomposition d : kBoth) {
    SCOPED_TRACE(name(d));
    const Checked one = polygonize_and_check(two_spheres(), {.cube_size = 0.1, .starts = {{-1.0, 0, 0}}, .decomposition = d});
    SCOPED_TRACE(summary(one));
    expect_closed_manifold(one, 2);
    for (const auto& v : one.result.mesh.vertices) ASSERT_LT(v[0], -0.9);  // all on the sphere at x = -2
    EXPECT_EQ(one.result.stats.seeds.size(), 1u);

    const Checked both =
        polygonize_and_check(two_spheres(), {.cube_size = 0.1, .starts = {{-1.0, 0, 0}, {3.0, 0, 0}}, .decomposition = d});
    SCOPED_TRACE(summary(both));
    EXPECT_TRUE(both.validity.valid());
    EXPECT_EQ(both.validity.components, 2u);
    for (const auto& comp : both.validity.component_info) EXPECT_EQ(comp.euler_characteristic, 2);
    EXPECT_EQ(both.result.stats.seeds.size(), 2u);
    // The first sphere's part is the one-start mesh itself (same lattice, same order).
    ASSERT_GT(both.result.mesh.vertices.size(), one.result.mesh.vertices.size());
    for (std::size_t i = 0; i < one.result.mesh.vertices.size(); ++i)
      ASSERT_EQ(both.result.mesh.vertices[i], one.result.mesh.vertices[i]);

    // A second start on the piece already polygonized adds nothing.
    const ContinuationMesh again =
        polygonize_continuation(two_spheres(), {.cube_size = 0.1, .starts = {{-1.0, 0, 0}, {-3.0, 0, 0}}, .decomposition = d});
    EXPECT_EQ(again.stats.starts_in_visited_cubes, 1u);
    EXPECT_EQ(again.mesh.triangles, one.result.mesh.triangles);
  }
}

TEST(ContinuationPolygonizer, SphereIsClosedAndOnTheSurface) {
  const double size = 0.05;
  const Checked c = polygonize_and_check(sphere(1.0), {.cube_size = size, .starts = {{0.3, 0.2, 0.1}}});
  SCOPED_TRACE(summary(c));
  expect_closed_manifold(c, 2);
  EXPECT_EQ(c.validity.surface.uncertified, 0u);
  EXPECT_LE(c.validity.surface.max_vertex_bound, size * std::sqrt(3.0) / 2048 * (1 + 1e-9));
  // The flat triangles of a cube-sized lattice lie within a fraction of a cube of the sphere.
  EXPECT_LE(c.validity.surface.max_face_estimate, 0.1 * size);
  // Counted evaluations: corners once each, bisections per vertex.
  EXPECT_EQ(c.result.stats.bisection_evaluations, 10 * c.result.mesh.vertices.size());
  EXPECT_GT(c.result.stats.corner_evaluations, c.result.stats.cubes);
}

TEST(ContinuationPolygonizer, TorusIsClosedWithEulerCharacteristicZero) {
  const Checked c = polygonize_and_check(torus(), {.cube_size = 0.03, .starts = {{0.0, 0.7, 0.0}}});
  SCOPED_TRACE(summary(c));
  expect_closed_manifold(c, 0);
}

TEST(ContinuationPolygonizer, TanglecubeHasGenusFive) {
  // Found without a start point (the surface crosses no axis), meshed whole from one seed.
  const Fn f = load_vm(std::string(GENMOD_DATA_DIR) + "/tanglecube.vm");
  const Checked c =
      polygonize_and_check(f, {.cube_size = 0.1, .bounds = Box3{Interval(-2.5, 2.5), Interval(-2.5, 2.5), Interval(-2.5, 2.5)}});
  SCOPED_TRACE(summary(c));
  expect_closed_manifold(c, -8);  // 2 - 2 * 5
}

TEST(ContinuationPolygonizer, SeedIsFoundInTheBoundsWithoutAStart) {
  ContinuationSettings s{.cube_size = 0.1, .bounds = Box3{Interval(-2, 2), Interval(-2, 2), Interval(-2, 2)}};
  const Checked c = polygonize_and_check(sphere(1.0), s);
  SCOPED_TRACE(summary(c));
  expect_closed_manifold(c, 2);
  ASSERT_EQ(c.result.stats.seeds.size(), 1u);
  const auto& p = c.result.stats.seeds[0];
  EXPECT_NEAR(std::hypot(p[0], p[1], p[2]), 1.0, 1e-3);
}

TEST(ContinuationPolygonizer, SameInputGivesBitwiseTheSameMesh) {
  for (CellDecomposition d : kBoth) {
    const ContinuationSettings s{.cube_size = 0.04, .starts = {{1.3, 0, 0}}, .decomposition = d};
    const ContinuationMesh a = polygonize_continuation(torus(), s);
    const ContinuationMesh b = polygonize_continuation(torus(), s);
    const ContinuationMesh c = polygonize_continuation(Tape(torus(), kXyz), s);
    for (const ContinuationMesh* m : {&b, &c}) {
      ASSERT_EQ(a.mesh.vertices.size(), m->mesh.vertices.size());
      EXPECT_EQ(std::memcmp(a.mesh.vertices.data(), m->mesh.vertices.data(), a.mesh.vertices.size() * sizeof(a.mesh.vertices[0])), 0);
      EXPECT_EQ(a.mesh.triangles, m->mesh.triangles);
      EXPECT_EQ(std::memcmp(a.normals.data(), m->normals.data(), a.normals.size() * sizeof(a.normals[0])), 0);
      EXPECT_EQ(a.stats.evaluations(), m->stats.evaluations());
    }
  }
}

// The vertices are placed in parallel (in rounds of 4096 and chunks fixed by the vertex
// numbers): one and two threads give bitwise the same mesh, normals and statistics, for both
// decompositions, several rounds (over 4096 vertices), and walks cut by limits.
TEST(ContinuationPolygonizer, OneAndTwoThreadsGiveBitwiseTheSameMesh) {
  std::vector<ContinuationSettings> cases;
  for (CellDecomposition d : kBoth) cases.push_back({.cube_size = 0.02, .starts = {{1.3, 0, 0}}, .decomposition = d});
  cases.push_back({.cube_size = 0.03, .starts = {{1.3, 0, 0}}, .max_cubes = 777});
  cases.push_back({.cube_size = 0.03, .starts = {{1.3, 0, 0}}, .bounds = Box3{Interval(0, 2), Interval(-2, 2), Interval(-2, 2)}});
  for (ContinuationSettings s : cases) {
    s.threads = 1;
    const ContinuationMesh a = polygonize_continuation(torus(), s);
    s.threads = 2;
    const ContinuationMesh b = polygonize_continuation(torus(), s);
    ASSERT_EQ(a.mesh.vertices.size(), b.mesh.vertices.size());
    EXPECT_EQ(std::memcmp(a.mesh.vertices.data(), b.mesh.vertices.data(), a.mesh.vertices.size() * sizeof(a.mesh.vertices[0])), 0);
    EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
    ASSERT_EQ(a.normals.size(), b.normals.size());
    EXPECT_EQ(std::memcmp(a.normals.data(), b.normals.data(), a.normals.size() * sizeof(a.normals[0])), 0);
    EXPECT_EQ(a.stats.corner_evaluations, b.stats.corner_evaluations);
    EXPECT_EQ(a.stats.bisection_evaluations, b.stats.bisection_evaluations);
    EXPECT_EQ(a.stats.normal_evaluations, b.stats.normal_evaluations);
    EXPECT_EQ(a.stats.max_bracket, b.stats.max_bracket);
    EXPECT_EQ(a.stats.cubes, b.stats.cubes);
    EXPECT_EQ(a.stats.limits_hit, b.stats.limits_hit);
    if (s.max_cubes == 10'000'000 && !s.bounds) {
      EXPECT_GT(a.mesh.vertices.size(), 4096u * 2);
    }
  }
  ContinuationSettings bad{.cube_size = 0.1, .starts = {{1.3, 0, 0}}};
  bad.threads = -1;
  EXPECT_THROW(polygonize_continuation(torus(), bad), std::invalid_argument);
}

TEST(ContinuationPolygonizer, CubeLimitIsReported) {
  const ContinuationMesh m = polygonize_continuation(sphere(1.0), {.cube_size = 0.05, .starts = {{1, 0, 0}}, .max_cubes = 100});
  EXPECT_EQ(m.stats.cubes, 100u);
  ASSERT_EQ(m.stats.limits_hit, std::vector<std::string>{"cubes"});
  const MeshValidity v = validate(m.mesh, {.check_self_intersections = false});
  EXPECT_GT(v.boundary_edges, 0u);  // cut where the limit stopped it
  // A second start after the limit adds nothing and is no error.
  const ContinuationMesh two = polygonize_continuation(
      two_spheres(), {.cube_size = 0.05, .starts = {{-1, 0, 0}, {1, 0, 0}}, .max_cubes = 100});
  EXPECT_EQ(two.stats.cubes, 100u);
  EXPECT_EQ(two.stats.seeds.size(), 1u);
  EXPECT_EQ(two.stats.limits_hit, std::vector<std::string>{"cubes"});
  // Cut anywhere, its vertices may touch in a point; the edges stay manifold and oriented.
  EXPECT_EQ(v.nonmanifold_edges, 0u);
  EXPECT_TRUE(v.oriented());
  // A stop request (Python's Ctrl-C) ends the walk and is reported.
  const std::atomic<bool> stop{true};
  const ContinuationMesh cancelled =
      polygonize_continuation(sphere(1.0), {.cube_size = 0.05, .starts = {{1, 0, 0}}, .cancel = &stop});
  EXPECT_EQ(cancelled.stats.limits_hit, std::vector<std::string>{"cancelled"});
  EXPECT_LT(cancelled.mesh.triangles.size(), m.mesh.triangles.size());
}

TEST(ContinuationPolygonizer, BoundsAreReportedAndCutUnboundedSurfaces) {
  // A plane is unbounded: only the bounds stop the walk.
  const Box3 box{Interval(-1, 1), Interval(-1, 1), Interval(-1, 1)};
  const ContinuationMesh plane = polygonize_continuation(Z - 0.01, {.cube_size = 0.1, .starts = {{0, 0, 0}}, .bounds = box});
  ASSERT_EQ(plane.stats.limits_hit, std::vector<std::string>{"bounds"});
  const MeshValidity v = validate(plane.mesh, {.check_self_intersections = false});
  EXPECT_GT(v.boundary_edges, 0u);
  EXPECT_EQ(v.components, 1u);
  EXPECT_EQ(v.euler_characteristic, 1);  // a disk
  for (const auto& p : plane.mesh.vertices) EXPECT_LE(std::max(std::abs(p[0]), std::abs(p[1])), 1.1);
  // A sphere inside the bounds does not touch them.
  const ContinuationMesh ball = polygonize_continuation(sphere(0.5), {.cube_size = 0.1, .starts = {{0.5, 0, 0}}, .bounds = box});
  EXPECT_TRUE(ball.stats.limits_hit.empty());
}

template <class E>
void expect_error(const Fn& f, const ContinuationSettings& s, const std::string& words) {
  try {
    polygonize_continuation(f, s);
    ADD_FAILURE() << "no exception; expected one saying: " << words;
  } catch (const E& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(ContinuationPolygonizer, BadInputIsRejectedWithMessagesNamingTheProblem) {
  using IA = std::invalid_argument;
  const Fn f = sphere(1.0);
  const std::vector<std::array<double, 3>> start{{1, 0, 0}};
  for (double size : {0.0, -0.1, std::nan(""), HUGE_VAL})
    expect_error<IA>(f, {.cube_size = size, .starts = start}, "cube_size must be finite and positive");
  expect_error<IA>(f, {.cube_size = 0.1, .starts = {{std::nan(""), 0, 0}}}, "start point 0 has a coordinate that is not finite");
  expect_error<IA>(f, {.cube_size = 0.1}, "no start point and no bounds");
  expect_error<IA>(f, {.cube_size = 0.1, .bounds = Box3{Interval(-1, 1), Interval(-1, HUGE_VAL), Interval(-1, 1)}},
                   "must be bounded");
  expect_error<IA>(f, {.cube_size = 0.1, .starts = start, .bisections = 0}, "bisections must be in 1..60");
  expect_error<IA>(f, {.cube_size = 0.1, .starts = start, .max_cubes = 0}, "max_cubes");
  expect_error<IA>(f, {.cube_size = 0.1, .starts = start, .search_samples = 0}, "search_samples");
  expect_error<IA>(f, {.cube_size = 0.1, .starts = start, .search_radius = 0.01}, "search_radius");
  expect_error<IA>(cat({X, Y}), {.cube_size = 0.1, .starts = start}, "must be scalar");
  expect_error<IA>(X + x(3), {.cube_size = 0.1, .starts = start}, "depends on x(3)");
  EXPECT_THROW(polygonize_continuation(Tape(X + Y), {.cube_size = 0.1, .starts = start}), IA);
  // A start far from the surface: f is positive at all samples within the search radius.
  expect_error<std::runtime_error>(f, {.cube_size = 0.1, .starts = {{10, 0, 0}}}, "is not near the surface");
  expect_error<std::runtime_error>(f, {.cube_size = 0.1, .bounds = Box3{Interval(3, 4), Interval(3, 4), Interval(3, 4)}},
                                   "surface was not found in the bounds");
  // A surface smaller than a cube: the seed is found, but no cube around it straddles.
  expect_error<std::runtime_error>(sphere(0.01), {.cube_size = 1.0, .starts = {{0, 0, 0}}}, "smaller than a cube");
}

}  // namespace
}  // namespace genmod
