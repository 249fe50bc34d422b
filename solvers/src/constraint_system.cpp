#include "genmod/solvers/constraint_system.hpp"

#include "genmod/kernel/expression.hpp"

#include <stdexcept>
#include <string>

namespace genmod {

Truth relation_truth(Relation rel, const Interval& h) noexcept {
  if (h.is_empty()) return Truth::False;
  const bool zero = h.lo() == 0.0 && h.hi() == 0.0;
  switch (rel) {
    case Relation::Eq:
      if (zero) return Truth::True;
      return h.contains_zero() ? Truth::Unknown : Truth::False;
    case Relation::Ne:
    case Relation::Nonzero:
      if (!h.contains_zero()) return Truth::True;
      return zero ? Truth::False : Truth::Unknown;
    case Relation::Lt:
      if (h.hi() < 0.0) return Truth::True;
      return h.lo() >= 0.0 ? Truth::False : Truth::Unknown;
    case Relation::Le:
      if (h.hi() <= 0.0) return Truth::True;
      return h.lo() > 0.0 ? Truth::False : Truth::Unknown;
    case Relation::Gt:
      if (h.lo() > 0.0) return Truth::True;
      return h.hi() <= 0.0 ? Truth::False : Truth::Unknown;
    case Relation::Ge:
      if (h.lo() >= 0.0) return Truth::True;
      return h.hi() < 0.0 ? Truth::False : Truth::Unknown;
  }
  return Truth::Unknown;
}

Relation negate(Relation rel) noexcept {
  switch (rel) {
    case Relation::Eq: return Relation::Ne;
    case Relation::Ne: return Relation::Eq;
    case Relation::Nonzero: return Relation::Eq;
    case Relation::Lt: return Relation::Ge;
    case Relation::Le: return Relation::Gt;
    case Relation::Gt: return Relation::Le;
    case Relation::Ge: return Relation::Lt;
  }
  return rel;
}

namespace {

bool relation_of(Op op, Relation& rel) {
  switch (op) {
    case Op::Eq: rel = Relation::Eq; return true;
    case Op::Ne: rel = Relation::Ne; return true;
    case Op::Lt: rel = Relation::Lt; return true;
    case Op::Le: rel = Relation::Le; return true;
    case Op::Gt: rel = Relation::Gt; return true;
    case Op::Ge: rel = Relation::Ge; return true;
    default: return false;
  }
}

Truth t_not(Truth a) {
  if (a == Truth::Unknown) return a;
  return a == Truth::True ? Truth::False : Truth::True;
}

}  // namespace

ConstraintSystem::ConstraintSystem(const Fn& constraint, Coordinates unknowns,
                                   Coordinates parameters) {
  if (constraint.dim() != 1)
    throw std::invalid_argument("genmod: solve: the constraint must be scalar (0/1 valued), got dimension " +
                                std::to_string(constraint.dim()));
  if (unknowns.empty()) throw std::invalid_argument("genmod: solve: no unknowns given");
  std::uint64_t listed = 0;
  auto add = [&](int c, const char* what) {
    if (c < 0 || c >= kMaxInputs)
      throw std::invalid_argument(std::string("genmod: solve: ") + what + " x(" + std::to_string(c) +
                                  ") is out of range");
    const std::uint64_t bit = std::uint64_t{1} << c;
    if (listed & bit)
      throw std::invalid_argument("genmod: solve: coordinate x(" + std::to_string(c) +
                                  ") is listed twice among the unknowns and parameters");
    listed |= bit;
    inputs_.push_back(c);
  };
  for (int c : unknowns) add(c, "unknown");
  for (int c : parameters) add(c, "parameter");
  num_unknowns_ = unknowns.size();
  const std::uint64_t extra = constraint.input_mask() & ~listed;
  if (extra != 0) {
    int c = 0;
    while (!((extra >> c) & 1u)) ++c;
    throw std::invalid_argument("genmod: solve: the constraint depends on x(" + std::to_string(c) +
                                "), which is neither an unknown nor a parameter (give it as a parameter interval)");
  }
  root_ = parse(constraint.node(0));
  collect_conjuncts(root_, false, pure_conjunction_);
}

std::uint32_t ConstraintSystem::parse(NodeId id) {
  const Fn f = Fn::of(id);
  const Expression e = expression(f);
  Node n{};
  Relation rel{};
  if (e.op == Op::And || e.op == Op::Or) {
    const std::uint32_t a = parse(e.operands[0].node(0));
    const std::uint32_t b = parse(e.operands[1].node(0));
    n.kind = e.op == Op::And ? Node::And : Node::Or;
    n.a = a;
    n.b = b;
  } else if (e.op == Op::Not) {
    n.kind = Node::Not;
    n.a = parse(e.operands[0].node(0));
  } else {
    Fn h;
    if (relation_of(e.op, rel)) {
      const Expression rhs = expression(e.operands[1]);
      const bool zero = rhs.op == Op::Const && rhs.value == 0.0;
      h = zero ? e.operands[0] : e.operands[0] - e.operands[1];
    } else {
      rel = Relation::Nonzero;
      h = f;
    }
    n.kind = Node::Atom;
    n.a = static_cast<std::uint32_t>(atoms_.size());
    atoms_.push_back(ConstraintAtom{h, rel, Tape(h, inputs_)});
  }
  nodes_.push_back(n);
  return static_cast<std::uint32_t>(nodes_.size() - 1);
}

void ConstraintSystem::collect_conjuncts(std::uint32_t node, bool negated, bool& pure) {
  const Node& n = nodes_[node];
  switch (n.kind) {
    case Node::Atom: {
      const Relation r = atoms_[n.a].rel;
      conjuncts_.push_back({n.a, negated ? negate(r) : r});
      return;
    }
    case Node::Not: collect_conjuncts(n.a, !negated, pure); return;
    case Node::And:
    case Node::Or:
      if ((n.kind == Node::And) != negated) {  // a conjunction (And, or negated Or)
        collect_conjuncts(n.a, negated, pure);
        collect_conjuncts(n.b, negated, pure);
      } else {
        pure = false;  // a disjunction: its atoms are not each necessary
      }
      return;
  }
}

Truth ConstraintSystem::combine(std::span<const Truth> v) const {
  // Nodes are stored children before parents, so one forward pass evaluates the tree.
  std::vector<Truth> t(nodes_.size());
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const Node& n = nodes_[i];
    switch (n.kind) {
      case Node::Atom: t[i] = v[n.a]; break;
      case Node::Not: t[i] = t_not(t[n.a]); break;
      case Node::And: {
        const Truth a = t[n.a], b = t[n.b];
        t[i] = (a == Truth::False || b == Truth::False) ? Truth::False
               : (a == Truth::True && b == Truth::True) ? Truth::True
                                                        : Truth::Unknown;
        break;
      }
      case Node::Or: {
        const Truth a = t[n.a], b = t[n.b];
        t[i] = (a == Truth::True || b == Truth::True) ? Truth::True
               : (a == Truth::False && b == Truth::False) ? Truth::False
                                                          : Truth::Unknown;
        break;
      }
    }
  }
  return t[root_];
}

Truth ConstraintSystem::evaluate(std::span<const Interval> box, std::span<std::uint8_t> tags, AtomValues& values,
                                 IntervalEvaluator& ev, std::size_t* evaluations) const {
  const std::size_t m = atoms_.size();
  values.value.assign(m, Truth::Unknown);
  values.range.assign(m, Interval::entire());
  values.fresh.assign(m, 0);
  values.error.assign(m, kNoError);
  values.maybe_error = false;
  for (std::size_t i = 0; i < m; ++i) {
    if (tags[i] != kTagUnknown) {
      values.value[i] = tags[i] == kTagTrue ? Truth::True : Truth::False;
      continue;
    }
    const Interval h = ev.eval(atoms_[i].tape, box)[0];
    const std::uint8_t err = ev.errors()[0];
    if (evaluations) ++*evaluations;
    values.fresh[i] = 1;
    values.range[i] = h;
    values.error[i] = err;
    // A certain error (or an empty range) makes the whole constraint NaN on the box.
    if (err == kCertainError || h.is_empty()) {
      values.value[i] = Truth::False;
      return Truth::False;
    }
    const Truth t = relation_truth(atoms_[i].rel, h);
    values.value[i] = t;
    if (err != kNoError)
      values.maybe_error = true;
    else if (t != Truth::Unknown)
      tags[i] = t == Truth::True ? kTagTrue : kTagFalse;
  }
  const Truth t = combine(values.value);
  if (t == Truth::True && values.maybe_error) return Truth::Unknown;
  return t;
}

}  // namespace genmod
