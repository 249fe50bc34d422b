// hair_clearance.hpp: over all pairs of hairs, a bounding-sphere rejection, then the
// untapered capsules (closest points of two segments: Ericson, Real-Time Collision Detection
// 5.1.9), then the tapered hulls' convex clearance by nested golden-section searches.
#include "hair_clearance.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace genmod::models::detail {

namespace {
using Vec = std::array<double, 3>;
Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
}  // namespace

double segment_distance(const Vec& p0, const Vec& p1, const Vec& q0, const Vec& q1) {
  const Vec d1 = sub(p1, p0), d2 = sub(q1, q0), r = sub(p0, q0);
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double s = 0.0, t = 0.0;
  if (a == 0.0 && e == 0.0) {
    // Two points.
  } else if (a == 0.0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = dot(d1, r);
    if (e == 0.0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = dot(d1, d2), denom = a * e - b * b;
      // Parallel segments (denom 0): any s works; take 0 and clamp t from it.
      s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  Vec gap;
  for (int k = 0; k < 3; ++k) gap[k] = (p0[k] + s * d1[k]) - (q0[k] + t * d2[k]);
  return std::sqrt(dot(gap, gap));
}

namespace {

// The minimum of a convex function on [0, 1] (golden-section search to 1e-9, endpoints
// compared too since the minimum may be at one).
template <class F>
std::pair<double, double> minimize_convex(F&& f) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = 0.0, hi = 1.0, x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = f(x1), f2 = f(x2);
  while (hi - lo > 1e-9) {
    if (f1 <= f2) {
      hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = f(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = f(x2);
    }
  }
  std::pair<double, double> best{x1, f1};
  for (double x : {0.0, 1.0, 0.5 * (lo + hi)}) {
    const double fx = f(x);
    if (fx < best.second) best = {x, fx};
  }
  return best;
}

Vec along(const HairCapsule& h, double s) {
  Vec p;
  for (int k = 0; k < 3; ++k) p[k] = h.base[k] + s * (h.tip[k] - h.base[k]);
  return p;
}

// min over (s, t) of |P(s) - Q(t)| - (1 - s^2) r_P - (1 - t^2) r_Q: as an overlap when <= 0.
std::optional<HairOverlap> tapered_overlap(const HairCapsule& p, const HairCapsule& q, std::size_t i, std::size_t j) {
  auto gap = [&](double s, double t) {
    const Vec d = sub(along(p, s), along(q, t));
    return std::sqrt(dot(d, d));
  };
  auto radii = [&](double s, double t) { return (1.0 - s * s) * p.radius + (1.0 - t * t) * q.radius; };
  // The inner minimum over t of a jointly convex function is convex in s.
  auto inner = [&](double s) { return minimize_convex([&](double t) { return gap(s, t) - radii(s, t); }); };
  const auto [s, clearance] = minimize_convex([&](double u) { return inner(u).second; });
  if (clearance > 0.0) return std::nullopt;
  const double t = inner(s).first;
  return HairOverlap{i, j, gap(s, t), radii(s, t)};
}

}  // namespace

std::optional<HairOverlap> deepest_hair_overlap(const std::vector<HairCapsule>& hairs) {
  // Bounding spheres: the segment's midpoint and half its length plus the radius.
  std::vector<Vec> centre(hairs.size());
  std::vector<double> reach(hairs.size());
  for (std::size_t i = 0; i < hairs.size(); ++i) {
    const HairCapsule& h = hairs[i];
    for (int k = 0; k < 3; ++k) centre[i][k] = 0.5 * (h.base[k] + h.tip[k]);
    const Vec d = sub(h.tip, h.base);
    reach[i] = 0.5 * std::sqrt(dot(d, d)) + h.radius;
  }
  std::optional<HairOverlap> deepest;
  for (std::size_t i = 0; i < hairs.size(); ++i)
    for (std::size_t j = i + 1; j < hairs.size(); ++j) {
      const Vec c = sub(centre[i], centre[j]);
      // 1e-9: the sphere test must not drop a touching pair to rounding.
      if (dot(c, c) > (reach[i] + reach[j]) * (reach[i] + reach[j]) * (1.0 + 1e-9)) continue;
      // The untapered capsules hold the tapered hulls: apart, so are they.
      const double d = segment_distance(hairs[i].base, hairs[i].tip, hairs[j].base, hairs[j].tip);
      if (d > hairs[i].radius + hairs[j].radius) continue;
      const std::optional<HairOverlap> o = tapered_overlap(hairs[i], hairs[j], i, j);
      if (o && (!deepest || o->distance - o->radii < deepest->distance - deepest->radii)) deepest = o;
    }
  return deepest;
}

}  // namespace genmod::models::detail
