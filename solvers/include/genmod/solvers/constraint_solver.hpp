// Interval constraint solution: Snyder's Algorithm 5.1 (branch and prune) with HC4
// contraction, interval Newton, existence and uniqueness certificates, aggregation and
// explicit limits (snyder.md sections 4.7-4.12). GENMOD's m_solve semantics: the constraint is
// solved for the chosen unknowns; any other coordinate it depends on is a free parameter given
// as an interval.
//
// The promise: no solution is ever lost. Every point x of the box with constraint(x) = 1 (for
// some parameter value in the parameter box) lies in a returned box, whatever the options and
// even when a limit stops the search (the boxes left unexplored are returned, marked
// Unexplored). Each returned box says what is certified and what is only possible.
//
// Example:
//   using namespace genmod;
//   Fn c = eq(square(x(0)) + square(x(1)), 1.0) && eq(x(0), x(1));
//   int unknowns[] = {0, 1};
//   SolveOptions opt;
//   opt.epsilon = 1e-8;
//   SolveResult r = solve(c, unknowns, {Interval(-2, 2), Interval(-2, 2)}, opt);
//   // r.boxes: two CertifiedUnique boxes around ±(1/√2, 1/√2);
//   // r.components: two components, each `unique`; r.report.limit == LimitHit::None.
//
// Per box (one round of the work list): evaluate the constraint's atoms (tags: decided atoms
// are inherited, section 4.12) -> False: discard; True: Feasible. Otherwise contract with HC4
// and interval Newton (when the top-level conjunction holds as many equalities as unknowns),
// re-evaluating while the box shrinks; certify with Krawczyk. Then accept (certified, or width
// < epsilon and every undecided equality's function width <= delta) or subdivide.
//
// Determinism: boxes are processed in rounds of `batch` boxes (in parallel with oneTBB), and the
// results of a round are merged in work-list order, so the output is bitwise identical for any
// thread count. It depends on `batch`; it is not reproducible when the time limit stops a
// search.
#pragma once

#include "genmod/kernel/coordinates.hpp"
#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/interval.hpp"
#include "genmod/solvers/aggregation.hpp"
#include "genmod/solvers/box.hpp"
#include "genmod/solvers/limits.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

namespace genmod {

// Which side a box is split along (snyder.md section 4.8).
enum class Subdivision : std::uint8_t {
  Cyclic,  // the thesis default: dimension d' = (d mod n) + 1, at the exact midpoint
  Widest,  // the widest side
  Smear,   // the side with the largest smear sum_i |dh_i/dx_j| * w(X_j) over the undecided atoms
};

// Order of the work list.
enum class Discipline : std::uint8_t {
  Fifo,     // breadth first (the thesis' fair order for the convergence proof)
  Lifo,     // depth first (small memory)
  Priority  // the widest box first (ties: the older box)
};

struct SolveOptions {
  // Accept an undecided box when its width (largest side) is below epsilon. > 0.
  double epsilon = 1e-6;
  // ... and when every undecided equality's function enclosure is at most delta wide
  // (section 4.10's w(□f(Y)) < δ). > 0; infinity disables the test.
  double delta = std::numeric_limits<double>::infinity();
  SearchLimits limits;
  Subdivision rule = Subdivision::Cyclic;
  Discipline order = Discipline::Fifo;
  bool use_hc4 = true;     // forward-backward contraction
  bool use_newton = true;  // interval Newton + certification on square equality systems
  bool use_tags = true;    // subconstraint tags (section 4.12)
  int max_contractions = 16;  // contraction passes per box while it shrinks by > 10 %
  int threads = 0;            // worker threads; 0 = oneTBB's default
  std::size_t batch = 64;     // boxes per parallel round (the output depends on it)
};

// Free parameters: coordinates that are neither unknowns nor fixed, given as intervals.
struct FreeParameters {
  std::vector<int> coords;
  Box values;  // one bounded, nonempty interval per coordinate
};

enum class SolutionStatus : std::uint8_t {
  CertifiedUnique,  // exactly one solution in the box (Krawczyk), for every parameter value
  Possible,         // undecided, small: may hold solutions of an equality (0, 1 or more)
  Feasible,         // every point satisfies the constraint (an inner box)
  Boundary,         // undecided, small, only inequalities undecided: on a feasible region's edge
  // Left by a limit: on the work list when max_boxes or the time limit stopped the search, or
  // not accepted (wider than epsilon) at max_depth, where it may not be split. Any status above
  // means the box was decided or accepted; a box at machine precision that cannot be split is
  // accepted as Possible / Boundary (that is the resolution of doubles, not a limit).
  Unexplored,
};
std::string_view status_name(SolutionStatus s) noexcept;

struct SolutionBox {
  Box box;  // the unknowns' sides only
  SolutionStatus status;
  int depth;  // subdivisions from the initial box
};

// A connected group of returned boxes (section 4.9).
struct SolutionComponent {
  Box hull;
  std::vector<std::size_t> members;  // indices into SolveResult::boxes
  std::size_t certified = 0;         // CertifiedUnique members: distinct solutions (interiors are disjoint)
  std::size_t feasible = 0;          // Feasible members
  // Certified: the component holds exactly one solution (Krawczyk on its slightly inflated
  // hull, or a single member certified). Only for square equality systems.
  bool unique = false;
};

struct SolveStats {
  std::size_t atom_evaluations = 0;  // relational inclusion-function evaluations
  std::size_t contractions = 0;      // HC4 passes
  std::size_t newton_steps = 0;      // interval Gauss-Seidel steps (applied)
  std::size_t splits = 0;
};

struct SolveResult {
  std::vector<SolutionBox> boxes;             // sorted by lower corner
  std::vector<SolutionComponent> components;  // aggregated boxes
  SearchReport report;                        // boxes processed, depth, the limit hit, time
  SolveStats stats;

  // True when no limit was hit (every box was decided or accepted).
  bool complete() const noexcept { return report.limit == LimitHit::None; }
  // The number of boxes with status s (named apart from the number of solutions, which it is
  // not: one solution may be covered by several boxes, and a solution certified only through
  // its component, by Krawczyk on the component's hull, sits in Possible boxes). The number of
  // certified solutions is unique_components().
  std::size_t box_count(SolutionStatus s) const noexcept;
  // Components certified to hold exactly one solution each (disjoint): the number of
  // certified solutions.
  std::size_t unique_components() const noexcept;
};

// Solves `constraint` (a 0/1-valued scalar Fn built with == != < <= > >= && || !) for the
// coordinates `unknowns` over `box` (one side per unknown). Throws std::invalid_argument
// naming the problem for: a box of the wrong dimension or with an empty, NaN or unbounded
// side; epsilon or delta not > 0 (or NaN); threads < 0; batch == 0; a constraint that is not
// scalar or depends on a coordinate that is neither an unknown nor a parameter; an unknown or
// parameter listed twice; parameters whose values do not match their coordinates. An
// unsatisfiable constraint returns no boxes (and complete()).
SolveResult solve(const Fn& constraint, Coordinates unknowns, const Box& box,
                  const SolveOptions& options = {}, const FreeParameters& parameters = {});

// The split of one box (section 4.8), exposed for tests: Cyclic splits dimension
// (last + 1) mod n at the midpoint. Returns the dimension used.
std::size_t cyclic_next(std::size_t last, std::size_t n) noexcept;

}  // namespace genmod
