#include "genmod/kernel/interval_evaluator.hpp"

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

inline Interval min_or_max(bool is_min, const Interval& a, const Interval& b) {
  if (a.is_empty() || b.is_empty()) return Interval::empty();
  return is_min ? Interval::unchecked(std::min(a.lo(), b.lo()), std::min(a.hi(), b.hi()))
                : Interval::unchecked(std::max(a.lo(), b.lo()), std::max(a.hi(), b.hi()));
}

// Choice of min(a, b) (or max with the roles of the bounds swapped): one side only when it is
// strictly on its side over the whole box and the dropped side cannot be an error (which
// would propagate at a point). Ties keep both, so pruning never changes a signed zero.
inline std::uint8_t min_choice(const Interval& a, const Interval& b, std::uint8_t ea, std::uint8_t eb) {
  if (a.is_empty() || b.is_empty()) return kChoiceBoth;
  if (a.hi() < b.lo() && eb == kNoError) return kChoiceFirst;
  if (b.hi() < a.lo() && ea == kNoError) return kChoiceSecond;
  return kChoiceBoth;
}

inline Interval rounded_floor_like(const Interval& x, bool is_floor, bool& jump) {
  const Interval r = is_floor ? floor(x) : ceil(x);
  if (!r.is_point()) jump = true;
  return r;
}

}  // namespace

std::span<const Interval> IntervalEvaluator::eval(const Tape& tape, std::span<const Interval> box) {
  detail::check_inputs(tape, box.size(), "IntervalEvaluator");
  for (std::size_t k = 0; k < box.size(); ++k) {
    const Interval& b = box[k];
    if (!b.is_empty() && !(b.lo() <= b.hi() && b.lo() < kInf && b.hi() > -kInf))
      throw std::invalid_argument("genmod: IntervalEvaluator: input " + std::to_string(k) + " is not a legal interval");
  }
  const auto clauses = tape.clauses();
  const std::span<const double> k = tape.constants();
  regs_.resize(tape.num_registers());
  err_.assign(tape.num_registers(), kNoError);
  slots_.resize(tape.num_call_slots());
  slot_err_.resize(tape.num_call_slots());
  choices_.assign(clauses.size(), kChoiceBoth);
  bool jump = false;  // some discontinuity may lie in the box

  Interval* r = regs_.data();
  std::uint8_t* e = err_.data();
  {
    RoundingScope up;
    for (std::size_t i = 0; i < clauses.size(); ++i) {
      const Clause& c = clauses[i];
      // Leaves and calls use `a` as an index into other tables, not as a register.
      const std::uint32_t ra = arity(c.op) >= 1 ? c.a : 0;
      const Interval a = r[ra];
      const std::uint8_t ea = e[ra];
      std::uint8_t err = ea;  // default: unary propagation
      Interval v;
      switch (c.op) {
        case Op::Const:
          v = Interval(k[c.a]);
          err = v.is_empty() ? kCertainError : kNoError;
          break;
        case Op::Load:
          v = box[c.a];
          err = v.is_empty() ? kCertainError : kNoError;
          break;
        case Op::Neg: v = Interval::unchecked(-a.hi(), -a.lo()); break;
        case Op::Square: v = cook(boost::numeric::square(raw(a))); break;
        case Op::Sqrt: v = fast_sqrt(a, err); break;
        case Op::Exp: v = exp(a); break;
        case Op::Log: v = log(a, &err); break;
        case Op::Sin: v = sin(a); err |= has_inf(a) ? kMaybeError : kNoError; break;
        case Op::Cos: v = cos(a); err |= has_inf(a) ? kMaybeError : kNoError; break;
        case Op::Tan: v = tan(a); err |= has_inf(a) ? kMaybeError : kNoError; break;
        case Op::Asin: v = asin(a, &err); break;
        case Op::Acos: v = acos(a, &err); break;
        case Op::Atan: v = atan(a); break;
        case Op::Abs: v = abs(a); break;
        case Op::Floor: v = rounded_floor_like(a, true, jump); break;
        case Op::Ceil: v = rounded_floor_like(a, false, jump); break;
        case Op::Not:
          v = a.is_empty() ? a : surely_false(a) ? kTrue : surely_true(a) ? kFalse : (jump = true, kUnknown);
          break;
        case Op::IsError:
          v = ea == kNoError ? kFalse : ea == kCertainError ? kTrue : (jump = true, kUnknown);
          err = kNoError;
          break;
        case Op::AddImm: v = cook(raw(a) + k[c.b]); break;
        case Op::MulImm:
          v = cook(raw(a) * k[c.b]);
          if (k[c.b] == 0.0 && unbounded(a)) err |= kMaybeError;  // 0 * inf
          break;
        case Op::SubImm: v = cook(k[c.b] - raw(a)); break;
        case Op::DivImmR: v = raw_divide(a, Interval(k[c.b]), err); break;
        case Op::DivImmL: v = raw_divide(Interval(k[c.b]), a, err); break;
        case Op::MinImm:
        case Op::MaxImm: {
          const bool is_min = c.op == Op::MinImm;
          const Interval kb(k[c.b]);
          v = min_or_max(is_min, a, kb);
          choices_[i] = is_min ? min_choice(a, kb, ea, kNoError) : min_choice(-a, -kb, ea, kNoError);
          break;
        }
        case Op::Call: {
          // Custom operators use protected arithmetic in the default rounding mode.
          const CallSite& cs = tape.calls()[c.a];
          std::vector<Interval> args(cs.num_args);
          std::uint8_t arg_err = kNoError;
          for (std::uint32_t j = 0; j < cs.num_args; ++j) {
            const std::uint32_t reg = tape.call_arg_registers()[cs.first_arg + j];
            args[j] = r[reg];
            arg_err |= e[reg];
          }
          std::fesetround(FE_TONEAREST);
          std::fill_n(slot_err_.begin() + cs.first_slot, cs.num_outputs, arg_err);
          dag::custom(cs.op_id).inclusion(args, std::span(slots_).subspan(cs.first_slot, cs.num_outputs),
                                          std::span(slot_err_).subspan(cs.first_slot, cs.num_outputs));
          std::fesetround(FE_UPWARD);
          jump = true;  // continuity of custom operators is not known
          continue;
        }
        case Op::CallOut:
          v = slots_[c.a];
          err = slot_err_[c.a];
          break;
        default: {
          const Interval b = r[c.b];
          const std::uint8_t eb = e[c.b];
          err = ea | eb;
          switch (c.op) {
            case Op::Add:
              v = cook(raw(a) + raw(b));
              if (unbounded(a, b)) err |= overflow_add(a, b);
              break;
            case Op::Sub:
              v = cook(raw(a) - raw(b));
              if (unbounded(a, b)) err |= overflow_add(a, -b);
              break;
            case Op::Mul:
              v = cook(raw(a) * raw(b));
              if (unbounded(a, b)) err |= overflow_mul(a, b);
              break;
            case Op::Div:
              v = raw_divide(a, b, err);
              if (has_inf(a) && has_inf(b)) err |= kMaybeError;
              break;
            case Op::Pow:
              v = pow(a, b, &err);
              if (unbounded(a, b)) err |= kMaybeError;
              break;
            case Op::Atan2:
              v = atan2(a, b);
              if (v.width() >= std::numbers::pi) jump = true;  // may straddle the branch cut
              break;
            case Op::Min:
              v = min_or_max(true, a, b);
              choices_[i] = min_choice(a, b, ea, eb);
              break;
            case Op::Max:
              v = min_or_max(false, a, b);
              choices_[i] = min_choice(-a, -b, ea, eb);
              break;
            case Op::Lt: case Op::Le: case Op::Gt: case Op::Ge: case Op::Eq: case Op::Ne:
              v = relation(c.op, a, b, jump);
              break;
            case Op::And: case Op::Or: v = logic(c.op, a, b, jump); break;
            case Op::Select: {
              const Interval& otherwise = r[c.c];
              const std::uint8_t ec = e[c.c];
              if (a.is_empty()) {
                v = a;
              } else if (surely_true(a)) {
                v = b;
                err = ea | eb;
                if (ea == kNoError) choices_[i] = kChoiceFirst;
              } else if (surely_false(a)) {
                v = otherwise;
                err = ea | ec;
                if (ea == kNoError) choices_[i] = kChoiceSecond;
              } else {
                // Either branch may be taken: an error in one is only possible, not certain.
                v = hull(b, otherwise);
                const std::uint8_t branch_err =
                    (eb == kCertainError && ec == kCertainError) ? kCertainError : ((eb | ec) & kMaybeError);
                err = ea | branch_err;
                jump = true;
              }
              break;
            }
            default: break;
          }
        }
      }
      if (v.is_empty()) err |= kCertainError;
      r[c.out] = v;
      e[c.out] = err;
    }
  }
  out_.resize(tape.num_outputs());
  out_err_.resize(tape.num_outputs());
  continuous_ = !jump;
  for (std::size_t j = 0; j < out_.size(); ++j) {
    out_[j] = r[tape.output_registers()[j]];
    out_err_[j] = e[tape.output_registers()[j]];
    if (out_err_[j] != kNoError) continuous_ = false;
  }
  return out_;
}

}  // namespace genmod
