#include "genmod/procedural/bezier_curve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace genmod {

BezierCurve::BezierCurve(std::vector<Vec3> control_points) : points_(std::move(control_points)) {
  if (points_.size() < 2)
    throw std::invalid_argument("BezierCurve: needs at least 2 control points, got " + std::to_string(points_.size()));
  for (std::size_t i = 0; i < points_.size(); ++i)
    for (int a = 0; a < 3; ++a)
      if (!std::isfinite(points_[i][a]))
        throw std::invalid_argument("BezierCurve: control point " + std::to_string(i) + " is not finite");
}

Vec3 BezierCurve::evaluate(double t) const {
  std::vector<Vec3> p = points_;
  for (std::size_t level = p.size() - 1; level > 0; --level)
    for (std::size_t i = 0; i < level; ++i) p[i] = p[i] * (1.0 - t) + p[i + 1] * t;
  return p[0];
}

namespace {

// de Casteljau on scalar Bernstein coefficients.
double bernstein_value(std::vector<double> c, double t) {
  for (std::size_t level = c.size() - 1; level > 0; --level)
    for (std::size_t i = 0; i < level; ++i) c[i] = c[i] * (1.0 - t) + c[i + 1] * t;
  return c[0];
}

// Splits coefficients over a piece at its middle into the two halves' coefficients (left and
// right have c's size).
void split_half(const std::vector<double>& c, std::vector<double>& left, std::vector<double>& right) {
  std::vector<double> work = c;
  const std::size_t n = c.size();
  for (std::size_t level = 0; level < n; ++level) {
    left[level] = work[0];
    right[n - 1 - level] = work[n - 1 - level];
    for (std::size_t i = 0; i + 1 < n - level; ++i) work[i] = 0.5 * (work[i] + work[i + 1]);
  }
}

bool one_sign(const std::vector<double>& c) {
  const bool all_positive = std::all_of(c.begin(), c.end(), [](double x) { return x > 0.0; });
  const bool all_negative = std::all_of(c.begin(), c.end(), [](double x) { return x < 0.0; });
  return all_positive || all_negative;
}

// Bisection of a sign change of g on [a, b] down to adjacent doubles (deterministic).
double refine_root(const std::vector<double>& g, double a, double b) {
  double ga = bernstein_value(g, a);
  if (ga == 0.0) return a;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double m = 0.5 * (a + b);
    if (m <= a || m >= b) break;
    const double gm = bernstein_value(g, m);
    if (gm == 0.0) return m;
    if ((gm < 0.0) == (ga < 0.0)) {
      a = m;
      ga = gm;
    } else {
      b = m;
    }
  }
  return std::abs(ga) <= std::abs(bernstein_value(g, b)) ? a : b;
}

bool nearer(const LineCurveHit& x, const LineCurveHit& y) {
  if (std::abs(x.s) != std::abs(y.s)) return std::abs(x.s) < std::abs(y.s);
  if ((x.s >= 0.0) != (y.s >= 0.0)) return x.s >= 0.0;
  return x.t < y.t;
}

constexpr double kRelativeTolerance = 1e-12;
constexpr int kMaxDepth = 30;
constexpr std::size_t kMaxPieces = 1u << 16;  // guards a near-degenerate curve, never reached in practice

}  // namespace

std::optional<LineCurveHit> intersect_line(const BezierCurve& curve, const Vec3& origin, const Vec3& direction,
                                           const Vec3& normal) {
  const Vec3 across = OpenMesh::cross(normal, direction);
  const auto& points = curve.control_points();
  std::vector<double> g(points.size()), s(points.size());
  double size = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 offset = points[i] - origin;
    g[i] = OpenMesh::dot(offset, across);
    s[i] = OpenMesh::dot(offset, direction);
    size = std::max({size, std::abs(g[i]), std::abs(s[i])});
  }
  const double tolerance = kRelativeTolerance * size;
  std::optional<LineCurveHit> best;
  auto offer = [&](double t) {
    LineCurveHit hit{bernstein_value(s, t), t};
    if (!best || nearer(hit, *best)) best = hit;
  };

  if (std::all_of(g.begin(), g.end(), [&](double x) { return std::abs(x) <= tolerance; })) {
    // The curve lies along the line: the nearest curve point along it, or the origin itself.
    const int samples = 64 * curve.degree() + 1;
    double previous = 0.0;
    for (int k = 0; k < samples; ++k) {
      const double t = static_cast<double>(k) / (samples - 1);
      const double sk = bernstein_value(s, t);
      if (k > 0 && (sk == 0.0 || (sk < 0.0) != (previous < 0.0))) offer(refine_root(s, t - 1.0 / (samples - 1), t));
      offer(t);
      previous = sk;
    }
    return best;
  }

  struct Piece {
    double a, b;
    int depth;
    std::vector<double> coefficients;
  };
  std::vector<Piece> stack{{0.0, 1.0, 0, g}};
  std::size_t visited = 0;
  while (!stack.empty()) {
    Piece piece = std::move(stack.back());
    stack.pop_back();
    if (one_sign(piece.coefficients)) continue;
    if (piece.depth < kMaxDepth && ++visited < kMaxPieces) {
      std::vector<double> left(piece.coefficients.size()), right(piece.coefficients.size());
      split_half(piece.coefficients, left, right);
      const double m = 0.5 * (piece.a + piece.b);
      // Right first, so the left half is examined first (the order does not change the result).
      stack.push_back({m, piece.b, piece.depth + 1, std::move(right)});
      stack.push_back({piece.a, m, piece.depth + 1, std::move(left)});
      continue;
    }
    const double ga = bernstein_value(g, piece.a), gb = bernstein_value(g, piece.b);
    if (ga == 0.0 || gb == 0.0 || (ga < 0.0) != (gb < 0.0)) {
      offer(refine_root(g, piece.a, piece.b));
    } else {
      const double m = 0.5 * (piece.a + piece.b);
      const double gm = bernstein_value(g, m);
      const double t = std::abs(gm) < std::min(std::abs(ga), std::abs(gb)) ? m : (std::abs(ga) <= std::abs(gb) ? piece.a : piece.b);
      if (std::abs(bernstein_value(g, t)) <= tolerance) offer(t);
    }
  }
  return best;
}

}  // namespace genmod
