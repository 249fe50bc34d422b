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
//    edge h), one thread; triangles, point and interval evaluations of f, CPU time;
//  - octree, adaptive: the same with the default max_cell (cells grow where the surface is
//    flat), min_feature = h.
// Evaluations are counted in one extra, untimed run of each mesher on f wrapped in a counting
// identity operator (counting_op.hpp): point evaluations ("pts") and interval evaluations
// ("boxes") of f's value tape; mesh_implicit's gradient and Hessian tapes are not counted. For
// the continuation polygonizer the wrapped count is checked against its own stats.
// The ratio columns divide each row's triangles, evaluations (points + boxes) and CPU time by
// those of the continuation (tetrahedra) row of the same shape and h, all from this run. Every mesh is
// validated outside the timing (valid = closed, manifold, outward, no self-intersections) with
// its largest certified vertex distance. CPU time is process CPU time, the median of the
// repeats (the machine is shared).
//
// --previews DIR writes each continuation mesh (tetrahedra, finest h) of the test shapes to
// DIR/<shape>.obj and a shaded picture DIR/<shape>.png.
#include "counting_op.hpp"
#include "genmod/kernel/vm_format.hpp"
#include "genmod/models/starfish.hpp"
#include "genmod/operators/shapes.hpp"
#include "genmod/tessellate/continuation_polygonizer.hpp"
#include "genmod/tessellate/implicit_mesher.hpp"
#include "genmod/tessellate/mesh_io.hpp"
#include "genmod/tessellate/png_io.hpp"
#include "genmod/tessellate/preview.hpp"
#include "genmod/tessellate/validate.hpp"

#include "../cpu_time.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace genmod;

using bench::cpu_seconds;
using bench::median_cpu;

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
  std::printf("%-11s %8s  %-22s %-26s %9s %10s %9s %8s %8s %8s %8s\n", "shape", "h", "mesher", "validate", "triangles",
              "f points", "f boxes", "cpu s", "tris x", "evals x", "cpu x");
  for (const Shape& shape : shapes) {
    if (!shape.in_comparison) continue;
    const Tape tape(shape.f, xyz);
    const ImplicitSurface surface(shape.f);
    const Box3 box{Interval(-shape.half, shape.half), Interval(-shape.half, shape.half), Interval(-shape.half, shape.half)};
    for (int k : {5, 6, 7}) {
      const double h = 2 * shape.half / (1 << k);
      ContinuationSettings tets{.cube_size = h, .starts = shape.starts};
      if (shape.starts.empty()) tets.bounds = box;
      ContinuationSettings cubes = tets;
      cubes.decomposition = CellDecomposition::cubes;
      const ImplicitMeshSettings uniform{.min_feature = h, .max_cell = h, .threads = 1};
      const ImplicitMeshSettings adaptive{.min_feature = h, .threads = 1};

      struct Row {
        const char* mesher;
        std::function<Mesh(const Fn&)> run;  // the mesher on f (counted) or on the plain shape (timed)
        std::function<Mesh()> run_timed;
      };
      const Row rows[4] = {
          {"continuation, tets", [&](const Fn& g) { return polygonize_continuation(g, tets).mesh; },
           [&] { return polygonize_continuation(tape, tets).mesh; }},
          {"continuation, cubes", [&](const Fn& g) { return polygonize_continuation(g, cubes).mesh; },
           [&] { return polygonize_continuation(tape, cubes).mesh; }},
          {"octree, uniform cells", [&](const Fn& g) { return mesh_implicit(g, box, uniform).mesh; },
           [&] { return mesh_implicit(surface, box, uniform).mesh; }},
          {"octree, adaptive", [&](const Fn& g) { return mesh_implicit(g, box, adaptive).mesh; },
           [&] { return mesh_implicit(surface, box, adaptive).mesh; }},
      };
      double base_tris = 0, base_evals = 0, base_cpu = 0;
      for (const Row& row : rows) {
        Mesh mesh;
        const double cpu = median_cpu(repeats, [&] { mesh = row.run_timed(); });
        const auto counter = std::make_shared<bench::CountingOp>();
        const Mesh counted_mesh = row.run(bench::counted(shape.f, counter));
        const double points = static_cast<double>(counter->points.load());
        const double boxes = static_cast<double>(counter->boxes.load());
        if (counted_mesh.triangles != mesh.triangles) std::printf("  (the counted run gave another mesh)\n");
        const double tris = static_cast<double>(mesh.triangles.size());
        if (base_tris == 0) base_tris = tris, base_evals = points + boxes, base_cpu = cpu;
        std::printf("%-11s %8.5f  %-22s %-26s %9zu %10.0f %9.0f %8.3f %8.2f %8.2f %8.2f\n", shape.name.c_str(), h,
                    row.mesher, check(mesh, tape, h).c_str(), mesh.triangles.size(), points, boxes, cpu, tris / base_tris,
                    (points + boxes) / base_evals, cpu / base_cpu);
        std::fflush(stdout);
      }
      // The continuation polygonizer's own count agrees with the counted run.
      const ContinuationMesh own = polygonize_continuation(tape, tets);
      const auto counter = std::make_shared<bench::CountingOp>();
      polygonize_continuation(bench::counted(shape.f, counter), tets);
      if (own.stats.evaluations() != counter->points.load())
        std::printf("  (stats.evaluations() = %zu, counted %zu)\n", own.stats.evaluations(), counter->points.load());
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
