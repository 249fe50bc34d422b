// Level-synchronous kd-tree subdivision: every node of one level is bounded in parallel, then
// the accepted ones become leaves and the others split in two. The tree depends only on the
// input, never on the thread count.
#include "kd_subdivision.hpp"

#include "genmod/kernel/interval_evaluator.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace genmod::parametric {

namespace {

constexpr int kUv[2] = {0, 1};
constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Node {
  std::uint32_t patch = 0;
  GridRect rect;
  int depth_u = 0, depth_v = 0;
};

enum class Verdict : std::uint8_t { Accept, SplitU, SplitV };

struct Bounded {
  double bound = kInfinity;
  Verdict verdict = Verdict::Accept;
};

double half_width(const Interval& x) { return 0.5 * (x.hi() - x.lo()); }
double magnitude(const Interval& x) { return std::max(std::abs(x.lo()), std::abs(x.hi())); }

// Relative slack for the round-to-nearest arithmetic of the bound formulas (a few ulps).
constexpr double kSlack = 1.0 + 1e-12;

// The second-order bound of a leaf X = [u0, u0 + a] x [v0, v0 + b], from the interval
// second derivatives over X. Proof: let a triangle have vertices p_i in X and p = sum l_i p_i
// (l_i >= 0, sum l_i = 1) a point of it, d_i = p_i - p = (du_i, dv_i). X is convex, so each
// segment p -> p_i lies in X, and where S is C^2 on X Taylor's theorem with the Lagrange
// remainder gives, per component j, S_j(p_i) = S_j(p) + grad S_j(p) d_i + 1/2 q_ij, with
//   q_ij = S_uu du_i^2 + (S_uv + S_vu) du_i dv_i + S_vv dv_i^2 at a point xi_ij of the segment.
// As sum l_i d_i = 0 the gradient terms cancel: S_j(p) - sum l_i S_j(p_i) = -1/2 sum l_i q_ij.
// sum l_i du_i^2 is the variance of a distribution on an interval of width a, so it lies in
// [0, a^2/4]; likewise sum l_i dv_i^2 in [0, b^2/4], and sum l_i |du_i dv_i| <= ab/4 by
// Cauchy-Schwarz. Each second derivative at xi_ij lies in its enclosure over X, so
//   sum l_i q_ij in [0, a^2/4] S_uu(X) + [-ab/4, ab/4] (S_uv(X) + S_vu(X)) + [0, b^2/4] S_vv(X),
// and the distance from the triangle's point to S(p) is at most the norm over j of half the
// magnitudes of these intervals. For a quadratic part of the same size this is half the
// linear bound (whose Jacobian widths are about |S_uu| a + |S_uv| b), and where S_uu and S_vv
// have opposite signs (a saddle) their terms partly cancel.
struct SecondOrder {
  std::array<Interval, 3> uu, cross, vv;  // per component: S_uu, S_uv + S_vu, S_vv over the leaf

  // The bound for a piece of widths a x b of the leaf (any sub-box: its enclosures lie within
  // these); rounded to nearest, covered by kSlack.
  double bound(double a, double b) const {
    const double a2 = 0.25 * a * a, ab = 0.25 * a * b, b2 = 0.25 * b * b;
    double sum2 = 0.0;
    for (std::size_t j = 0; j < 3; ++j) {
      const double c = ab * std::max(std::abs(cross[j].lo()), std::abs(cross[j].hi()));
      const double hi = a2 * std::max(uu[j].hi(), 0.0) + c + b2 * std::max(vv[j].hi(), 0.0);
      const double lo = a2 * std::min(uu[j].lo(), 0.0) - c + b2 * std::min(vv[j].lo(), 0.0);
      const double e = 0.5 * std::max(hi, -lo);
      sum2 += e * e;
    }
    return std::sqrt(sum2);
  }
};

struct NodeBounder {
  IntervalEvaluator value_ev, jacobian_ev, hessian_ev;

  Bounded bound(const CompiledPatch& p, const Node& n, const AdaptiveMeshOptions& o) {
    const Interval u(grid_value(p.u, n.rect.u0), grid_value(p.u, n.rect.u1));
    const Interval v(grid_value(p.v, n.rect.v0), grid_value(p.v, n.rect.v1));
    const std::array<Interval, 2> box{u, v};
    const auto s = value_ev.eval(p.value, box);
    bool finite = true, error = false;
    double diameter2 = 0.0;
    for (std::size_t j = 0; j < 3; ++j) {
      finite = finite && s[j].is_bounded() && !s[j].is_empty();
      error = error || value_ev.errors()[j] != 0;
      diameter2 += s[j].width() * s[j].width();
    }
    const double a = u.hi() - u.lo(), b = v.hi() - v.lo();
    Bounded r;
    // The box encloses every defined value, so its diameter bounds the distance even where
    // the surface may be undefined (a vertex there is an error, reported by the mesher).
    if (finite) r.bound = std::sqrt(diameter2) * kSlack;
    // Jacobian: the interpolation bound and the direction to split.
    const auto jac = jacobian_ev.eval(p.jacobian, box);
    bool jacobian_ok = true;
    double len_u = 0.0, len_v = 0.0, linear2 = 0.0;
    for (std::size_t j = 0; j < 3; ++j) {
      const Interval& su = jac[j];
      const Interval& sv = jac[3 + j];
      jacobian_ok = jacobian_ok && su.is_bounded() && sv.is_bounded() && !su.is_empty() && !sv.is_empty() &&
                    jacobian_ev.errors()[j] == 0 && jacobian_ev.errors()[3 + j] == 0;
      len_u = std::max(len_u, magnitude(su) * a);
      len_v = std::max(len_v, magnitude(sv) * b);
      const double e = 0.5 * (half_width(su) * a + half_width(sv) * b);
      linear2 += e * e;
    }
    const bool smooth = o.bound == LeafBound::Best && jacobian_ok && finite && !error && value_ev.continuous();
    if (smooth) r.bound = std::min(r.bound, std::sqrt(linear2) * kSlack);
    // Second derivatives: the second-order bound (above), where S is C^2 on the leaf (the
    // Jacobian continuous too, the second derivatives bounded and continuous). Skipped for a
    // leaf the cheaper bounds accept already, unless a refine criterion decides the splits
    // (then the tolerance does not, and the leaf's reported bound should be the tightest).
    if (smooth && jacobian_ev.continuous() && (r.bound > o.tolerance || o.refine)) {
      const auto h = hessian_ev.eval(p.hessian, box);
      bool hessian_ok = hessian_ev.continuous();
      for (std::size_t k = 0; k < 12; ++k)
        hessian_ok = hessian_ok && h[k].is_bounded() && !h[k].is_empty() && hessian_ev.errors()[k] == 0;
      if (hessian_ok) {
        SecondOrder q;
        for (std::size_t j = 0; j < 3; ++j) q.uu[j] = h[j], q.cross[j] = h[3 + j] + h[6 + j], q.vv[j] = h[9 + j];
        r.bound = std::min(r.bound, q.bound(a, b) * kSlack);
      }
    }
    const bool refine = o.refine && o.refine(n.patch, u, v);
    // A periodic axis closes into a loop, which needs at least three vertices to be a
    // surface: a thin tube (a hair) within the tolerance with one or two leaves around would
    // mesh as a flat double strip. Four leaves around at least (two splits).
    const bool loop_u = p.periodic_u && n.rect.u1 - n.rect.u0 > kGridSize / 4;
    const bool loop_v = p.periodic_v && n.rect.v1 - n.rect.v0 > kGridSize / 4;
    if (loop_u || loop_v) {
      r.verdict = loop_u ? Verdict::SplitU : Verdict::SplitV;
      return r;
    }
    if (r.bound <= o.tolerance && !refine) return r;
    // Split the direction along which the piece is longer (the parameter extent when the
    // Jacobian has no finite bound), within the depth limit.
    const int depth_limit = std::isfinite(r.bound) ? o.max_depth : std::min(o.max_depth, o.unbounded_depth);
    const bool can_u = n.depth_u < depth_limit, can_v = n.depth_v < depth_limit;
    if (!can_u && !can_v) return r;  // accepted at the depth limit
    bool split_u = jacobian_ok ? len_u >= len_v : (n.rect.u1 - n.rect.u0) >= (n.rect.v1 - n.rect.v0);
    if (!can_u) split_u = false;
    if (!can_v) split_u = true;
    r.verdict = split_u ? Verdict::SplitU : Verdict::SplitV;
    return r;
  }
};

}  // namespace

CompiledPatch compile_patch(const SurfacePatch& patch) {
  const Fn& s = patch.surface;
  const Fn su = derivative(s, 0), sv = derivative(s, 1);
  return CompiledPatch{Tape(s, kUv),
                       Tape(cat({su, sv}), kUv),
                       Tape(cat({derivative(su, 0), derivative(su, 1), derivative(sv, 0), derivative(sv, 1)}), kUv),
                       patch.u,
                       patch.v,
                       patch.periodic_u,
                       patch.periodic_v};
}

Subdivision subdivide(const std::vector<CompiledPatch>& patches, const AdaptiveMeshOptions& options) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  Subdivision out;
  out.leaves.resize(patches.size());
  std::vector<Node> level;
  for (std::uint32_t p = 0; p < patches.size(); ++p) level.push_back({p, GridRect{}, 0, 0});
  tbb::enumerable_thread_specific<NodeBounder> bounders;
  std::vector<Bounded> verdicts;
  std::size_t leaf_count = 0;
  bool depth_hit = false;
  while (!level.empty()) {
    verdicts.assign(level.size(), Bounded{});
    tbb::parallel_for(std::size_t{0}, level.size(), [&](std::size_t i) {
      verdicts[i] = bounders.local().bound(patches[level[i].patch], level[i], options);
    });
    out.interval_evaluations += level.size();
    std::size_t splits = 0;
    for (std::size_t i = 0; i < level.size(); ++i) {
      const Node& n = level[i];
      if (verdicts[i].verdict != Verdict::Accept) {
        ++splits;
      } else if (verdicts[i].bound > options.tolerance && std::isfinite(verdicts[i].bound) &&
                 n.depth_u >= options.max_depth && n.depth_v >= options.max_depth) {
        depth_hit = true;
      }
    }
    // Limits: stop splitting when the next level would exceed the leaf budget or time is up;
    // the nodes of this level then become leaves with the bounds they have.
    const bool over_leaves = leaf_count + level.size() + splits > options.max_leaves;
    const bool over_time =
        options.max_seconds > 0.0 && std::chrono::duration<double>(Clock::now() - start).count() > options.max_seconds;
    const bool cancelled = options.cancel != nullptr && options.cancel->load(std::memory_order_relaxed);
    if (splits > 0 && over_leaves) out.limits_hit.push_back("leaves");
    if (splits > 0 && over_time && !over_leaves) out.limits_hit.push_back("time");
    if (splits > 0 && cancelled && !over_leaves && !over_time) out.limits_hit.push_back("cancelled");
    const bool stop = over_leaves || over_time || cancelled;
    std::vector<Node> next;
    next.reserve(stop ? 0 : 2 * splits);
    for (std::size_t i = 0; i < level.size(); ++i) {
      const Node& n = level[i];
      const Verdict v = verdicts[i].verdict;
      if (v == Verdict::Accept || stop) {
        out.leaves[n.patch].push_back({n.rect, verdicts[i].bound});
        ++leaf_count;
        continue;
      }
      Node lo = n, hi = n;
      if (v == Verdict::SplitU) {
        const std::int64_t mid = (n.rect.u0 + n.rect.u1) / 2;
        lo.rect.u1 = hi.rect.u0 = mid;
        lo.depth_u = hi.depth_u = n.depth_u + 1;
      } else {
        const std::int64_t mid = (n.rect.v0 + n.rect.v1) / 2;
        lo.rect.v1 = hi.rect.v0 = mid;
        lo.depth_v = hi.depth_v = n.depth_v + 1;
      }
      next.push_back(lo);
      next.push_back(hi);
    }
    if (stop) break;
    level = std::move(next);
  }
  if (depth_hit) out.limits_hit.push_back("depth");
  return out;
}

}  // namespace genmod::parametric
