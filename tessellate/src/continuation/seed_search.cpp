#include "continuation/seed_search.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace genmod::continuation {

namespace {

using Point = std::array<double, 3>;

// The radical inverse of n in a prime base: the Halton sequence, deterministic and well
// spread, so the search does not depend on a random generator's implementation.
double radical_inverse(std::uint64_t n, std::uint64_t base) {
  double result = 0.0, scale = 1.0 / static_cast<double>(base);
  for (; n > 0; n /= base, scale /= static_cast<double>(base)) result += static_cast<double>(n % base) * scale;
  return result;
}

Point halton(std::uint64_t n) { return {radical_inverse(n, 2), radical_inverse(n, 3), radical_inverse(n, 5)}; }

// Bisects between a and b (on opposite sides) until the bracket is below
// cube_size * 2^-bisections; returns its midpoint.
Point converge(Evaluator& f, Point a, Point b, bool a_inside, double cube_size, int bisections) {
  const double length = std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
  int steps = bisections;
  if (length > cube_size) steps += static_cast<int>(std::ceil(std::log2(length / cube_size)));
  Point in = a_inside ? a : b, out = a_inside ? b : a;
  for (int s = 0; s < steps; ++s) {
    const Point m{0.5 * (in[0] + out[0]), 0.5 * (in[1] + out[1]), 0.5 * (in[2] + out[2])};
    const double v = f.eval(std::span<const Point>(&m, 1))[0];
    (is_inside(v) ? in : out) = m;
  }
  return {0.5 * (in[0] + out[0]), 0.5 * (in[1] + out[1]), 0.5 * (in[2] + out[2])};
}

const char* side_name(double v) { return std::isnan(v) ? "not a number (outside)" : v < 0.0 ? "negative (inside)" : "non-negative (outside)"; }

}  // namespace

std::span<const double> Evaluator::eval(std::span<const std::array<double, 3>> points) {
  const std::size_t n = points.size();
  out_.resize(n);
  if (n == 0) return {};
  // The points are read in place: coordinate k of point p is points[p][k], a stride of 3.
  static_assert(sizeof(std::array<double, 3>) == 3 * sizeof(double));
  const double* inputs[3] = {&points[0][0], &points[0][1], &points[0][2]};
  double* outputs[1] = {out_.data()};
  batch_.eval(f_, inputs, n, outputs, 3, 1);
  count += n;
  return {out_.data(), n};
}

Point search_around(Evaluator& f, const Point& start, double radius, int samples, double cube_size, int bisections) {
  const double v0 = f.eval(std::span<const Point>(&start, 1))[0];
  const bool inside = is_inside(v0);
  const double w0 = 0.5 * cube_size;
  const double growth = samples > 1 ? std::pow(radius / w0, 1.0 / (samples - 1)) : 1.0;
  std::vector<Point> chunk;
  double w = w0;
  for (int first = 0; first < samples; first += static_cast<int>(BatchEvaluator::kChunk)) {
    const int n = std::min<int>(samples - first, static_cast<int>(BatchEvaluator::kChunk));
    chunk.resize(n);
    for (int m = 0; m < n; ++m) {
      const Point h = halton(static_cast<std::uint64_t>(first + m) + 1);
      const double half = samples > 1 ? std::min(radius, w) : radius;
      for (int k = 0; k < 3; ++k) chunk[m][k] = start[k] + half * (2.0 * h[k] - 1.0);
      w *= growth;
    }
    const std::span<const double> v = f.eval(chunk);
    for (int m = 0; m < n; ++m)
      if (is_inside(v[m]) != inside) return converge(f, start, chunk[m], inside, cube_size, bisections);
  }
  std::ostringstream msg;
  msg.precision(17);
  msg << "genmod: polygonize_continuation: the start point (" << start[0] << ", " << start[1] << ", " << start[2]
      << ") is not near the surface: f is " << side_name(v0) << " there and on the same side at all " << samples
      << " samples within " << radius << " of it (search_radius)";
  throw std::runtime_error(msg.str());
}

Point search_box(Evaluator& f, const Box3& box, int samples, double cube_size, int bisections) {
  std::vector<Point> chunk;
  bool have[2] = {false, false};
  Point found[2];
  double first_value = 0.0;
  for (int first = 0; first < samples; first += static_cast<int>(BatchEvaluator::kChunk)) {
    const int n = std::min<int>(samples - first, static_cast<int>(BatchEvaluator::kChunk));
    chunk.resize(n);
    for (int m = 0; m < n; ++m) {
      // Sample 0 is the box centre, then the Halton points.
      const Point h = first + m == 0 ? Point{0.5, 0.5, 0.5} : halton(static_cast<std::uint64_t>(first + m));
      for (int k = 0; k < 3; ++k) chunk[m][k] = box[k].lo() + h[k] * (box[k].hi() - box[k].lo());
    }
    const std::span<const double> v = f.eval(chunk);
    if (first == 0) first_value = v[0];
    for (int m = 0; m < n; ++m) {
      const int side = is_inside(v[m]) ? 1 : 0;
      if (!have[side]) {
        have[side] = true;
        found[side] = chunk[m];
      }
      if (have[0] && have[1]) return converge(f, found[1], found[0], true, cube_size, bisections);
    }
  }
  std::ostringstream msg;
  msg << "genmod: polygonize_continuation: no start point was given and the surface was not found in the bounds: f is "
      << side_name(first_value) << " at the box centre and on the same side at all " << samples << " samples";
  throw std::runtime_error(msg.str());
}

}  // namespace genmod::continuation
