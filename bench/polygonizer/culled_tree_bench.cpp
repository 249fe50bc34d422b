// Meshing a tree-like skeleton of many Gaussian convolution segments (Bloomenthal §1.4,
// §10.2; issue 11): interval culling against the plain sum, in one run:
//   genmod_culled_tree_bench [--counts 1000,10000] [--h 0.08] [--repeats N] [--full-limit N]
//                            [--kernel bspline|wyvill|gaussian]
//
// The kernel is the cubic B-spline by default (compact support: the culled field culls the
// gradient and Hessian tapes too). With the Gaussian the value and gradient are culled with
// the tail bounds of culled_field_bounds.cpp, and the Hessian (the mesher's gradient mean
// value form) too, as the segments have constant radii; the extra row culled-noH is the same
// culled field with cull_second_derivatives = false (Hessian tape paying every segment, as
// before that culling), timed as the culled mesher is, so its ratio is the Hessian culling's
// gain.
//
// The skeleton is models::tree_segments(count) (binary branching, 35 degree turns, length 1
// and radius 0.12 shrinking by 0.97 per generation). The solid is 1/2 - D < 0. For each count,
// at equal cell size h (every mesher's cells have edge h: the octree box is a cube of side
// 2^k h and min_feature = max_cell = h, the continuation cube_size is h):
//  - culled: mesh_implicit on the culled field (culled_field.hpp: per-box culling of the
//    segments far from an octree cell, inside one custom operator; the mesher also prunes
//    the tape per cell);
//  - plain: mesh_implicit on the plain sum of all segment convolutions (no culling; interval
//    arithmetic cannot drop a term of a sum, so every evaluation pays every segment);
//  - every (sub-box only, with --every): mesh_implicit on the same culled-field operator with
//    every element declared Falloff::none, so that every box and point evaluates every
//    element: the culled mesher without culling, without the plain sum's huge derivative tapes;
//  - continuation: Bloomenthal's continuation polygonizer (tetrahedra) on the plain sum,
//    from a start on the trunk (its point evaluations pay every segment either way).
// Each is timed (process CPU time, one thread; the culled mesher the median of --repeats, the
// baselines once) on the full box when the count is at most --full-limit (default 100; the
// culled mesher up to --culled-full-limit, default 1000), and always on a sub-box: the cube of
// side 2^m h >= --sub-side (default 1.5) centred on the trunk at (0, 0, 0.5), so the
// baselines stay affordable at 10,000 segments. The ratios divide
// each baseline's CPU time by the culled time on the same box in the same run. When a
// baseline is not run on the full box, its full-box time is extrapolated as (its sub-box
// time) x (culled surface cells, full box) / (culled surface cells, sub-box): the baselines'
// cost is per cell and per segment, and the number of segments is the same in both boxes.
// Every mesh is validated outside the timing. Above --plain-limit (default 1000) the plain
// mesher is not run: compiling the plain sum's symbolic Hessian for mesh_implicit took more
// than the machine's 23 GB at 10,000 segments.
#include "genmod/models/bloomenthal_models.hpp"
#include "genmod/operators/convolution.hpp"
#include "genmod/tessellate/continuation_polygonizer.hpp"
#include "genmod/tessellate/implicit_mesher.hpp"
#include "genmod/tessellate/validate.hpp"

#include "../cpu_time.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

namespace {

using namespace genmod;

using bench::cpu_seconds;
using bench::median_cpu;

// The cube of side 2^k h (the smallest >= side) centred at c.
Box3 lattice_cube(const std::array<double, 3>& c, double side, double h) {
  const double s = h * std::exp2(std::ceil(std::log2(side / h)));
  return {Interval(c[0] - s / 2, c[0] + s / 2), Interval(c[1] - s / 2, c[1] + s / 2), Interval(c[2] - s / 2, c[2] + s / 2)};
}

struct Row {
  double cpu = 0;
  std::size_t triangles = 0, cells = 0;
  double tape = 0;
  bool valid = false;
  bool cut = false;  // the continuation stopped at the box (its mesh is open there)
};

Row run_mesher(const ImplicitSurface& s, const Box3& box, double h, int repeats) {
  ImplicitMesh m;
  const ImplicitMeshSettings settings{.min_feature = h, .max_cell = h, .threads = 1};
  Row r;
  r.cpu = median_cpu(repeats, [&] { m = mesh_implicit(s, box, settings); });
  r.triangles = m.mesh.triangles.size();
  r.cells = m.stats.surface_cells;
  r.tape = m.stats.mean_tape_length;
  r.valid = validate(m.mesh).valid();
  return r;
}

Row run_continuation(const Tape& t, const Box3& box, const std::array<double, 3>& start, double h, int repeats) {
  ContinuationMesh m;
  ContinuationSettings settings;
  settings.cube_size = h;
  settings.starts = {start};
  settings.bounds = box;
  Row r;
  r.cpu = median_cpu(repeats, [&] { m = polygonize_continuation(t, settings); });
  r.triangles = m.mesh.triangles.size();
  r.cells = m.stats.cubes;
  r.cut = std::find(m.stats.limits_hit.begin(), m.stats.limits_hit.end(), "bounds") != m.stats.limits_hit.end();
  const MeshValidity v = validate(m.mesh);
  r.valid = r.cut ? v.manifold() : v.closed() && v.manifold();
  return r;
}

void print(const char* count_box, const char* method, const Row& r, double culled_cpu) {
  std::printf("%-16s %-13s %9.3f %8.1fx %10zu %9zu %8.1f %s\n", count_box, method, r.cpu, r.cpu / culled_cpu, r.triangles,
              r.cells, r.tape, r.valid ? (r.cut ? "yes (cut at box)" : "yes") : "NO");
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> counts{1000, 10000};
  double h = 0.08;
  int repeats = 3, full_limit = 100, culled_full_limit = 1000;
  double sub_side = 1.5;
  int plain_limit = 1000;
  bool every = false;
  Kernel kernel = Kernel::bspline;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--counts") {
      counts.clear();
      for (char* p = std::strtok(argv[i + 1], ","); p; p = std::strtok(nullptr, ",")) counts.push_back(std::atoi(p));
    } else if (a == "--h") {
      h = std::atof(argv[i + 1]);
    } else if (a == "--repeats") {
      repeats = std::max(1, std::atoi(argv[i + 1]));
    } else if (a == "--kernel") {
      const std::string k = argv[i + 1];
      kernel = k == "gaussian" ? Kernel::gaussian : k == "wyvill" ? Kernel::wyvill : Kernel::bspline;
    } else if (a == "--sub-side") {
      sub_side = std::atof(argv[i + 1]);
    } else if (a == "--plain-limit") {
      plain_limit = std::atoi(argv[i + 1]);
    } else if (a == "--culled-full-limit") {
      culled_full_limit = std::atoi(argv[i + 1]);
    } else if (a == "--every") {
      every = std::atoi(argv[i + 1]) != 0;
    } else if (a == "--full-limit") {
      full_limit = std::atoi(argv[i + 1]);
    } else {
      std::fprintf(stderr, "usage: %s [--counts 1000,10000] [--h 0.08] [--repeats N] [--full-limit N] [--culled-full-limit N] [--plain-limit N] [--sub-side S] [--every 0|1] [--kernel bspline|wyvill|gaussian]\n", argv[0]);
      return 2;
    }
  }
  std::printf("culled tree: %s kernel, cell size h = %g, one thread, CPU seconds (median of %d); ratio = CPU / culled CPU on the same box\n",
              kernel == Kernel::gaussian ? "gaussian" : kernel == Kernel::wyvill ? "wyvill" : "bspline", h, repeats);
  std::printf("%-16s %-13s %9s %9s %10s %9s %8s %s\n", "count/box", "method", "cpu_s", "ratio", "triangles", "cells",
              "tape", "valid");
  for (const int n : counts) {
    const std::vector<models::ConvolutionSegment> segs = models::tree_segments(n);
    const models::SegmentBounds b = models::segment_bounds(segs, 3.0);
    const std::array<double, 3> centre{(b.lo[0] + b.hi[0]) / 2, (b.lo[1] + b.hi[1]) / 2, (b.lo[2] + b.hi[2]) / 2};
    const double side = std::max({b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]});
    const Box3 full = lattice_cube(centre, side, h);
    const Box3 sub = lattice_cube({0.0, 0.0, 0.5}, sub_side, h);
    const std::array<double, 3> start{0.12, 0.0, 0.5};  // on the trunk's surface (radius 0.12)

    const Fn culled_d = models::culled_convolution(segs, kernel), plain_d = models::summed_convolution(segs, kernel);
    const ImplicitSurface culled(density_to_implicit(culled_d));
    const bool gaussian = kernel == Kernel::gaussian;
    const ImplicitSurface culled_no_h(density_to_implicit(
        gaussian ? culled_field(models::convolution_elements(segs, kernel), {.cull_second_derivatives = false}) : culled_d));
    // The plain sum's symbolic gradient and Hessian tapes grow with the count (at 10,000
    // segments they did not fit in 23 GB): above --plain-limit the plain mesher is skipped.
    const bool run_plain = n <= plain_limit;
    const ImplicitSurface plain(run_plain ? density_to_implicit(plain_d) : density_to_implicit(segment_convolution(segs[0].a, segs[0].b, segs[0].r1)));
    const Tape plain_tape(density_to_implicit(plain_d));

    const std::string tag_full = std::to_string(n) + " full", tag_sub = std::to_string(n) + " sub";
    Row cf;
    if (n <= culled_full_limit) {
      cf = run_mesher(culled, full, h, repeats);
      print(tag_full.c_str(), "culled", cf, cf.cpu);
      if (gaussian) print(tag_full.c_str(), "culled-noH", run_mesher(culled_no_h, full, h, repeats), cf.cpu);
    }
    if (n <= full_limit) {
      const Row pf = run_mesher(plain, full, h, 1);
      print(tag_full.c_str(), "plain", pf, cf.cpu);
      const Row kf = run_continuation(plain_tape, full, start, h, 1);
      print(tag_full.c_str(), "continuation", kf, cf.cpu);
    }
    const Row cs = run_mesher(culled, sub, h, repeats);
    print(tag_sub.c_str(), "culled", cs, cs.cpu);
    if (gaussian) print(tag_sub.c_str(), "culled-noH", run_mesher(culled_no_h, sub, h, repeats), cs.cpu);
    Row ps;
    if (run_plain) {
      ps = run_mesher(plain, sub, h, 1);
      print(tag_sub.c_str(), "plain", ps, cs.cpu);
    } else {
      std::printf("%-16s %-13s skipped (count > --plain-limit %d)\n", tag_sub.c_str(), "plain", plain_limit);
    }
    if (every) {
      std::vector<FieldElement> es = models::convolution_elements(segs, kernel);
      for (FieldElement& e : es) e.falloff = Falloff::none;
      const ImplicitSurface all(density_to_implicit(culled_field(es)));
      print(tag_sub.c_str(), "every", run_mesher(all, sub, h, 1), cs.cpu);
    }
    const Row ks = run_continuation(plain_tape, sub, start, h, 1);
    print(tag_sub.c_str(), "continuation", ks, cs.cpu);
    if (n > full_limit && n <= culled_full_limit && run_plain) {
      const double scale = static_cast<double>(cf.cells) / static_cast<double>(cs.cells);
      std::printf("%-16s extrapolated: plain %.1f s (%.1fx culled), continuation %.1f s (%.1fx), cell ratio %.1f\n",
                  tag_full.c_str(), ps.cpu * scale, ps.cpu * scale / cf.cpu, ks.cpu * scale, ks.cpu * scale / cf.cpu, scale);
    }
    std::fflush(stdout);
  }
  return 0;
}
