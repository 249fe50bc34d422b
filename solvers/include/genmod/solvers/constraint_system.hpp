// ConstraintSystem: a 0/1-valued constraint Fn taken apart into relational atoms joined by
// logic (snyder.md sections 4.4, 4.7, 4.12), ready for branch and prune.
//
// Every relation f rel g of the constraint becomes an atom h rel 0 with h = f - g, compiled
// into its own tape; && || ! become the logic tree above the atoms. A scalar that is not a
// relation but is used as a truth value ("nonzero is true") is an atom h != 0 (Nonzero).
//
// Example:
//   Fn c = eq(square(x(0)) + square(x(1)), 1.0) && (x(0) < x(1));
//   int unknowns[] = {0, 1};
//   ConstraintSystem sys(c, unknowns);          // 2 atoms: x0^2+x1^2-1 == 0, x0-x1 < 0
//   std::vector<std::uint8_t> tags(sys.num_atoms(), kTagUnknown);
//   AtomValues v;
//   IntervalEvaluator ev;
//   Box box = {Interval(-1, 0), Interval(0.5, 1)};
//   Truth t = sys.evaluate(box, tags, v, ev);   // False / True / Unknown over the box
//
// Inputs: every tape takes the unknowns first, then the free parameters (in the given order);
// a box passed to evaluate() has one interval per input in that order.
//
// Error semantics follow the kernel's point evaluation: a relation or logic operator with an
// error operand (NaN) gives NaN, so a point where some atom fails (sqrt of a negative, ...) is
// never a solution. An atom certainly failing over a box rejects the box; an atom that may fail
// keeps the box from being reported as wholly feasible.
#pragma once

#include "genmod/kernel/coordinates.hpp"
#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/interval.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/tape.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace genmod {

// h rel 0.
enum class Relation : std::uint8_t { Eq, Ne, Lt, Le, Gt, Ge, Nonzero };

// Ternary truth of a constraint over a box ([0,0], [1,1], [0,1] of snyder.md section 4.4).
enum class Truth : std::uint8_t { False = 0, True = 1, Unknown = 2 };

// Subconstraint tags (snyder.md section 4.12): an atom decided (without possible error) on a
// box keeps its value on every sub-box, so it is not evaluated again.
inline constexpr std::uint8_t kTagFalse = 0, kTagTrue = 1, kTagUnknown = 2;

struct ConstraintAtom {
  Fn h;           // the function compared with 0
  Relation rel;
  Tape tape;      // h over (unknowns, parameters)
};

// One evaluation's per-atom results (scratch reused across calls).
struct AtomValues {
  std::vector<Truth> value;        // truth of each atom over the box
  std::vector<Interval> range;     // enclosure of h (only for atoms evaluated this time)
  std::vector<std::uint8_t> fresh; // 1 if the atom was evaluated (not taken from a tag)
  std::vector<std::uint8_t> error; // ErrorBits of each evaluated atom (0 for tagged atoms)
  bool maybe_error = false;        // some atom may fail somewhere in the box
};

class ConstraintSystem {
 public:
  // Logic tree node: an atom leaf or a logic operator over child nodes.
  struct Node {
    enum Kind : std::uint8_t { Atom, And, Or, Not } kind;
    std::uint32_t a = 0, b = 0;  // Atom: a = atom index; And/Or: children; Not: a = child
  };

  // Throws std::invalid_argument if the constraint is not scalar, if an unknown or parameter
  // is listed twice or out of range, or if the constraint depends on a coordinate that is
  // neither an unknown nor a parameter (the message names the coordinate).
  ConstraintSystem(const Fn& constraint, Coordinates unknowns, Coordinates parameters = {});

  std::size_t num_unknowns() const noexcept { return num_unknowns_; }
  std::size_t num_parameters() const noexcept { return inputs_.size() - num_unknowns_; }
  std::span<const int> inputs() const noexcept { return inputs_; }
  std::size_t num_atoms() const noexcept { return atoms_.size(); }
  std::span<const ConstraintAtom> atoms() const noexcept { return atoms_; }
  std::span<const Node> nodes() const noexcept { return nodes_; }
  std::uint32_t root() const noexcept { return root_; }

  // Atoms that must hold at every solution: the top-level conjuncts (through && and through
  // ! of ||), with their relation after pushing negations in.
  struct Conjunct {
    std::size_t atom;
    Relation rel;  // effective relation (negation applied)
  };
  std::span<const Conjunct> conjuncts() const noexcept { return conjuncts_; }
  // True when the whole constraint is the conjunction of conjuncts() (no || below the top).
  bool is_conjunction() const noexcept { return pure_conjunction_; }

  // Ternary value over `box` (unknowns then parameters). Atoms whose tag is decided are not
  // evaluated; `tags` is updated for atoms decided without possible error on this box.
  // `evaluations` (optional) counts atom evaluations (relational inclusion-function calls).
  Truth evaluate(std::span<const Interval> box, std::span<std::uint8_t> tags, AtomValues& values,
                 IntervalEvaluator& ev, std::size_t* evaluations = nullptr) const;
  // The tree's value from given atom values (ternary logic of snyder.md section 4.4).
  Truth combine(std::span<const Truth> atom_values) const;

 private:
  std::uint32_t parse(NodeId id);
  void collect_conjuncts(std::uint32_t node, bool negated, bool& pure);

  std::vector<int> inputs_;
  std::size_t num_unknowns_ = 0;
  std::vector<ConstraintAtom> atoms_;
  std::vector<Node> nodes_;
  std::uint32_t root_ = 0;
  std::vector<Conjunct> conjuncts_;
  bool pure_conjunction_ = true;
};

// Truth of `h rel 0` from an enclosure of h (no error handling).
Truth relation_truth(Relation rel, const Interval& h) noexcept;
// The relation of !(h rel 0) (Nonzero negates to Eq, Eq to Ne, Lt to Ge, ...).
Relation negate(Relation rel) noexcept;

}  // namespace genmod
