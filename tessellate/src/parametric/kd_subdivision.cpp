// Level-synchronous kd-tree subdivision: every node of one level is bounded in parallel, then
// the accepted ones become leaves and the others split (in two, or into the pieces their
// second derivatives predict). The tree depends only on the input, never on the thread count.
#include "kd_subdivision.hpp"

#include "genmod/kernel/interval_evaluator.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace genmod::parametric {

namespace {

constexpr int kUv[2] = {0, 1};
constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Node {
  std::uint32_t patch = 0;
  GridRect rect;
};

// A node's bound and what to do with it: split into pieces_u x pieces_v equal parts (both 1:
// accept it as a leaf).
struct Bounded {
  double bound = kInfinity;
  int pieces_u = 1, pieces_v = 1;
  std::size_t evaluations = 1;  // pieces bounded to decide (the node and any trial halves)
  bool accepted() const { return pieces_u == 1 && pieces_v == 1; }
};

// The most pieces per axis of one split planned from the second derivatives (below); a
// leaf that needs more is halved first, so that the plan is made from enclosures over a
// smaller piece, closer to the pieces' own. Equal parts of any number fit the grid, but 2
// measured best: more pieces per split (4, 8) put T-points of differently divided
// neighbours on both sides of an edge (2.3-2.5 triangles per leaf against 2.1), and the
// plan from a parent's enclosures overestimates its pieces' bounds (they are accepted at
// 0.6-0.7 of the tolerance), which together cost more than finer quantization saves:
// genmod_parametric_bench 1e-3 triangles at 2 / 8 pieces: sphere 5296 / 5536, torus
// 4896 / 5392, wing 1678 / 1935, banana 4720 / 5160.
constexpr int kMaxPieces = 2;

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

// What one interval evaluation of a piece tells: its bound, its second-order enclosures (when
// S is C^2 there) and its longest extents in space along u and v.
struct Measured {
  double bound = kInfinity;
  std::optional<SecondOrder> second_order;
  bool jacobian_ok = false;
  bool smooth = false;  // the linear bound applies (S continuous, Jacobian bounded)
  double len_u = 0.0, len_v = 0.0;
};

struct NodeBounder {
  IntervalEvaluator value_ev, jacobian_ev, hessian_ev;

  Measured measure(const CompiledPatch& p, const GridRect& rect, const AdaptiveMeshOptions& o) {
    const Interval u(grid_value(p.u, rect.u0), grid_value(p.u, rect.u1));
    const Interval v(grid_value(p.v, rect.v0), grid_value(p.v, rect.v1));
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
    Measured r;
    // The box encloses every defined value, so its diameter bounds the distance even where
    // the surface may be undefined (a vertex there is an error, reported by the mesher).
    if (finite) r.bound = std::sqrt(diameter2) * kSlack;
    // Jacobian: the interpolation bound and the direction to split.
    const auto jac = jacobian_ev.eval(p.jacobian, box);
    bool jacobian_ok = true;
    double linear2 = 0.0;
    for (std::size_t j = 0; j < 3; ++j) {
      const Interval& su = jac[j];
      const Interval& sv = jac[3 + j];
      jacobian_ok = jacobian_ok && su.is_bounded() && sv.is_bounded() && !su.is_empty() && !sv.is_empty() &&
                    jacobian_ev.errors()[j] == 0 && jacobian_ev.errors()[3 + j] == 0;
      r.len_u = std::max(r.len_u, magnitude(su) * a);
      r.len_v = std::max(r.len_v, magnitude(sv) * b);
      const double e = 0.5 * (half_width(su) * a + half_width(sv) * b);
      linear2 += e * e;
    }
    r.jacobian_ok = jacobian_ok;
    const bool smooth = o.bound == LeafBound::Best && jacobian_ok && finite && !error && value_ev.continuous();
    r.smooth = smooth;
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
        SecondOrder& q = r.second_order.emplace();
        for (std::size_t j = 0; j < 3; ++j) q.uu[j] = h[j], q.cross[j] = h[3 + j] + h[6 + j], q.vv[j] = h[9 + j];
        r.bound = std::min(r.bound, q.bound(a, b) * kSlack);
      }
    }
    return r;
  }

  Bounded bound(const CompiledPatch& p, const Node& n, const AdaptiveMeshOptions& o) {
    const Measured m = measure(p, n.rect, o);
    Bounded r;
    r.bound = m.bound;
    const double a = grid_value(p.u, n.rect.u1) - grid_value(p.u, n.rect.u0);
    const double b = grid_value(p.v, n.rect.v1) - grid_value(p.v, n.rect.v0);
    const bool refine = o.refine && o.refine(n.patch, Interval(grid_value(p.u, n.rect.u0), grid_value(p.u, n.rect.u1)),
                                             Interval(grid_value(p.v, n.rect.v0), grid_value(p.v, n.rect.v1)));
    // Splits are limited to pieces at least `finest` grid steps wide per axis.
    const int depth_limit = std::isfinite(r.bound) ? o.max_depth : std::min(o.max_depth, o.unbounded_depth);
    const std::int64_t finest = kGridSize >> depth_limit;
    const std::int64_t width_u = n.rect.u1 - n.rect.u0, width_v = n.rect.v1 - n.rect.v0;
    const int most_u = static_cast<int>(std::min<std::int64_t>(width_u / finest, kMaxPieces));
    const int most_v = static_cast<int>(std::min<std::int64_t>(width_v / finest, kMaxPieces));
    // A periodic axis closes into a loop, which needs at least three vertices to be a
    // surface: a thin tube (a hair) within the tolerance with one or two leaves around would
    // mesh as a flat double strip. Four leaves around at least (two splits).
    const bool loop_u = p.periodic_u && width_u > kGridSize / 4;
    const bool loop_v = p.periodic_v && width_v > kGridSize / 4;
    if (loop_u || loop_v) {
      (loop_u ? r.pieces_u : r.pieces_v) = 2;
      return r;
    }
    if (r.bound <= o.tolerance && !refine) return r;
    if (most_u < 2 && most_v < 2) return r;  // accepted at the depth limit
    const bool over = !(r.bound <= o.tolerance);
    if (m.second_order && over && plan(*m.second_order, a, b, o.tolerance, most_u, most_v, r)) return r;
    // Halve the direction along which the piece is longer (the parameter extent when the
    // Jacobian has no finite bound), unless the halves' own bounds say otherwise.
    bool split_u = m.jacobian_ok ? m.len_u >= m.len_v : width_u >= width_v;
    if (over && m.smooth && most_u >= 2 && most_v >= 2) {
      // Without second derivatives to plan from, the split whose worse half has the smaller
      // bound. The longer side is the wrong guess where the bound is
      // held up by a jump of the Jacobian across the other axis (the gear's polyline
      // schedule: S_v jumps at its corners): halving the long side there leaves that jump
      // in every half. Four more evaluations per split node (the chosen halves are
      // evaluated again at the next level), so only where the linear bound applies: where
      // only the box diameter does (S may jump: the spoon's pieces) the trial did not pay,
      // spoon 87,119 -> 265,857 evaluations, 9.0 -> 21 s CPU, for 3% fewer leaves.
      GridRect lo = n.rect, hi = n.rect;
      lo.u1 = hi.u0 = n.rect.u0 + width_u / 2;
      const double by_u = std::max(measure(p, lo, o).bound, measure(p, hi, o).bound);
      lo = hi = n.rect;
      lo.v1 = hi.v0 = n.rect.v0 + width_v / 2;
      const double by_v = std::max(measure(p, lo, o).bound, measure(p, hi, o).bound);
      r.evaluations += 4;
      // Only a clear win overrides the longer side: where the bound barely moves either way
      // (loose enclosures, the bottle's inverted curve) the greedy choice keeps cutting one
      // axis into slivers whose enclosures never tighten (the bottle at 3e-3 ran past
      // 400,000 leaves, 77,490 before; with the 0.9 margin 69,598).
      constexpr double kClearWin = 0.9;
      if (split_u ? by_v < kClearWin * by_u : by_u < kClearWin * by_v) split_u = !split_u;
    }
    if (most_u < 2) split_u = false;
    if (most_v < 2) split_u = true;
    (split_u ? r.pieces_u : r.pieces_v) = 2;
    return r;
  }

  // Plans the split of a leaf of widths a x b whose bound is over the tolerance from its
  // second-order enclosures, which bound every piece of it too: the fewest pieces_u x
  // pieces_v equal parts whose predicted bound meets the tolerance (the larger margin among
  // equal counts) is the shape the curvatures ask for. Within kMaxPieces per axis (and the
  // depth limit) that is the split; otherwise the axis that needs more pieces is halved.
  // Halving the longer side in space instead ignores how the bound grows with each side:
  // a wing's span is its long side but nearly straight, and leaves accepted after such
  // halvings sit far below the tolerance (the wing's at 0.37 of it in the median; 9316
  // triangles, now 1678). The pieces' own bounds decide whether they are accepted: the
  // plan only predicts. False when no plan of up to 64 x 64 pieces meets the tolerance.
  static bool plan(const SecondOrder& q, double a, double b, double tol, int most_u, int most_v, Bounded& r) {
    constexpr int kSearch = 64;  // pieces per axis considered for the shape
    int best_u = 0, best_v = 0;
    double best_bound = kInfinity;
    for (int ku = 1; ku <= kSearch && (best_u == 0 || ku <= best_u * best_v); ++ku) {
      // The fewest pieces along v for ku along u (the bound decreases in kv).
      if (q.bound(a / ku, b / kSearch) > tol) continue;
      int lo = 0, hi = kSearch;  // bound(kv = hi) <= tol; kv = lo is too few
      while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        (q.bound(a / ku, b / mid) <= tol ? hi : lo) = mid;
      }
      const double predicted = q.bound(a / ku, b / hi);
      const long count = static_cast<long>(ku) * hi, best = static_cast<long>(best_u) * best_v;
      if (best_u == 0 || count < best || (count == best && predicted < best_bound))
        best_u = ku, best_v = hi, best_bound = predicted;
    }
    if (best_u == 0 || best_u * best_v < 2) return false;
    if (best_u <= most_u && best_v <= most_v) {
      r.pieces_u = best_u, r.pieces_v = best_v;
      return true;
    }
    // Too many at once: halve the axis that needs the most pieces.
    bool split_u = best_u >= best_v;
    if (most_u < 2) split_u = false;
    if (most_v < 2) split_u = true;
    (split_u ? r.pieces_u : r.pieces_v) = 2;
    return true;
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
  for (std::uint32_t p = 0; p < patches.size(); ++p) level.push_back({p, GridRect{}});
  tbb::enumerable_thread_specific<NodeBounder> bounders;
  std::vector<Bounded> verdicts;
  std::size_t leaf_count = 0;
  bool depth_hit = false;
  while (!level.empty()) {
    verdicts.assign(level.size(), Bounded{});
    tbb::parallel_for(std::size_t{0}, level.size(), [&](std::size_t i) {
      verdicts[i] = bounders.local().bound(patches[level[i].patch], level[i], options);
    });
    for (const Bounded& b : verdicts) out.interval_evaluations += b.evaluations;
    std::size_t splits = 0, children = 0;
    const std::int64_t finest = kGridSize >> options.max_depth;
    for (std::size_t i = 0; i < level.size(); ++i) {
      const Node& n = level[i];
      if (!verdicts[i].accepted()) {
        ++splits;
        children += static_cast<std::size_t>(verdicts[i].pieces_u * verdicts[i].pieces_v);
      } else if (verdicts[i].bound > options.tolerance && std::isfinite(verdicts[i].bound) &&
                 n.rect.u1 - n.rect.u0 < 2 * finest && n.rect.v1 - n.rect.v0 < 2 * finest) {
        depth_hit = true;
      }
    }
    // Limits: stop splitting when the next level would exceed the leaf budget or time is up;
    // the nodes of this level then become leaves with the bounds they have.
    const bool over_leaves = leaf_count + level.size() - splits + children > options.max_leaves;
    const bool over_time =
        options.max_seconds > 0.0 && std::chrono::duration<double>(Clock::now() - start).count() > options.max_seconds;
    const bool cancelled = options.cancel != nullptr && options.cancel->load(std::memory_order_relaxed);
    if (splits > 0 && over_leaves) out.limits_hit.push_back("leaves");
    if (splits > 0 && over_time && !over_leaves) out.limits_hit.push_back("time");
    if (splits > 0 && cancelled && !over_leaves && !over_time) out.limits_hit.push_back("cancelled");
    const bool stop = over_leaves || over_time || cancelled;
    std::vector<Node> next;
    next.reserve(stop ? 0 : children);
    for (std::size_t i = 0; i < level.size(); ++i) {
      const Node& n = level[i];
      const Bounded& b = verdicts[i];
      if (b.accepted() || stop) {
        out.leaves[n.patch].push_back({n.rect, b.bound});
        ++leaf_count;
        continue;
      }
      // Equal parts on the integer grid (a part's corners are shared bit for bit by its
      // neighbours, whatever the division; grid_value is one formula).
      const std::int64_t wu = n.rect.u1 - n.rect.u0, wv = n.rect.v1 - n.rect.v0;
      for (int i_v = 0; i_v < b.pieces_v; ++i_v)
        for (int i_u = 0; i_u < b.pieces_u; ++i_u) {
          Node c = n;
          c.rect.u0 = n.rect.u0 + wu * i_u / b.pieces_u;
          c.rect.u1 = n.rect.u0 + wu * (i_u + 1) / b.pieces_u;
          c.rect.v0 = n.rect.v0 + wv * i_v / b.pieces_v;
          c.rect.v1 = n.rect.v0 + wv * (i_v + 1) / b.pieces_v;
          next.push_back(c);
        }
    }
    if (stop) break;
    level = std::move(next);
  }
  if (depth_hit) out.limits_hit.push_back("depth");
  return out;
}

}  // namespace genmod::parametric
