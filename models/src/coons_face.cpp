// Coons patch caps (see coons_face.hpp).
#include "coons_face.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace genmod::models::detail {

namespace {

// edge at the parameter a + (b - a) x(i), wrapped into [0, 1]: an arc may cross u = 1. The
// wrap is a select between the two in-range pieces, not w - floor(w): the edge curve is closed,
// so the arc is continuous there, and each piece's interval bound stays tight (floor's jump
// would make every box around the wrap enclose the whole curve).
Fn edge_arc(const Fn& edge, double a, double b, int i) {
  const Fn w = a + (b - a) * x(i);
  if (std::min(a, b) >= 0.0 && std::max(a, b) <= 1.0) return compose(edge, 0, w);
  return select(w < 1.0, compose(edge, 0, min(w, Fn(1.0))), compose(edge, 0, max(w - 1.0, Fn(0.0))));
}

}  // namespace

Fn coons_face(const Fn& edge, const std::array<double, 4>& k) {
  if (!(k[0] < k[1] && k[1] < k[2] && k[2] < k[3] && k[3] < k[0] + 1.0))
    throw std::invalid_argument("coons_face: the corners must increase within one period");
  const Fn s = x(0), t = x(1);
  const Fn bottom = edge_arc(edge, k[0], k[1], 0), right = edge_arc(edge, k[1], k[2], 1);
  const Fn top = edge_arc(edge, k[3], k[2], 0), left = edge_arc(edge, k[0] + 1.0, k[3], 1);
  auto corner = [&](double u) { return compose(edge, 0, Fn(u - static_cast<double>(u >= 1.0))); };
  const Fn p00 = corner(k[0]), p10 = corner(k[1]), p11 = corner(k[2]), p01 = corner(k[3]);
  const Fn bilinear = (1.0 - s) * (1.0 - t) * p00 + s * (1.0 - t) * p10 + (1.0 - s) * t * p01 + s * t * p11;
  return (1.0 - t) * bottom + t * top + (1.0 - s) * left + s * right - bilinear;
}

Fn coons_face_flipped(const Fn& edge, const std::array<double, 4>& corners) {
  return compose_all(coons_face(edge, corners), std::vector<int>{0, 1}, cat({x(1), x(0)}));
}

}  // namespace genmod::models::detail
