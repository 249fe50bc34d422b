#include "genmod/kernel/interval_evaluator.hpp"

#include "tape_data.hpp"

#include "custom_call.hpp"

#include <algorithm>
#include <cfenv>
#include <numbers>

namespace genmod {
namespace {

using interval_detail::cook;
using interval_detail::next_down;
using interval_detail::raw;

constexpr double kInf = std::numeric_limits<double>::infinity();

const Interval kFalse = Interval::unchecked(0.0, 0.0);
const Interval kTrue = Interval::unchecked(1.0, 1.0);
const Interval kUnknown = Interval::unchecked(0.0, 1.0);

// Inside the RoundingScope: sqrt rounds up, so the upper bound is direct and the lower bound
// steps down one ulp unless the root is exact.
inline Interval fast_sqrt(const Interval& x, std::uint8_t& err) {
  if (x.is_empty() || x.hi() < 0.0) {
    err |= kCertainError;
    return Interval::empty();
  }
  double lo = x.lo();
  if (lo < 0.0) {
    err |= kMaybeError;
    lo = 0.0;
  }
  const double r = std::sqrt(lo);
  const double lo_root = (r * r == lo) ? r : std::max(0.0, next_down(r));
  return Interval::unchecked(lo_root, std::sqrt(x.hi()));
}

// Division inside the scope; a divisor containing 0 is a possible error (certain for [0,0]).
inline Interval raw_divide(const Interval& a, const Interval& b, std::uint8_t& err) {
  if (a.is_empty() || b.is_empty()) return Interval::empty();
  if (b.contains_zero()) err |= (b.lo() == 0.0 && b.hi() == 0.0) ? kCertainError : kMaybeError;
  return cook(raw(a) / raw(b));
}

// At a point, an infinite value (overflow) can turn into NaN (an error): inf - inf, 0 * inf,
// inf / inf, sin(inf), ... Bounded intervals cannot; unbounded ones flag a possible error.
// Summing the bounds tests all four for infinity at once (a false alarm on huge finite bounds
// only costs the exact check).
inline bool unbounded(const Interval& a, const Interval& b) { return !std::isfinite(a.lo() + a.hi() + b.lo() + b.hi()); }
inline bool unbounded(const Interval& a) { return !std::isfinite(a.lo() + a.hi()); }
inline bool has_inf(const Interval& a) { return std::isinf(a.lo()) || std::isinf(a.hi()); }

inline std::uint8_t overflow_add(const Interval& a, const Interval& b) {  // inf + -inf
  return ((a.hi() == kInf && b.lo() == -kInf) || (a.lo() == -kInf && b.hi() == kInf)) ? kMaybeError : kNoError;
}
inline std::uint8_t overflow_mul(const Interval& a, const Interval& b) {  // 0 * inf
  return ((has_inf(a) && b.contains_zero()) || (has_inf(b) && a.contains_zero())) ? kMaybeError : kNoError;
}

// Relations give [0,0], [1,1] or [0,1] (unknown).
inline Interval relation(Op op, const Interval& a, const Interval& b, bool& ambiguous) {
  if (a.is_empty() || b.is_empty()) return Interval::empty();
  bool yes = false, no = false;
  switch (op) {
    case Op::Lt: yes = a.hi() < b.lo(); no = a.lo() >= b.hi(); break;
    case Op::Le: yes = a.hi() <= b.lo(); no = a.lo() > b.hi(); break;
    case Op::Gt: yes = a.lo() > b.hi(); no = a.hi() <= b.lo(); break;
    case Op::Ge: yes = a.lo() >= b.hi(); no = a.hi() < b.lo(); break;
    case Op::Eq:
      yes = a.is_point() && b.is_point() && a.lo() == b.lo();
      no = a.hi() < b.lo() || b.hi() < a.lo();
      break;
    case Op::Ne:
      no = a.is_point() && b.is_point() && a.lo() == b.lo();
      yes = a.hi() < b.lo() || b.hi() < a.lo();
      break;
    default: break;
  }
  if (yes) return kTrue;
  if (no) return kFalse;
  ambiguous = true;
  return kUnknown;
}

// Truth of a 0/1 or general value: definitely nonzero, definitely zero, or unknown.
inline bool surely_true(const Interval& x) { return !x.is_empty() && !x.contains_zero(); }
inline bool surely_false(const Interval& x) { return x.lo() == 0.0 && x.hi() == 0.0; }

inline Interval logic(Op op, const Interval& a, const Interval& b, bool& ambiguous) {
  if (a.is_empty() || b.is_empty()) return Interval::empty();
  if (op == Op::And) {
    if (surely_false(a) || surely_false(b)) return kFalse;
    if (surely_true(a) && surely_true(b)) return kTrue;
  } else {
    if (surely_true(a) || surely_true(b)) return kTrue;
    if (surely_false(a) && surely_false(b)) return kFalse;
  }
  ambiguous = true;
  return kUnknown;
}

// min / max; an empty operand (a certain error) gives an empty result (NaN bounds).
inline Interval min_of(const Interval& a, const Interval& b) {
  if (a.is_empty() || b.is_empty()) return Interval::empty();
  return Interval::unchecked(std::min(a.lo(), b.lo()), std::min(a.hi(), b.hi()));
}
inline Interval max_of(const Interval& a, const Interval& b) {
  if (a.is_empty() || b.is_empty()) return Interval::empty();
  return Interval::unchecked(std::max(a.lo(), b.lo()), std::max(a.hi(), b.hi()));
}

// Choice of min(a, b): one side only when it is strictly below the other over the whole box
// and the dropped side cannot be an error (which would propagate at a point). Ties keep
// both, so pruning never changes a signed zero. NaN bounds (empty) compare false: both.
inline std::uint8_t min_choice(const Interval& a, const Interval& b, std::uint8_t ea, std::uint8_t eb) {
  if (a.hi() < b.lo() && eb == kNoError) return kChoiceFirst;
  if (b.hi() < a.lo() && ea == kNoError) return kChoiceSecond;
  return kChoiceBoth;
}
inline std::uint8_t max_choice(const Interval& a, const Interval& b, std::uint8_t ea, std::uint8_t eb) {
  if (a.lo() > b.hi() && eb == kNoError) return kChoiceFirst;
  if (b.lo() > a.hi() && ea == kNoError) return kChoiceSecond;
  return kChoiceBoth;
}

// Rounded sums inside the RoundingScope (upward): the upper bound rounds up directly, the
// lower bound is -(-a - b) (Boost's "opposite" trick). An empty operand's NaN bounds
// propagate, so no emptiness test is needed.
inline double barrier(double x) { return interval_detail::RoundingControl::force_rounding(x); }
inline Interval add_up(double alo, double ahi, double blo, double bhi) {
  return Interval::unchecked(-barrier(-alo - blo), barrier(ahi + bhi));
}

inline Interval rounded_floor_like(const Interval& x, bool is_floor, bool& jump) {
  const Interval r = is_floor ? floor(x) : ceil(x);
  if (!r.is_point()) jump = true;
  return r;
}

// The common case without error bits: a plain tape (plain_op()) over a bounded box, where an
// error can only come from a non-finite bound (an overflow) or a square root of an interval
// reaching below 0. Computes the same intervals and choices as the full loop below does when
// no error bit is set anywhere, and returns false (the caller runs the full loop) where one
// may be: some bound is not finite (their sum is not; an empty interval's NaN bounds too), or
// a root's operand reaches below 0. Saves the error bytes' loads and stores of every clause.
bool run_plain(std::span<const Clause> clauses, std::span<const double> k, std::span<const Interval> box, Interval* r,
               std::uint8_t* choice) {
  double sum = 0.0;  // of every result's bounds: finite iff all are (or a false alarm on overflow)
  bool negative_root = false;
  for (std::size_t i = 0; i < clauses.size(); ++i) {
    const Clause& c = clauses[i];
    const auto A = [&]() -> const Interval& { return r[c.a]; };
    const auto B = [&]() -> const Interval& { return r[c.b]; };
    Interval v;
    switch (c.op) {
      case Op::Max:
        choice[i] = max_choice(A(), B(), kNoError, kNoError);
        v = max_of(A(), B());
        break;
      case Op::Min:
        choice[i] = min_choice(A(), B(), kNoError, kNoError);
        v = min_of(A(), B());
        break;
      case Op::Add: v = add_up(A().lo(), A().hi(), B().lo(), B().hi()); break;
      case Op::Sub: v = add_up(A().lo(), A().hi(), -B().hi(), -B().lo()); break;
      case Op::AddImm: v = add_up(A().lo(), A().hi(), k[c.b], k[c.b]); break;
      case Op::SubImm: v = add_up(k[c.b], k[c.b], -A().hi(), -A().lo()); break;
      case Op::Neg: v = -A(); break;
      case Op::MaxImm: {
        const Interval kb(k[c.b]);
        choice[i] = max_choice(A(), kb, kNoError, kNoError);
        v = max_of(A(), kb);
        break;
      }
      case Op::MinImm: {
        const Interval kb(k[c.b]);
        choice[i] = min_choice(A(), kb, kNoError, kNoError);
        v = min_of(A(), kb);
        break;
      }
      case Op::Square: v = cook(boost::numeric::square(raw(A()))); break;
      case Op::Sqrt: {
        negative_root = negative_root || A().lo() < 0.0;
        std::uint8_t err = kNoError;
        v = fast_sqrt(A(), err);
        break;
      }
      case Op::Mul: v = cook(raw(A()) * raw(B())); break;
      case Op::MulImm: v = cook(raw(A()) * k[c.b]); break;
      case Op::Const: v = Interval::unchecked(k[c.a], k[c.a]); break;
      case Op::Load: v = box[c.a]; break;
      default: return false;  // not a plain tape
    }
    sum += v.lo() + v.hi();
    r[c.out] = v;
  }
  return std::isfinite(sum) && !negative_root;
}

}  // namespace

void IntervalEvaluator::run(const Tape& tape, std::span<const Interval> box, std::span<const Clause> clauses,
                            std::span<const std::uint32_t> call_args, std::uint32_t num_registers) {
  detail::check_inputs(tape, box.size(), "IntervalEvaluator");
  for (std::size_t k = 0; k < box.size(); ++k) {
    const Interval& b = box[k];
    if (!b.is_empty() && !(b.lo() <= b.hi() && b.lo() < kInf && b.hi() > -kInf))
      throw std::invalid_argument("genmod: IntervalEvaluator: input " + std::to_string(k) + " is not a legal interval");
  }
  const std::span<const double> k = tape.constants();
  regs_.resize(num_registers);
  err_.assign(num_registers, kNoError);
  slots_.resize(detail::num_call_slots(tape));
  slot_err_.resize(detail::num_call_slots(tape));
  choices_.assign(clauses.size(), kChoiceBoth);
  clauses_base_ = clauses.data();
  call_args_src_ = call_args;
  bool jump = false;  // some discontinuity may lie in the box

  Interval* r = regs_.data();
  std::uint8_t* e = err_.data();
  std::uint8_t* choice = choices_.data();
  {
    RoundingScope up;
    if (detail::tape_data(tape).plain && run_plain(clauses, k, box, r, choice)) {
      jump_ = false;
      return;
    }
    std::fill(choices_.begin(), choices_.end(), kChoiceBoth);  // the plain loop may have set some
    for (std::size_t i = 0; i < clauses.size(); ++i) {
      const Clause& c = clauses[i];
      // Operands are looked up only by the cases that have them: leaves and calls use `a` as
      // an index into other tables, and immediate forms use `b` for the constant.
      const auto A = [&]() -> const Interval& { return r[c.a]; };
      const auto B = [&]() -> const Interval& { return r[c.b]; };
      const std::uint32_t out = c.out;
      switch (c.op) {
        // The most frequent operations first (Prospero: max, sub, add-imm, min, neg).
        case Op::Max:
          choice[i] = max_choice(A(), B(), e[c.a], e[c.b]);
          e[out] = e[c.a] | e[c.b];
          r[out] = max_of(A(), B());
          break;
        case Op::Min:
          choice[i] = min_choice(A(), B(), e[c.a], e[c.b]);
          e[out] = e[c.a] | e[c.b];
          r[out] = min_of(A(), B());
          break;
        case Op::Add: {
          const Interval v = add_up(A().lo(), A().hi(), B().lo(), B().hi());
          e[out] = e[c.a] | e[c.b] | (std::isfinite(v.lo() + v.hi()) ? std::uint8_t{kNoError} : overflow_add(A(), B()));
          r[out] = v;
          break;
        }
        case Op::Sub: {
          const Interval v = add_up(A().lo(), A().hi(), -B().hi(), -B().lo());
          e[out] = e[c.a] | e[c.b] | (std::isfinite(v.lo() + v.hi()) ? std::uint8_t{kNoError} : overflow_add(A(), -B()));
          r[out] = v;
          break;
        }
        case Op::AddImm: {
          const double kb = k[c.b];  // finite (see the tape compiler)
          e[out] = e[c.a];
          r[out] = add_up(A().lo(), A().hi(), kb, kb);
          break;
        }
        case Op::SubImm: {
          const double kb = k[c.b];
          e[out] = e[c.a];
          r[out] = add_up(kb, kb, -A().hi(), -A().lo());
          break;
        }
        case Op::Neg:
          e[out] = e[c.a];
          r[out] = -A();
          break;
        case Op::MaxImm: {
          const Interval kb(k[c.b]);
          choice[i] = max_choice(A(), kb, e[c.a], kNoError);
          e[out] = e[c.a];
          r[out] = max_of(A(), kb);
          break;
        }
        case Op::MinImm: {
          const Interval kb(k[c.b]);
          choice[i] = min_choice(A(), kb, e[c.a], kNoError);
          e[out] = e[c.a];
          r[out] = min_of(A(), kb);
          break;
        }
        case Op::Square:
          e[out] = e[c.a];
          r[out] = cook(boost::numeric::square(raw(A())));
          break;
        case Op::Sqrt: {
          std::uint8_t err = e[c.a];
          r[out] = fast_sqrt(A(), err);
          e[out] = err;
          break;
        }
        case Op::Mul:
          e[out] = e[c.a] | e[c.b] | (std::isfinite(A().lo() + A().hi() + B().lo() + B().hi()) ? std::uint8_t{kNoError} : overflow_mul(A(), B()));
          r[out] = cook(raw(A()) * raw(B()));
          break;
        case Op::MulImm:
          // 0 * inf at a point is NaN: an unbounded operand times 0 may be an error.
          e[out] = e[c.a] | ((k[c.b] == 0.0 && unbounded(A())) ? kMaybeError : kNoError);
          r[out] = cook(raw(A()) * k[c.b]);
          break;
        case Op::Const: {
          const Interval v(k[c.a]);
          e[out] = v.is_empty() ? kCertainError : kNoError;
          r[out] = v;
          break;
        }
        case Op::Load:
          e[out] = box[c.a].is_empty() ? kCertainError : kNoError;
          r[out] = box[c.a];
          break;
        case Op::Call:
          if (!call(tape, c.a)) jump = true;
          break;
        case Op::CallOut:
          e[out] = slot_err_[c.a];
          r[out] = slots_[c.a];
          break;
        default: {
          const std::uint8_t ea = e[c.a];
          std::uint8_t err = ea;
          const Interval v = other_op(c, k, err, jump);
          e[out] = err;
          r[out] = v;
          break;
        }
      }
    }
  }
  jump_ = jump;
}

std::span<const Interval> IntervalEvaluator::eval(const Tape& tape, std::span<const Interval> box) {
  run(tape, box, detail::clauses(tape), detail::call_arg_registers(tape), tape.num_registers());
  finish(detail::output_registers(tape));
  return out_;
}

void IntervalEvaluator::eval_ssa(const Tape& tape, std::span<const Interval> box) {
  run(tape, box, detail::ssa(tape), detail::call_arg_values(tape), detail::num_values(tape));
}

void IntervalEvaluator::finish(std::span<const std::uint32_t> output_registers) {
  out_.resize(output_registers.size());
  out_err_.resize(output_registers.size());
  continuous_ = !jump_;
  for (std::size_t j = 0; j < out_.size(); ++j) {
    out_[j] = regs_[output_registers[j]];
    out_err_[j] = err_[output_registers[j]];
    if (out_err_[j] != kNoError) continuous_ = false;
  }
}

// The less frequent operations, out of the hot loop. `err` holds the first operand's error
// bits on entry.
Interval IntervalEvaluator::other_op(const Clause& c, std::span<const double> k, std::uint8_t& err, bool& jump) {
  const std::uint8_t ea = err;
  const Interval& a = regs_[c.a];  // every operation here has a first operand
  switch (c.op) {
    case Op::Exp: return exp(a);
    case Op::Log: return log(a, &err);
    case Op::Sin: err |= has_inf(a) ? kMaybeError : kNoError; return sin(a);
    case Op::Cos: err |= has_inf(a) ? kMaybeError : kNoError; return cos(a);
    case Op::Tan: err |= has_inf(a) ? kMaybeError : kNoError; return tan(a);
    case Op::Asin: return asin(a, &err);
    case Op::Acos: return acos(a, &err);
    case Op::Atan: return atan(a);
    case Op::Abs: return abs(a);
    case Op::Floor: return rounded_floor_like(a, true, jump);
    case Op::Ceil: return rounded_floor_like(a, false, jump);
    case Op::Not:
      if (a.is_empty()) return a;
      if (surely_false(a)) return kTrue;
      if (surely_true(a)) return kFalse;
      jump = true;
      return kUnknown;
    case Op::IsError:
      err = kNoError;
      if (ea == kNoError) return kFalse;
      if (ea == kCertainError) return kTrue;
      jump = true;
      return kUnknown;
    case Op::DivImmR: return raw_divide(a, Interval(k[c.b]), err);
    case Op::DivImmL: return raw_divide(Interval(k[c.b]), a, err);
    default: break;
  }
  // Binary and ternary operations.
  const Interval& b = regs_[c.b];
  const std::uint8_t eb = err_[c.b];
  err = ea | eb;
  switch (c.op) {
    case Op::Div: {
      const Interval v = raw_divide(a, b, err);
      if (has_inf(a) && has_inf(b)) err |= kMaybeError;  // inf / inf
      return v;
    }
    case Op::Pow: {
      const Interval v = pow(a, b, &err);
      if (unbounded(a, b)) err |= kMaybeError;
      return v;
    }
    case Op::Atan2: {
      const Interval v = atan2(a, b);
      if (v.width() >= std::numbers::pi) jump = true;  // may straddle the branch cut
      return v;
    }
    case Op::Lt: case Op::Le: case Op::Gt: case Op::Ge: case Op::Eq: case Op::Ne:
      return relation(c.op, a, b, jump);
    case Op::And: case Op::Or: return logic(c.op, a, b, jump);
    case Op::Select: {
      const Interval& otherwise = regs_[c.c];
      const std::uint8_t ec = err_[c.c];
      if (a.is_empty()) return a;
      if (surely_true(a)) {
        err = ea | eb;
        if (ea == kNoError) choices_[&c - clauses_base_] = kChoiceFirst;
        return b;
      }
      if (surely_false(a)) {
        err = ea | ec;
        if (ea == kNoError) choices_[&c - clauses_base_] = kChoiceSecond;
        return otherwise;
      }
      // Either branch may be taken: an error in one is only possible, not certain.
      const std::uint8_t branch_err =
          (eb == kCertainError && ec == kCertainError) ? kCertainError : ((eb | ec) & kMaybeError);
      err = ea | branch_err;
      jump = true;
      return hull(b, otherwise);
    }
    // Handled by eval's loop or by the unary switch above; Var and Custom are never on
    // tapes. Listed (no default) so that an opcode added to the table without an enclosure
    // does not compile.
    case Op::Const: case Op::Var: case Op::Neg: case Op::Square: case Op::Sqrt: case Op::Exp: case Op::Log:
    case Op::Sin: case Op::Cos: case Op::Tan: case Op::Asin: case Op::Acos: case Op::Atan: case Op::Abs:
    case Op::Floor: case Op::Ceil: case Op::Not: case Op::IsError: case Op::Add: case Op::Sub: case Op::Mul:
    case Op::Min: case Op::Max: case Op::Custom: case Op::AddImm: case Op::MulImm: case Op::SubImm:
    case Op::DivImmR: case Op::DivImmL: case Op::MinImm: case Op::MaxImm: case Op::Load: case Op::Call:
    case Op::CallOut:
      break;
  }
  return Interval::entire();  // not reached
}

// Runs custom call site `call`; custom operators use protected arithmetic in the default
// rounding mode, so the evaluator's upward mode is suspended around them. Returns whether the
// operator is continuous on the arguments' box.
bool IntervalEvaluator::call(const Tape& tape, std::uint32_t call) {
  const CallSite& cs = detail::calls(tape)[call];
  call_args_.resize(cs.num_args);
  std::uint8_t arg_err = kNoError;
  for (std::uint32_t j = 0; j < cs.num_args; ++j) {
    const std::uint32_t reg = call_args_src_[cs.first_arg + j];
    call_args_[j] = regs_[reg];
    arg_err |= err_[reg];
  }
  std::fill_n(slot_err_.begin() + cs.first_slot, cs.num_outputs, arg_err);
  interval_detail::set_rounding_direction(interval_detail::kRoundNearest);
  const CustomOp& op = *cs.op;
  const bool continuous =
      op.inclusion_continuous(call_args_, std::span(slots_).subspan(cs.first_slot, cs.num_outputs),
                              std::span(slot_err_).subspan(cs.first_slot, cs.num_outputs));
  interval_detail::set_rounding_direction(interval_detail::kRoundUpward);
  return continuous;
}

}  // namespace genmod
