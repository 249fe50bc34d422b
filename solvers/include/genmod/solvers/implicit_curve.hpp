// Implicit curve approximation: Snyder's Algorithm 5.3 (snyder.md section 5.2), the curve
// F(x) = 0 of n - 1 equations in n unknowns over a box X, as linked polylines.
//
// Example:
//   using namespace genmod;
//   Fn f = square(x(0)) + square(x(1)) - 0.5;
//   int coords[] = {0, 1};
//   ImplicitCurveOptions opt;
//   opt.acceptance_width = 0.2;
//   ImplicitCurve c = approximate_implicit_curve(f, coords, {Interval(-1, 1), Interval(-1, 1)}, opt);
//   // c.components: one closed Polyline; c.complete()
//
// The steps (section 5.2.2):
//  1. Proximate boxes: bisect X (widest side, at the midpoint: a kd-tree) and discard boxes where
//     some component of the natural / mean value / monotonicity enclosure of F excludes 0, until
//     the box is narrower than `acceptance_width` (□G ≡ w(Y) < w).
//  2. Global parameterizability, the robust test (Theorem 5.5, the Interval Implicit Function
//     Theorem): the box is parameterizable in x_k if the interval Jacobian minor J_k (column k
//     removed) is regular: 0 ∉ det□(J_k) (cofactor expansion), or, tighter and still sound,
//     mid(J_k)^-1 J_k is strictly diagonally dominant. No such k: bisect and retest.
//  3. Boundary intersections: on each of the 2n faces (one coordinate fixed) the curve is a
//     finite set of points, found with solve() (Algorithm 5.1, all solutions, aggregated). A face
//     shared by two equal boxes is solved once (cache keyed by the exact face).
//  4. Sortability: the face-point boxes must be disjoint in x_k; otherwise bisect.
//  5. Links in a box: sort the face points by x_k; adjacent points k, k+1 are linked iff the
//     slice x_k = (ub X^k_k + lb X^{k+1}_k) / 2 of the box holds a (certified unique) curve point,
//     which is kept as an extra sample. An uncertified slice answer bisects the box.
//  6. Components: face-point boxes that overlap (up to the point tolerance, point_epsilon times
//     the size of X) are one node: a point found on several faces, e.g. at a corner, or by two
//     neighbors of different size (every box holds the true point, so boxes of one point always
//     overlap); the tolerance also merges a crossing that passes within rounding of a kd-tree
//     corner. Boxes on the two ends of a periodic coordinate (or at a corner of several) are
//     one node too, kept as separate images so the polyline lists both (Polyline::wraps).
//     Walking the link graph gives polylines: closed, or open with both ends on ∂X.
//  Face and slice points certified unique by solve() are narrowed with interval Newton.
//
// Intervals are sacred: a box that stays unresolved (the parameterizability test or a face /
// slice solve still fails below `min_width` or at max_depth, e.g. at a singular point) or is
// left unexplored by a limit is returned with its status; polylines that end there say so
// (End::Unresolved), and complete() is false. The union of the returned boxes covers the curve:
// every discarded box is proved free of it (F excludes 0, or global parameterizability leaves no
// room for a piece of curve that touches the box's boundary in fewer than 2 points other than a
// touching point, which a neighbor box holds).
//
// Assumptions (section 5.2.1): F is C^1 where the curve is, the curve is a 1-manifold whose
// components are closed or end on ∂X, and it meets the faces of the boxes in finitely many
// points. Violations show up as unresolved boxes, not as wrong output.
//
// Thread safety: each call compiles its own tapes; calls may run concurrently.
#pragma once

#include "genmod/kernel/coordinates.hpp"
#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/interval.hpp"
#include "genmod/solvers/box.hpp"
#include "genmod/solvers/limits.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace genmod {

struct ImplicitCurveOptions {
  // □G: a proximate box is narrower than this (largest side). > 0.
  double acceptance_width = 0.1;
  // Boxes narrower than this that still fail the parameterizability, sortability or slice
  // tests are reported Unresolved instead of bisected. 0 = acceptance_width * 1e-4.
  double min_width = 0.0;
  // Width of the boxes that locate face and slice points (solve()'s epsilon), relative to the
  // largest side of X. > 0.
  double point_epsilon = 1e-10;
  // Uncertified face points closer than this (relative to the largest side of X) are one point:
  // where the curve touches a box face tangentially (a turning point on a bisection line), the
  // face's double root comes back as fragments spread over about sqrt(rounding). >= 0.
  double touch_tolerance = 1e-7;
  // Coordinates (values from `coords`) whose two ends of X are the same point (u of a torus):
  // a polyline reaching one end continues at the other.
  std::vector<int> periodic;
  // Keep the slice points of step 5 as extra samples between two face points.
  bool slice_samples = true;
  // Which global parameterizability test accepts a narrow box (snyder.md 5.2.3 / 5.2.4):
  //  * Robust (Theorem 5.5): a Jacobian minor is regular over the box; then every slice in that
  //    coordinate holds at most one curve point. Never misses a component.
  //  * Heuristic: the box's boundary points are sortable in some coordinate and, when there are
  //    more than two, the hyperplane through each inner one meets the curve exactly once
  //    (boundary univalence). Accepts larger boxes (fewer face solves) and works where the
  //    robust test cannot (non-C^1 or singular Jacobians), but assumes that no closed component
  //    lies entirely inside one box: a loop smaller than the acceptance width may be missed.
  enum class Test : std::uint8_t { Robust, Heuristic } parameterizability = Test::Robust;
  // Limits of the whole run: max_boxes counts boxes of the subdivision (face and slice solves
  // get their own small budgets), max_depth the bisections along one path, time in seconds.
  SearchLimits limits;
};

enum class CurveBoxStatus : std::uint8_t {
  Proximate,   // parameterizable, narrow, its face points sorted and linked
  Unresolved,  // holds the curve possibly, but the tests failed down to min_width / max_depth
  Unexplored,  // left when a limit stopped the search
};
std::string_view curve_box_status_name(CurveBoxStatus s) noexcept;

struct CurveBox {
  Box box;                 // one side per coordinate of `coords`
  CurveBoxStatus status;
  int depth;               // bisections from X
  int parameter = -1;      // Proximate: index (into coords) of the parameterizing coordinate
  std::size_t links = 0;   // Proximate: curve pieces crossing the box
};

// How an open polyline ends.
enum class CurveEnd : std::uint8_t {
  None,        // closed polyline
  Boundary,    // on ∂X (a non-periodic side)
  Unresolved,  // at an unresolved or unexplored box (or at a node with more than 2 links)
};
std::string_view curve_end_name(CurveEnd e) noexcept;

struct Polyline {
  // Points in order, one value per coordinate of `coords`. A closed polyline does not repeat
  // its first point at the end.
  std::vector<std::vector<double>> points;
  bool closed = false;
  CurveEnd front = CurveEnd::None, back = CurveEnd::None;
  // i in wraps: points[i] -> points[i + 1] (closed: points[(i + 1) % size]) crosses a periodic
  // boundary (the two points are the two images of one curve point).
  std::vector<std::size_t> wraps;
};

struct ImplicitCurveStats {
  std::size_t proximate = 0, unresolved = 0, unexplored = 0;
  std::size_t face_solves = 0, face_cache_hits = 0, slice_solves = 0;
  std::size_t nodes = 0;          // distinct boundary intersections
  std::size_t branch_nodes = 0;   // nodes with more than 2 links (should be 0)
};

struct ImplicitCurve {
  std::vector<Polyline> components;
  std::vector<CurveBox> boxes;  // the proximate, unresolved and unexplored leaves
  SearchReport report;
  ImplicitCurveStats stats;
  // No limit hit, no unresolved box, no branch node.
  bool complete() const noexcept {
    return report.limit == LimitHit::None && stats.unresolved == 0 && stats.unexplored == 0 &&
           stats.branch_nodes == 0;
  }
};

// Approximates F(x) = 0 (F has n - 1 components, n = coords.size() >= 2, over the coordinates
// `coords`) in the box X (one bounded side per coordinate). Throws std::invalid_argument naming
// the problem: a wrong dimension of F or X, an empty / unbounded / NaN side, F depending on a
// coordinate outside `coords`, a coordinate listed twice, a periodic coordinate not in
// `coords`, acceptance_width / point_epsilon not > 0, min_width < 0.
ImplicitCurve approximate_implicit_curve(const Fn& F, Coordinates coords, const Box& X,
                                         const ImplicitCurveOptions& options = {});

// --- The parameterizability test (Theorem 5.5), exposed for tests and other algorithms. ---

// Interval determinant (cofactor expansion) of the m x m matrix obtained from the row-major
// m x (m + 1) interval matrix `jacobian` by removing column `skip`.
Interval jacobian_minor_determinant(std::span<const Interval> jacobian, std::size_t m, std::size_t skip);
// True if every real matrix in that minor is nonsingular: 0 ∉ the determinant, or the midpoint
// preconditioned minor is strictly diagonally dominant.
bool jacobian_minor_regular(std::span<const Interval> jacobian, std::size_t m, std::size_t skip);
// The coordinates k (indices into coords) in which the curve F = 0 is globally parameterizable
// over `box` by Theorem 5.5 (at most one curve point on every slice x_k = c of the box).
std::vector<int> parameterizable_coordinates(const Fn& F, Coordinates coords, const Box& box);

}  // namespace genmod
