// Algorithm 5.3, implicit curve approximation (snyder.md section 5.2). See implicit_curve.hpp.
#include "genmod/solvers/implicit_curve.hpp"

#include "genmod/solvers/aggregation.hpp"

#include "genmod/kernel/inclusion.hpp"
#include "genmod/solvers/constraint_solver.hpp"
#include "genmod/solvers/interval_newton.hpp"

#include "union_find.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace genmod {

std::string_view curve_box_status_name(CurveBoxStatus s) noexcept {
  switch (s) {
    case CurveBoxStatus::Proximate: return "proximate";
    case CurveBoxStatus::Unresolved: return "unresolved";
    case CurveBoxStatus::Unexplored: return "unexplored";
  }
  return "?";
}

std::string_view curve_end_name(CurveEnd e) noexcept {
  switch (e) {
    case CurveEnd::None: return "none";
    case CurveEnd::Boundary: return "boundary";
    case CurveEnd::Unresolved: return "unresolved";
  }
  return "?";
}

namespace {


// Boxes closer than tol in every side are one point (aggregation's touches()). Boxes of one
// true point always overlap (each holds it); tol also merges a crossing found at distance ~
// rounding from a kd-tree corner on two faces (the curve then cuts the corner through a piece
// of length ~ 1e-16 that no slice solve can certify).
bool boxes_overlap(const Box& a, const Box& b, double tol) { return touches(a, b, tol); }

using detail::UnionFind;

// Unions overlapping boxes (sweep over the lower bound of side 0).
void unite_overlapping(const std::vector<Box>& boxes, std::span<const std::size_t> ids, double tol, UnionFind& uf) {
  std::vector<std::size_t> order(ids.begin(), ids.end());
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return boxes[a][0].lo() < boxes[b][0].lo() || (boxes[a][0].lo() == boxes[b][0].lo() && a < b);
  });
  for (std::size_t i = 0; i < order.size(); ++i)
    for (std::size_t j = i + 1; j < order.size() && boxes[order[j]][0].lo() - tol <= boxes[order[i]][0].hi(); ++j)
      if (boxes_overlap(boxes[order[i]], boxes[order[j]], tol)) uf.unite(order[i], order[j]);
}

struct Link {
  std::size_t a, b;             // point-box indices
  bool has_sample = false;
  std::vector<double> sample;   // slice point (coords order)
};

enum class SliceAnswer { None, Link, Ambiguous };

class CurveBuilder {
 public:
  CurveBuilder(const Fn& F, std::span<const int> coords, const Box& X, const ImplicitCurveOptions& opt)
      : coords_(coords.begin(), coords.end()), n_(coords.size()), X_(X), opt_(opt), incl_(F, coords),
        constraint_(eq(F, 0.0)), eq_fn_(F) {
    min_width_ = opt.min_width > 0 ? opt.min_width : opt.acceptance_width * 1e-4;
    double scale = 0;
    for (const Interval& s : X) scale = std::max(scale, s.width());
    point_opt_.epsilon = opt.point_epsilon * scale;
    merge_tol_ = point_opt_.epsilon;
    touch_tol_ = std::max(merge_tol_, opt.touch_tolerance * scale);
    point_opt_.threads = 1;
    point_opt_.limits.max_boxes = 20000;
    point_opt_.limits.max_depth = 200;
    point_opt_.limits.cancel = opt.limits.cancel;
    periodic_.assign(n_, false);
    newton_.resize(n_);
    for (int p : opt.periodic) {
      const auto it = std::find(coords_.begin(), coords_.end(), p);
      periodic_[static_cast<std::size_t>(it - coords_.begin())] = true;
    }
  }

  ImplicitCurve run();

 private:
  struct Work {
    Box box;
    int depth;
  };

  bool limit_reached();
  void split_or_unresolved(const Work& w, std::deque<Work>& work);
  bool solve_face(const Box& Y, std::size_t j, bool high, std::vector<std::size_t>& out);
  void merge_touching_fragments(std::vector<Box>& found, std::vector<bool>& certified) const;
  SliceAnswer solve_slice(const Box& Y, std::size_t k, double c, std::vector<double>& sample);
  Box refine(std::size_t fixed, double c, const SolutionComponent& comp);
  bool process(const Work& w, const std::vector<int>& candidates, std::vector<Link>& links, int& param);
  void assemble();

  std::vector<int> coords_;
  std::size_t n_;
  Box X_;
  ImplicitCurveOptions opt_;
  InclusionFunction incl_;
  Fn constraint_;
  Fn eq_fn_;  // F itself (the square systems for interval Newton)
  double min_width_ = 0;
  SolveOptions point_opt_;
  double merge_tol_ = 0;
  double touch_tol_ = 0;  // uncertified fragments of one face point (merge_touching_fragments)
  std::vector<bool> periodic_;
  LimitWatch watch_{opt_.limits};

  std::vector<std::optional<IntervalNewton>> newton_;  // per fixed coordinate
  std::vector<Box> points_;  // boundary-intersection boxes (n sides each)
  std::map<std::vector<double>, std::pair<bool, std::vector<std::size_t>>> face_cache_;
  std::vector<Link> links_;
  ImplicitCurve out_;
};

bool CurveBuilder::limit_reached() {
  SearchReport& r = out_.report;
  if (r.limit != LimitHit::None && r.limit != LimitHit::MaxDepth) return true;
  const LimitHit hit = watch_.reached(r.boxes_processed);
  if (hit == LimitHit::None) return false;
  if (r.limit == LimitHit::None) r.limit = hit;
  return true;
}

void CurveBuilder::split_or_unresolved(const Work& w, std::deque<Work>& work) {
  const double wd = width(w.box);
  if (wd > min_width_ && w.depth < opt_.limits.max_depth) {
    auto [a, b] = bisect(w.box, widest_side(w.box));
    work.push_back({std::move(a), w.depth + 1});
    work.push_back({std::move(b), w.depth + 1});
    return;
  }
  if (w.depth >= opt_.limits.max_depth && out_.report.limit == LimitHit::None) out_.report.limit = LimitHit::MaxDepth;
  out_.boxes.push_back({w.box, CurveBoxStatus::Unresolved, w.depth, -1, 0});
  ++out_.stats.unresolved;

}

// solve() accepts a certified box as soon as Krawczyk succeeds, whatever its width: narrow it
// with interval Newton (the unique zero stays inside). Returns the component's sides for the
// unknowns (all but `fixed`).
Box CurveBuilder::refine(std::size_t fixed, double c, const SolutionComponent& comp) {
  Box b = comp.hull;
  if (!comp.unique || width(b) <= point_opt_.epsilon) return b;
  if (!newton_[fixed]) {
    std::vector<int> unknowns;
    for (std::size_t i = 0; i < n_; ++i)
      if (i != fixed) unknowns.push_back(coords_[i]);
    const int param[] = {coords_[fixed]};
    newton_[fixed].emplace(eq_fn_, unknowns, param);
  }
  Box nb = b;
  nb.push_back(Interval(c, c));
  for (int it = 0; it < 60 && width(std::span<const Interval>(nb.data(), n_ - 1)) > point_opt_.epsilon; ++it) {
    const double before = width(std::span<const Interval>(nb.data(), n_ - 1));
    if (newton_[fixed]->contract(nb) != NewtonStatus::Contracted) break;
    for (std::size_t i = 0; i + 1 < nb.size(); ++i)
      if (nb[i].is_empty()) return b;  // cannot happen for a certified box; keep the hull
    if (!(width(std::span<const Interval>(nb.data(), n_ - 1)) < 0.9 * before)) break;
  }
  nb.pop_back();
  return nb;
}

// Where the curve touches a face tangentially, the face system has a double root: its
// residual is quadratic there, so the solver cannot exclude boxes over a spread of about
// sqrt(rounding) around the touching point and returns them as several uncertified fragments
// (a few 1e-9 apart on the acceptance suite's cylinders). They are one boundary point: the
// uncertified components closer than the touch tolerance are replaced by their hull (single
// linkage). Certified components are never merged. Merging keeps every box's points, and
// whether the curve touches, crosses twice inside the hull or passes just short of the face, it
// is one arc through that hull, so the links stay right; two distinct branches merged by it
// would show as a branch node (complete() false), not as a wrong curve.
void CurveBuilder::merge_touching_fragments(std::vector<Box>& found, std::vector<bool>& certified) const {
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t a = 0; a < found.size() && !merged; ++a)
      for (std::size_t b = a + 1; b < found.size() && !merged; ++b)
        if (!certified[a] && !certified[b] && touches(found[a], found[b], touch_tol_)) {
          found[a] = hull(found[a], found[b]);
          found.erase(found.begin() + static_cast<std::ptrdiff_t>(b));
          certified.erase(certified.begin() + static_cast<std::ptrdiff_t>(b));
          merged = true;
        }
  }
}

// Boundary intersections on the face x_j = (high ? hi : lo) of Y: the (n-1)-unknown system
// F = 0 with x_j a fixed parameter. False when the solve did not finish.
bool CurveBuilder::solve_face(const Box& Y, std::size_t j, bool high, std::vector<std::size_t>& out) {
  const double c = high ? Y[j].hi() : Y[j].lo();
  std::vector<double> key;
  key.reserve(2 * n_);
  key.push_back(static_cast<double>(j));
  key.push_back(c);
  for (std::size_t i = 0; i < n_; ++i)
    if (i != j) {
      key.push_back(Y[i].lo());
      key.push_back(Y[i].hi());
    }
  if (auto it = face_cache_.find(key); it != face_cache_.end()) {
    ++out_.stats.face_cache_hits;
    out.insert(out.end(), it->second.second.begin(), it->second.second.end());
    return it->second.first;
  }
  ++out_.stats.face_solves;
  std::vector<int> unknowns;
  Box sub;
  for (std::size_t i = 0; i < n_; ++i)
    if (i != j) {
      unknowns.push_back(coords_[i]);
      sub.push_back(Y[i]);
    }
  FreeParameters fixed{{coords_[j]}, {Interval(c, c)}};
  const SolveResult r = solve(constraint_, unknowns, sub, point_opt_, fixed);
  std::vector<Box> found;
  std::vector<bool> certified;
  for (const SolutionComponent& comp : r.components) {
    found.push_back(refine(j, c, comp));
    certified.push_back(comp.unique);
  }
  merge_touching_fragments(found, certified);
  std::vector<std::size_t> ids;
  for (const Box& h : found) {
    Box p;
    for (std::size_t i = 0, q = 0; i < n_; ++i) p.push_back(i == j ? Interval(c, c) : h[q++]);
    ids.push_back(points_.size());
    points_.push_back(std::move(p));
  }
  const bool ok = r.complete();
  out.insert(out.end(), ids.begin(), ids.end());
  face_cache_.emplace(std::move(key), std::make_pair(ok, std::move(ids)));
  return ok;
}

// Does the slice x_k = c of Y hold a curve point? Certified yes (one unique component), proved
// no (nothing returned by a complete solve), or undecided.
SliceAnswer CurveBuilder::solve_slice(const Box& Y, std::size_t k, double c, std::vector<double>& sample) {
  ++out_.stats.slice_solves;
  std::vector<int> unknowns;
  Box sub;
  for (std::size_t i = 0; i < n_; ++i)
    if (i != k) {
      unknowns.push_back(coords_[i]);
      sub.push_back(Y[i]);
    }
  FreeParameters fixed{{coords_[k]}, {Interval(c, c)}};
  const SolveResult r = solve(constraint_, unknowns, sub, point_opt_, fixed);
  if (!r.complete()) return SliceAnswer::Ambiguous;
  if (r.components.empty()) return SliceAnswer::None;
  if (r.components.size() != 1 || !r.components[0].unique) return SliceAnswer::Ambiguous;
  const Box h = refine(k, c, r.components[0]);
  sample.assign(n_, c);
  for (std::size_t i = 0, q = 0; i < n_; ++i)
    if (i != k) sample[i] = h[q++].mid();
  return SliceAnswer::Link;
}

// Steps 3-5 on a narrow parameterizable box. False: the box must be bisected (or is unresolved).
bool CurveBuilder::process(const Work& w, const std::vector<int>& candidates, std::vector<Link>& links, int& param) {
  const Box& Y = w.box;
  std::vector<std::size_t> ids;
  for (std::size_t j = 0; j < n_; ++j)
    for (bool high : {false, true})
      if (!solve_face(Y, j, high, ids)) return false;
  // Points found on several faces of Y (corners) are one boundary intersection: group them.
  UnionFind uf(points_.size());
  unite_overlapping(points_, ids, merge_tol_, uf);
  std::map<std::size_t, Box> groups;  // root -> hull
  for (std::size_t id : ids) {
    const std::size_t r = uf.find(id);
    auto [it, fresh] = groups.emplace(r, points_[id]);
    if (!fresh) it->second = hull(it->second, points_[id]);
  }
  links.clear();
  param = candidates.empty() ? -1 : candidates[0];
  if (groups.size() <= 1) return true;  // no piece of curve enters Y (Step 5: 0 or 1 points)
  std::vector<std::pair<std::size_t, Box>> pts(groups.begin(), groups.end());
  for (int k : candidates) {
    const auto kk = static_cast<std::size_t>(k);
    std::sort(pts.begin(), pts.end(), [&](const auto& a, const auto& b) {
      return a.second[kk].lo() < b.second[kk].lo() || (a.second[kk].lo() == b.second[kk].lo() && a.first < b.first);
    });
    bool sortable = true;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i)
      if (!(pts[i].second[kk].hi() < pts[i + 1].second[kk].lo())) sortable = false;
    if (!sortable) continue;
    std::vector<Link> found;
    bool ok = true;
    // Heuristic test, step 5: the hyperplane through each inner boundary point meets the curve
    // only there, so no point before it can connect to one after it.
    if (opt_.parameterizability == ImplicitCurveOptions::Test::Heuristic)
      for (std::size_t i = 1; i + 1 < pts.size() && ok; ++i) {
        std::vector<double> unused;
        ok = solve_slice(Y, kk, pts[i].second[kk].mid(), unused) == SliceAnswer::Link;
      }
    for (std::size_t i = 0; i + 1 < pts.size() && ok; ++i) {
      const double c = 0.5 * (pts[i].second[kk].hi() + pts[i + 1].second[kk].lo());
      std::vector<double> sample;
      switch (solve_slice(Y, kk, c, sample)) {
        case SliceAnswer::None: break;
        case SliceAnswer::Link: found.push_back({pts[i].first, pts[i + 1].first, opt_.slice_samples, sample}); break;
        case SliceAnswer::Ambiguous: ok = false; break;
      }
    }
    if (!ok) continue;
    links = std::move(found);
    param = k;
    return true;
  }
  return false;
}

ImplicitCurve CurveBuilder::run() {
  std::deque<Work> work;
  work.push_back({X_, 0});
  std::vector<Interval> jac;
  std::vector<Link> links;
  while (!work.empty()) {
    Work w = std::move(work.front());
    work.pop_front();
    if (limit_reached()) {
      out_.boxes.push_back({std::move(w.box), CurveBoxStatus::Unexplored, w.depth, -1, 0});
      ++out_.stats.unexplored;
      continue;
    }
    ++out_.report.boxes_processed;
    out_.report.deepest = std::max(out_.report.deepest, w.depth);
    const std::vector<Interval> range = incl_.eval(w.box, kAllForms, &jac);
    bool excluded = false;
    for (const Interval& v : range)
      if (v.is_empty() || !v.contains_zero()) excluded = true;
    if (excluded) continue;  // Step 1: no curve in the box
    if (!(width(w.box) < opt_.acceptance_width)) {
      if (w.depth >= opt_.limits.max_depth) {
        split_or_unresolved(w, work);
      } else {
        auto [a, b] = bisect(w.box, widest_side(w.box));
        work.push_back({std::move(a), w.depth + 1});
        work.push_back({std::move(b), w.depth + 1});
      }
      continue;
    }
    std::vector<int> candidates;  // Step 2: Theorem 5.5, or every coordinate for the heuristic test
    const bool heuristic = opt_.parameterizability == ImplicitCurveOptions::Test::Heuristic;
    if (heuristic || jac.size() == (n_ - 1) * n_)
      for (std::size_t k = 0; k < n_; ++k)
        if (heuristic || jacobian_minor_regular(jac, n_ - 1, k)) candidates.push_back(static_cast<int>(k));
    int param = -1;
    if (candidates.empty() || !process(w, candidates, links, param)) {
      split_or_unresolved(w, work);
      continue;
    }
    out_.boxes.push_back({w.box, CurveBoxStatus::Proximate, w.depth, param, links.size()});
    ++out_.stats.proximate;
    for (Link& l : links) links_.push_back(std::move(l));
  }
  assemble();
  out_.report.seconds = watch_.seconds();
  return std::move(out_);
}

// Step 6: nodes (overlapping point boxes and their periodic images), and the walk into polylines.
void CurveBuilder::assemble() {
  const std::size_t np = points_.size();
  const double tol = merge_tol_;
  // Nodes: point boxes that overlap (up to tol), directly or through a periodic image (each
  // point box touching the high end of periodic sides is also compared shifted down by the
  // period, for every subset of those sides: a corner of a doubly periodic domain is one point).
  UnionFind uf(np);
  std::vector<std::size_t> all(np);
  std::iota(all.begin(), all.end(), std::size_t{0});
  unite_overlapping(points_, all, tol, uf);
  std::vector<std::size_t> per;
  for (std::size_t i = 0; i < n_; ++i)
    if (periodic_[i]) per.push_back(i);
  if (!per.empty()) {
    std::vector<std::size_t> low;  // boxes touching a low end of a periodic side
    for (std::size_t p = 0; p < np; ++p)
      for (std::size_t i : per)
        if (points_[p][i].lo() <= X_[i].lo() + tol) {
          low.push_back(p);
          break;
        }
    for (std::size_t p = 0; p < np; ++p) {
      std::vector<std::size_t> high;
      for (std::size_t i : per)
        if (points_[p][i].hi() >= X_[i].hi() - tol) high.push_back(i);
      for (std::size_t mask = 1; mask < (std::size_t{1} << high.size()); ++mask) {
        Box img = points_[p];
        for (std::size_t b = 0; b < high.size(); ++b)
          if (mask & (std::size_t{1} << b)) {
            const std::size_t i = high[b];
            const double period = X_[i].hi() - X_[i].lo();
            // The image at the low end; its side always holds X_i.lo (rounding of the shift).
            img[i] = hull(Interval(img[i].lo() - period, img[i].hi() - period), Interval(X_[i].lo()));
          }
        for (std::size_t q : low)
          if (q != p && boxes_overlap(img, points_[q], tol)) uf.unite(p, q);
      }
    }
  }
  // Images: within a node, the point boxes that overlap without a shift (one position each).
  UnionFind img(np);
  {
    std::map<std::size_t, std::vector<std::size_t>> members;
    for (std::size_t p = 0; p < np; ++p) members[uf.find(p)].push_back(p);
    for (auto& [root, ms] : members) unite_overlapping(points_, ms, tol, img);
  }
  std::map<std::size_t, Box> meet, hulls;  // per image root
  for (std::size_t p = 0; p < np; ++p) {
    const std::size_t r = img.find(p);
    auto [it, fresh] = meet.emplace(r, points_[p]);
    auto [ht, hfresh] = hulls.emplace(r, points_[p]);
    if (!fresh)
      for (std::size_t i = 0; i < n_; ++i) it->second[i] = intersect(it->second[i], points_[p][i]);
    if (!hfresh) ht->second = hull(ht->second, points_[p]);
  }
  // A point's position: per side, the midpoint of the intersection of its image's boxes (each
  // holds the true point, so this is usually tighter than the hull), else of the hull.
  auto position = [&](std::size_t p) {
    const std::size_t r = img.find(p);
    const Box& m = meet.at(r);
    const Box& h = hulls.at(r);
    std::vector<double> pos(n_);
    for (std::size_t i = 0; i < n_; ++i) pos[i] = (m[i].is_empty() ? h[i] : m[i]).mid();
    return pos;
  };

  struct Edge {
    std::size_t a, b;  // point boxes
    const Link* link;
  };
  std::vector<Edge> edges;
  std::map<std::size_t, std::vector<std::size_t>> adj;  // node root -> edges
  for (const Link& l : links_) {
    adj[uf.find(l.a)].push_back(edges.size());
    adj[uf.find(l.b)].push_back(edges.size());
    edges.push_back({l.a, l.b, &l});
  }
  out_.stats.nodes = adj.size();
  for (const auto& [v, es] : adj)
    if (es.size() > 2) ++out_.stats.branch_nodes;
  std::map<std::size_t, bool> boundary;  // node root -> touches a non-periodic side of X
  for (std::size_t p = 0; p < np; ++p) {
    bool on = false;
    for (std::size_t i = 0; i < n_; ++i)
      if (!periodic_[i] && (points_[p][i].lo() <= X_[i].lo() || points_[p][i].hi() >= X_[i].hi())) on = true;
    boundary[uf.find(p)] |= on;
  }
  auto end_kind = [&](std::size_t v) {
    return adj.at(v).size() == 1 && boundary[v] ? CurveEnd::Boundary : CurveEnd::Unresolved;
  };

  std::vector<bool> used(edges.size(), false);
  // Follows unused edges from node `start` along edge `e`; stops at a node without exactly 2
  // links or when no unused edge is left. Returns the last node and the point box arrived at.
  auto walk = [&](std::size_t start, std::size_t e, Polyline& pl) {
    std::size_t from = uf.find(edges[e].a) == start ? edges[e].a : edges[e].b;
    pl.points.push_back(position(from));
    while (true) {
      used[e] = true;
      const Edge& ed = edges[e];
      const std::size_t to = ed.a == from ? ed.b : ed.a;
      if (ed.link->has_sample) pl.points.push_back(ed.link->sample);
      pl.points.push_back(position(to));
      const std::size_t cur = uf.find(to);
      const auto& es = adj.at(cur);
      std::size_t ne = edges.size();
      if (es.size() == 2)
        for (std::size_t f : es)
          if (!used[f]) ne = f;
      if (ne == edges.size()) return std::make_pair(cur, to);
      e = ne;
      from = uf.find(edges[e].a) == cur && (uf.find(edges[e].b) != cur || edges[e].a != to) ? edges[e].a : edges[e].b;
      if (img.find(from) != img.find(to)) {  // leaves through another periodic image
        pl.wraps.push_back(pl.points.size() - 1);
        pl.points.push_back(position(from));
      }
    }
  };
  for (const auto& [v, es] : adj) {
    if (es.size() == 2) continue;
    for (std::size_t e : es) {
      if (used[e]) continue;
      Polyline pl;
      const auto [last, arrived] = walk(v, e, pl);
      (void)arrived;
      pl.front = end_kind(v);
      pl.back = end_kind(last);
      out_.components.push_back(std::move(pl));
    }
  }
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (used[e]) continue;
    Polyline pl;
    const std::size_t start = uf.find(edges[e].a);
    const auto [last, arrived] = walk(start, e, pl);
    if (last == start) {
      pl.closed = true;
      if (img.find(arrived) == img.find(edges[e].a))
        pl.points.pop_back();  // the start again
      else
        pl.wraps.push_back(pl.points.size() - 1);  // closes through a periodic image
    } else {  // cannot happen with degrees <= 2; report it as an unresolved open piece
      pl.front = pl.back = CurveEnd::Unresolved;
    }
    out_.components.push_back(std::move(pl));
  }
}

}  // namespace

ImplicitCurve approximate_implicit_curve(const Fn& F, Coordinates coords, const Box& X,
                                         const ImplicitCurveOptions& options) {
  const std::string who = "approximate_implicit_curve";
  const std::size_t n = coords.size();
  if (n < 2) throw std::invalid_argument("genmod: " + who + ": need at least 2 coordinates");
  if (F.dim() != n - 1)
    throw std::invalid_argument("genmod: " + who + ": F has " + std::to_string(F.dim()) + " components, expected " +
                                std::to_string(n - 1) + " (coords.size() - 1)");
  std::uint64_t mask = 0;
  for (int c : coords) {
    if (c < 0 || c >= 64) throw std::invalid_argument("genmod: " + who + ": coordinate " + std::to_string(c) + " out of range");
    if (mask & (std::uint64_t{1} << c))
      throw std::invalid_argument("genmod: " + who + ": coordinate " + std::to_string(c) + " listed twice");
    mask |= std::uint64_t{1} << c;
  }
  if (F.input_mask() & ~mask) {
    for (int i : F.inputs())
      if (!(mask & (std::uint64_t{1} << i)))
        throw std::invalid_argument("genmod: " + who + ": F depends on x(" + std::to_string(i) + "), which is not in coords");
  }
  check_search_box(X, n, who);
  if (!(options.acceptance_width > 0)) throw std::invalid_argument("genmod: " + who + ": acceptance_width must be > 0");
  if (!(options.touch_tolerance >= 0)) throw std::invalid_argument("genmod: " + who + ": touch_tolerance must be >= 0");
  if (!(options.point_epsilon > 0)) throw std::invalid_argument("genmod: " + who + ": point_epsilon must be > 0");
  if (!(options.min_width >= 0)) throw std::invalid_argument("genmod: " + who + ": min_width must be >= 0");
  for (int p : options.periodic)
    if (p < 0 || p >= 64 || !(mask & (std::uint64_t{1} << p)))
      throw std::invalid_argument("genmod: " + who + ": periodic coordinate " + std::to_string(p) + " is not in coords");
  CurveBuilder b(F, coords, X, options);
  return b.run();
}

}  // namespace genmod
