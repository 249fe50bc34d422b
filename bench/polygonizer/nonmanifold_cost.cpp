// The non-manifold polygonizer's cost (research/bloomenthal.md §5.7.8, claim 35) against the
// conventional bisection polygonizer, in one run:
//   genmod_nonmanifold_bench [--previews DIR]
//
// Per cube size h, on the binary sphere |p| = 1 (regions: inside, outside):
//  - model: the paper's count per tetrahedron crossed by the surface, nothing shared: f_reg
//    evaluations of its six edges (n = 16 sections, m = 4 halvings: 15 samples per edge plus
//    m + 1 per crossing) over f evaluations of bisection with m = 8 on the same tetrahedra (8
//    per crossed edge). The paper: 108/24 = 4.5 with three crossings, 112/32 = 3.5 with four.
//  - measured: evaluations per crossing cube as run, with every edge and vertex shared
//    between neighbours: the non-manifold polygonizer's (samples + refinement) per cube it
//    polygonized, and polygonize_continuation's bisections per cube with bisections = 8 and
//    six tetrahedra per cube (corners and normals excluded in both), and their ratio. CPU time
//    of each (process CPU, one run).
// Then the three-region half balls and the sphere-square (Fig. 4.9), with the evaluations by
// purpose, the face and internal vertices and the time.
//
// --previews DIR writes the three-region half balls (h = 0.05) to DIR/half_balls.obj with a
// shaded picture DIR/half_balls.png and a cut-away DIR/half_balls_cut.png (the quarter x > 0,
// y < 0 removed, so the disc between the two halves shows), seen from above and from below.
#include "genmod/tessellate/continuation_polygonizer.hpp"
#include "genmod/tessellate/mesh_io.hpp"
#include "genmod/tessellate/nonmanifold_polygonizer.hpp"
#include "genmod/tessellate/png_io.hpp"
#include "genmod/tessellate/preview.hpp"
#include "tessellate/region_shapes.hpp"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace genmod;

const Fn X = x(0), Y = x(1), Z = x(2);
const Fn R = sqrt(square(X) + square(Y) + square(Z));

Box3 cube_box(double h) { return {Interval(-h, h), Interval(-h, h), Interval(-h, h)}; }

double cpu_ms(std::clock_t start) { return 1000.0 * static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC; }

using test::half_balls;
using test::sphere_square;

void print_regions(const char* name, double h, const std::vector<Fn>& regions, const NonmanifoldSettings& s) {
  const std::clock_t t0 = std::clock();
  const RegionMesh m = polygonize_regions(regions, s);
  const double ms = cpu_ms(t0);
  const auto& st = m.stats;
  std::printf("%-13s %6.3f %8zu %7zu %9zu %9zu %9zu %9zu %6zu %6zu %4zu %9.1f\n", name, h, m.mesh.triangles.size(),
              st.cubes, st.corner_evaluations, st.sample_evaluations, st.refine_evaluations, st.face_evaluations,
              st.face_vertices, st.internal_vertices, st.face_vertex_fallbacks, ms);
}

}  // namespace

int main(int argc, char** argv) {
  std::string previews;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--previews" && i + 1 < argc) {
      previews = argv[++i];
    } else {
      std::fprintf(stderr, "usage: genmod_nonmanifold_bench [--previews DIR]\n");
      return 2;
    }
  }
  const std::vector<Fn> sphere{1.0 - R, R - 1.0};
  const double sizes[] = {0.2, 0.1, 0.05};
  std::printf("binary sphere |p| = 1: f_reg (n = 16, m = 4) against bisection (m = 8)\n");
  std::printf("%6s | %8s %8s %8s %8s %7s | %8s %8s %8s %7s | %8s %8s %7s %7s\n", "h", "tets", "crossed", "nm/tet",
              "bis/tet", "ratio", "nm cubes", "nm/cube", "cont cub", "bis/cub", "ratio", "nm ms", "cont ms", "t ratio");
  for (const double h : sizes) {
    const std::clock_t t0 = std::clock();
    const RegionMesh m = polygonize_regions(sphere, {.cube_size = h, .bounds = cube_box(1.0 + 2.3 * h)});
    const double nm_ms = cpu_ms(t0);
    const auto& s = m.stats;
    const double tets = static_cast<double>(s.crossing_tetrahedra);
    const double nm_tet = static_cast<double>(s.crossing_tetrahedron_edge_evaluations) / tets;
    const double bis_tet = 8.0 * static_cast<double>(s.crossing_tetrahedron_crossed_edges) / tets;
    const std::clock_t t1 = std::clock();
    const ContinuationMesh c = polygonize_continuation(
        R - 1.0, {.cube_size = h, .starts = {{1.0, 0.0, 0.0}}, .bisections = 8, .normals = false});
    const double cont_ms = cpu_ms(t1);
    const double nm_cube = static_cast<double>(s.sample_evaluations + s.refine_evaluations) / s.cubes;
    const double bis_cube = static_cast<double>(c.stats.bisection_evaluations) / c.stats.cubes;
    std::printf("%6.3f | %8zu %8.2f %8.1f %8.1f %7.2f | %8zu %8.1f %8zu %7.1f | %8.2f %8.1f %8.1f %7.2f\n", h,
                s.crossing_tetrahedra, s.crossing_tetrahedron_crossed_edges / tets, nm_tet, bis_tet, nm_tet / bis_tet,
                s.cubes, nm_cube, c.stats.cubes, bis_cube, nm_cube / bis_cube, nm_ms, cont_ms, nm_ms / cont_ms);
  }
  std::printf("\nseveral regions (evaluations of f_reg by purpose)\n");
  std::printf("%-13s %6s %8s %7s %9s %9s %9s %9s %6s %6s %4s %9s\n", "shape", "h", "tris", "cubes", "corners", "samples",
              "refine", "face", "fverts", "iverts", "fall", "cpu ms");
  for (const double h : sizes) {
    print_regions("half balls", h, half_balls(0.7), {.cube_size = h, .bounds = cube_box(0.7 + 2.3 * h)});
    print_regions("sphere-square", h, sphere_square(0.6, 1.0),
                  {.cube_size = h, .bounds = cube_box(1.0 + 2.3 * h), .interest = {{0, 2}, {0, 3}, {2, 3}}});
  }
  if (!previews.empty()) {
    std::filesystem::create_directories(previews);
    const RegionMesh m = polygonize_regions(half_balls(0.7), {.cube_size = 0.05, .bounds = cube_box(0.7 + 2.3 * 0.05)});
    write_mesh(m.mesh, previews + "/half_balls.obj");
    write_png(previews + "/half_balls.png", preview(m.mesh));
    Mesh cut{m.mesh.vertices, {}};
    for (const auto& t : m.mesh.triangles) {
      double cx = 0.0, cy = 0.0;
      for (auto v : t) {
        cx += m.mesh.vertices[v][0];
        cy += m.mesh.vertices[v][1];
      }
      if (!(cx > 0.0 && cy < 0.0)) cut.triangles.push_back(t);
    }
    write_png(previews + "/half_balls_cut.png", preview(cut));
    // From below the disc faces the eye (its normals point from the upper half, region 0,
    // into the lower, region 1).
    write_png(previews + "/half_balls_cut_below.png", preview(cut, {.view = {1.0, -1.5, -1.2}}));
    std::printf("\npreviews: %zu triangles -> %s/half_balls.{obj,png}, half_balls_cut{,_below}.png\n", m.mesh.triangles.size(),
                previews.c_str());
  }
  return 0;
}
