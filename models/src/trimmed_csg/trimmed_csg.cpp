// Algorithm 5.4 (CSG-like operations with trimmed surfaces), see trimmed_csg.hpp for the steps.
#include "genmod/models/trimmed_csg.hpp"

#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/solvers/queries.hpp"
#include "genmod/tessellate/kd_tree.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace genmod::models {
namespace {

struct VInfo {
  long id = -1;
};
struct FInfo {
  int region = -1;
};
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VInfo, K>;
using Fb0 = CGAL::Constrained_triangulation_face_base_2<K>;
using Fb = CGAL::Triangulation_face_base_with_info_2<FInfo, K, Fb0>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using P2 = K::Point_2;

// One vertex of an intersection chain: (u, v, s, t) and the mesh vertex it is.
struct ChainVertex {
  std::array<double, 4> p;
  std::uint32_t id;
};
struct Chain {
  std::vector<ChainVertex> v;
  std::vector<int> jump;  // jump[k]: the coordinate that jumps on edge k -> k+1 (cyclic), or -1
};

struct Evaluator3 {
  Tape tape;
  PointEvaluator ev;
  explicit Evaluator3(const Fn& f) : tape(f, std::vector<int>{0, 1}) {}
  std::array<double, 3> at(double a, double b) {
    const double in[2] = {a, b};
    auto y = ev.eval(tape, std::span<const double>(in, 2));
    return {y[0], y[1], y[2]};
  }
};

double seg_dist2(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay;
  const double l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const double ex = ax + t * dx - px, ey = ay + t * dy - py;
  return ex * ex + ey * ey;
}

// The adaptive sampling kd-tree (Step 5): a leaf is accepted when the interval box of the
// surface over it is at most `tol` wide in every coordinate, or at max_depth.
KdTree sampling_tree(const Fn& surface, double tol, int max_depth, std::size_t& capped) {
  const KdBox domain{Interval(0, 1), Interval(0, 1)};
  KdTree tree = KdTree::full(domain);
  const Tape tape(surface, std::vector<int>{0, 1});
  IntervalEvaluator iev;
  std::vector<std::pair<KdTree::Index, int>> stack{{tree.root(), 0}};
  while (!stack.empty()) {
    const auto [leaf, depth] = stack.back();
    stack.pop_back();
    const KdBox box = tree.box(leaf);
    auto y = iev.eval(tape, std::span<const Interval>(box));
    double w = 0.0;
    for (std::size_t j = 0; j < 3; ++j) w = std::max(w, std::isfinite(y[j].width()) ? y[j].width() : 1e300);
    if (w <= tol) continue;
    if (depth >= max_depth) {
      ++capped;
      continue;
    }
    const auto kids = tree.split(leaf, static_cast<std::size_t>(depth % 2));
    stack.push_back({kids[0], depth + 1});
    stack.push_back({kids[1], depth + 1});
  }
  return tree;
}

struct Builder {
  std::vector<std::array<double, 3>> verts;
  std::uint32_t add(const std::array<double, 3>& p) {
    verts.push_back(p);
    return static_cast<std::uint32_t>(verts.size() - 1);
  }
};

struct Piece {
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::size_t classifications = 0, unknown = 0, capped = 0, inside_curve_leaves = 0;
};

// Steps 5-7 for one surface: coords (c0, c1) of the chains are its parameters.
// One intersection curve of the surface with another: its chains, the coordinates of the
// surface's parameters in them, and the 4-D kd-tree of its proximate boxes.
struct CurveUse {
  const std::vector<Chain>* chains;
  int c0, c1;
  const KdTree* tree;
};

Piece trim_piece(const std::vector<ClosedSurface>& all, std::size_t index, const std::vector<CurveUse>& uses,
                 const CsgSolid& solid, const TrimmedCsgOptions& options, Builder& b) {
  Piece out;
  const ClosedSurface& surf = all[index];
  Evaluator3 eval(surf.surface);
  // Step 2: the projected intersection kd-trees; Step 6: merged with the sampling tree
  // add-only, so that no intersection leaf is subdivided.
  KdTree merged(KdBox{Interval(0, 1), Interval(0, 1)});
  std::vector<KdBox> curve_leaves;
  for (const CurveUse& use : uses) {
    const std::size_t keep[2] = {static_cast<std::size_t>(use.c0), static_cast<std::size_t>(use.c1)};
    const KdTree projected = project(*use.tree, keep);
    if (projected.empty()) continue;
    for (KdTree::Index l : projected.leaves()) curve_leaves.push_back(projected.box(l));
    if (merged.empty())
      merged = projected;
    else
      merge_addonly(merged, projected);
  }
  const KdTree samp = sampling_tree(surf.surface, options.tolerance, options.max_depth, out.capped);
  if (merged.empty())
    merged = samp;
  else
    merge_addonly(merged, samp);

  // Constraint segments in this surface's parameters.
  struct Seg {
    const ChainVertex *a, *b;
    double ax, ay, bx, by;
  };
  std::vector<Seg> segs;
  std::vector<double> lengths;
  for (const CurveUse& use : uses)
    for (const Chain& ch : *use.chains) {
      const int c0 = use.c0, c1 = use.c1;
      const std::size_t n = ch.v.size();
      for (std::size_t k = 0; k < n; ++k) {
        const ChainVertex& a = ch.v[k];
        const ChainVertex& q = ch.v[(k + 1) % n];
        if (ch.jump[k] == c0 || ch.jump[k] == c1 || a.id == q.id) continue;
        segs.push_back({&a, &q, a.p[c0], a.p[c1], q.p[c0], q.p[c1]});
        lengths.push_back(std::hypot(q.p[c1] - a.p[c1], q.p[c0] - a.p[c0]));
      }
    }
  double clear = 0.0;
  if (!lengths.empty()) {
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    clear = 0.3 * lengths[lengths.size() / 2];
  }
  const double clear2 = clear * clear;
  auto clear_of_curve = [&](double x, double y) {
    for (const Seg& s : segs)
      if (seg_dist2(x, y, s.ax, s.ay, s.bx, s.by) < clear2) return false;
    return true;
  };
  auto inside_curve_leaf = [&](double x, double y) {
    for (const KdBox& bx : curve_leaves)
      if (x > bx[0].lo() && x < bx[0].hi() && y > bx[1].lo() && y < bx[1].hi()) return true;
    return false;
  };

  // Sample points: the corners of the merged tree's leaves (no corner lies inside an
  // intersection leaf, which is never subdivided), clear of the curve.
  std::set<std::pair<double, double>> pts;
  for (KdTree::Index l : merged.leaves()) {
    const KdBox bx = merged.box(l);
    for (double x : {bx[0].lo(), bx[0].hi()})
      for (double y : {bx[1].lo(), bx[1].hi()}) pts.insert({x, y});
  }
  std::set<std::pair<double, double>> kept;
  auto is_corner = [](double x, double y) { return (x == 0 || x == 1) && (y == 0 || y == 1); };
  // Step 6's invariant: no leaf corner lies strictly inside an intersection leaf.
  for (auto [x, y] : pts)
    if (inside_curve_leaf(x, y)) ++out.inside_curve_leaves;
  for (auto [x, y] : pts) {
    if (is_corner(x, y)) {
      kept.insert({x, y});
      continue;
    }
    if ((surf.periodic_u && (x == 0 || x == 1)) || (surf.periodic_v && (y == 0 || y == 1))) continue;
    if (!inside_curve_leaf(x, y) && clear_of_curve(x, y)) kept.insert({x, y});
  }
  // Periodic sides: the same samples on both ends, so that they weld.
  auto pair_side = [&](bool along_u) {
    std::set<double> values;
    for (auto [x, y] : pts) {
      const double side = along_u ? x : y, other = along_u ? y : x;
      if ((side == 0 || side == 1) && other != 0 && other != 1) values.insert(other);
    }
    for (double w : values) {
      const double x0 = along_u ? 0.0 : w, y0 = along_u ? w : 0.0;
      const double x1 = along_u ? 1.0 : w, y1 = along_u ? w : 1.0;
      if (inside_curve_leaf(x0, y0) || inside_curve_leaf(x1, y1) || !clear_of_curve(x0, y0) ||
          !clear_of_curve(x1, y1))
        continue;
      kept.insert({x0, y0});
      kept.insert({x1, y1});
    }
  };
  if (surf.periodic_u) pair_side(true);
  if (surf.periodic_v) pair_side(false);

  // Mesh vertices of the samples (periodic ends and degenerate sides welded).
  std::map<std::pair<double, double>, std::uint32_t> ids;
  auto canon = [&](double x, double y) {
    if (surf.periodic_u && x == 1) x = 0;
    if (surf.periodic_v && y == 1) y = 0;
    return std::make_pair(x, y);
  };
  for (auto [x, y] : kept) {
    const auto key = canon(x, y);
    if (!ids.count(key)) ids[key] = b.add(eval.at(key.first, key.second));
  }
  // A side whose samples are all one point (a pole) becomes one vertex.
  std::map<std::uint32_t, std::uint32_t> alias;
  for (int side = 0; side < 4; ++side) {
    const bool along_u = side < 2;
    if ((along_u && surf.periodic_u) || (!along_u && surf.periodic_v)) continue;
    const double at = (side % 2 == 0) ? 0.0 : 1.0;
    std::vector<std::uint32_t> on;
    for (auto& [key, id] : ids)
      if ((along_u ? key.first : key.second) == at) on.push_back(id);
    if (on.size() < 2) continue;
    bool one = true;
    for (std::uint32_t id : on)
      for (int j = 0; j < 3; ++j)
        if (std::abs(b.verts[id][j] - b.verts[on[0]][j]) > 1e-9) one = false;
    if (one)
      for (std::uint32_t id : on) alias[id] = on[0];
  }
  auto final_id = [&](long id) {
    const auto it = alias.find(static_cast<std::uint32_t>(id));
    return it == alias.end() ? static_cast<std::uint32_t>(id) : it->second;
  };

  // Step 7: the constrained triangulation of the samples and the projected curve.
  // The curve's vertices first: a sample at the same parameters is the curve's vertex.
  CDT cdt;
  std::map<const ChainVertex*, CDT::Vertex_handle> handles;
  for (const CurveUse& use : uses)
    for (const Chain& ch : *use.chains)
      for (const ChainVertex& cv : ch.v) {
        auto vh = cdt.insert(P2(cv.p[use.c0], cv.p[use.c1]));
        if (vh->info().id < 0) vh->info().id = cv.id;
        handles[&cv] = vh;
      }
  for (auto [x, y] : kept) {
    auto vh = cdt.insert(P2(x, y));
    if (vh->info().id < 0) vh->info().id = ids.at(canon(x, y));
  }
  for (const Seg& s : segs) cdt.insert_constraint(handles.at(s.a), handles.at(s.b));
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (v->info().id < 0) throw std::runtime_error("trimmed_csg: projected intersection curves cross each other");

  // Regions between constraints, each classified once against the other solid.
  int regions = 0;
  std::vector<CDT::Face_handle> best;
  std::vector<double> best_area;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info().region >= 0) continue;
    const int r = regions++;
    best.push_back(f);
    best_area.push_back(-1.0);
    std::vector<CDT::Face_handle> work{f};
    f->info().region = r;
    while (!work.empty()) {
      CDT::Face_handle g = work.back();
      work.pop_back();
      const double area = std::abs(CGAL::area(g->vertex(0)->point(), g->vertex(1)->point(), g->vertex(2)->point()));
      if (area > best_area[r]) {
        best_area[r] = area;
        best[r] = g;
      }
      for (int i = 0; i < 3; ++i) {
        CDT::Face_handle h = g->neighbor(i);
        if (cdt.is_infinite(h) || h->info().region >= 0 || cdt.is_constrained(CDT::Edge(g, i))) continue;
        h->info().region = r;
        work.push_back(h);
      }
    }
  }
  // A region is on the result's boundary when the solid differs on the two sides of the
  // surface there (the other surfaces' insides fixed by one classification each); the result
  // lies on the surface's outer side when it holds only with the surface's inside false.
  std::vector<char> keep_region(regions, 0), flip_region(regions, 0);
  for (int r = 0; r < regions; ++r) {
    const CDT::Face_handle f = best[r];
    const P2 c = CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    const std::array<double, 3> p = eval.at(c.x(), c.y());
    std::vector<char> inside(all.size(), 0);
    for (std::size_t j = 0; j < all.size(); ++j) {
      if (j == index) continue;
      const Classification cl = classify_point(all[j].surface, p);
      ++out.classifications;
      if (cl.where != PointClass::Inside && cl.where != PointClass::Outside) {
        ++out.unknown;
        throw std::runtime_error("trimmed_csg: a region's point could not be classified");
      }
      inside[j] = cl.where == PointClass::Inside;
    }
    inside[index] = 1;
    const bool with = solid(inside);
    inside[index] = 0;
    const bool without = solid(inside);
    keep_region[r] = with != without;
    flip_region[r] = without;
    if (std::getenv("GENMOD_CSG_DEBUG"))
      std::fprintf(stderr, "surface %zu region %d at (%g %g) -> (%g %g %g) keep %d flip %d\n", index, r, c.x(), c.y(),
                   p[0], p[1], p[2], int(keep_region[r]), int(flip_region[r]));
  }
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!keep_region[f->info().region]) continue;
    const bool flip = flip_region[f->info().region];
    std::array<std::uint32_t, 3> t{final_id(f->vertex(0)->info().id), final_id(f->vertex(1)->info().id),
                                   final_id(f->vertex(2)->info().id)};
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
    if (flip) std::swap(t[1], t[2]);
    out.triangles.push_back(t);
  }
  return out;
}

}  // namespace

namespace {

// Steps 1-3 for one pair of surfaces.
struct PairCurve {
  std::vector<Chain> chains;
  KdTree tree{KdBox(4, Interval(0, 1))};
  std::size_t components = 0;
  bool complete = false;
};

PairCurve pair_curve(const ClosedSurface& first, const ClosedSurface& second, const TrimmedCsgOptions& options,
                     Builder& b, std::set<std::uint32_t>& seam) {
  PairCurve out;
  // Step 1: the intersection curve in (u, v, s, t).
  SurfaceIntersectionOptions co{.periodic_u = first.periodic_u, .periodic_v = first.periodic_v,
                                .periodic_s = second.periodic_u, .periodic_t = second.periodic_v, .curve = {}};
  co.curve.acceptance_width = options.curve_width;
  co.curve.limits.time_limit = options.curve_time;
  const bool periodic[] = {co.periodic_u, co.periodic_v, co.periodic_s, co.periodic_t};
  const SurfaceIntersection si = surface_intersection(first.surface, second.surface, {}, {}, co);
  out.complete = si.complete();
  if (!out.complete) throw std::runtime_error("trimmed_csg: the intersection curve is incomplete");
  out.components = si.curve.components.size();

  // Step 2: the 4-D kd-tree of the proximate boxes.
  const KdBox domain4(4, Interval(0, 1));
  for (const CurveBox& cb : si.curve.boxes)
    if (cb.status == CurveBoxStatus::Proximate) out.tree.insert_addonly(box_address(domain4, cb.box));

  // Step 3: chains with periodic crossings made explicit (one vertex on both sides of the cut).
  Evaluator3 eval_first(first.surface);
  std::vector<Chain>& chains = out.chains;
  for (const Polyline& pl : si.curve.components) {
    if (!pl.closed) throw std::runtime_error("trimmed_csg: an intersection curve is not closed");
    const std::size_t n = pl.points.size();
    const std::set<std::size_t> wraps(pl.wraps.begin(), pl.wraps.end());
    Chain ch;
    long reuse = -1;
    std::optional<std::array<double, 4>> next_image;
    for (std::size_t i = 0; i < n; ++i) {
      std::array<double, 4> p{}, q{};
      // Snapped onto the parameter rectangles' sides where within 1e-9 of them (so a curve
      // end on a side lies exactly on the triangulation's boundary).
      auto snap = [](double w) { return std::abs(w) < 1e-9 ? 0.0 : std::abs(w - 1.0) < 1e-9 ? 1.0 : w; };
      for (int c = 0; c < 4; ++c) {
        p[c] = snap(pl.points[i][c]);
        q[c] = snap(pl.points[(i + 1) % n][c]);
      }
      if (next_image) {
        p = *next_image;
        next_image.reset();
      }
      const std::uint32_t id = reuse >= 0 ? static_cast<std::uint32_t>(reuse) : b.add(eval_first.at(p[0], p[1]));
      reuse = -1;
      seam.insert(id);
      ch.v.push_back({p, id});
      ch.jump.push_back(-1);
      if (!wraps.count(i)) continue;
      int c = -1;
      double gap = 0.0;
      for (int pc = 0; pc < 4; ++pc)
        if (periodic[pc] && std::abs(q[pc] - p[pc]) > gap) gap = std::abs(q[pc] - p[pc]), c = pc;
      if (c < 0 || gap < 0.5) continue;
      const double side = p[c] > q[c] ? 1.0 : 0.0;
      if (std::abs(p[c] - side) < 1e-12 && std::abs(q[c] - (1.0 - side)) < 1e-12) {
        // The two points are the two images of one curve point.
        // The solver's two images may differ in the last bits of the other coordinates:
        // the second image is made p with only coordinate c changed, one vertex.
        ch.jump.back() = c;
        std::array<double, 4> image = p;
        image[c] = 1.0 - side;
        if (i + 1 < n) {
          reuse = id;
          next_image = image;
        } else {
          ch.v.front().id = id;  // closing edge: the first point is the same vertex
          ch.v.front().p = image;
        }
        continue;
      }
      std::array<double, 4> qq = q;
      qq[c] += side == 1.0 ? 1.0 : -1.0;
      const double lam = std::clamp((side - p[c]) / (qq[c] - p[c]), 0.0, 1.0);
      std::array<double, 4> x1{};
      for (int k = 0; k < 4; ++k) x1[k] = p[k] + lam * (qq[k] - p[k]);
      x1[c] = side;
      std::array<double, 4> x2 = x1;
      x2[c] = 1.0 - side;
      const std::uint32_t xid = b.add(eval_first.at(x1[0], x1[1]));
      seam.insert(xid);
      ch.v.push_back({x1, xid});
      ch.jump.push_back(c);
      ch.v.push_back({x2, xid});
      ch.jump.push_back(-1);
    }
    if (std::getenv("GENMOD_CSG_DEBUG")) {
      std::fprintf(stderr, "chain: %zu points, %zu vertices, wraps", n, ch.v.size());
      for (std::size_t w : pl.wraps)
        std::fprintf(stderr, " %zu:(%g %g %g %g)->(%g %g %g %g)", w, pl.points[w][0], pl.points[w][1], pl.points[w][2],
                     pl.points[w][3], pl.points[(w + 1) % n][0], pl.points[(w + 1) % n][1], pl.points[(w + 1) % n][2],
                     pl.points[(w + 1) % n][3]);
      std::fprintf(stderr, "\n");
    }
    chains.push_back(std::move(ch));
  }

  return out;
}

}  // namespace

TrimmedCsgResult trimmed_csg(const std::vector<ClosedSurface>& surfaces, const CsgSolid& solid,
                             const TrimmedCsgOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (surfaces.size() < 2) throw std::invalid_argument("trimmed_csg: needs at least two surfaces");
  TrimmedCsgResult result;
  Builder b;
  std::set<std::uint32_t> seam;
  // C(n, 2) runs of Steps 1-3 (the curves of different pairs must not meet).
  std::vector<PairCurve> curves;
  std::vector<std::vector<CurveUse>> uses(surfaces.size());
  curves.reserve(surfaces.size() * (surfaces.size() - 1) / 2);
  result.curve_complete = true;
  for (std::size_t i = 0; i < surfaces.size(); ++i)
    for (std::size_t j = i + 1; j < surfaces.size(); ++j) {
      curves.push_back(pair_curve(surfaces[i], surfaces[j], options, b, seam));
      const PairCurve& c = curves.back();
      result.curve_components += c.components;
      result.curve_complete = result.curve_complete && c.complete;
      uses[i].push_back({&c.chains, 0, 1, &c.tree});
      uses[j].push_back({&c.chains, 2, 3, &c.tree});
    }
  std::vector<Piece> pieces;
  for (std::size_t k = 0; k < surfaces.size(); ++k) {
    pieces.push_back(trim_piece(surfaces, k, uses[k], solid, options, b));
    result.classifications += pieces.back().classifications;
    result.capped_leaves += pieces.back().capped;
    result.samples_inside_curve_leaves += pieces.back().inside_curve_leaves;
    result.triangles_per_surface.push_back(pieces.back().triangles.size());
  }
  result.triangles_first = result.triangles_per_surface[0];
  result.triangles_second = result.triangles_per_surface[1];

  // Compact to the used vertices.
  std::vector<long> remap(b.verts.size(), -1);
  std::vector<int> users(b.verts.size(), 0);
  for (const Piece& piece : pieces) {
    std::vector<char> mark(b.verts.size(), 0);
    for (const auto& t : piece.triangles)
      for (std::uint32_t v : t) {
        mark[v] = 1;
        if (remap[v] < 0) {
          remap[v] = static_cast<long>(result.mesh.vertices.size());
          result.mesh.vertices.push_back(b.verts[v]);
        }
      }
    for (std::size_t v = 0; v < mark.size(); ++v) users[v] += mark[v];
    for (const auto& t : piece.triangles)
      result.mesh.triangles.push_back({static_cast<std::uint32_t>(remap[t[0]]), static_cast<std::uint32_t>(remap[t[1]]),
                                       static_cast<std::uint32_t>(remap[t[2]])});
  }
  for (std::uint32_t v : seam)
    if (remap[v] >= 0) {
      result.seam.push_back(static_cast<std::uint32_t>(remap[v]));
      if (users[v] >= 2) ++result.seam_vertices_in_both;
    }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

TrimmedCsgResult trimmed_csg(const ClosedSurface& first, const ClosedSurface& second, CsgOperation op,
                             const TrimmedCsgOptions& options) {
  CsgSolid solid;
  switch (op) {
    case CsgOperation::Union: solid = [](const std::vector<char>& in) { return in[0] || in[1]; }; break;
    case CsgOperation::Intersection: solid = [](const std::vector<char>& in) { return in[0] && in[1]; }; break;
    case CsgOperation::Difference: solid = [](const std::vector<char>& in) { return in[0] && !in[1]; }; break;
  }
  return trimmed_csg(std::vector<ClosedSurface>{first, second}, solid, options);
}

}  // namespace genmod::models
