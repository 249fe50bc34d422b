// Octree construction (level by level, each level classified in parallel) and queries.
#include "implicit/octree.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <optional>

namespace genmod::implicit {
namespace {

struct Decision {
  CellKind kind = CellKind::Outside;
  bool certified = false;
  bool bounded_gradient = true;
  bool split = false;  // wants to be split (kind is then Surface, used if the split is refused)
  std::optional<CellTapes> tapes;  // Surface: the pruned tapes
};

std::array<Interval, 3> cell_box(const Frame& frame, const Cell& c) {
  const std::uint32_t s = c.size();
  const Vec3 lo = frame.point(c.corner);
  const Vec3 hi = frame.point({c.corner[0] + s, c.corner[1] + s, c.corner[2] + s});
  return {Interval(lo[0], hi[0]), Interval(lo[1], hi[1]), Interval(lo[2], hi[2])};
}

// Plantinga and Vegter's test: any two gradients in G have a positive dot product.
bool normals_in_a_cone(const std::array<Interval, 3>& g) {
  namespace id = interval_detail;
  const RoundingScope up;
  id::Raw dot = id::raw(g[0]) * id::raw(g[0]);
  dot += id::raw(g[1]) * id::raw(g[1]);
  dot += id::raw(g[2]) * id::raw(g[2]);
  return dot.lower() > 0.0;
}

// The mean value form f(m) + sum g_k (X_k - m_k).
Interval mean_value_form(const Interval& fm, const std::array<Interval, 3>& g, const std::array<Interval, 3>& box,
                         const std::array<Interval, 3>& m) {
  namespace id = interval_detail;
  const RoundingScope up;
  id::Raw sum = id::raw(fm);
  for (int k = 0; k < 3; ++k) sum += id::raw(g[k]) * (id::raw(box[k]) - id::raw(m[k]));
  return id::cook(sum);
}

Decision classify(const Cell& c, const CellTapes& parent, const ClassifyContext& ctx, ClassifyWorker& w) {
  Decision d;
  const std::array<Interval, 3> box = cell_box(*ctx.frame, c);
  std::array<int, 3> active{};
  const Interval s = ctx.frame->clip(box, &active);
  if (s.lo() > 0.0) return d;  // outside the box
  Interval f = w.intervals.eval(parent.value, box)[0];
  const std::uint8_t err = w.intervals.errors()[0];
  // Mean value forms need continuity (no comparison, select or floor that can jump here).
  const bool f_continuous = w.intervals.continuous();
  ++w.evaluations;
  // Points where f is an error count as outside, as in render_sign.
  if (err == kCertainError) return d;
  if (err == kNoError && f.lo() >= 0.0) return d;
  if (err == kNoError && std::max(f.hi(), s.hi()) < 0.0) {
    d.kind = CellKind::Inside;
    return d;
  }
  CellTapes tapes{parent.value.simplify(w.intervals.choices(), w.simplifier), parent.gradient};

  // g = max(f, clip): f is the maximum somewhere iff f.hi >= clip.lo.
  const bool f_active = f.hi() >= s.lo();
  std::array<Interval, 3> g = {Interval::empty(), Interval::empty(), Interval::empty()};
  bool gradient_continuous = false;
  if (f_active) {
    const auto gf = w.intervals.eval(parent.gradient, box);
    bool gerr = false;
    for (std::uint8_t e : w.intervals.errors()) gerr = gerr || e != kNoError;
    tapes.gradient = parent.gradient.simplify(w.intervals.choices(), w.simplifier);
    for (int k = 0; k < 3; ++k) g[k] = gerr ? Interval::entire() : gf[static_cast<std::size_t>(k)];
    d.bounded_gradient = !gerr;
    gradient_continuous = w.intervals.continuous();
    if (!gerr && err == kNoError && f_continuous) {
      // The mean value form f(m) + grad f(X) (X - m) is second order in the cell's size: it
      // removes most cells the natural extension only guesses may hold surface.
      std::array<Interval, 3> center;
      for (int k = 0; k < 3; ++k) center[k] = Interval(box[k].mid());
      const Interval fm = w.intervals.eval(tapes.value, center)[0];
      if (w.intervals.errors()[0] == kNoError) {
        f = intersect(f, mean_value_form(fm, g, box, center));
        if (f.lo() >= 0.0) return d;
        if (std::max(f.hi(), s.hi()) < 0.0) {
          d.kind = CellKind::Inside;
          return d;
        }
      }
    }
  }
  d.kind = CellKind::Surface;
  d.tapes = std::move(tapes);
  // f's gradients matter only where f can be the zero of g.
  if (f.hi() < 0.0) {
    g = {Interval::empty(), Interval::empty(), Interval::empty()};
    d.bounded_gradient = true;
  }
  // The clip's gradients matter only where the clip can be the zero of g: where it reaches
  // 0 and is the maximum.
  const bool clip_active = s.hi() >= f.lo() && s.hi() >= 0.0;
  if (clip_active)
    for (int a = 0; a < 3; ++a) {
      if (active[a] == 0) continue;
      for (int k = 0; k < 3; ++k) {
        const Interval part = k != a ? Interval(0.0) : active[a] == 1 ? Interval(1.0)
                                                     : active[a] == -1 ? Interval(-1.0) : Interval(-1.0, 1.0);
        g[k] = g[k].is_empty() ? part : hull(g[k], part);
      }
    }
  d.certified = d.bounded_gradient && normals_in_a_cone(g);
  if (!d.certified && d.bounded_gradient && gradient_continuous && f_active && f.hi() >= 0.0 && !clip_active) {
    // The gradient's mean value form grad f(m) + H(X) (X - m) is tighter on small cells
    // (where the gradient is continuous: a min or max of two active parts jumps).
    std::array<Interval, 3> center;
    for (int k = 0; k < 3; ++k) center[k] = Interval(box[k].mid());
    const auto gm_span = w.intervals.eval(d.tapes->gradient, center);
    bool ok = true;
    for (std::uint8_t e : w.intervals.errors()) ok = ok && e == kNoError;
    const std::array<Interval, 3> gm{gm_span[0], gm_span[1], gm_span[2]};
    if (ok) {
      const auto h = w.intervals.eval(*ctx.hessian, box);
      for (std::uint8_t e : w.intervals.errors()) ok = ok && e == kNoError;
      ok = ok && w.intervals.continuous();
      if (ok) {
        // Symmetric: xx xy xz yy yz zz.
        const std::array<std::array<Interval, 3>, 3> hm{{{h[0], h[1], h[2]}, {h[1], h[3], h[4]}, {h[2], h[4], h[5]}}};
        for (int k = 0; k < 3; ++k) g[k] = intersect(g[k], mean_value_form(gm[k], hm[k], box, center));
        d.certified = normals_in_a_cone(g);
      }
    }
  }
  // A wide normal cone means detail (curvature, a crease, a small part): split down to
  // min_feature. Without gradient bounds (a formula whose derivative fails, like the 0/0 of
  // |max(q, 0)| in an exact box distance) the meshing checks decide instead.
  d.split = c.level < ctx.max_cell_level || (!d.certified && d.bounded_gradient && c.level < ctx.min_level);
  return d;
}

}  // namespace

Octree::Octree(const ImplicitSurface& surface, const ClassifyContext& context,
               std::chrono::steady_clock::time_point deadline, const std::atomic<bool>* cancel,
               ImplicitMeshStats& stats)
    : context_(context) {
  cells_.push_back(Cell{});
  std::vector<Pending> pending{{0, {surface.value(), surface.gradient()}}};
  bool timed_out = false;
  while (!pending.empty()) {
    if (!timed_out && cancel != nullptr && cancel->load(std::memory_order_relaxed)) {
      timed_out = true;
      stats.limits_hit.emplace_back("cancelled");
    } else if (!timed_out && std::chrono::steady_clock::now() > deadline) {
      timed_out = true;
      stats.limits_hit.emplace_back("seconds");
    }
    pending = classify_all(pending, !timed_out, stats);
  }
}

std::vector<Octree::Pending> Octree::classify_all(std::vector<Pending>& pending, bool allow_split,
                                                  ImplicitMeshStats& stats) {
  std::vector<Decision> decisions(pending.size());
  tbb::enumerable_thread_specific<ClassifyWorker> workers;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pending.size(), 16), [&](const auto& r) {
    ClassifyWorker& w = workers.local();
    for (std::size_t i = r.begin(); i != r.end(); ++i)
      decisions[i] = classify(cells_[pending[i].cell], pending[i].tapes, context_, w);
  });
  for (const ClassifyWorker& w : workers) stats.interval_evaluations += w.evaluations;

  // Applied in order, so the cell numbering does not depend on the threads.
  std::vector<Pending> next;
  for (std::size_t i = 0; i < pending.size(); ++i) {
    Decision& d = decisions[i];
    const std::uint32_t index = pending[i].cell;
    bool split = d.kind == CellKind::Surface && d.split && allow_split;
    if (split && !room_for_children(stats)) split = false;
    if (split) {
      const Cell parent = cells_[index];
      const std::uint32_t half = parent.size() / 2;
      cells_[index].kind = CellKind::Internal;
      cells_[index].children = static_cast<std::uint32_t>(cells_.size());
      for (std::uint32_t b = 0; b < 8; ++b) {
        Cell child;
        child.corner = {parent.corner[0] + (b & 1 ? half : 0), parent.corner[1] + (b & 2 ? half : 0),
                        parent.corner[2] + (b & 4 ? half : 0)};
        child.level = static_cast<std::uint8_t>(parent.level + 1);
        next.push_back({static_cast<std::uint32_t>(cells_.size()), *d.tapes});
        cells_.push_back(child);
      }
      continue;
    }
    Cell& c = cells_[index];
    c.kind = d.kind;
    c.certified = d.certified;
    c.bounded_gradient = d.bounded_gradient;
    if (d.kind == CellKind::Surface) {
      c.tapes = static_cast<std::uint32_t>(tapes_.size());
      tape_bytes_ += d.tapes->value.memory_bytes() + d.tapes->gradient.memory_bytes();
      tapes_.push_back(std::move(*d.tapes));
    }
  }
  return next;
}

bool Octree::room_for_children(ImplicitMeshStats& stats) const {
  const char* limit = cells_.size() + 8 > context_.settings->max_cells ? "cells"
                      : memory_bytes() > context_.settings->max_memory ? "memory"
                                                                        : nullptr;
  if (limit && std::find(stats.limits_hit.begin(), stats.limits_hit.end(), limit) == stats.limits_hit.end())
    stats.limits_hit.emplace_back(limit);
  return limit == nullptr;
}

void Octree::split(const std::vector<std::uint32_t>& surface_cells, ImplicitMeshStats& stats) {
  std::vector<Pending> children;
  for (std::uint32_t index : surface_cells) {
    if (!room_for_children(stats)) break;
    const Cell parent = cells_[index];
    const CellTapes tapes = tapes_[parent.tapes];
    const std::uint32_t half = parent.size() / 2;
    cells_[index].kind = CellKind::Internal;
    cells_[index].children = static_cast<std::uint32_t>(cells_.size());
    cells_[index].tapes = kNone;
    for (std::uint32_t b = 0; b < 8; ++b) {
      Cell child;
      child.corner = {parent.corner[0] + (b & 1 ? half : 0), parent.corner[1] + (b & 2 ? half : 0),
                      parent.corner[2] + (b & 4 ? half : 0)};
      child.level = static_cast<std::uint8_t>(parent.level + 1);
      children.push_back({static_cast<std::uint32_t>(cells_.size()), tapes});
      cells_.push_back(child);
    }
  }
  classify_all(children, /*allow_split=*/false, stats);
}

namespace {

// From node `idx`, down to the node of `level` holding lattice point q (or a leaf above).
std::uint32_t descend(const std::vector<Cell>& cells, std::uint32_t idx, const std::array<std::uint32_t, 3>& q,
                      int level) {
  while (cells[idx].kind == CellKind::Internal && cells[idx].level < level) {
    const int shift = kLatticeBits - cells[idx].level - 1;
    const std::uint32_t b = ((q[0] >> shift) & 1u) | (((q[1] >> shift) & 1u) << 1) | (((q[2] >> shift) & 1u) << 2);
    idx = cells[idx].children + b;
  }
  return idx;
}

}  // namespace

Octree::Neighborhood Octree::neighborhood(const Cell& c) const {
  // The 3 x 3 x 3 block of c's size around c lies in the 2 x 2 x 2 block of twice that size
  // that holds c and extends toward c's position in its parent: find those 8 nodes, then step
  // one level down.
  Neighborhood nb;
  nb.fill(kNone);
  if (c.level == 0) {
    nb[13] = 0;
    return nb;
  }
  const std::int64_t size = c.size(), big = 2 * size;
  std::int64_t base[3];  // low corner of the 2 x 2 x 2 block of parent-sized nodes
  for (int k = 0; k < 3; ++k) {
    const std::int64_t parent = (c.corner[k] / big) * big;
    base[k] = c.corner[k] == parent ? parent - big : parent;
  }
  std::uint32_t block[8];
  for (int b = 0; b < 8; ++b) {
    const std::int64_t q[3] = {base[0] + (b & 1 ? big : 0), base[1] + (b & 2 ? big : 0), base[2] + (b & 4 ? big : 0)};
    if (q[0] < 0 || q[1] < 0 || q[2] < 0 || q[0] >= kRootSize || q[1] >= kRootSize || q[2] >= kRootSize) {
      block[b] = kNone;
      continue;
    }
    block[b] = descend(cells_, 0, {static_cast<std::uint32_t>(q[0]), static_cast<std::uint32_t>(q[1]), static_cast<std::uint32_t>(q[2])},
                       c.level - 1);
  }
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const std::int64_t q[3] = {c.corner[0] + dx * size, c.corner[1] + dy * size, c.corner[2] + dz * size};
        int b = 0;
        for (int k = 0; k < 3; ++k) b |= (q[k] >= base[k] + big ? 1 : 0) << k;
        std::uint32_t idx = block[b];
        if (idx == kNone) continue;
        if (cells_[idx].kind == CellKind::Internal && cells_[idx].level < c.level) {
          const int shift = kLatticeBits - cells_[idx].level - 1;
          const std::uint32_t cb = ((static_cast<std::uint32_t>(q[0]) >> shift) & 1u) |
                                   (((static_cast<std::uint32_t>(q[1]) >> shift) & 1u) << 1) |
                                   (((static_cast<std::uint32_t>(q[2]) >> shift) & 1u) << 2);
          idx = cells_[idx].children + cb;
        }
        nb[static_cast<std::size_t>(9 * (dz + 1) + 3 * (dy + 1) + (dx + 1))] = idx;
      }
  return nb;
}

void Octree::face_pieces(const Cell& c, const Neighborhood& nb, int axis, int side,
                         std::vector<std::array<std::uint32_t, 4>>& out) const {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const std::uint32_t size = c.size();
  out.clear();
  const std::array<std::uint32_t, 4> own{c.corner[u], c.corner[v], c.corner[u] + size, c.corner[v] + size};
  int offset[3] = {0, 0, 0};
  offset[axis] = side;
  const std::uint32_t idx = nb[static_cast<std::size_t>(9 * (offset[2] + 1) + 3 * (offset[1] + 1) + (offset[0] + 1))];
  if (idx == kNone || cells_[idx].kind != CellKind::Internal) {
    out.push_back(own);
    return;
  }
  // The neighbour is split: its leaves on the side facing c.
  const std::uint32_t facing_bit = side > 0 ? 0u : 1u;
  std::uint32_t stack[8 * kLatticeBits];
  int top = 0;
  stack[top++] = idx;
  while (top > 0) {
    const Cell& n = cells_[stack[--top]];
    if (n.kind != CellKind::Internal) {
      out.push_back({n.corner[u], n.corner[v], n.corner[u] + n.size(), n.corner[v] + n.size()});
      continue;
    }
    for (std::uint32_t b = 0; b < 8; ++b)
      if (((b >> axis) & 1u) == facing_bit) stack[top++] = n.children + b;
  }
}

void Octree::surface_leaves_touching(const std::array<std::uint32_t, 3>& lo, const std::array<std::uint32_t, 3>& hi,
                                     std::vector<std::uint32_t>& out) const {
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const std::uint32_t i = stack.back();
    stack.pop_back();
    const Cell& n = cells_[i];
    bool meets = true;
    for (int k = 0; k < 3; ++k) meets = meets && n.corner[k] <= hi[k] && lo[k] <= n.corner[k] + n.size();
    if (!meets) continue;
    if (n.kind == CellKind::Internal) {
      for (std::uint32_t b = 0; b < 8; ++b) stack.push_back(n.children + b);
    } else if (n.kind == CellKind::Surface) {
      out.push_back(i);
    }
  }
}

void Octree::points_on_segment(const Cell& c, const Neighborhood& nb, int axis, const std::array<std::uint32_t, 3>& on,
                               std::uint32_t t0, std::uint32_t t1, std::vector<std::uint32_t>& out) const {
  // Points inside the segment (length L) can only come from leaves smaller than L in the four
  // cells of size L around it; descend into each of those that is split, along the line only.
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const std::uint32_t length = t1 - t0;
  int level = kLatticeBits;
  while (level > 0 && (kRootSize >> level) < length) --level;
  const std::int64_t size = c.size();
  out.clear();
  std::uint32_t stack[8 * kLatticeBits];
  for (int quadrant = 0; quadrant < 4; ++quadrant) {
    // (Quadrants whose node is a leaf of at least the segment's length add nothing; the
    // descent below finds that out in one step when the node is c's neighbour itself.)
    std::array<std::int64_t, 3> q{};
    q[axis] = t0;
    q[u] = static_cast<std::int64_t>(on[u]) - (quadrant & 1 ? length : 0);
    q[v] = static_cast<std::int64_t>(on[v]) - (quadrant & 2 ? length : 0);
    int slot = 0, scale = 1;
    bool inside_root = true;
    for (int k = 0; k < 3; ++k) {
      inside_root = inside_root && q[k] >= 0 && q[k] < kRootSize;
      const std::int64_t d = q[k] - c.corner[k];
      const int o = d < 0 ? -1 : d >= size ? 1 : 0;
      slot += (o + 1) * scale;
      scale *= 3;
    }
    if (!inside_root || nb[static_cast<std::size_t>(slot)] == kNone) continue;
    const std::uint32_t idx =
        descend(cells_, nb[static_cast<std::size_t>(slot)],
                {static_cast<std::uint32_t>(q[0]), static_cast<std::uint32_t>(q[1]), static_cast<std::uint32_t>(q[2])}, level);
    if (cells_[idx].kind != CellKind::Internal) continue;  // a leaf at least as long as the segment
    int top = 0;
    stack[top++] = idx;
    while (top > 0) {
      const Cell& n = cells_[stack[--top]];
      const std::uint32_t s = n.size();
      if (n.kind != CellKind::Internal) {
        for (std::uint32_t t : {n.corner[axis], n.corner[axis] + s})
          if (t0 < t && t < t1) out.push_back(t);
        continue;
      }
      // Children along the line: the ones whose u and v ranges end or start on it.
      for (std::uint32_t b = 0; b < 8; ++b) {
        const Cell& ch = cells_[n.children + b];
        const std::uint32_t cs = ch.size();
        const bool on_u = ch.corner[u] == on[u] || ch.corner[u] + cs == on[u];
        const bool on_v = ch.corner[v] == on[v] || ch.corner[v] + cs == on[v];
        if (on_u && on_v) stack[top++] = n.children + b;
      }
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace genmod::implicit
