// Forward-backward (HC4-revise) contraction of a box against a ConstraintSystem
// (Benhamou et al. 1999; IBEX's CtcHC4, research/anchors.md section 4).
//
// For each atom h rel 0 the kernel's TapeContractor (genmod/kernel/tape_contractor.hpp)
// evaluates the tape of h forward with the kernel's enclosures, intersects the root with the
// set the relation allows ([0,0] for ==, (-inf,0] for < and <=, [0,inf) for > and >=), and
// projects the result back through the clauses onto the unknowns. && contracts with each
// side in turn, || takes the hull of the contractions of both sides, ! is pushed into the
// relations.
//
// Soundness: every projection is computed with outward-rounded interval operations, so a
// point of the box that satisfies the constraint is never removed. Points where h fails (sqrt
// of a negative, division by zero) are not solutions (the constraint is NaN there) and may be
// removed. Parameters (inputs after the unknowns) are read but never narrowed.
//
// Example:
//   int unknowns[] = {0, 1};
//   ConstraintSystem sys(eq(square(x(0)) + square(x(1)), 1.0), unknowns);
//   Hc4Contractor hc4(sys);
//   Box b = {Interval(0.9, 2.0), Interval(-0.1, 0.1)};
//   bool maybe = hc4.contract(b);             // b shrinks to about [0.99, 1] x [-0.1, 0.1]
#pragma once

#include "genmod/kernel/tape_contractor.hpp"
#include "genmod/solvers/box.hpp"
#include "genmod/solvers/constraint_system.hpp"

#include <span>
#include <vector>

namespace genmod {

class Hc4Contractor {
 public:
  // Keeps a reference to `system`, which must outlive the contractor. Cheap to copy (one copy
  // per thread: the scratch memory is per object).
  explicit Hc4Contractor(const ConstraintSystem& system);

  // Contracts `box` (unknowns then parameters) in place. Returns false when the box holds no
  // solution (then `box` is unspecified). `atom_values` (optional, one per atom) skips atoms
  // already known true and rejects with atoms known false, from a prior evaluation.
  bool contract(std::span<Interval> box, std::span<const Truth> atom_values = {});

  // Contracts against one atom with an explicit relation (h rel 0). False when no point fits.
  bool contract_atom(std::size_t atom, Relation rel, std::span<Interval> box);

  // Whether atom i gets the backward projection (TapeContractor::projects: its tape has no
  // select, is-error or custom call); every atom gets the forward check.
  // std::out_of_range for an atom index the system does not have.
  bool supports(std::size_t atom) const;

 private:
  bool contract_node(std::uint32_t node, bool negated, std::span<Interval> box, std::span<const Truth> values);

  const ConstraintSystem* sys_;
  TapeContractor tape_;
};

}  // namespace genmod
