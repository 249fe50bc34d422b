#include "genmod/kernel/tape_contractor.hpp"

#include "tape_data.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

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

// Clauses whose result can be a number where an operand is an error: below them the
// projections' premise (every value is a number at a solution) fails.
bool hides_errors(Op op) noexcept { return op == Op::Select || op == Op::IsError || op == Op::Call; }

}  // namespace

bool TapeContractor::projects(const Tape& tape) noexcept {
  return std::none_of(detail::ssa(tape).begin(), detail::ssa(tape).end(), [](const Clause& c) { return hides_errors(c.op); });
}

bool TapeContractor::contract(const Tape& tape, std::span<Interval> box, const Interval& target,
                              std::size_t narrowable) {
  if (tape.num_outputs() != 1)
    throw std::invalid_argument("genmod: TapeContractor: the tape has " + std::to_string(tape.num_outputs()) +
                                " outputs, expected 1");
  // Forward: the evaluator's enclosures and error bits for every SSA value.
  forward_.eval_ssa(tape, box);
  const std::uint32_t root = detail::output_values(tape)[0];
  if (forward_.err_[root] == kCertainError) return false;  // f is NaN everywhere on the box
  v_.assign(forward_.regs_.begin(), forward_.regs_.end());
  // Empty values that are not certain errors are NaN bounds of a possible overflow (inf - inf):
  // they bound nothing.
  for (std::size_t i = 0; i < v_.size(); ++i)
    if (v_[i].is_empty() && forward_.err_[i] != kCertainError) v_[i] = Interval::entire();
  if (!narrow(v_[root], target)) return false;
  if (!projects(tape)) return true;
  return project(tape, box, narrowable);
}

// Backward: projects each clause's (narrowed) value onto its operands. Every user of a value
// comes after it on the tape, so a value is final when its clause is reached. Where every
// value is a number at every solution (projects()), a certain error anywhere makes f one too,
// which contract() has already rejected.
bool TapeContractor::project(const Tape& tape, std::span<Interval> box, std::size_t narrowable) {
  const std::span<const Clause> ssa = detail::ssa(tape);
  const std::span<const double> k = tape.constants();
  for (std::size_t i = ssa.size(); i-- > 0;) {
    const Clause& c = ssa[i];
    const Interval y = v_[c.out];
    switch (c.op) {
      case Op::Load:
        if (c.a < narrowable && !narrow(box[c.a], y)) return false;
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
      // No projection: the operands are unchanged (always sound). Listed, not defaulted, so
      // that an opcode added to the table gets a decision here.
      case Op::Const: case Op::Var: case Op::Sin: case Op::Cos: case Op::Tan: case Op::Atan: case Op::Floor:
      case Op::Ceil: case Op::Not: case Op::IsError: case Op::Pow: case Op::Atan2: case Op::Lt: case Op::Le:
      case Op::Gt: case Op::Ge: case Op::Eq: case Op::Ne: case Op::And: case Op::Or: case Op::Select:
      case Op::Custom: case Op::Call: case Op::CallOut:
        break;
    }
  }
  return true;
}

}  // namespace genmod
