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

struct NodeBounder {
  IntervalEvaluator value_ev, jacobian_ev;

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
    if (o.bound == LeafBound::Best && jacobian_ok && finite && !error && value_ev.continuous())
      r.bound = std::min(r.bound, std::sqrt(linear2) * kSlack);
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
  return CompiledPatch{Tape(s, kUv), Tape(cat({derivative(s, 0), derivative(s, 1)}), kUv), patch.u, patch.v,
                       patch.periodic_u, patch.periodic_v};
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
