// validate(): every defect it reports, on small meshes built by hand, and the distance to
// the true surface on a sphere against the exact distance.
#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/tessellate/validate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace genmod {
namespace {

Mesh tetrahedron(double s = 1.0, std::array<double, 3> o = {0, 0, 0}) {
  Mesh m;
  m.vertices = {{o[0], o[1], o[2]}, {o[0] + s, o[1], o[2]}, {o[0], o[1] + s, o[2]}, {o[0], o[1], o[2] + s}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

// An axis-aligned cube [lo, hi]^3 as 12 outward triangles.
Mesh cube(double lo, double hi) {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.vertices.push_back({i & 1 ? hi : lo, i & 2 ? hi : lo, i & 4 ? hi : lo});
  // Each face as a quad (a, b, c, d), counter-clockwise seen from outside.
  const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  return m;
}

void append(Mesh& to, const Mesh& from, bool flip = false) {
  const auto base = static_cast<std::uint32_t>(to.vertices.size());
  to.vertices.insert(to.vertices.end(), from.vertices.begin(), from.vertices.end());
  for (auto t : from.triangles) {
    if (flip) std::swap(t[1], t[2]);
    to.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
}

// The icosahedron subdivided `levels` times with vertices projected on the unit sphere.
Mesh icosphere(int levels) {
  const double p = (1.0 + std::sqrt(5.0)) / 2.0;
  Mesh m;
  m.vertices = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
                {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
  m.triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  auto normalize = [](std::array<double, 3> v) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return std::array<double, 3>{v[0] / n, v[1] / n, v[2] / n};
  };
  for (auto& v : m.vertices) v = normalize(v);
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      const auto& va = m.vertices[a];
      const auto& vb = m.vertices[b];
      m.vertices.push_back(normalize({va[0] + vb[0], va[1] + vb[1], va[2] + vb[2]}));
      const auto id = static_cast<std::uint32_t>(m.vertices.size() - 1);
      mid.emplace(key, id);
      return id;
    };
    std::vector<std::array<std::uint32_t, 3>> next;
    for (const auto& t : m.triangles) {
      const std::uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({t[1], bc, ab});
      next.push_back({t[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    m.triangles = std::move(next);
  }
  return m;
}

TEST(Validate, TetrahedronIsValid) {
  const MeshValidity v = validate(tetrahedron());
  EXPECT_TRUE(v.valid()) << describe(v);
  EXPECT_EQ(v.edges, 6u);
  EXPECT_EQ(v.components, 1u);
  EXPECT_EQ(v.euler_characteristic, 2);
  EXPECT_NEAR(v.volume, 1.0 / 6.0, 1e-15);
  ASSERT_EQ(v.component_info.size(), 1u);
  EXPECT_EQ(v.component_info[0].nesting_level, 0);
}

TEST(Validate, InvertedMeshIsNotOutward) {
  Mesh m;
  append(m, tetrahedron(), /*flip=*/true);
  const MeshValidity v = validate(m);
  EXPECT_TRUE(v.closed() && v.manifold() && v.oriented());
  EXPECT_TRUE(v.orientation_checked);
  EXPECT_FALSE(v.outward);
  EXPECT_FALSE(v.valid());
  EXPECT_LT(v.volume, 0.0);
}

TEST(Validate, CubeWithCavity) {
  Mesh m = cube(0.0, 3.0);
  append(m, cube(1.0, 2.0), /*flip=*/true);  // the cavity's normals point into it
  MeshValidity v = validate(m);
  EXPECT_TRUE(v.valid()) << describe(v);
  EXPECT_EQ(v.components, 2u);
  EXPECT_EQ(v.euler_characteristic, 4);
  EXPECT_NEAR(v.volume, 27.0 - 1.0, 1e-12);
  EXPECT_EQ(v.component_info[0].nesting_level, 0);
  EXPECT_EQ(v.component_info[1].nesting_level, 1);

  Mesh wrong = cube(0.0, 3.0);
  append(wrong, cube(1.0, 2.0));  // inner shell facing outward: not the boundary of a solid
  v = validate(wrong);
  EXPECT_TRUE(v.orientation_checked);
  EXPECT_FALSE(v.outward);
  EXPECT_FALSE(v.component_info[1].outward);
  EXPECT_TRUE(v.component_info[0].outward);
}

TEST(Validate, OpenAndMisorientedMeshes) {
  Mesh open = cube(0, 1);
  open.triangles.pop_back();
  MeshValidity v = validate(open);
  EXPECT_EQ(v.boundary_edges, 3u);
  EXPECT_FALSE(v.closed());
  EXPECT_FALSE(v.orientation_checked);
  EXPECT_FALSE(v.valid());

  Mesh flipped = cube(0, 1);
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
  v = validate(flipped);
  EXPECT_TRUE(v.closed());
  EXPECT_EQ(v.misoriented_edges, 3u);
  EXPECT_FALSE(v.valid());
}

TEST(Validate, DuplicatedSeamVerticesAreOpen) {
  // The cube with one face's vertices duplicated: closed only after welding.
  Mesh m = cube(0, 1);
  for (int t = 0; t < 2; ++t)
    for (auto& i : m.triangles[t]) {
      m.vertices.push_back(m.vertices[i]);
      i = static_cast<std::uint32_t>(m.vertices.size() - 1);
    }
  const MeshValidity v = validate(m);
  EXPECT_GT(v.boundary_edges, 0u);
  EXPECT_GT(v.coincident_vertices, 0u);
  EXPECT_GT(v.self_intersections, 0u);  // the loose face touches its neighbours
  EXPECT_FALSE(v.valid());
}

TEST(Validate, NonManifoldEdgeAndVertex) {
  // Two tetrahedra sharing the vertex (0, 0, 0).
  Mesh bowtie = tetrahedron();
  Mesh other = tetrahedron(-1.0);  // mirrored through the origin: shares vertex (0,0,0)
  const auto base = static_cast<std::uint32_t>(bowtie.vertices.size());
  bowtie.vertices.insert(bowtie.vertices.end(), other.vertices.begin() + 1, other.vertices.end());
  for (auto t : other.triangles) {
    for (auto& i : t) i = i == 0 ? 0 : i - 1 + base;
    bowtie.triangles.push_back(t);  // the point reflection reverses orientation: flip back
    std::swap(bowtie.triangles.back()[1], bowtie.triangles.back()[2]);
  }
  MeshValidity v = validate(bowtie);
  EXPECT_TRUE(v.closed());
  EXPECT_EQ(v.nonmanifold_edges, 0u);
  EXPECT_EQ(v.nonmanifold_vertices, 1u);
  EXPECT_EQ(v.self_intersections, 0u);
  EXPECT_FALSE(v.valid());

  Mesh fin;  // three triangles on one edge
  fin.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  fin.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  v = validate(fin);
  EXPECT_EQ(v.nonmanifold_edges, 1u);
  EXPECT_FALSE(v.manifold());
}

TEST(Validate, SelfIntersectionsAndDegenerateTriangles) {
  Mesh two;
  append(two, tetrahedron());
  append(two, tetrahedron(1.0, {0.2, 0.2, 0.2}));
  MeshValidity v = validate(two);
  EXPECT_GT(v.self_intersections, 0u);
  EXPECT_TRUE(v.closed() && v.manifold() && v.oriented());
  EXPECT_FALSE(v.orientation_checked);
  EXPECT_FALSE(v.valid());

  Mesh apart;
  append(apart, tetrahedron());
  append(apart, tetrahedron(1.0, {2.0, 0.0, 0.0}));
  v = validate(apart);
  EXPECT_EQ(v.self_intersections, 0u);
  EXPECT_TRUE(v.valid()) << describe(v);

  // Two coplanar triangles sharing one vertex, one folded over the other.
  Mesh fold;
  fold.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0.5, 0}, {0.5, 1, 0}};
  fold.triangles = {{0, 1, 2}, {0, 3, 4}};
  EXPECT_EQ(validate(fold).self_intersections, 1u);
  // ... and sharing an edge, on the same side of it.
  fold.triangles = {{0, 1, 2}, {0, 1, 4}};
  EXPECT_EQ(validate(fold).self_intersections, 1u);
  // Sharing an edge, on opposite sides (a flat pair): fine.
  fold.vertices.push_back({0.5, -1, 0});
  fold.triangles = {{0, 1, 2}, {1, 0, 5}};
  EXPECT_EQ(validate(fold).self_intersections, 0u);

  Mesh degenerate = tetrahedron();
  degenerate.vertices.push_back({0.5, 0, 0});
  degenerate.triangles.push_back({0, 1, 4});  // collinear corners
  degenerate.triangles.push_back({0, 0, 1});  // repeated index
  v = validate(degenerate);
  EXPECT_EQ(v.degenerate_triangles, 2u);
  EXPECT_FALSE(v.valid());

  Mesh bad_index = tetrahedron();
  bad_index.triangles.push_back({0, 1, 9});
  v = validate(bad_index);
  EXPECT_EQ(v.invalid_indices, 1u);
  EXPECT_FALSE(v.closed());
}

TEST(Validate, TorusLatticeHasEulerZero) {
  const Fn u = x(0) * (2 * M_PI), w = x(1) * (2 * M_PI);
  const Fn r = 1.0 + 0.3 * cos(w);
  const Fn torus = cat({r * cos(u), r * sin(u), 0.3 * sin(w)});
  const Mesh m = mesh_parametric(torus, {0, 0, 1, 24}, {1, 0, 1, 12}, {.periodic_u = true, .periodic_v = true});
  const MeshValidity v = validate(m);
  EXPECT_TRUE(v.closed() && v.manifold() && v.oriented()) << describe(v);
  EXPECT_EQ(v.euler_characteristic, 0);
  EXPECT_EQ(v.self_intersections, 0u);
  EXPECT_TRUE(v.orientation_checked);
}

TEST(Validate, SurfaceDistanceOfAnIcosphere) {
  const Mesh m = icosphere(3);
  const Fn p[3] = {x(0), x(1), x(2)};
  const Tape sphere(sqrt(square(p[0]) + square(p[1]) + square(p[2])) - 1.0);
  const MeshValidity v = validate(m, {.surface = &sphere, .face_samples = 4});
  EXPECT_TRUE(v.valid()) << describe(v);
  ASSERT_TRUE(v.has_surface_distance);
  EXPECT_EQ(v.surface.uncertified, 0u);
  EXPECT_LT(v.surface.max_vertex_bound, 1e-12);
  // The exact distance of a point q inside the unit sphere is 1 - |q|; the deepest samples
  // are the face centroids.
  double deepest = 0;
  for (const auto& t : m.triangles) {
    double c[3];
    for (int d = 0; d < 3; ++d) c[d] = (m.vertices[t[0]][d] + m.vertices[t[1]][d] + m.vertices[t[2]][d]) / 3.0;
    deepest = std::max(deepest, 1.0 - std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]));
  }
  EXPECT_GE(v.surface.max_face_bound, deepest);          // a bound, never below the truth
  EXPECT_LE(v.surface.max_face_bound, 1.001 * deepest);  // and tight for a sphere
  EXPECT_NEAR(v.surface.max_face_estimate, deepest, 1e-3 * deepest);
}

TEST(Validate, AnErrorIsNoSignChange) {
  // f = sqrt(1.2 - |p|^2) + 0.5 is positive wherever it is defined and an error (NaN) beyond
  // |p| = sqrt(1.2): it has no surface, so no point may be certified, although every ray
  // outward from the unit icosphere reaches the error region within the search radius.
  const Mesh m = icosphere(2);
  const Fn p[3] = {x(0), x(1), x(2)};
  const Tape no_surface(sqrt(1.2 - (square(p[0]) + square(p[1]) + square(p[2]))) + 0.5);
  const MeshValidity v = validate(m, {.surface = &no_surface, .face_samples = 1, .search_radius = 0.5});
  ASSERT_TRUE(v.has_surface_distance);
  EXPECT_EQ(v.surface.uncertified_vertices, m.vertices.size());
  EXPECT_EQ(v.surface.uncertified, m.vertices.size() + m.triangles.size());
  EXPECT_EQ(v.surface.max_vertex_bound, 0.0);
}

TEST(Validate, RejectsBadOptions) {
  const Tape planar(x(0) + x(1));
  EXPECT_THROW(validate(tetrahedron(), {.surface = &planar}), std::invalid_argument);
  EXPECT_THROW(validate(tetrahedron(), {.face_samples = 65}), std::invalid_argument);
  const MeshValidity empty = validate(Mesh{});
  EXPECT_FALSE(empty.valid());
}

}  // namespace
}  // namespace genmod
