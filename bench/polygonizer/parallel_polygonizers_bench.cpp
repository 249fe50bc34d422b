// The continuation and non-manifold polygonizers on 1 and 2 threads (issue 11):
//   genmod_parallel_polygonizers_bench [--repeats N] [--only NAME-PREFIX]
// For each shape, the median wall and process CPU seconds of N runs (default 5) with
// settings.threads = 1 and = 2, their ratios, and whether the two meshes are bitwise equal.
// Shapes: the continuation on a torus (a cheap f) and on the plain sum of 100 Gaussian tree
// segments (models::tree_segments, an f of ~100 terms); the non-manifold polygonizer on the
// sphere-and-square regions of its tests and on two regions split by that segment sum.
// The machine is shared: read the ratios, not the seconds.
#include "genmod/models/bloomenthal_models.hpp"
#include "genmod/operators/convolution.hpp"
#include "genmod/operators/shapes.hpp"
#include "genmod/tessellate/continuation_polygonizer.hpp"
#include "genmod/tessellate/nonmanifold_polygonizer.hpp"
#include "tessellate/region_shapes.hpp"

#include "../cpu_time.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

using namespace genmod;

struct Timing {
  double wall = 0, cpu = 0;
};

// Median wall and CPU seconds of `repeats` runs of run().
template <class F>
Timing median_times(int repeats, F&& run) {
  std::vector<double> wall, cpu;
  for (int i = 0; i < repeats; ++i) {
    const auto w0 = std::chrono::steady_clock::now();
    const double c0 = bench::cpu_seconds();
    run();
    cpu.push_back(bench::cpu_seconds() - c0);
    wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count());
  }
  std::sort(wall.begin(), wall.end());
  std::sort(cpu.begin(), cpu.end());
  return {wall[wall.size() / 2], cpu[cpu.size() / 2]};
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

void print(const char* name, std::size_t triangles, const Timing& one, const Timing& two, bool same) {
  std::printf("%-26s %9zu %8.3f %8.3f %8.3f %8.3f %7.2fx %7.2fx  %s\n", name, triangles, one.wall, two.wall, one.cpu, two.cpu,
              one.wall / two.wall, two.cpu / one.cpu, same ? "yes" : "NO");
}

void continuation(const char* name, const Fn& f, ContinuationSettings s, int repeats) {
  ContinuationMesh m1, m2;
  s.threads = 1;
  const Timing one = median_times(repeats, [&] { m1 = polygonize_continuation(f, s); });
  s.threads = 2;
  const Timing two = median_times(repeats, [&] { m2 = polygonize_continuation(f, s); });
  const bool same = same_bits(m1.mesh.vertices, m2.mesh.vertices) && m1.mesh.triangles == m2.mesh.triangles &&
                    same_bits(m1.normals, m2.normals);
  print(name, m1.mesh.triangles.size(), one, two, same);
}

void regions(const char* name, const std::vector<Fn>& r, NonmanifoldSettings s, int repeats) {
  RegionMesh m1, m2;
  s.threads = 1;
  const Timing one = median_times(repeats, [&] { m1 = polygonize_regions(r, s); });
  s.threads = 2;
  const Timing two = median_times(repeats, [&] { m2 = polygonize_regions(r, s); });
  const bool same = same_bits(m1.mesh.vertices, m2.mesh.vertices) && m1.mesh.triangles == m2.mesh.triangles &&
                    m1.regions == m2.regions;
  print(name, m1.mesh.triangles.size(), one, two, same);
}

}  // namespace

int main(int argc, char** argv) {
  int repeats = 5;
  std::string only;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--repeats") == 0) repeats = std::max(1, std::atoi(argv[i + 1]));
    if (std::strcmp(argv[i], "--only") == 0) only = argv[i + 1];
  }
  const auto wanted = [&](const char* name) { return std::string(name).rfind(only, 0) == 0; };
  std::printf("1 vs 2 threads, median of %d runs; wall ratio = wall(1) / wall(2) (speed-up), cpu ratio = cpu(2) / cpu(1) (overhead)\n",
              repeats);
  std::printf("%-26s %9s %8s %8s %8s %8s %8s %8s  %s\n", "shape", "triangles", "wall_1", "wall_2", "cpu_1", "cpu_2", "wall", "cpu",
              "bitwise");
  const std::vector<models::ConvolutionSegment> segs = models::tree_segments(100);
  const Fn tree = density_to_implicit(models::summed_convolution(segs));
  if (wanted("continuation torus")) continuation("continuation torus", implicit_torus(1.0, 0.3), {.cube_size = 0.01, .starts = {{1.3, 0, 0}}}, repeats);
  if (wanted("continuation tree-100")) continuation("continuation tree-100", tree, {.cube_size = 0.04, .starts = {{0.12, 0, 0.5}}}, repeats);
  if (wanted("nonmanifold sphere-square")) regions("nonmanifold sphere-square", test::sphere_square(0.6, 1.0),
          {.cube_size = 0.03, .bounds = {Interval(-1.23, 1.23), Interval(-1.23, 1.23), Interval(-1.23, 1.23)},
           .interest = {{0, 2}, {0, 3}, {2, 3}}},
          repeats);
  const models::SegmentBounds b = models::segment_bounds(segs, 3.0);
  if (wanted("nonmanifold tree-100")) regions("nonmanifold tree-100", {tree, -tree},
          {.cube_size = 0.1, .bounds = {Interval(b.lo[0], b.hi[0]), Interval(b.lo[1], b.hi[1]), Interval(b.lo[2], b.hi[2])}},
          repeats);
  return 0;
}
