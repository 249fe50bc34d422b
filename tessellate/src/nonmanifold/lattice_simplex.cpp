#include "nonmanifold/lattice_simplex.hpp"

#include <algorithm>

namespace genmod::nonmanifold {

LatticeSimplex make_simplex(const std::uint64_t* keys, const SimplexPoint* corners, int size) {
  LatticeSimplex s;
  s.size = std::clamp(size, 0, 4);
  for (std::size_t i = 0; i < static_cast<std::size_t>(s.size); ++i) {  // insertion by key
    std::size_t j = i;
    for (; j > 0 && s.keys[j - 1] > keys[i]; --j) {
      s.keys[j] = s.keys[j - 1];
      s.corners[j] = s.corners[j - 1];
    }
    s.keys[j] = keys[i];
    s.corners[j] = corners[i];
  }
  return s;
}

namespace {

bool has(const LatticeSimplex& s, std::uint64_t key) {
  return std::find(s.keys.begin(), s.keys.begin() + s.size, key) != s.keys.begin() + s.size;
}

// Appends corner i of `from` to `to`; false when `to` is full.
bool append(LatticeSimplex& to, const LatticeSimplex& from, int i) {
  if (to.size == 4) return false;
  to.keys[static_cast<std::size_t>(to.size)] = from.keys[static_cast<std::size_t>(i)];
  to.corners[static_cast<std::size_t>(to.size)] = from.corners[static_cast<std::size_t>(i)];
  ++to.size;
  return true;
}

LatticeSimplex sorted(const LatticeSimplex& s) { return make_simplex(s.keys.data(), s.corners.data(), s.size); }

}  // namespace

bool is_face_of(const LatticeSimplex& inner, const LatticeSimplex& outer) {
  for (int i = 0; i < inner.size; ++i)
    if (!has(outer, inner.keys[static_cast<std::size_t>(i)])) return false;
  return true;
}

LatticeSimplex join(const LatticeSimplex& a, const LatticeSimplex& b) {
  LatticeSimplex u = a;
  for (int i = 0; i < b.size; ++i)
    if (!has(u, b.keys[static_cast<std::size_t>(i)]) && !append(u, b, i)) return {};
  return sorted(u);
}

LatticeSimplex meet(const LatticeSimplex& a, const LatticeSimplex& b) {
  LatticeSimplex m;
  for (int i = 0; i < a.size; ++i)
    if (has(b, a.keys[static_cast<std::size_t>(i)])) append(m, a, i);
  return m;  // a's order is increasing, so is m's
}

SimplexPoint nearest_on(const LatticeSimplex& s, const SimplexPoint& p, LatticeSimplex& holder) {
  holder = s;
  if (s.size == 1) return s.corners[0];
  const SimplexPoint& a = s.corners[0];
  const SimplexPoint& b = s.corners[1];
  const SimplexPoint d{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const double t = ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1] + (p[2] - a[2]) * d[2]) / dd;
  if (!(t > 0.0) || !(t < 1.0)) {  // an end: a corner of its own
    const int end = t >= 1.0 ? 1 : 0;
    holder = make_simplex(&s.keys[static_cast<std::size_t>(end)], &s.corners[static_cast<std::size_t>(end)], 1);
    return s.corners[static_cast<std::size_t>(end)];
  }
  return {a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]};
}

}  // namespace genmod::nonmanifold
