// Bloomenthal's continuation polygonizer (the classic fixed-size baseline) against genmod's
// adaptive octree mesher at equal cell size, in one run:
//   genmod_polygonizer_bench [--repeats N] [--previews DIR]
//
// For each shape and cell size h (a power-of-two fraction of the octree's box, so both use
// cells of edge h):
//  - continuation, tetrahedra and cubes: polygonize_continuation with cube_size = h from a
//    start on the surface; triangles, evaluations of f (corners + bisections + normals + seed
//    search, counted), CPU time;
//  - octree, uniform: mesh_implicit with min_feature = max_cell = h (every surface cell of
//    edge h), one thread; triangles, interval cell classifications (its point evaluations
//    are not counted by the mesher), CPU time;
//  - octree, adaptive: the same with the default max_cell (cells grow where the surface is
//    flat), min_feature = h.
// Ratios are octree / continuation (tetrahedra), measured in this run. Every mesh is
// validated outside the timing (valid = closed, manifold, outward, no self-intersections) with
// its largest certified vertex distance. CPU time is process CPU time, the median of the
// repeats (the machine is shared).
//
// --previews DIR writes each continuation mesh (tetrahedra, finest h) of the test shapes to
// DIR/<shape>.obj and a shaded picture DIR/<shape>.png.
#include "genmod/kernel/vm_format.hpp"
#include "genmod/models/starfish.hpp"
#include "genmod/operators/shapes.hpp"
#include "genmod/tessellate/continuation_polygonizer.hpp"
#include "genmod/tessellate/implicit_mesher.hpp"
#include "genmod/tessellate/mesh_io.hpp"
#include "genmod/tessellate/png_io.hpp"
#include "genmod/tessellate/preview.hpp"
#include "genmod/tessellate/validate.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace {

using namespace genmod;

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

template <class F>
double median_cpu(int repeats, F&& run) {
  std::vector<double> t;
  for (int i = 0; i < repeats; ++i) {
    const double t0 = cpu_seconds();
    run();
    t.push_back(cpu_seconds() - t0);
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

struct Shape {
  std::string name;
  Fn f;
  double half;                                 // octree box [-half, half]^3
  std::vector<std::array<double, 3>> starts;  // empty: searched in the box
  bool in_comparison;
};

std::string check(const Mesh& m, const Tape& f, double h) {
  const MeshValidity v = validate(m, {.surface = &f, .face_samples = 0, .search_radius = 4 * h});
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s chi=%ld d=%.1e", v.valid() ? "valid" : "INVALID", v.euler_characteristic,
                v.surface.max_vertex_bound);
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  int repeats = 3;
  std::string previews;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--repeats" && i + 1 < argc) {
      repeats = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--previews" && i + 1 < argc) {
      previews = argv[++i];
    } else {
      std::fprintf(stderr, "usage: genmod_polygonizer_bench [--repeats N] [--previews DIR]\n");
      return 2;
    }
  }
  const Fn X = x(0), Y = x(1), Z = x(2);
  const std::vector<Shape> shapes = {
      {"sphere", sqrt(square(X) + square(Y) + square(Z)) - 1.0, 1.5, {{1.0, 0.0, 0.0}}, true},
      {"torus", implicit_torus(1.0, 0.3), 1.5, {{1.3, 0.0, 0.0}}, true},
      {"tanglecube", load_vm(std::string(GENMOD_DATA_DIR) + "/tanglecube.vm"), 2.5, {}, true},
      {"two_spheres", csg_union(implicit_sphere(1.0, cat({-2.0, 0.0, 0.0})), implicit_sphere(1.0, cat({2.0, 0.0, 0.0}))), 3.5,
       {{-1.0, 0.0, 0.0}}, false},
      {"starfish", models::starfish_implicit(), 1.0, {{0.0, 0.0, 0.1}}, false},
  };
  const int xyz[3] = {0, 1, 2};
  std::printf("%-11s %8s | %-28s %9s %9s %8s | %9s %8s | %-22s %9s %9s %8s | %9s %9s %8s | %7s %7s %7s\n", "shape", "h",
              "continuation (tetrahedra)", "tris", "evals", "cpu s", "cube tris", "cpu s", "octree, uniform cells", "tris",
              "intervals", "cpu s", "adapt tris", "intervals", "cpu s", "tris x", "cpu x", "adapt x");
  for (const Shape& shape : shapes) {
    if (!shape.in_comparison) continue;
    const Tape tape(shape.f, xyz);
    const ImplicitSurface surface(shape.f);
    const Box3 box{Interval(-shape.half, shape.half), Interval(-shape.half, shape.half), Interval(-shape.half, shape.half)};
    for (int k : {5, 6, 7}) {
      const double h = 2 * shape.half / (1 << k);
      ContinuationSettings cs{.cube_size = h, .starts = shape.starts};
      if (shape.starts.empty()) cs.bounds = box;
      ContinuationMesh tet, cube;
      const double t_tet = median_cpu(repeats, [&] { tet = polygonize_continuation(tape, cs); });
      ContinuationSettings cc = cs;
      cc.decomposition = CellDecomposition::cubes;
      const double t_cube = median_cpu(repeats, [&] { cube = polygonize_continuation(tape, cc); });
      ImplicitMesh uni, ada;
      const double t_uni = median_cpu(
          repeats, [&] { uni = mesh_implicit(surface, box, {.min_feature = h, .max_cell = h, .threads = 1}); });
      const double t_ada = median_cpu(repeats, [&] { ada = mesh_implicit(surface, box, {.min_feature = h, .threads = 1}); });
      std::printf("%-11s %8.5f | %-28s %9zu %9zu %8.3f | %9zu %8.3f | %-22s %9zu %9zu %8.3f | %9zu %9zu %8.3f | %7.2f %7.2f %7.2f\n",
                  shape.name.c_str(), h, check(tet.mesh, tape, h).c_str(), tet.mesh.triangles.size(),
                  tet.stats.evaluations(), t_tet, cube.mesh.triangles.size(), t_cube, check(uni.mesh, tape, h).c_str(),
                  uni.mesh.triangles.size(), uni.stats.interval_evaluations, t_uni, ada.mesh.triangles.size(),
                  ada.stats.interval_evaluations, t_ada,
                  static_cast<double>(uni.mesh.triangles.size()) / static_cast<double>(tet.mesh.triangles.size()),
                  t_uni / t_tet, t_ada / t_tet);
      std::printf("%-11s %8s   cubes: %s\n", "", "", check(cube.mesh, tape, h).c_str());
      std::fflush(stdout);
    }
  }
  if (!previews.empty()) {
    std::filesystem::create_directories(previews);
    for (const Shape& shape : shapes) {
      const double h = 2 * shape.half / (shape.name == "starfish" ? 96 : 64);
      ContinuationSettings cs{.cube_size = h, .starts = shape.starts};
      if (shape.starts.empty())
        cs.bounds = Box3{Interval(-shape.half, shape.half), Interval(-shape.half, shape.half), Interval(-shape.half, shape.half)};
      const ContinuationMesh m = polygonize_continuation(shape.f, cs);
      const std::string base = previews + "/" + shape.name;
      write_mesh(m.mesh, base + ".obj");
      write_png(base + ".png", preview(m.mesh));
      const Tape tape(shape.f, xyz);
      std::printf("preview %s: %zu triangles, %s -> %s.png\n", shape.name.c_str(), m.mesh.triangles.size(),
                  check(m.mesh, tape, h).c_str(), base.c_str());
    }
  }
  return 0;
}
