// Seams and poles from the declared periodic axes and from samples of every patch edge.
#include "edge_gluing.hpp"

#include "genmod/kernel/point_evaluator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>

namespace genmod::parametric {

GridPoint edge_point(const EdgeRef& e, std::int64_t t) {
  switch (e.side) {
    case 0: return {e.patch, t, 0};
    case 1: return {e.patch, kGridSize, t};
    case 2: return {e.patch, t, kGridSize};
    default: return {e.patch, 0, t};
  }
}

std::int64_t edge_index(int side, const GridPoint& p) { return side == 0 || side == 2 ? p.u : p.v; }

bool on_edge(int side, const GridPoint& p) {
  switch (side) {
    case 0: return p.v == 0;
    case 1: return p.u == kGridSize;
    case 2: return p.v == kGridSize;
    default: return p.u == 0;
  }
}

namespace {

// from_lo + (t - lo) (to_hi - to_lo) / (hi - lo), flipped when reversed, rounded to the grid.
std::int64_t map_range(std::int64_t t, std::int64_t lo, std::int64_t hi, std::int64_t to_lo, std::int64_t to_hi,
                       bool reversed) {
  if (!reversed && lo == to_lo && hi == to_hi) return t;
  if (reversed && lo == 0 && hi == kGridSize && to_lo == 0 && to_hi == kGridSize) return kGridSize - t;
  long double f = static_cast<long double>(t - lo) / static_cast<long double>(hi - lo);
  if (reversed) f = 1.0L - f;
  return to_lo + static_cast<std::int64_t>(std::llround(f * static_cast<long double>(to_hi - to_lo)));
}

}  // namespace

std::int64_t Glue::to_a(std::int64_t t) const { return map_range(t, b_lo, b_hi, a_lo, a_hi, reversed); }
std::int64_t Glue::to_b(std::int64_t t) const { return map_range(t, a_lo, a_hi, b_lo, b_hi, reversed); }

namespace {

constexpr int kSamples = 33;
using Point3 = std::array<double, 3>;

double distance(const Point3& a, const Point3& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

struct EdgeSamples {
  EdgeRef edge;
  std::array<Point3, kSamples> at;
  bool finite = true;
  double chord = 0.0;  // the largest distance between consecutive samples
};

// False when p is farther than two chords from every sample of a: then no point of a's curve
// is near p, as long as the curve between consecutive samples stays within two chords of
// them (locate assumes as much: it searches next to the nearest sample only). This skips the
// golden-section search for edges that are far apart (hundreds of patches: the bear's hairs).
bool may_lie_on(const EdgeSamples& a, const Point3& p, double eps) {
  for (const Point3& q : a.at)
    if (distance(q, p) <= 2.0 * a.chord + eps) return true;
  return false;
}

Point3 eval_edge(const EdgeRef& e, double t, const std::vector<CompiledPatch>& compiled, PointEvaluator& ev) {
  const CompiledPatch& c = compiled[e.patch];
  const bool along_u = e.side == 0 || e.side == 2;
  const double fixed = (e.side == 1 || e.side == 2) ? 1.0 : 0.0;
  const double fu = along_u ? t : fixed, fv = along_u ? fixed : t;
  const double uv[2] = {fu >= 1.0 ? c.u.hi() : c.u.lo() + (c.u.hi() - c.u.lo()) * fu,
                        fv >= 1.0 ? c.v.hi() : c.v.lo() + (c.v.hi() - c.v.lo()) * fv};
  const auto s = ev.eval(c.value, uv);
  return {s[0], s[1], s[2]};
}

// The parameter (fraction of the edge) of a's point nearest to p, if within eps.
std::optional<double> locate(const EdgeSamples& a, const Point3& p, const std::vector<CompiledPatch>& compiled,
                             double eps, PointEvaluator& ev) {
  int best = 0;
  for (int k = 1; k < kSamples; ++k)
    if (distance(a.at[k], p) < distance(a.at[best], p)) best = k;
  // Golden-section search on the two sample intervals around the nearest sample.
  double lo = std::max(0, best - 1) / double(kSamples - 1), hi = std::min(kSamples - 1, best + 1) / double(kSamples - 1);
  auto f = [&](double t) { return distance(eval_edge(a.edge, t, compiled, ev), p); };
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = f(x1), f2 = f(x2);
  for (int it = 0; it < 80 && hi - lo > 1e-15; ++it) {
    if (f1 < f2) {
      hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = f(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = f(x2);
    }
  }
  double t = 0.5 * (lo + hi);
  // Ends of the edge and grid points are preferred when they are as good.
  for (double c : {0.0, 1.0, std::round(t * kGridSize) / kGridSize})
    if (f(c) <= eps) {
      if (c == 0.0 || c == 1.0 || std::abs(c - t) < 1e-9) t = c;
    }
  if (!(f(t) <= eps)) return std::nullopt;
  return t;
}

// True when b's samples at the fractions [b_from, b_to] of b lie on a at the fractions mapped
// linearly onto [a_from, a_to]. The map is checked as found (unrounded): the glue's grid
// rounding moves a mapped point by up to about one grid step, 2^-30 of a's parameter range,
// which on a fast edge (a rim of length L >> extent) is more than the tolerance; that
// rounding is the mesher's to measure (seam deviation), not a reason to refuse the glue.
bool verified(const EdgeSamples& a, const EdgeSamples& b, double b_from, double b_to, double a_from, double a_to,
              const std::vector<CompiledPatch>& compiled, double eps, PointEvaluator& ev) {
  for (int k = 0; k < kSamples; ++k) {
    const double fb = static_cast<double>(k) / (kSamples - 1);
    if (fb < b_from || fb > b_to) continue;
    const double ta = a_from + (fb - b_from) / (b_to - b_from) * (a_to - a_from);
    if (!(distance(eval_edge(a.edge, std::clamp(ta, 0.0, 1.0), compiled, ev), b.at[k]) <= eps)) return false;
  }
  return true;
}

// Edge b glued to a part of edge a (one glue, or two across a's periodic seam), when b's
// samples lie on a at linearly mapped parameters.
std::vector<Glue> match_part(const EdgeSamples& a, bool a_wraps, const EdgeSamples& b,
                             const std::vector<CompiledPatch>& compiled, double eps, PointEvaluator& ev) {
  if (!may_lie_on(a, b.at[0], eps) || !may_lie_on(a, b.at[kSamples - 1], eps)) return {};
  const std::optional<double> start = locate(a, b.at[0], compiled, eps, ev);
  if (!start) return {};
  const std::optional<double> end = locate(a, b.at[kSamples - 1], compiled, eps, ev);
  if (!end || std::abs(*end - *start) < 1e-6) return {};
  const std::int64_t s = std::llround(*start * kGridSize), e = std::llround(*end * kGridSize);
  if (verified(a, b, 0.0, 1.0, *start, *end, compiled, eps, ev))
    return {Glue{a.edge, b.edge, e < s, std::min(s, e), std::max(s, e)}};
  if (!a_wraps) return {};
  // An end of b on a's seam is located at either end of a (whichever the rounding of the
  // samples favours); b may reach the seam from the other side (a cap's piece that starts or
  // ends where a's loop starts).
  auto other_end = [](std::int64_t t) { return t == 0 ? kGridSize : t == kGridSize ? std::int64_t{0} : -1; };
  auto at = [](std::int64_t t, double found) { return t == 0 || t == kGridSize ? static_cast<double>(t) / kGridSize : found; };
  for (const auto& [s2, e2] : {std::pair{other_end(s), e}, std::pair{s, other_end(e)}}) {
    if (s2 < 0 || e2 < 0 || s2 == e2) continue;
    if (verified(a, b, 0.0, 1.0, at(s2, *start), at(e2, *end), compiled, eps, ev))
      return {Glue{a.edge, b.edge, e2 < s2, std::min(s2, e2), std::max(s2, e2)}};
  }
  // The other way round a's loop: through its seam (a at 0 = a at 1), where b is at t.
  const std::optional<double> seam = locate(b, a.at[0], compiled, eps, ev);
  if (!seam) return {};
  const std::int64_t t = std::llround(*seam * kGridSize);
  if (t <= 0 || t >= kGridSize) return {};
  // s > e: b runs up from s to the seam, then up from 0 to e; s < e: down to 0, down from 1.
  const double seam_a_first = s > e ? 1.0 : 0.0;
  if (!verified(a, b, 0.0, *seam, *start, seam_a_first, compiled, eps, ev) ||
      !verified(a, b, *seam, 1.0, 1.0 - seam_a_first, *end, compiled, eps, ev))
    return {};
  Glue first{a.edge, b.edge, s < e, s > e ? s : 0, s > e ? kGridSize : s, 0, t};
  Glue second{a.edge, b.edge, s < e, s > e ? 0 : e, s > e ? e : kGridSize, t, kGridSize};
  return {first, second};
}

}  // namespace

EdgeTopology find_edge_topology(const std::vector<SurfacePatch>& patches, const std::vector<CompiledPatch>& compiled,
                                const AdaptiveMeshOptions& options) {
  EdgeTopology topology;
  std::vector<std::array<bool, 4>> taken(patches.size(), {false, false, false, false});
  for (std::uint32_t p = 0; p < patches.size(); ++p) {
    if (patches[p].periodic_u) {
      topology.glues.push_back({{p, 3}, {p, 1}, false});
      taken[p][1] = taken[p][3] = true;
    }
    if (patches[p].periodic_v) {
      topology.glues.push_back({{p, 0}, {p, 2}, false});
      taken[p][0] = taken[p][2] = true;
    }
  }
  if (!options.glue_edges) return topology;

  // Samples of every free edge, and the extent of all of them for the tolerance.
  PointEvaluator ev;
  std::vector<EdgeSamples> edges;
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (std::uint32_t p = 0; p < patches.size(); ++p)
    for (int side = 0; side < 4; ++side) {
      if (taken[p][side]) continue;
      EdgeSamples e{{p, side}, {}, true};
      for (int k = 0; k < kSamples; ++k) {
        const GridPoint g = edge_point(e.edge, (kGridSize / (kSamples - 1)) * k);
        const double uv[2] = {grid_value(compiled[p].u, g.u), grid_value(compiled[p].v, g.v)};
        const auto s = ev.eval(compiled[p].value, uv);
        for (int j = 0; j < 3; ++j) {
          e.at[k][j] = s[j];
          e.finite = e.finite && std::isfinite(s[j]);
          if (std::isfinite(s[j])) lo[j] = std::min(lo[j], s[j]), hi[j] = std::max(hi[j], s[j]);
        }
      }
      for (int k = 1; k < kSamples; ++k) e.chord = std::max(e.chord, distance(e.at[k - 1], e.at[k]));
      if (e.finite) edges.push_back(e);
    }
  if (edges.empty()) return topology;
  const double extent = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  const double eps = options.glue_tolerance * std::max(extent, 1e-300);

  auto coincide = [&](const EdgeSamples& a, const EdgeSamples& b, bool reversed) {
    for (int k = 0; k < kSamples; ++k)
      if (!(distance(a.at[k], b.at[reversed ? kSamples - 1 - k : k]) <= eps)) return false;
    return true;
  };
  std::vector<bool> used(edges.size(), false), partly_used(edges.size(), false);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    bool point = true;
    for (int k = 1; k < kSamples && point; ++k) point = distance(edges[i].at[0], edges[i].at[k]) <= eps;
    if (point) {
      topology.collapsed.push_back(edges[i].edge);
      used[i] = true;
    }
  }
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (used[i]) continue;
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      if (used[j]) continue;
      for (const bool reversed : {false, true})
        if (coincide(edges[i], edges[j], reversed)) {
          topology.glues.push_back({edges[i].edge, edges[j].edge, reversed});
          used[i] = used[j] = true;
          break;
        }
      if (used[i]) break;
    }
  }
  // Parts: a free edge b whose ends lie on another edge a.
  for (std::size_t j = 0; j < edges.size(); ++j) {
    if (used[j]) continue;
    for (std::size_t i = 0; i < edges.size(); ++i) {
      if (i == j || (used[i] && !partly_used[i])) continue;
      const EdgeRef& ea = edges[i].edge;
      const bool wraps = (ea.side == 0 || ea.side == 2) ? patches[ea.patch].periodic_u : patches[ea.patch].periodic_v;
      const std::vector<Glue> g = match_part(edges[i], wraps, edges[j], compiled, eps, ev);
      if (g.empty()) continue;
      topology.glues.insert(topology.glues.end(), g.begin(), g.end());
      used[j] = true;
      used[i] = partly_used[i] = true;
      break;
    }
  }
  return topology;
}

}  // namespace genmod::parametric
