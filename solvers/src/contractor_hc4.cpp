#include "genmod/solvers/contractor.hpp"

#include "genmod/solvers/interval_newton.hpp"

#include <cmath>
#include <limits>

namespace genmod {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// An arithmetic projection that produced NaN bounds (inf - inf, 0 * inf) says nothing: use
// the whole line instead (never shrink on a meaningless result).
Interval guard(const Interval& r) { return r.is_empty() ? Interval::entire() : r; }

Interval hull_of(const Interval& a, const Interval& b) {
  if (a.is_empty()) return b;
  if (b.is_empty()) return a;
  return hull(a, b);
}

// x := x ∩ r; false when the result is empty.
bool narrow(Interval& x, const Interval& r) {
  x = intersect(x, r);
  return !x.is_empty();
}

// x := hull of (x ∩ piece) over the pieces of an extended quotient.
bool narrow(Interval& x, const IntervalPair& p) {
  if (p.first.is_empty() && p.second.is_empty()) {
    x = Interval::empty();
    return false;
  }
  x = hull_of(intersect(x, p.first), intersect(x, p.second));
  return !x.is_empty();
}

bool supported_op(Op op) {
  switch (op) {
    case Op::Const: case Op::Load: case Op::Neg: case Op::Square: case Op::Sqrt: case Op::Exp: case Op::Log:
    case Op::Sin: case Op::Cos: case Op::Tan: case Op::Asin: case Op::Acos: case Op::Atan: case Op::Abs:
    case Op::Floor: case Op::Ceil: case Op::Add: case Op::Sub: case Op::Mul: case Op::Div: case Op::Pow:
    case Op::Atan2: case Op::Min: case Op::Max: case Op::AddImm: case Op::MulImm: case Op::SubImm:
    case Op::DivImmR: case Op::DivImmL: case Op::MinImm: case Op::MaxImm:
      return true;
    default:
      return false;
  }
}

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

Hc4Contractor::Hc4Contractor(const ConstraintSystem& system) : sys_(&system) {
  for (const ConstraintAtom& atom : system.atoms()) {
    const Tape& t = atom.tape;
    bool ok = t.num_outputs() == 1 && t.calls().empty() && t.size() > 0;
    for (const Clause& c : t.ssa()) ok = ok && supported_op(c.op);
    supported_.push_back(ok ? 1 : 0);
  }
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
  if (!any || !supported_[atom]) return true;
  const Tape& tape = sys_->atoms()[atom].tape;
  const std::span<const Clause> ssa = tape.ssa();
  const std::span<const double> k = tape.constants();
  const std::size_t n = ssa.size();
  const std::size_t unknowns = sys_->num_unknowns();
  v_.assign(tape.num_values(), Interval::entire());  // by SSA value id

  // Forward: natural interval extension, protected (outward-rounded) operations.
  for (std::size_t i = 0; i < n; ++i) {
    const Clause& c = ssa[i];
    auto A = [&]() -> const Interval& { return v_[c.a]; };
    auto B = [&]() -> const Interval& { return v_[c.b]; };
    Interval r;
    switch (c.op) {
      case Op::Const: r = Interval(k[c.a]); break;
      case Op::Load: r = box[c.a]; break;
      case Op::Neg: r = -A(); break;
      case Op::Square: r = square(A()); break;
      case Op::Sqrt: r = sqrt(A()); break;
      case Op::Exp: r = exp(A()); break;
      case Op::Log: r = log(A()); break;
      case Op::Sin: r = sin(A()); break;
      case Op::Cos: r = cos(A()); break;
      case Op::Tan: r = tan(A()); break;
      case Op::Asin: r = asin(A()); break;
      case Op::Acos: r = acos(A()); break;
      case Op::Atan: r = atan(A()); break;
      case Op::Abs: r = abs(A()); break;
      case Op::Floor: r = floor(A()); break;
      case Op::Ceil: r = ceil(A()); break;
      case Op::Add: r = guard(A() + B()); break;
      case Op::Sub: r = guard(A() - B()); break;
      case Op::Mul: r = guard(A() * B()); break;
      case Op::Div: r = divide(A(), B()); break;
      case Op::Pow: r = pow(A(), B()); break;
      case Op::Atan2: r = atan2(A(), B()); break;
      case Op::Min: r = min(A(), B()); break;
      case Op::Max: r = max(A(), B()); break;
      case Op::AddImm: r = guard(A() + Interval(k[c.b])); break;
      case Op::MulImm: r = guard(A() * Interval(k[c.b])); break;
      case Op::SubImm: r = guard(Interval(k[c.b]) - A()); break;
      case Op::DivImmR: r = divide(A(), Interval(k[c.b])); break;
      case Op::DivImmL: r = divide(Interval(k[c.b]), A()); break;
      case Op::MinImm: r = min(A(), Interval(k[c.b])); break;
      case Op::MaxImm: r = max(A(), Interval(k[c.b])); break;
      default: r = Interval::entire(); break;  // unreachable (unsupported tapes are skipped)
    }
    // An empty value is a certain error (the kernel's enclosures return the empty set only
    // then): h is NaN everywhere on the box, so no point is a solution.
    if (r.is_empty()) return false;
    v_[c.out] = r;
  }
  if (!narrow(v_[tape.output_values()[0]], target)) return false;

  // Backward: project each clause's (narrowed) value onto its operands. Every user of a value
  // comes after it, so a value is final when its clause is reached.
  for (std::size_t i = n; i-- > 0;) {
    const Clause& c = ssa[i];
    const Interval y = v_[c.out];
    switch (c.op) {
      case Op::Load:
        if (c.a < unknowns && !narrow(box[c.a], y)) return false;
        break;
      case Op::Neg:
        if (!narrow(v_[c.a], -y)) return false;
        break;
      case Op::Add:
        if (!narrow(v_[c.a], guard(y - v_[c.b]))) return false;
        if (!narrow(v_[c.b], guard(y - v_[c.a]))) return false;
        break;
      case Op::Sub:
        if (!narrow(v_[c.a], guard(y + v_[c.b]))) return false;
        if (!narrow(v_[c.b], guard(v_[c.a] - y))) return false;
        break;
      case Op::Mul:
        if (!narrow(v_[c.a], extended_divide(y, v_[c.b]))) return false;
        if (!narrow(v_[c.b], extended_divide(y, v_[c.a]))) return false;
        break;
      case Op::Div:  // y = a / b with b != 0 at every solution
        if (!narrow(v_[c.a], guard(y * v_[c.b]))) return false;
        if (!narrow(v_[c.b], extended_divide(v_[c.a], y))) return false;
        break;
      case Op::AddImm:
        if (!narrow(v_[c.a], guard(y - Interval(k[c.b])))) return false;
        break;
      case Op::SubImm:
        if (!narrow(v_[c.a], guard(Interval(k[c.b]) - y))) return false;
        break;
      case Op::MulImm:
        if (k[c.b] != 0.0 && std::isfinite(k[c.b]) && !narrow(v_[c.a], extended_divide(y, Interval(k[c.b]))))
          return false;
        break;
      case Op::DivImmR:
        if (k[c.b] != 0.0 && std::isfinite(k[c.b]) && !narrow(v_[c.a], guard(y * Interval(k[c.b])))) return false;
        break;
      case Op::DivImmL:
        if (k[c.b] != 0.0 && std::isfinite(k[c.b]) && !narrow(v_[c.a], extended_divide(Interval(k[c.b]), y)))
          return false;
        break;
      case Op::Square: {
        const Interval y0 = intersect(y, Interval::unchecked(0.0, kInf));
        if (y0.is_empty()) return false;
        const Interval s = sqrt(y0);
        if (!narrow(v_[c.a], IntervalPair{Interval::unchecked(-s.hi(), -s.lo()), s})) return false;
        break;
      }
      case Op::Sqrt: {
        const Interval y0 = intersect(y, Interval::unchecked(0.0, kInf));
        if (y0.is_empty()) return false;
        if (!narrow(v_[c.a], square(y0))) return false;
        break;
      }
      case Op::Exp: {
        const Interval y0 = intersect(y, Interval::unchecked(0.0, kInf));
        if (y0.is_empty() || y0.hi() <= 0.0) return false;
        if (!narrow(v_[c.a], guard(log(y0)))) return false;
        break;
      }
      case Op::Log:
        if (!narrow(v_[c.a], guard(exp(y)))) return false;
        break;
      case Op::Asin:
      case Op::Acos:
        if (!narrow(v_[c.a], Interval(-1.0, 1.0))) return false;
        break;
      case Op::Abs: {
        const Interval y0 = intersect(y, Interval::unchecked(0.0, kInf));
        if (y0.is_empty()) return false;
        if (!narrow(v_[c.a], IntervalPair{-y0, y0})) return false;
        break;
      }
      case Op::Min:
      case Op::MinImm: {
        const Interval b = c.op == Op::Min ? v_[c.b] : Interval(k[c.b]);
        const Interval ge = Interval::unchecked(y.lo(), kInf);
        if (!narrow(v_[c.a], ge)) return false;
        if (b.lo() > y.hi() && !narrow(v_[c.a], y)) return false;  // a must be the minimum
        if (c.op == Op::Min) {
          if (!narrow(v_[c.b], ge)) return false;
          if (v_[c.a].lo() > y.hi() && !narrow(v_[c.b], y)) return false;
        }
        break;
      }
      case Op::Max:
      case Op::MaxImm: {
        const Interval b = c.op == Op::Max ? v_[c.b] : Interval(k[c.b]);
        const Interval le = Interval::unchecked(-kInf, y.hi());
        if (!narrow(v_[c.a], le)) return false;
        if (b.hi() < y.lo() && !narrow(v_[c.a], y)) return false;  // a must be the maximum
        if (c.op == Op::Max) {
          if (!narrow(v_[c.b], le)) return false;
          if (v_[c.a].hi() < y.lo() && !narrow(v_[c.b], y)) return false;
        }
        break;
      }
      default: break;  // no projection: operands unchanged (always sound)
    }
  }
  return true;
}

}  // namespace genmod
