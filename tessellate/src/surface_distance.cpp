// Distance of a mesh from the surface f = 0 (validate.hpp, SurfaceDistance).
#include "validate_internal.hpp"

#include "genmod/kernel/gradient_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace genmod::validation {
namespace {

struct Result {
  double bound = -1.0;     // certified upper bound, < 0 when none was found
  double estimate = 0.0;   // |f| / |grad f|
};

struct Evaluators {
  PointEvaluator point;
  GradientEvaluator gradient;
};

// The distance from p to the first sign change of f found on the ray p + t dir (dir a unit
// vector), trying steps slightly past `estimate` and then growing geometrically up to
// `search_radius`, bisected once found; < 0 when there is none.
double sign_change_along(const Tape& tape, PointEvaluator& point, const std::array<double, 3>& p, double f,
                         const double dir[3], double estimate, double search_radius) {
  static constexpr double kFactors[] = {1.0 + 1e-9, 1.0 + 1e-6, 1.001, 1.01, 1.05, 1.1, 1.2, 1.35, 1.5, 1.75,
                                        2.0,         2.5,         3.0,   4.0,  5.0,  6.5, 8.0, 10.0, 13.0};
  auto flips = [&](double t) {
    const double q[3] = {p[0] + t * dir[0], p[1] + t * dir[1], p[2] + t * dir[2]};
    const double fq = point.eval(tape, q)[0];
    // An error (NaN) is no sign change: f need not vanish between a value and an error.
    return fq == 0.0 || (!std::isnan(fq) && (fq > 0) != (f > 0));
  };
  double same = 0.0;  // a step with f's sign (0: the point itself)
  for (double factor : kFactors) {
    double t = estimate * factor;
    if (t > search_radius && factor > 1.1) break;
    if (!flips(t)) {
      same = t;
      continue;
    }
    for (int i = 0; i < 12 && t - same > 1e-3 * t; ++i) {
      const double mid = 0.5 * (same + t);
      if (flips(mid)) t = mid;
      else same = mid;
    }
    // |q - p| as evaluated (dir is a unit vector up to rounding).
    const double q[3] = {p[0] + t * dir[0], p[1] + t * dir[1], p[2] + t * dir[2]};
    const double dx = q[0] - p[0], dy = q[1] - p[1], dz = q[2] - p[2];
    return std::sqrt(dx * dx + dy * dy + dz * dz);
  }
  return -1.0;
}

// The 26 directions of the lattice (axes, face and body diagonals), unit length.
const std::vector<std::array<double, 3>> kLatticeDirections = [] {
  std::vector<std::array<double, 3>> d;
  for (int a = -1; a <= 1; ++a)
    for (int b = -1; b <= 1; ++b)
      for (int c = -1; c <= 1; ++c) {
        const double len = std::sqrt(double(a * a + b * b + c * c));
        if (len > 0) d.push_back({a / len, b / len, c / len});
      }
  return d;
}();

// Looks for a sign change of f from p along the descent direction; where that finds none, or
// one farther than the first-order estimate (near a kink of f the gradient can point away
// from the nearest surface, and across a crease the nearest surface point is off the
// gradient), also along the 26 lattice directions, keeping the nearest.
Result distance_at(const Tape& tape, Evaluators& ev, const std::array<double, 3>& p, double search_radius) {
  Result r;
  ev.gradient.eval(tape, p);
  const double f = ev.gradient.values()[0];
  const auto g = ev.gradient.jacobian();
  if (f == 0.0) {
    r.bound = 0.0;
    return r;
  }
  const double gn = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  if (!std::isfinite(f) || !std::isfinite(gn) || gn == 0.0) {
    r.estimate = std::numeric_limits<double>::infinity();
    return r;
  }
  r.estimate = std::fabs(f) / gn;
  const double s = f > 0 ? -1.0 / gn : 1.0 / gn;
  const double descent[3] = {s * g[0], s * g[1], s * g[2]};
  r.bound = sign_change_along(tape, ev.point, p, f, descent, r.estimate, search_radius);
  if (r.bound >= 0 && r.bound <= 1.01 * r.estimate) return r;
  for (const auto& dir : kLatticeDirections) {
    const double radius = r.bound >= 0 ? std::min(search_radius, r.bound) : search_radius;
    const double b = sign_change_along(tape, ev.point, p, f, dir.data(), std::min(r.estimate, radius), radius);
    if (b >= 0 && (r.bound < 0 || b < r.bound)) r.bound = b;
  }
  return r;
}

// Barycentric sample k of `count` inside a triangle: the centroid first, then a Kronecker
// sequence folded into the triangle.
std::array<double, 3> sample_weights(int k) {
  if (k == 0) return {1.0 / 3, 1.0 / 3, 1.0 / 3};
  double u = std::fmod(0.5 + k * 0.7548776662466927, 1.0);
  double v = std::fmod(0.5 + k * 0.5698402909980532, 1.0);
  if (u + v > 1.0) {
    u = 1.0 - u;
    v = 1.0 - v;
  }
  return {1.0 - u - v, u, v};
}

struct Accumulator {
  double max_vertex_bound = 0, max_vertex_estimate = 0, max_face_bound = 0, max_face_estimate = 0;
  double sum_face_estimate = 0;
  std::size_t face_points = 0, uncertified_faces = 0, uncertified_vertices = 0;

  void add(const Result& r, bool vertex) {
    if (r.bound < 0) ++(vertex ? uncertified_vertices : uncertified_faces);
    double& bound = vertex ? max_vertex_bound : max_face_bound;
    double& estimate = vertex ? max_vertex_estimate : max_face_estimate;
    if (r.bound > bound) bound = r.bound;
    if (r.estimate > estimate) estimate = r.estimate;
    if (!vertex) {
      sum_face_estimate += r.estimate;
      ++face_points;
    }
  }
  void join(const Accumulator& o) {
    max_vertex_bound = std::max(max_vertex_bound, o.max_vertex_bound);
    max_vertex_estimate = std::max(max_vertex_estimate, o.max_vertex_estimate);
    max_face_bound = std::max(max_face_bound, o.max_face_bound);
    max_face_estimate = std::max(max_face_estimate, o.max_face_estimate);
    sum_face_estimate += o.sum_face_estimate;
    face_points += o.face_points;
    uncertified_faces += o.uncertified_faces;
    uncertified_vertices += o.uncertified_vertices;
  }
};

}  // namespace

SurfaceDistance measure_surface_distance(const Mesh& mesh, const Tape& surface, int face_samples,
                                         double search_radius, int threads) {
  const std::size_t nv = mesh.vertices.size(), nt = mesh.triangles.size();
  const std::size_t n = nv + nt * static_cast<std::size_t>(face_samples);
  tbb::enumerable_thread_specific<Evaluators> evaluators;
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  // Fixed-size chunks joined in order: the sums are the same for any thread count.
  const Accumulator acc = arena.execute([&] {
    return tbb::parallel_deterministic_reduce(
        tbb::blocked_range<std::size_t>(0, n, 4096), Accumulator{},
        [&](const tbb::blocked_range<std::size_t>& range, Accumulator a) {
          Evaluators& ev = evaluators.local();
          for (std::size_t i = range.begin(); i != range.end(); ++i) {
            if (i < nv) {
              a.add(distance_at(surface, ev, mesh.vertices[i], search_radius), true);
              continue;
            }
            const std::size_t t = (i - nv) / static_cast<std::size_t>(face_samples);
            const int k = static_cast<int>((i - nv) % static_cast<std::size_t>(face_samples));
            const auto w = sample_weights(k);
            const auto& tri = mesh.triangles[t];
            if (tri[0] >= nv || tri[1] >= nv || tri[2] >= nv) continue;  // reported by validate
            std::array<double, 3> p{};
            for (int d = 0; d < 3; ++d)
              p[d] = w[0] * mesh.vertices[tri[0]][d] + w[1] * mesh.vertices[tri[1]][d] +
                     w[2] * mesh.vertices[tri[2]][d];
            a.add(distance_at(surface, ev, p, search_radius), false);
          }
          return a;
        },
        [](Accumulator a, const Accumulator& b) {
          a.join(b);
          return a;
        });
  });
  SurfaceDistance d;
  d.points = n;
  d.max_vertex_bound = acc.max_vertex_bound;
  d.max_vertex_estimate = acc.max_vertex_estimate;
  d.max_face_bound = acc.max_face_bound;
  d.max_face_estimate = acc.max_face_estimate;
  d.mean_face_estimate = acc.face_points ? acc.sum_face_estimate / static_cast<double>(acc.face_points) : 0.0;
  d.uncertified = acc.uncertified_faces + acc.uncertified_vertices;
  d.uncertified_vertices = acc.uncertified_vertices;
  return d;
}

}  // namespace genmod::validation
