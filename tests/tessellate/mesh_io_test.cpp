// Mesh files: bitwise round trips in every format, every write checked (/dev/full, an
// unwritable directory), malformed files named with their line and problem, and a mesh of
// mesh_implicit still valid after a round trip.
#include "genmod/tessellate/implicit_mesher.hpp"
#include "genmod/tessellate/mesh_io.hpp"
#include "genmod/tessellate/validate.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace genmod {
namespace {

namespace fs = std::filesystem;

const char* const kExtensions[] = {".obj", ".ply", ".stl", ".off"};

class MeshFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("genmod_mesh_io_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path file(const std::string& name) const { return dir_ / name; }
  fs::path write_text(const std::string& name, const std::string& text) const {
    std::ofstream(file(name), std::ios::binary) << text;
    return file(name);
  }

  fs::path dir_;
};

// The error message of a call, or "no exception".
template <class Call>
std::string message_of(Call&& call) {
  try {
    call();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "no exception";
}

bool same_bits(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::memcmp(a.data(), b.data(), sizeof a) == 0;
}

// An octahedron whose coordinates need all 17 digits, with extreme and signed-zero values;
// its vertices are used in order of first appearance (so STL reads them back in order).
Mesh awkward_octahedron() {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> jitter(-1e-3, 1e-3);
  Mesh m;
  const double axes[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  for (const auto& a : axes) m.vertices.push_back({a[0] + jitter(rng) / 3, a[1] + jitter(rng) / 7, a[2] + jitter(rng)});
  m.vertices[0][1] = -0.0;
  m.vertices[1][0] = 5e-324;  // the smallest subnormal
  m.vertices[2][0] = 1.0 / 3.0 * 1e-300;
  m.vertices[3][2] = -0.1;
  m.triangles = {{0, 1, 2}, {1, 3, 2}, {3, 4, 2}, {4, 0, 2}, {1, 0, 5}, {3, 1, 5}, {4, 3, 5}, {0, 4, 5}};
  return m;
}

TEST_F(MeshFiles, RoundTripIsBitwiseInEveryFormat) {
  const Mesh m = awkward_octahedron();
  for (const char* ext : kExtensions) {
    SCOPED_TRACE(ext);
    const fs::path path = file(std::string("octahedron") + ext);
    write_mesh(m, path);
    const Mesh r = read_mesh(path);
    ASSERT_EQ(r.vertices.size(), m.vertices.size());
    EXPECT_EQ(r.triangles, m.triangles);
    for (std::size_t v = 0; v < m.vertices.size(); ++v) EXPECT_TRUE(same_bits(r.vertices[v], m.vertices[v])) << v;
  }
}

TEST_F(MeshFiles, StlCornersReadBackAtTheirExactPositions) {
  // Vertices not in order of first appearance, one unused: STL renumbers, positions stay exact.
  Mesh m = awkward_octahedron();
  m.vertices.push_back({9, 9, 9});
  for (auto& t : m.triangles) std::swap(t[0], t[2]);
  write_mesh(m, file("m.stl"));
  const Mesh r = read_mesh(file("m.stl"));
  ASSERT_EQ(r.triangles.size(), m.triangles.size());
  EXPECT_EQ(r.vertices.size(), 6u);  // merged by position, the unused one gone
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_TRUE(same_bits(r.vertices[r.triangles[t][k]], m.vertices[m.triangles[t][k]])) << t << " " << k;
}

TEST_F(MeshFiles, FullDeviceThrowsForEveryFormat) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  Mesh small = awkward_octahedron();
  Mesh large;  // more than the writer's 1 MB buffer, so a write fails before the flush
  for (std::uint32_t i = 0; i < 60000; ++i) {
    large.vertices.push_back({i / 7.0, i / 9.0, i / 11.0});
    if (i >= 2) large.triangles.push_back({i - 2, i - 1, i});
  }
  for (const char* ext : kExtensions)
    for (const Mesh* m : {&small, &large}) {
      SCOPED_TRACE(ext);
      const fs::path link = file(std::string("full") + ext);
      fs::remove(link);
      fs::create_symlink("/dev/full", link);
      const std::string what = message_of([&] { write_mesh(*m, link); });
      EXPECT_NE(what.find(link.string()), std::string::npos) << what;
      EXPECT_NE(what.find("No space left on device"), std::string::npos) << what;
      EXPECT_TRUE(fs::exists("/dev/full"));  // a device is never removed
      EXPECT_THROW(write_mesh(*m, link), MeshFileError);
    }
}

TEST_F(MeshFiles, UnwritablePlacesThrowNamingThePath) {
  const Mesh m = awkward_octahedron();
  write_text("plain.txt", "not a directory");
  for (const char* ext : kExtensions) {
    SCOPED_TRACE(ext);
    const fs::path missing = file("no/such/dir") / (std::string("m") + ext);
    const std::string what = message_of([&] { write_mesh(m, missing); });
    EXPECT_NE(what.find(missing.string()), std::string::npos) << what;
    EXPECT_NE(what.find("does not exist"), std::string::npos) << what;
    const fs::path under_file = file("plain.txt") / (std::string("m") + ext);
    EXPECT_THROW(write_mesh(m, under_file), MeshFileError);
    // A directory no one may write to (sysfs refuses new files even to root).
    if (fs::is_directory("/sys")) {
      const fs::path denied = fs::path("/sys") / (std::string("genmod_mesh_io_test") + ext);
      const std::string why = message_of([&] { write_mesh(m, denied); });
      EXPECT_NE(why.find(denied.string()), std::string::npos) << why;
      EXPECT_THROW(write_mesh(m, denied), MeshFileError);
    }
  }
  EXPECT_THROW(write_mesh(m, file("m.xyz")), std::invalid_argument);
  Mesh bad = m;
  bad.triangles.push_back({0, 1, 999});
  EXPECT_NE(message_of([&] { write_mesh(bad, file("bad.obj")); }).find("vertex 999"), std::string::npos);
  EXPECT_FALSE(fs::exists(file("bad.obj")));
  bad = m;
  bad.vertices[2][1] = std::nan("");
  EXPECT_NE(message_of([&] { write_mesh(bad, file("bad.off")); }).find("not finite"), std::string::npos);
}

// Each malformed file's message names the file and contains every needle.
struct Malformed {
  const char* name;
  std::string contents;
  std::vector<std::string> needles;
};

TEST_F(MeshFiles, MalformedFilesNameTheProblem) {
  const std::string tri_obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  std::string short_stl(84, '\0');
  short_stl[80] = 2;  // announces 2 triangles, has none
  const std::vector<Malformed> cases = {
      {"index.obj", tri_obj + "f 1 2 4\n", {"line 4", "vertex index 4", "3 vertices"}},
      {"zero.obj", tri_obj + "f 0 1 2\n", {"line 4", "index 0"}},
      {"number.obj", "v 0 0 0\nv 1 zero 0\n", {"line 2", "'zero'", "not a finite number"}},
      {"short.obj", "v 0 0\n", {"line 1", "missing z coordinate"}},
      {"corners.obj", tri_obj + "f 1 2\n", {"line 4", "at least 3 corners"}},
      {"junk.obj", tri_obj + "12 3 4\n", {"line 4", "unknown statement '12'"}},
      {"count.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n", {"announces 4 vertices", "ends after 3"}},
      {"faces.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", {"announces 2 faces", "ends after 1"}},
      {"index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", {"line 6", "vertex index 3"}},
      {"header.off", "COFF\n3 1 0\n", {"line 1", "'COFF'", "not supported"}},
      {"extra.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n", {"line 7", "data after"}},
      {"number.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1e999 0\n3 0 1 2\n", {"line 5", "'1e999'"}},
      {"magic.ply", "PLY\n", {"does not start with 'ply'"}},
      {"noend.ply", "ply\nformat ascii 1.0\nelement vertex 1\n", {"end_header"}},
      {"ascii.ply",
       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 x\n0 1 0\n3 0 1 2\n",
       {"line 11", "vertex 1", "'x'"}},
      {"index.ply",
       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
       {"face 0", "vertex index 7"}},
      {"truncated.ply",
       "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty double x\nproperty double y\n"
       "property double z\nend_header\n" + std::string(30, '\0'),
       {"vertex 1", "ends inside it"}},
      {"noxyz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n", {"no property y"}},
      {"type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n", {"line 4", "unknown property type 'quad'"}},
      {"garbage.stl", "hello", {"neither ASCII STL", "binary STL"}},
      {"short.stl", short_stl, {"announces 2 triangles"}},
      {"ascii.stl", "solid t\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n endloop\nendfacet\n",
       {"line 6", "at least 3 vertices"}},
      {"cut.stl", "solid t\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n", {"expected 'endloop'", "end of the file"}},
  };
  for (const Malformed& c : cases) {
    SCOPED_TRACE(c.name);
    const fs::path path = write_text(c.name, c.contents);
    const std::string what = message_of([&] { (void)read_mesh(path); });
    EXPECT_NE(what.find(path.string()), std::string::npos) << what;
    for (const std::string& needle : c.needles) EXPECT_NE(what.find(needle), std::string::npos) << what;
    EXPECT_THROW((void)read_mesh(path), MeshFileError);
  }
  const std::string missing = message_of([&] { (void)read_mesh(file("missing.obj")); });
  EXPECT_NE(missing.find("does not exist"), std::string::npos) << missing;
  EXPECT_THROW((void)read_mesh(file("m.xyz")), std::invalid_argument);
}

TEST_F(MeshFiles, ReadersAcceptTheFormatsVariants) {
  // OBJ: texture and normal indices, negative indices, a quad (fanned), ignored statements.
  const Mesh obj = read_mesh(write_text("v.obj",
                                        "# comment\nmtllib x.mtl\no thing\nv 0 0 0\nv 1 0 0\nv 1 1 0 1.0\nv 0 1 0\n"
                                        "vt 0 0\nvn 0 0 1\ns off\nf 1/1/1 2/1/1 3//1 -1\r\n"));
  EXPECT_EQ(obj.vertices.size(), 4u);
  EXPECT_EQ(obj.triangles, (std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}, {0, 2, 3}}));
  // OFF: comments, a quad, counts on the OFF line.
  const Mesh off = read_mesh(write_text("v.off", "OFF 4 1 0\n# c\n0 0 0\n1 0 0\n\n1 1 0\n0 1 0\n4 0 1 2 3\n"));
  EXPECT_EQ(off.triangles.size(), 2u);
  // PLY: ASCII with extra properties and elements; big-endian binary.
  const Mesh ascii = read_mesh(write_text("a.ply",
                                          "ply\nformat ascii 1.0\ncomment c\nelement vertex 3\nproperty float x\n"
                                          "property float y\nproperty float z\nproperty uchar red\n"
                                          "element face 1\nproperty list uchar int vertex_index\nproperty int flags\n"
                                          "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
                                          "0 0 0 255\n1 0 0 255\n0 1 0.25 255\n3 0 1 2 7\n0 1\n"));
  ASSERT_EQ(ascii.vertices.size(), 3u);
  EXPECT_EQ(ascii.vertices[2][2], 0.25);
  EXPECT_EQ(ascii.triangles.size(), 1u);
  std::string big = "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
                    "property double z\nelement face 1\nproperty list uchar ushort vertex_indices\nend_header\n";
  const double coords[9] = {0, 0, 0, 1, 0, 0, 0, 1, 1.0 / 3};
  for (double c : coords)
    for (int k = 7; k >= 0; --k) big.push_back(static_cast<char>((std::bit_cast<std::uint64_t>(c) >> (8 * k)) & 0xff));
  big += std::string("\3\0\0\0\1\0\2", 7);
  const Mesh be = read_mesh(write_text("b.ply", big));
  ASSERT_EQ(be.vertices.size(), 3u);
  EXPECT_EQ(be.vertices[2][2], 1.0 / 3);
  EXPECT_EQ(be.triangles, (std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}}));
  // Binary STL (float32), two triangles sharing an edge: corners merged into 4 vertices.
  std::string stl(80, ' ');
  stl += std::string("\2\0\0\0", 4);
  const float tris[2][9] = {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {1, 0, 0, 1, 1, 0, 0, 1, 0}};
  for (const auto& t : tris) {
    stl += std::string(12, '\0');
    for (float f : t)
      for (int k = 0; k < 4; ++k) stl.push_back(static_cast<char>((std::bit_cast<std::uint32_t>(f) >> (8 * k)) & 0xff));
    stl += std::string(2, '\0');
  }
  const Mesh binary = read_mesh(write_text("b.stl", stl));
  EXPECT_EQ(binary.vertices.size(), 4u);
  EXPECT_EQ(binary.triangles, (std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}, {1, 3, 2}}));
}

TEST_F(MeshFiles, ImplicitMeshStaysValidThroughEveryFormat) {
  const Fn X = x(0), Y = x(1), Z = x(2);
  // A torus: genus 1, curved everywhere, vertices on no lattice.
  const Fn ring = sqrt(square(X) + square(Y)) - 0.6;
  const Fn f = sqrt(square(ring) + square(Z)) - 0.25;
  const ImplicitMesh m = mesh_implicit(f, {Interval(-1, 1), Interval(-1, 1), Interval(-1, 1)}, {.min_feature = 0.05});
  const MeshValidity before = validate(m.mesh);
  ASSERT_TRUE(before.valid()) << describe(before);
  for (const char* ext : kExtensions) {
    SCOPED_TRACE(ext);
    const fs::path path = file(std::string("torus") + ext);
    write_mesh(m.mesh, path);
    const Mesh r = read_mesh(path);
    const MeshValidity after = validate(r);
    EXPECT_TRUE(after.valid()) << describe(after);
    EXPECT_EQ(after.vertices, before.vertices);
    EXPECT_EQ(after.triangles, before.triangles);
    EXPECT_EQ(after.euler_characteristic, 0);
    EXPECT_NEAR(after.volume, before.volume, 1e-12 * before.volume);
  }
}

}  // namespace
}  // namespace genmod
