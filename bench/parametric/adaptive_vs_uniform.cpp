// Adaptive kd-tree meshes against uniform lattices at equal certified error, on every gallery
// model, in one run (genmod_parametric_bench [relative tolerance, default 1e-3] [model ...]:
// the models named, or the whole gallery).
//
// For each model at its defaults, with tolerance = rel x the model's extent:
//  - adaptive: mesh_adaptive's triangles, CPU time (median of 3) and certified bound;
//  - uniform: the same mesher forced to a uniform 2^k x 2^k kd-tree (a lattice with the same
//    certified per-cell bound), for the smallest k whose bound meets the tolerance; its
//    triangle count is reported as measured, and also scaled to the exact n x n lattice that
//    the quadratic convergence of the bound predicts (n = 2^k sqrt(bound_k / tol)), which is
//    the fair count (a power of two overshoots by up to 4x).
// Ratios are uniform / adaptive. Time is process CPU time (the machine is shared).
#include "genmod/models/gallery.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

namespace {

using namespace genmod;

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

struct Run {
  AdaptiveMesh mesh;
  double cpu = 0.0;
};

Run timed(const std::vector<SurfacePatch>& patches, const AdaptiveMeshOptions& o, int repeats) {
  std::vector<double> times;
  Run r;
  for (int i = 0; i < repeats; ++i) {
    const double t0 = cpu_seconds();
    r.mesh = mesh_adaptive(patches, o);
    times.push_back(cpu_seconds() - t0);
  }
  std::sort(times.begin(), times.end());
  r.cpu = times[times.size() / 2];
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const double rel = argc > 1 ? std::atof(argv[1]) : 1e-3;
  if (!(rel > 0)) {
    std::fprintf(stderr, "usage: genmod_parametric_bench [relative tolerance > 0] [model ...]\n");
    return 2;
  }
  const std::vector<std::string> only(argv + std::min(argc, 2), argv + argc);
  std::printf("%-24s %10s %9s %9s %12s %12s %8s %8s %9s\n", "model", "tolerance", "adaptive", "cpu s", "uniform 2^k",
              "uniform fit", "ratio", "cpu s", "cpu ratio");
  double log_ratio_sum = 0.0, ratio_sum = 0.0;
  int count = 0;
  for (const models::Model& model : models::gallery()) {
    if (!only.empty() && std::find(only.begin(), only.end(), model.name) == only.end()) continue;
    const models::ParameterValues params = models::resolve_parameters(model);
    const Fn surface = model.build(params);
    const std::vector<SurfacePatch> patches = models::model_patches(model, surface, params);
    const double tol = rel * models::model_extent(model, surface, params);
    // 120 s: the slowest model (bottle, whose every point inverts a curve) needs about 30 s.
    AdaptiveMeshOptions adaptive_options{.tolerance = tol, .max_leaves = 2'000'000, .max_seconds = 120, .threads = 1};
    const Run adaptive = timed(patches, adaptive_options, 3);
    if (!adaptive.mesh.limits_hit.empty() || !std::isfinite(adaptive.mesh.distance_bound)) {
      std::printf("%-24s %10.3g  adaptive stopped at a limit (%s), bound %g: not compared\n", model.name.c_str(), tol,
                  adaptive.mesh.limits_hit.empty() ? "unbounded leaves" : adaptive.mesh.limits_hit.front().c_str(),
                  adaptive.mesh.distance_bound);
      continue;
    }
    // Uniform: split every leaf until it is 2^-k of the domain on both axes.
    Run uniform;
    int k = 2;
    for (; k <= 11; ++k) {
      AdaptiveMeshOptions o{.tolerance = 1e300, .max_depth = k, .max_leaves = 8'000'000, .max_seconds = 20, .threads = 1};
      const double side = std::ldexp(1.0, -k);
      o.refine = [&patches, side](std::size_t p, const Interval& u, const Interval& v) {
        return (u.hi() - u.lo()) > side * (patches[p].u.hi() - patches[p].u.lo()) * 1.0000001 ||
               (v.hi() - v.lo()) > side * (patches[p].v.hi() - patches[p].v.lo()) * 1.0000001;
      };
      uniform = timed(patches, o, 1);
      if (uniform.mesh.distance_bound <= tol) break;
    }
    const double measured = static_cast<double>(uniform.mesh.mesh.triangles.size());
    const double fit = uniform.mesh.distance_bound <= tol && std::isfinite(uniform.mesh.distance_bound)
                           ? measured * std::max(uniform.mesh.distance_bound / tol, 0.25)
                           : measured;
    const double adaptive_tris = static_cast<double>(std::max<std::size_t>(adaptive.mesh.mesh.triangles.size(), 1));
    const double ratio = fit / adaptive_tris;
    std::printf("%-24s %10.3g %9zu %9.3f %12.0f %12.0f %8.2f %8.3f %9.2f%s\n", model.name.c_str(), tol,
                adaptive.mesh.mesh.triangles.size(), adaptive.cpu, measured, fit, ratio, uniform.cpu,
                uniform.cpu / std::max(adaptive.cpu, 1e-9),
                uniform.mesh.distance_bound <= tol ? "" : "  (uniform did not reach the tolerance at 2^11)");
    log_ratio_sum += std::log(ratio);
    ratio_sum += ratio;
    ++count;
  }
  std::printf("triangle ratio uniform/adaptive over %d models: mean %.2f, geometric mean %.2f\n", count,
              ratio_sum / count, std::exp(log_ratio_sum / count));
  return 0;
}
