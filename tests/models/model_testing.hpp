// Helpers shared by the model tests (tests/models/*_test.cpp): point evaluation, sample
// parameters, error messages and small vector and polyline geometry.
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/curve.hpp"
#include "genmod/operators/vector.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <initializer_list>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod::models::testing {

// A point of the plane.
using P2 = std::array<double, 2>;

// f at x(0) = u, x(1) = v (v may be left out for a function of x(0) alone).
inline std::vector<double> at(const Fn& f, double u, double v = 0.0) {
  const std::vector<double> point{u, v};
  return evaluate(f, point);
}

// The curve c at parameter t.
inline std::vector<double> at(const Curve& c, double t) {
  const std::vector<double> point{t};
  return evaluate(c(x(0)), point);
}

// Point evaluation of f at values of x(0), x(1), ... (one compiled tape, many points).
class Eval {
 public:
  explicit Eval(const Fn& f) : tape_(f), inputs_(f.inputs()) {}
  std::vector<double> operator()(std::initializer_list<double> coords) {
    const std::vector<double> c(coords);
    std::vector<double> point;
    for (int i : inputs_) point.push_back(c.at(static_cast<std::size_t>(i)));
    const auto y = ev_.eval(tape_, std::span<const double>(point));
    return {y.begin(), y.end()};
  }

 private:
  Tape tape_;
  std::vector<int> inputs_;
  PointEvaluator ev_;
};

// Sample parameters in [0, 1], both ends included.
inline const std::vector<double> kSamples{0.0, 0.013, 0.21, 0.37, 0.5, 0.618, 0.83, 0.97, 1.0};

// Claim 28 for a wire product S of the cross section g(u, v) along the planar wire d(v)
// (both given in (x(0), x(1))), at every pair of kSamples: the section is perpendicular to
// the wire, (S - (d, 0)) . (t, 0) = 0 with t = d'/|d'|; |S_xy - d| = |g1|; S_z = g2.
inline void expect_wire_product(const Fn& surface, const Fn& cross, const Fn& wire) {
  Eval s(surface), g(cross), d(wire), t(normalize(derivative(wire, 1)));
  for (double u : kSamples)
    for (double v : kSamples) {
      const auto S = s({u, v}), G = g({u, v}), D = d({u, v}), T = t({u, v});
      const double dx = S[0] - D[0], dy = S[1] - D[1];
      EXPECT_NEAR(dx * T[0] + dy * T[1], 0.0, 1e-12) << u << ", " << v;
      EXPECT_NEAR(std::hypot(dx, dy), std::abs(G[0]), 1e-12) << u << ", " << v;
      EXPECT_NEAR(S[2], G[1], 1e-15) << u << ", " << v;
    }
}

// The message of the std::invalid_argument that f() throws, or "(no exception)".
template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no exception)";
}

// Dot product of 3-vectors.
inline double dot3(const std::vector<double>& a, const std::vector<double>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
// Length of a 3-vector.
inline double norm3(const std::vector<double>& a) { return std::sqrt(dot3(a, a)); }

// Distance from q to the polyline.
inline double distance(const std::vector<P2>& line, P2 q) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const P2 a = line[i], b = line[i + 1];
    const double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
    const double t = len2 > 0 ? std::clamp(((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(q[0] - a[0] - t * dx, q[1] - a[1] - t * dy));
  }
  return best;
}

// A curve in space: its point at t in [0, 1].
using SpaceCurve = std::function<std::vector<double>(double)>;

// Distance from q to the curve c: the nearest of `samples` + 1 samples, then a golden-section
// search for the minimum of |c(t) - q| around it (accurate to rounding on smooth curves).
inline double distance_to_curve(const SpaceCurve& c, const std::vector<double>& q, int samples = 2048) {
  auto dist = [&](double t) {
    const auto p = c(std::clamp(t, 0.0, 1.0));
    double d2 = 0.0;
    for (std::size_t k = 0; k < q.size(); ++k) d2 += (p[k] - q[k]) * (p[k] - q[k]);
    return std::sqrt(d2);
  };
  int best = 0;
  double best_d = dist(0.0);
  for (int i = 1; i <= samples; ++i)
    if (const double d = dist(static_cast<double>(i) / samples); d < best_d) best_d = d, best = i;
  double a = static_cast<double>(best - 1) / samples, b = static_cast<double>(best + 1) / samples;
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int it = 0; it < 80; ++it) {
    const double c1 = b - g * (b - a), c2 = a + g * (b - a);
    if (dist(c1) < dist(c2)) b = c2;
    else a = c1;
  }
  return std::min(best_d, dist(0.5 * (a + b)));
}

// The four edges of the patch f over [0, 1]^2 (u = 0, u = 1, v = 0, v = 1) as curves; `f`
// must outlive them.
inline std::vector<SpaceCurve> patch_edges(Eval& f) {
  return {[&f](double t) { return f({0.0, t}); }, [&f](double t) { return f({1.0, t}); },
          [&f](double t) { return f({t, 0.0}); }, [&f](double t) { return f({t, 1.0}); }};
}

// The divergence theorem's three volumes of a surface made of patches (u, v) -> S over
// [u0, u1] x [v0, v1]: V_k = sum of the integrals of S_k (S_u x S_v)_k du dv (k = x, y, z),
// by the midpoint rule on n x n cells. For a closed surface oriented outward the three are
// equal (the enclosed volume); a missing face makes them differ.
struct PatchDomain {
  Fn surface;
  double u0 = 0.0, u1 = 1.0, v0 = 0.0, v1 = 1.0;
};
inline std::array<double, 3> flux_volumes(const std::vector<PatchDomain>& patches, int n) {
  std::array<double, 3> vol{0.0, 0.0, 0.0};
  for (const PatchDomain& p : patches) {
    Eval s(p.surface), nrm(cross(derivative(p.surface, 0), derivative(p.surface, 1)));
    const double du = (p.u1 - p.u0) / n, dv = (p.v1 - p.v0) / n;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double u = p.u0 + (i + 0.5) * du, v = p.v0 + (j + 0.5) * dv;
        const auto q = s({u, v}), m = nrm({u, v});
        for (int k = 0; k < 3; ++k) vol[static_cast<std::size_t>(k)] += q[k] * m[k] * du * dv;
      }
  }
  return vol;
}

}  // namespace genmod::models::testing
