// Elementary enclosures: genmod's own outward-rounded versions of the C library functions.
//
// Method. Each function evaluates the C library (glibc's libm) at the ends of the argument (the
// corners of the box for atan2 and pow), in whatever rounding mode is current, and widens each
// result outward by a few one-ulp bit steps (interval_detail::next_down / next_up, which do
// not depend on the rounding mode). The function's monotonicity, or for sin / cos / tan its
// quadrant structure, says which ends give which bounds. Each bound is then clamped by what
// is known exactly about the function: its range (|sin| <= 1, exp >= 0, ...) and on which
// side of a special value the true value lies (exp x >= 1 for x >= 0, atan x >= 0 for x >= 0,
// sin x >= 0 in quadrants 0 and 1, ...). This keeps exact values exact (cos 0 = 1, exp 0 = 1,
// log 1 = 0, atan 0 = 0, so that log([0, 1]) = [-inf, 0] holds without ulp noise) and bounds
// on the right side of them.
//
// How far to widen. glibc's double functions are not correctly rounded but carry small,
// documented errors in every rounding mode (glibc's libm-test-ulps lists them per mode;
// directed modes matter because the interval evaluators call us inside a RoundingScope).
// Measured against MPFR on 200000 random arguments per function and mode (glibc 2.36):
//   sin, cos, tan, atan, atan2:  <= 0.56 ulp in all four modes  -> widen by kUlpsStable = 2
//   exp, log, pow, asin, acos:   <= 0.52 ulp to nearest, up to 1.23 ulp in directed modes
//                                (glibc's table lists up to 2)  -> widen by kUlpsDirected = 3
// n one-ulp steps cover any error below n - 1/2 ulps, also where the result crosses a power
// of two (the ulp changes size there): a margin of about one ulp over the errors known.
// One exception: sin, cos and tan of huge arguments very near a multiple of pi/2 carry an
// absolute error from glibc's argument reduction (see kLargeArgument), widened separately.
// tests/kernel/interval_mpfi_test.cpp checks every function against MPFI in all four
// rounding modes, including the doubles nearest to multiples of pi/2 in every binade.
// sqrt (correctly rounded) and square (Boost's correctly rounded product) are the tightest
// enclosures.
#include "genmod/kernel/interval.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace genmod {
namespace {

using interval_detail::next_down;
using interval_detail::next_up;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMax = std::numeric_limits<double>::max();

// Double bounds of pi and pi/2: the nearest doubles lie below the true values.
constexpr double kPiLo = 0x1.921fb54442d18p+1;
constexpr double kPiHi = 0x1.921fb54442d19p+1;
constexpr double kHalfPiLo = 0x1.921fb54442d18p+0;
constexpr double kHalfPiHi = 0x1.921fb54442d19p+0;

constexpr int kUlpsStable = 2;
constexpr int kUlpsDirected = 3;

// Width thresholds for the periodic functions. `b - a` is computed in the current rounding
// mode (error below one ulp, ~1e-15), so with a threshold a little below the period every
// interval a full period wide is caught; the few narrower ones caught too just get the
// (still valid) whole range.
constexpr double kBelowTwoPi = 6.28;
constexpr double kBelowPi = 3.14;

double step_down(double v, int ulps) noexcept {
  for (int i = 0; i < ulps; ++i) v = next_down(v);
  return v;
}

double step_up(double v, int ulps) noexcept {
  for (int i = 0; i < ulps; ++i) v = next_up(v);
  return v;
}

// Bounds of f(x) from the C library value v = f(x), for a function whose true value f(x) is
// known to be >= `least` (lower) or <= `most` (upper). The clamp keeps exact values such as
// exp 0 = 1 or atan 0 = 0 exact, and bounds on the right side of them.
double lower(double v, int ulps, double least) noexcept { return std::max(step_down(v, ulps), least); }
double upper(double v, int ulps, double most) noexcept { return std::min(step_up(v, ulps), most); }

// An interval from bounds that enclose a nonempty set of values. A lower bound of +inf (or
// an upper bound of -inf) can only mean "beyond every double"; DBL_MAX is then still a
// valid bound and keeps the interval legal.
Interval make(double lo, double hi) noexcept {
  if (lo == kInf) lo = kMax;
  if (hi == -kInf) hi = -kMax;
  return Interval::unchecked(lo, hi);
}

void flag(std::uint8_t* err, std::uint8_t bits) noexcept {
  if (err) *err |= bits;
}

// The part of x inside the domain [dlo, dhi], flagging an error where x leaves it: maybe if
// part of x is outside, certain if all of it is. An empty x counts as a certain error, as in
// divide(): it only arises from a certain error upstream.
Interval restrict_to_domain(const Interval& x, double dlo, double dhi, std::uint8_t* err) noexcept {
  const Interval inside = intersect(x, Interval::unchecked(dlo, dhi));
  if (inside.is_empty())
    flag(err, kCertainError);
  else if (x.lo() < dlo || x.hi() > dhi)
    flag(err, kMaybeError);
  return inside;
}

// ---- sqrt ---------------------------------------------------------------------------------

// Below this, r*r - v might underflow past the subnormals and round to 0, so the residual
// test below could not tell an exact root from an inexact one.
constexpr double kExactResidualMin = 0x1p-900;

// sqrt is correctly rounded in every IEEE rounding mode, so r = sqrt(v) is one of the two
// doubles around the true root. The sign of the residual r*r - v, computed exactly by one
// fma (the exact value is a nonzero multiple of 2^-1004 or zero, so rounding keeps its sign),
// tells on which side r lies.
double sqrt_lo(double v) noexcept {
  const double r = std::sqrt(v);
  if (r == 0.0) return 0.0;
  if (v < kExactResidualMin) return next_down(r);
  return std::fma(r, r, -v) > 0.0 ? next_down(r) : r;
}

double sqrt_hi(double v) noexcept {
  const double r = std::sqrt(v);
  if (r == 0.0 || r == kInf) return r;
  if (v < kExactResidualMin) return next_up(r);
  return std::fma(r, r, -v) < 0.0 ? next_up(r) : r;
}

// ---- sin, cos and tan ---------------------------------------------------------------------

// Below 1.5 in magnitude (< pi/2) the only multiple of pi/2 is 0, so signs follow from x.
constexpr double kNearZero = 1.5;

// Large arguments. glibc reduces |x| >= 105414350 (~2^26.65) modulo pi/2 with a double-double
// multiple of 2/pi, which leaves an absolute error of up to ~1.5e-28 (~2^-92) beyond one ulp
// in sin and cos near their zeros (measured at the doubles nearest to multiples of pi/2 in
// every binade, in all rounding modes; there the relative error reaches 1e5 ulps). Below that
// threshold the error stays under one ulp. Bounds at arguments from 2^26 on are therefore
// widened also by the absolute kReductionError = 2^-80, a margin of 2^12, where it matters:
// for values below kReductionMatters in magnitude (above, it is under 2^-7 ulp and the ulp
// widening absorbs it). For tan = sin / cos the error becomes kReductionError (1 + tan^2).
constexpr double kLargeArgument = 0x1p26;
constexpr double kReductionError = 0x1p-80;
constexpr double kReductionMatters = 0x1p-20;

// v - e and v + e rounded outward in any mode: the exact result lies between the neighbours
// of the rounded one.
double minus(double v, double e) noexcept { return next_down(v - e); }
double plus(double v, double e) noexcept { return next_up(v + e); }

// Bounds of the C library value v of sin or cos at x: kUlpsStable ulps, plus the reduction
// error for large x.
double trig_lo(double v, double x) noexcept {
  const double lo = step_down(v, kUlpsStable);
  return (std::abs(x) >= kLargeArgument && std::abs(v) < kReductionMatters) ? minus(lo, kReductionError) : lo;
}

double trig_hi(double v, double x) noexcept {
  const double hi = step_up(v, kUlpsStable);
  return (std::abs(x) >= kLargeArgument && std::abs(v) < kReductionMatters) ? plus(hi, kReductionError) : hi;
}

// The quadrant q of a double x, 0..3: x lies in [q pi/2, (q+1) pi/2) modulo 2 pi. Near 0 it
// follows from the sign of x; elsewhere from the signs of the C library's sin x and cos x (s
// and c). Those signs are right: no double of magnitude >= 1.5 is within ~4.7e-19 of a
// multiple of pi/2, so |sin x|, |cos x| >= ~4.7e-19 there, far above the absolute errors
// above, and the relative errors are far below 1.
int quadrant(double x, double s, double c) noexcept {
  if (std::abs(x) < kNearZero) return x >= 0.0 ? 0 : 3;
  if (s >= 0.0) return c > 0.0 ? 0 : 1;
  return c < 0.0 ? 2 : 3;
}

// Whether walking up from quadrant qa across `crossed` quadrant boundaries passes boundary
// `boundary` (boundary j is the point j pi/2 modulo 2 pi, where quadrant j begins).
bool passes(int qa, int crossed, int boundary) noexcept {
  int steps = (boundary - qa + 4) % 4;
  if (steps == 0) steps = 4;
  return steps <= crossed;
}

// Bounds of sin (is_sin) or cos at one end `at` in quadrant q, from the C library value v.
// The quadrant gives the sign of the true value (sin >= 0 in quadrants 0 and 1, cos >= 0 in 0
// and 3), which keeps the bounds on the right side of 0; sin(+-0) = +-0 is exact.
double end_lo(double v, double at, int q, bool is_sin) noexcept {
  if (is_sin && at == 0.0) return v;
  const bool nonnegative = is_sin ? q <= 1 : (q == 0 || q == 3);
  return std::max(trig_lo(v, at), nonnegative ? 0.0 : -1.0);
}

double end_hi(double v, double at, int q, bool is_sin) noexcept {
  if (is_sin && at == 0.0) return v;
  const bool nonpositive = is_sin ? q >= 2 : (q == 1 || q == 2);
  return std::min(trig_hi(v, at), nonpositive ? 0.0 : 1.0);
}

// Range of sin (max_boundary = 1: max at pi/2, min at 3 pi/2) or cos (max_boundary = 0: max
// at 0, min at pi) over x, from the C library values at both ends.
Interval sin_or_cos(const Interval& x, int max_boundary) noexcept {
  if (x.is_empty()) return Interval::empty();
  const double a = x.lo(), b = x.hi();
  if (!(b - a < kBelowTwoPi)) return Interval::unchecked(-1.0, 1.0);  // also unbounded x
  const double sa = std::sin(a), ca = std::cos(a), sb = std::sin(b), cb = std::cos(b);
  const int qa = quadrant(a, sa, ca), qb = quadrant(b, sb, cb);
  // Boundaries crossed from a to b. The same quadrant at both ends means none (width below
  // pi/2) or all four (width above 3 pi/2): comparing the width with pi tells them apart.
  int crossed = (qb - qa + 4) % 4;
  if (crossed == 0 && b - a > kPiLo) crossed = 4;
  const bool is_sin = max_boundary == 1;
  const double fa = is_sin ? sa : ca, fb = is_sin ? sb : cb;
  const double lo_ends = std::min(end_lo(fa, a, qa, is_sin), end_lo(fb, b, qb, is_sin));
  const double hi_ends = std::max(end_hi(fa, a, qa, is_sin), end_hi(fb, b, qb, is_sin));
  const double lo = passes(qa, crossed, (max_boundary + 2) % 4) ? -1.0 : lo_ends;
  const double hi = passes(qa, crossed, max_boundary) ? 1.0 : hi_ends;
  return Interval::unchecked(lo, hi);
}

// Bounds of tan at a lower end a / upper end b of an interval without a pole. tan a has the
// sign of a on (-1.5, 1.5) (inside (-pi/2, pi/2)), and elsewhere the sign of the C library
// value, which is right there (see quadrant()). The sign keeps the bound on the right side of
// 0, which makes tan 0 = 0 exact.
bool tan_nonnegative(double x, double t) noexcept { return std::abs(x) < kNearZero ? x >= 0.0 : t > 0.0; }
bool tan_nonpositive(double x, double t) noexcept { return std::abs(x) < kNearZero ? x <= 0.0 : t < 0.0; }

// The reduction error in tan x (see kLargeArgument), where it matters: near 0 and near poles.
double tan_reduction_error(double x, double t) noexcept {
  const double m = std::abs(t);
  if (std::abs(x) < kLargeArgument || (m >= kReductionMatters && m <= 1.0 / kReductionMatters)) return 0.0;
  return kReductionError * (1.0 + m * m);  // rounding here is far inside the 2^12 margin
}

double tan_lo(double a) noexcept {
  const double t = std::tan(a), e = tan_reduction_error(a, t);
  const double lo = step_down(t, kUlpsStable);
  return std::max(e > 0.0 ? minus(lo, e) : lo, tan_nonnegative(a, t) ? 0.0 : -kInf);
}

double tan_hi(double b) noexcept {
  const double t = std::tan(b), e = tan_reduction_error(b, t);
  const double hi = step_up(t, kUlpsStable);
  return std::min(e > 0.0 ? plus(hi, e) : hi, tan_nonpositive(b, t) ? 0.0 : kInf);
}

// ---- pow ----------------------------------------------------------------------------------

// Whether the C library's pow(x, y) is exact: 1^y = x^0 = 1, and the powers of 0 and +inf
// (0, 1 or +inf). C's Annex F defines these special cases exactly. (x^1 is not among them:
// glibc computes it like any other power and may be an ulp off in directed rounding modes.)
bool pow_is_exact(double x, double y) noexcept { return x == 1.0 || y == 0.0 || x == 0.0 || x == kInf; }

struct Bounds {
  double lo, hi;
};

// Bounds of x^y for one corner with x >= 0. Inexact values are widened and kept on their known
// side of 1: x^y >= 1 if x >= 1 and y >= 0 or x <= 1 and y <= 0, else 0 <= x^y <= 1.
Bounds pow_corner(double x, double y) noexcept {
  if (y == 1.0) return {x, x};
  const double v = std::pow(x, y);
  if (pow_is_exact(x, y)) return {v, v};
  const bool at_least_one = (x >= 1.0) == (y >= 0.0);
  return {lower(v, kUlpsDirected, at_least_one ? 1.0 : 0.0), upper(v, kUlpsDirected, at_least_one ? kInf : 1.0)};
}

// x^y over the box [p, q] x y with 0 <= p. For fixed y, x^y is monotone in x (also with the
// conventions 0^y = 0, 1, inf for y >0, =0, <0 and inf^y = inf, 1, 0); for fixed x it is
// monotone in y (y ln x is linear in y). So the range is the hull of the four corner values.
// The point x = 0 is excluded for y < 0 (0^negative is an error): over [0, 0] the exponents
// are restricted to y >= 0, elsewhere the corner value pow(0, y<0) = inf is a valid bound.
Interval pow_nonnegative_base(double p, double q, Interval y) noexcept {
  if (p == 0.0) p = 0.0;  // +0: pow(-0, odd negative) would be -inf
  if (q == 0.0) q = 0.0;
  if (q == 0.0) {
    y = intersect(y, Interval::unchecked(0.0, kInf));
    if (y.is_empty()) return Interval::empty();
  }
  double lo = kInf, hi = -kInf;
  for (const double base : {p, q}) {
    for (const double exponent : {y.lo(), y.hi()}) {
      const Bounds corner = pow_corner(base, exponent);
      lo = std::min(lo, corner.lo);
      hi = std::max(hi, corner.hi);
    }
  }
  return make(lo, hi);
}

// x^k over negative bases x in [a, b] (a < 0, b <= 0) for the integers k in [kl, kh]:
// x^k = (-1)^k |x|^k. One integer gives an exact sign; several give both signs.
Interval pow_negative_base(double a, double b, double kl, double kh) noexcept {
  const Interval magnitude = pow_nonnegative_base(-b, -a, Interval::unchecked(kl, kh));
  if (magnitude.is_empty()) return magnitude;
  if (kl == kh) {
    const bool odd = std::fmod(kl, 2.0) != 0.0;
    return odd ? -magnitude : magnitude;
  }
  return Interval::unchecked(-magnitude.hi(), magnitude.hi());
}

// Error state of pow over the box, from point::pow's semantics: an error where x < 0 and y is
// not an integer, or where x = 0 and y < 0.
std::uint8_t pow_errors(const Interval& x, const Interval& y, bool y_has_integer) noexcept {
  const bool y_has_noninteger = !(y.is_point() && y_has_integer);
  const bool x_has_negative = x.lo() < 0.0, x_has_zero = x.contains_zero();
  const bool some_valid = x.hi() > 0.0 || (x_has_zero && y.hi() >= 0.0) || (x_has_negative && y_has_integer);
  const bool some_error = (x_has_negative && y_has_noninteger) || (x_has_zero && y.lo() < 0.0);
  if (!some_valid) return kCertainError;
  return some_error ? kMaybeError : kNoError;
}

}  // namespace

Interval square(const Interval& x) noexcept {
  if (x.is_empty()) return Interval::empty();
  RoundingScope upward;  // Boost's raw square rounds correctly only in the upward mode
  return interval_detail::cook(boost::numeric::square(interval_detail::raw(x)));
}

Interval sqrt(const Interval& x, std::uint8_t* err) noexcept {
  const Interval d = restrict_to_domain(x, 0.0, kInf, err);
  if (d.is_empty()) return d;
  return Interval::unchecked(sqrt_lo(d.lo()), sqrt_hi(d.hi()));
}

Interval exp(const Interval& x) noexcept {
  if (x.is_empty()) return Interval::empty();
  // e^x >= 0 always, >= 1 for x >= 0 and <= 1 for x <= 0 (so exp 0 = 1 exactly).
  const double a = x.lo(), b = x.hi();
  const double lo = lower(std::exp(a), kUlpsDirected, a >= 0.0 ? 1.0 : 0.0);
  const double hi = upper(std::exp(b), kUlpsDirected, b <= 0.0 ? 1.0 : kInf);
  return make(lo, hi);
}

Interval log(const Interval& x, std::uint8_t* err) noexcept {
  // Domain (0, inf]: log 0 is an error, so [0, 0] is a certain error and [0, b] a possible one.
  if (x.is_empty() || x.hi() <= 0.0) {
    flag(err, kCertainError);
    return Interval::empty();
  }
  if (x.lo() <= 0.0) flag(err, kMaybeError);
  // log x >= 0 for x >= 1 and <= 0 for x <= 1 (so log 1 = 0 exactly).
  const double a = x.lo(), b = x.hi();
  const double lo = a <= 0.0 ? -kInf : lower(std::log(a), kUlpsDirected, a >= 1.0 ? 0.0 : -kInf);
  const double hi = upper(std::log(b), kUlpsDirected, b <= 1.0 ? 0.0 : kInf);
  return make(lo, hi);
}

Interval sin(const Interval& x) noexcept { return sin_or_cos(x, 1); }

Interval cos(const Interval& x) noexcept { return sin_or_cos(x, 0); }

Interval tan(const Interval& x) noexcept {
  if (x.is_empty()) return Interval::empty();
  const double a = x.lo(), b = x.hi();
  // The poles pi/2 + k pi are the zeros of cos. An interval narrower than pi holds at most
  // one, and holds one exactly when cos changes sign between its ends (cos is never 0 at a
  // double, and its sign from glibc is right: see quadrant()).
  if (!(b - a < kBelowPi) || (std::cos(a) > 0.0) != (std::cos(b) > 0.0)) return Interval::entire();
  return Interval::unchecked(tan_lo(a), tan_hi(b));
}

Interval asin(const Interval& x, std::uint8_t* err) noexcept {
  const Interval d = restrict_to_domain(x, -1.0, 1.0, err);
  if (d.is_empty()) return d;
  // Increasing, odd, with range [-pi/2, pi/2].
  const double a = d.lo(), b = d.hi();
  return Interval::unchecked(lower(std::asin(a), kUlpsDirected, a >= 0.0 ? 0.0 : -kHalfPiHi),
                             upper(std::asin(b), kUlpsDirected, b <= 0.0 ? 0.0 : kHalfPiHi));
}

Interval acos(const Interval& x, std::uint8_t* err) noexcept {
  const Interval d = restrict_to_domain(x, -1.0, 1.0, err);
  if (d.is_empty()) return d;
  // Decreasing, with range [0, pi]; acos x >= pi/2 for x <= 0 and <= pi/2 for x >= 0.
  const double a = d.lo(), b = d.hi();
  return Interval::unchecked(lower(std::acos(b), kUlpsDirected, b <= 0.0 ? kHalfPiLo : 0.0),
                             upper(std::acos(a), kUlpsDirected, a >= 0.0 ? kHalfPiHi : kPiHi));
}

Interval atan(const Interval& x) noexcept {
  if (x.is_empty()) return Interval::empty();
  // Increasing, odd, with range (-pi/2, pi/2).
  const double a = x.lo(), b = x.hi();
  return Interval::unchecked(lower(std::atan(a), kUlpsStable, a >= 0.0 ? 0.0 : -kHalfPiHi),
                             upper(std::atan(b), kUlpsStable, b <= 0.0 ? 0.0 : kHalfPiHi));
}

Interval atan2(const Interval& y, const Interval& x) noexcept {
  if (y.is_empty() || x.is_empty()) return Interval::empty();
  // The angle jumps from pi to -pi across the negative x axis (and atan2(-0, x<0) = -pi), and
  // every angle is near the origin: a box touching either gets the whole range.
  if (y.contains_zero() && x.lo() <= 0.0) return Interval::unchecked(-kPiHi, kPiHi);
  // Elsewhere the angle is continuous on the (convex) box, and the extreme angles are those
  // of supporting rays through the origin, which touch the box at corners. The angle has the
  // sign of y, and |angle| <= pi/2 when x >= 0.
  const double limit = x.lo() >= 0.0 ? kHalfPiHi : kPiHi;
  const double least = y.lo() >= 0.0 ? 0.0 : -limit, most = y.hi() <= 0.0 ? 0.0 : limit;
  double lo = kInf, hi = -kInf;
  for (const double yy : {y.lo(), y.hi()}) {
    for (const double xx : {x.lo(), x.hi()}) {
      const double angle = std::atan2(yy, xx);
      lo = std::min(lo, lower(angle, kUlpsStable, least));
      hi = std::max(hi, upper(angle, kUlpsStable, most));
    }
  }
  return Interval::unchecked(lo, hi);
}

Interval pow(const Interval& x, const Interval& y, std::uint8_t* err) noexcept {
  if (x.is_empty() || y.is_empty()) {
    flag(err, kCertainError);
    return Interval::empty();
  }
  // The integers kl..kh in y are the exponents defined for negative bases.
  const double kl = std::ceil(y.lo()), kh = std::floor(y.hi());
  const bool y_has_integer = kl <= kh;
  flag(err, pow_errors(x, y, y_has_integer));
  Interval value = Interval::empty();
  if (x.hi() >= 0.0) value = pow_nonnegative_base(std::max(x.lo(), 0.0), x.hi(), y);
  if (x.lo() < 0.0 && y_has_integer) value = hull(value, pow_negative_base(x.lo(), std::min(x.hi(), 0.0), kl, kh));
  return value;
}

Interval abs(const Interval& x) noexcept {
  if (x.is_empty()) return Interval::empty();
  if (x.lo() >= 0.0) return x;
  if (x.hi() <= 0.0) return -x;
  return Interval::unchecked(0.0, std::max(-x.lo(), x.hi()));
}

// floor, ceil, min and max are exact in every rounding mode.
Interval floor(const Interval& x) noexcept {
  if (x.is_empty()) return Interval::empty();
  return Interval::unchecked(std::floor(x.lo()), std::floor(x.hi()));
}

Interval ceil(const Interval& x) noexcept {
  if (x.is_empty()) return Interval::empty();
  return Interval::unchecked(std::ceil(x.lo()), std::ceil(x.hi()));
}

Interval min(const Interval& a, const Interval& b) noexcept {
  if (a.is_empty() || b.is_empty()) return Interval::empty();
  return Interval::unchecked(std::min(a.lo(), b.lo()), std::min(a.hi(), b.hi()));
}

Interval max(const Interval& a, const Interval& b) noexcept {
  if (a.is_empty() || b.is_empty()) return Interval::empty();
  return Interval::unchecked(std::max(a.lo(), b.lo()), std::max(a.hi(), b.hi()));
}

}  // namespace genmod
