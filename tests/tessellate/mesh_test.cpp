// Parametric meshes: topology of periodic and open lattices, orientation, file round trips.
#include "genmod/tessellate/mesh.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <utility>

namespace genmod {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

Fn torus(double r_major, double r_minor) {
  const Fn u = x(0), v = x(1);
  const Fn ring = r_major + r_minor * cos(v);
  return cat({ring * cos(u), ring * sin(u), r_minor * sin(v)});
}

// Directed edge -> number of triangles using it in that direction.
std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed_edges(const Mesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> e;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++e[{t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)]}];
  return e;
}

std::size_t undirected_edge_count(const Mesh& m) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> e;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const auto a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      e.insert({std::min(a, b), std::max(a, b)});
    }
  return e.size();
}

TEST(ParametricMesh, PeriodicTorusIsClosedAndConsistentlyOriented) {
  const std::size_t nu = 24, nv = 12;
  const Mesh m = mesh_parametric(torus(2.0, 0.5), {0, 0.0, kTwoPi, nu}, {1, 0.0, kTwoPi, nv}, {true, true});
  ASSERT_EQ(m.vertices.size(), nu * nv);
  ASSERT_EQ(m.triangles.size(), 2 * nu * nv);
  const auto directed = directed_edges(m);
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << "directed edge used twice: " << edge.first << "->" << edge.second;
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u)
        << "edge " << edge.first << "-" << edge.second << " has no opposite half";
  }
  const std::size_t e = undirected_edge_count(m);
  EXPECT_EQ(directed.size(), 2 * e);  // every edge shared by exactly two triangles
  const long euler = static_cast<long>(m.vertices.size()) - static_cast<long>(e) + static_cast<long>(m.triangles.size());
  EXPECT_EQ(euler, 0);
  // Orientation: outward normals (away from the core circle) at the first triangle.
  const auto& t = m.triangles[0];
  const auto& a = m.vertices[t[0]];
  const auto& b = m.vertices[t[1]];
  const auto& c = m.vertices[t[2]];
  const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n[3] = {ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0]};
  const double out[3] = {a[0] - 2.0, a[1], a[2]};  // a is near u = 0: core point (2, 0, 0)
  const double dot = n[0] * out[0] + n[1] * out[1] + n[2] * out[2];
  EXPECT_NE(dot, 0.0);  // consistent sign is what matters; record it is outward for S_u x S_v
  EXPECT_GT(dot, 0.0);
}

TEST(ParametricMesh, OpenSphereLatticeCounts) {
  const Fn u = x(0), v = x(1);
  const Fn sphere = cat({cos(u) * cos(v), sin(u) * cos(v), sin(v)});
  const std::size_t nu = 17, nv = 9;
  const Mesh open = mesh_parametric(sphere, {0, 0.0, kTwoPi, nu}, {1, -1.5, 1.5, nv});
  EXPECT_EQ(open.vertices.size(), nu * nv);
  EXPECT_EQ(open.triangles.size(), 2 * (nu - 1) * (nv - 1));
  EXPECT_EQ(undirected_edge_count(open), (nu - 1) * nv + nu * (nv - 1) + (nu - 1) * (nv - 1));
  for (const auto& [edge, count] : directed_edges(open)) EXPECT_EQ(count, 1);
  // Periodic in u only: a cylinder-like band, V - E + F = 0 with two boundary loops.
  const Mesh band = mesh_parametric(sphere, {0, 0.0, kTwoPi, nu}, {1, -1.5, 1.5, nv}, {true, false});
  EXPECT_EQ(band.vertices.size(), nu * nv);
  EXPECT_EQ(band.triangles.size(), 2 * nu * (nv - 1));
  const long euler = static_cast<long>(band.vertices.size()) - static_cast<long>(undirected_edge_count(band)) +
                     static_cast<long>(band.triangles.size());
  EXPECT_EQ(euler, 0);
  // Vertex (i, j) is S at the lattice point; periodic u spacing is 2 pi / N_u.
  const Mesh plain = mesh_parametric(sphere, {0, 0.0, kTwoPi, nu}, {1, -1.5, 1.5, nv}, {true, false, LatticeMethod::Plain});
  EXPECT_EQ(plain.vertices, band.vertices);
}

TEST(ParametricMesh, FilesRoundTripInAllFormats) {
  const Mesh m = mesh_parametric(torus(2.0, 0.5), {0, 0.0, kTwoPi, 16}, {1, 0.0, kTwoPi, 8}, {true, true});
  const auto dir = std::filesystem::temp_directory_path() / "genmod_mesh_test";
  std::filesystem::create_directories(dir);
  for (const char* ext : {".obj", ".ply", ".stl", ".off", ".OBJ"}) {
    const auto path = dir / (std::string("torus") + ext);
    write_mesh(m, path);
    const Mesh r = read_mesh(path);
    EXPECT_EQ(r.vertices.size(), m.vertices.size()) << ext;
    EXPECT_EQ(r.triangles.size(), m.triangles.size()) << ext;
  }
  std::filesystem::remove_all(dir);
}

TEST(ParametricMesh, ErrorsNameTheProblem) {
  const Mesh m = mesh_parametric(torus(2.0, 0.5), {0, 0.0, kTwoPi, 4}, {1, 0.0, kTwoPi, 4}, {true, true});
  auto message = [](auto&& call) -> std::string {
    try {
      call();
    } catch (const std::exception& e) {
      return e.what();
    }
    return "no exception";
  };
  EXPECT_NE(message([&] { write_mesh(m, "/tmp/x.xyz"); }).find("unknown mesh file extension '.xyz'"), std::string::npos);
  EXPECT_NE(message([&] { write_mesh(m, "/nonexistent_dir_genmod/x.obj"); }).find("does not exist"), std::string::npos);
  EXPECT_NE(message([&] { (void)read_mesh("/nonexistent_dir_genmod/x.obj"); }).find("does not exist"), std::string::npos);
  EXPECT_NE(message([&] { (void)mesh_parametric(x(0), {0, 0, 1, 4}, {1, 0, 1, 4}); }).find("dimension 3"),
            std::string::npos);
  EXPECT_NE(message([&] { (void)mesh_parametric(torus(2, 0.5), {0, 0, 1, 2}, {1, 0, 1, 4}, {true, false}); })
                .find("at least 3 samples when periodic"),
            std::string::npos);
  EXPECT_NE(message([&] { (void)mesh_parametric(cat({x(0), x(1), x(2)}), {0, 0, 1, 4}, {1, 0, 1, 4}); }).find("x(2)"),
            std::string::npos);
  Mesh bad = m;
  bad.triangles.push_back({0, 1, 999});
  EXPECT_NE(message([&] { write_mesh(bad, "/tmp/genmod_bad.obj"); }).find("vertex 999"), std::string::npos);
}

}  // namespace
}  // namespace genmod
