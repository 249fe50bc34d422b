#include "genmod/solvers/contractor.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace genmod {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The set of h values `h rel 0` allows (closed: a superset is always sound); `none` is
// cleared when the relation gives no contraction (!=).
Interval allowed(Relation rel, bool& any) {
  any = true;
  switch (rel) {
    case Relation::Eq: return Interval(0.0);
    case Relation::Lt: case Relation::Le: return Interval::unchecked(-kInf, 0.0);
    case Relation::Gt: case Relation::Ge: return Interval::unchecked(0.0, kInf);
    case Relation::Ne: case Relation::Nonzero: break;
  }
  any = false;
  return Interval::entire();
}

}  // namespace

Hc4Contractor::Hc4Contractor(const ConstraintSystem& system) : sys_(&system) {}

bool Hc4Contractor::supports(std::size_t atom) const {
  if (atom >= sys_->atoms().size())
    throw std::out_of_range("genmod: Hc4Contractor: atom " + std::to_string(atom) + " of " +
                            std::to_string(sys_->atoms().size()));
  return TapeContractor::projects(sys_->atoms()[atom].tape);
}

bool Hc4Contractor::contract(std::span<Interval> box, std::span<const Truth> values) {
  return contract_node(sys_->root(), false, box, values);
}

bool Hc4Contractor::contract_node(std::uint32_t node, bool negated, std::span<Interval> box,
                                  std::span<const Truth> values) {
  const ConstraintSystem::Node& n = sys_->nodes()[node];
  switch (n.kind) {
    case ConstraintSystem::Node::Atom: {
      if (!values.empty()) {
        const Truth t = values[n.a];
        if (t != Truth::Unknown) return (t == Truth::True) != negated;  // decided: keep or reject whole
      }
      const Relation rel = negated ? negate(sys_->atoms()[n.a].rel) : sys_->atoms()[n.a].rel;
      return contract_atom(n.a, rel, box);
    }
    case ConstraintSystem::Node::Not: return contract_node(n.a, !negated, box, values);
    case ConstraintSystem::Node::And:
    case ConstraintSystem::Node::Or: {
      if ((n.kind == ConstraintSystem::Node::And) != negated)
        return contract_node(n.a, negated, box, values) && contract_node(n.b, negated, box, values);
      // A disjunction: the solutions lie in the hull of both sides' contractions.
      std::vector<Interval> left(box.begin(), box.end()), right(box.begin(), box.end());
      const bool l = contract_node(n.a, negated, left, values);
      const bool r = contract_node(n.b, negated, right, values);
      if (!l && !r) return false;
      for (std::size_t i = 0; i < box.size(); ++i)
        box[i] = !l ? right[i] : !r ? left[i] : hull(left[i], right[i]);
      return true;
    }
  }
  return true;
}

bool Hc4Contractor::contract_atom(std::size_t atom, Relation rel, std::span<Interval> box) {
  bool any = false;
  const Interval target = allowed(rel, any);
  const Tape& tape = sys_->atoms()[atom].tape;
  if (!any || tape.num_outputs() != 1) return true;
  return tape_.contract(tape, box, target, sys_->num_unknowns());
}

}  // namespace genmod
