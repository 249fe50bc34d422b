// genmod::Interval: a closed interval of reals with outward-rounded arithmetic.
//
// Storage and basic arithmetic come from Boost.Interval. Two ways to compute:
//
//  * `Interval` operators and functions are *protected*: each call sets the FPU to round
//    upward and restores the caller's mode, so they are correct anywhere (and cost a mode
//    switch per call).
//  * Inside a `RoundingScope` (upward rounding for its lifetime) the evaluators use the raw
//    unprotected operations of `interval_detail` below, which assume the upward mode. This is
//    what makes an interval tape evaluation cost about as much as plain double pairs
//    (see research/anchors.md section 5).
//
// Legal values: [lo, hi] with lo <= hi, lo < +inf and hi > -inf (so unbounded intervals such
// as [-inf, 3] or [-inf, inf] are legal), and the empty interval (both bounds NaN).
// Elementary functions (sin, exp, ...) are genmod's own enclosures, not Boost's: they call the
// C library and widen the result outward, and are checked against MPFI in the tests.
#pragma once

#include <boost/numeric/interval.hpp>

#if defined(__x86_64__) && defined(__SSE2_MATH__)
#include <xmmintrin.h>
#endif

#include <cfenv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iosfwd>
#include <limits>
#include <utility>

namespace genmod {

namespace interval_detail {
namespace bi = boost::numeric::interval_lib;

// The rounding direction of double arithmetic. With SSE2 math (x86-64) that is two bits of
// the MXCSR register, set here directly: the C library's fesetround also rewrites the x87
// control word, which double arithmetic does not use, and a save, set and restore through it
// costs three times as much (33 ns against 11 ns on the development machine; protected
// operations and custom operator calls pay it every time). Only the direction bits change:
// exception flags and the other modes are left alone. genmod changes the direction only
// through these; the C library's double functions read MXCSR as well.
#if defined(__x86_64__) && defined(__SSE2_MATH__)
using RoundingDirection = unsigned int;
inline constexpr RoundingDirection kRoundingBits = 0x6000u;
inline constexpr RoundingDirection kRoundNearest = 0x0000u, kRoundDownward = 0x2000u, kRoundUpward = 0x4000u,
                                   kRoundTowardZero = 0x6000u;
inline RoundingDirection rounding_direction() noexcept { return _mm_getcsr() & kRoundingBits; }
inline void set_rounding_direction(RoundingDirection d) noexcept { _mm_setcsr((_mm_getcsr() & ~kRoundingBits) | d); }
#else
using RoundingDirection = int;
inline constexpr RoundingDirection kRoundNearest = FE_TONEAREST, kRoundDownward = FE_DOWNWARD,
                                   kRoundUpward = FE_UPWARD, kRoundTowardZero = FE_TOWARDZERO;
inline RoundingDirection rounding_direction() noexcept { return std::fegetround(); }
inline void set_rounding_direction(RoundingDirection d) noexcept { std::fesetround(d); }
#endif

// Boost's rounding control with the direction switches above and a cheaper barrier. Boost
// stores and reloads every rounded result through a volatile double (meant for x87 extended
// precision); with SSE2 arithmetic the result is already rounded, and an empty asm that claims
// to modify the register keeps the compiler from folding or moving it across mode changes, at
// no cost.
struct RoundingControl : bi::rounding_control<double> {
  using rounding_mode = RoundingDirection;
  static void get_rounding_mode(rounding_mode& mode) noexcept { mode = rounding_direction(); }
  static void set_rounding_mode(rounding_mode mode) noexcept { set_rounding_direction(mode); }
  static void upward() noexcept { set_rounding_direction(kRoundUpward); }
  static void downward() noexcept { set_rounding_direction(kRoundDownward); }
  static void to_nearest() noexcept { set_rounding_direction(kRoundNearest); }
  static void toward_zero() noexcept { set_rounding_direction(kRoundTowardZero); }
#if defined(__x86_64__) && defined(__SSE2_MATH__)
  static double force_rounding(double r) noexcept {
    asm volatile("" : "+x"(r));
    return r;
  }
#endif
};

// Boost policies: "opposite trick" rounding (FPU kept upward, lower bounds computed as
// -(-a - b)), checking that allows empty and unbounded values instead of throwing.
using Checking = bi::checking_base<double>;
using Protected =
    boost::numeric::interval<double, bi::policies<bi::save_state<bi::rounded_arith_opp<double, RoundingControl>>, Checking>>;
using Raw = bi::unprotect<Protected>::type;
}  // namespace interval_detail

// Error state of a value: bit 0 = an error (sqrt of a negative, log 0, x/0, ...) is possible,
// bit 1 = an error is certain. Combine with bitwise or; Certain implies Possible.
enum ErrorBits : std::uint8_t { kNoError = 0, kMaybeError = 1, kCertainError = 3 };

class Interval {
 public:
  using Boost = interval_detail::Protected;

  constexpr Interval() noexcept : lo_(0.0), hi_(0.0) {}
  // The degenerate interval [x, x]. +-inf becomes [DBL_MAX, inf] / [-inf, -DBL_MAX];
  // NaN becomes the empty interval.
  Interval(double x) noexcept  // NOLINT(google-explicit-constructor): numbers convert
      : lo_(x == std::numeric_limits<double>::infinity() ? std::numeric_limits<double>::max() : x),
        hi_(x == -std::numeric_limits<double>::infinity() ? -std::numeric_limits<double>::max() : x) {}
  // [lo, hi]; throws std::invalid_argument if a bound is NaN, lo > hi, lo == +inf or hi == -inf.
  Interval(double lo, double hi);
  // Unchecked construction; the caller guarantees a legal value.
  static constexpr Interval unchecked(double lo, double hi) noexcept { return Interval(lo, hi, Tag{}); }

  static constexpr Interval empty() noexcept {
    return unchecked(std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN());
  }
  static constexpr Interval entire() noexcept {
    return unchecked(-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity());
  }

  constexpr double lo() const noexcept { return lo_; }
  constexpr double hi() const noexcept { return hi_; }
  bool is_empty() const noexcept { return !(lo_ <= hi_); }
  bool is_point() const noexcept { return lo_ == hi_; }
  bool is_bounded() const noexcept { return std::isfinite(lo_) && std::isfinite(hi_); }
  bool contains(double x) const noexcept { return lo_ <= x && x <= hi_; }
  bool contains_zero() const noexcept { return lo_ <= 0.0 && 0.0 <= hi_; }
  // True if every value of `inner` lies in this interval (the empty set lies in anything).
  bool contains(const Interval& inner) const noexcept {
    return inner.is_empty() || (lo_ <= inner.lo_ && inner.hi_ <= hi_);
  }
  // Width rounded upward; 0 for the empty interval.
  double width() const noexcept;
  // A point inside the interval (finite whenever the interval holds a finite number).
  double mid() const noexcept;

  Boost boost() const noexcept { return Boost(lo_, hi_, true); }
  static Interval from_boost(const Boost& b) noexcept { return unchecked(b.lower(), b.upper()); }

  friend bool operator==(const Interval& a, const Interval& b) noexcept {
    return (a.is_empty() && b.is_empty()) || (a.lo_ == b.lo_ && a.hi_ == b.hi_);
  }

 private:
  struct Tag {};
  constexpr Interval(double lo, double hi, Tag) noexcept : lo_(lo), hi_(hi) {}
  double lo_, hi_;
};

Interval hull(const Interval& a, const Interval& b) noexcept;
Interval intersect(const Interval& a, const Interval& b) noexcept;
bool overlaps(const Interval& a, const Interval& b) noexcept;
std::ostream& operator<<(std::ostream& os, const Interval& x);

// Sets upward rounding for its lifetime and restores the previous mode. Raw interval
// operations (interval_detail::*) are valid only inside one. Not copyable; one per thread.
class RoundingScope {
 public:
  RoundingScope() noexcept : saved_(interval_detail::rounding_direction()) {
    interval_detail::set_rounding_direction(interval_detail::kRoundUpward);
  }
  ~RoundingScope() { interval_detail::set_rounding_direction(saved_); }
  RoundingScope(const RoundingScope&) = delete;
  RoundingScope& operator=(const RoundingScope&) = delete;

 private:
  interval_detail::RoundingDirection saved_;
};

// Protected arithmetic (correct in any rounding mode).
Interval operator+(const Interval& a, const Interval& b) noexcept;
Interval operator-(const Interval& a, const Interval& b) noexcept;
Interval operator*(const Interval& a, const Interval& b) noexcept;
// Division; a divisor containing 0 gives the hull of the quotient (possibly unbounded), a
// divisor equal to [0,0] gives the empty interval. `err` (optional) receives the error state.
Interval divide(const Interval& a, const Interval& b, std::uint8_t* err = nullptr) noexcept;
inline Interval operator/(const Interval& a, const Interval& b) noexcept { return divide(a, b); }
inline Interval operator-(const Interval& a) noexcept { return Interval::unchecked(-a.hi(), -a.lo()); }
inline Interval& operator+=(Interval& a, const Interval& b) noexcept { return a = a + b; }
inline Interval& operator-=(Interval& a, const Interval& b) noexcept { return a = a - b; }
inline Interval& operator*=(Interval& a, const Interval& b) noexcept { return a = a * b; }

// Extended division (for interval Newton): the set {q : x = q y for some x in a, y in b}
// as up to two disjoint pieces; `second` is empty when it is one interval.
// [1,2]/[-1,1] = (-inf,-1] and [1,inf); [-1,1]/[0,0] = entire; [1,2]/[0,0] = empty.
struct IntervalPair {
  Interval first, second;
};
IntervalPair extended_divide(const Interval& a, const Interval& b) noexcept;

// Elementary enclosures. Each is valid in any rounding mode (inside a RoundingScope too) and
// contains the exact range of the function over the argument. Functions with a restricted
// domain enclose the values over the part of the argument inside the domain and, when `err`
// is given, or-in kMaybeError (part of the argument is outside) or kCertainError (all of it).
Interval square(const Interval& x) noexcept;
Interval sqrt(const Interval& x, std::uint8_t* err = nullptr) noexcept;
Interval exp(const Interval& x) noexcept;
Interval log(const Interval& x, std::uint8_t* err = nullptr) noexcept;  // error at x <= 0
Interval sin(const Interval& x) noexcept;
Interval cos(const Interval& x) noexcept;
Interval tan(const Interval& x) noexcept;                               // entire across a pole
Interval asin(const Interval& x, std::uint8_t* err = nullptr) noexcept;  // error outside [-1,1]
Interval acos(const Interval& x, std::uint8_t* err = nullptr) noexcept;  // error outside [-1,1]
Interval atan(const Interval& x) noexcept;
Interval atan2(const Interval& y, const Interval& x) noexcept;  // angle of (x, y), in [-pi, pi]
// x^y. Error where x < 0 and y is not an integer, and where x = 0 and y < 0.
Interval pow(const Interval& x, const Interval& y, std::uint8_t* err = nullptr) noexcept;
Interval abs(const Interval& x) noexcept;
Interval floor(const Interval& x) noexcept;
Interval ceil(const Interval& x) noexcept;
Interval min(const Interval& a, const Interval& b) noexcept;
Interval max(const Interval& a, const Interval& b) noexcept;

// Point versions with genmod's error semantics: an error gives NaN (which every operator
// propagates). These define what the point evaluators compute.
namespace point {
inline double div(double a, double b) noexcept { return b == 0.0 ? std::numeric_limits<double>::quiet_NaN() : a / b; }
inline double log(double a) noexcept { return a > 0.0 ? std::log(a) : std::numeric_limits<double>::quiet_NaN(); }
// pow with errors for 0^negative (std::pow gives inf) and negative^non-integer (NaN), and
// with NaN propagation (std::pow(1, NaN) and std::pow(NaN, 0) are 1, which would hide an error).
inline double pow(double a, double b) noexcept {
  return (a == 0.0 && b < 0.0) || a != a || b != b ? std::numeric_limits<double>::quiet_NaN() : std::pow(a, b);
}
// min/max that propagate NaN (std::fmin would drop it, hiding an error).
inline double min(double a, double b) noexcept { return (a < b || a != a) ? a : b; }
inline double max(double a, double b) noexcept { return (a > b || a != a) ? a : b; }
}  // namespace point

namespace interval_detail {

// One-ulp steps that work in any rounding mode (bit arithmetic, not nextafter).
inline double next_up(double x) noexcept {
  if (x != x || x == std::numeric_limits<double>::infinity()) return x;
  if (x == 0.0) return std::numeric_limits<double>::denorm_min();
  std::int64_t i;
  std::memcpy(&i, &x, 8);
  i += (i >= 0) ? 1 : -1;
  std::memcpy(&x, &i, 8);
  return x;
}
inline double next_down(double x) noexcept { return -next_up(-x); }

// Raw operations: valid only inside a RoundingScope. They work on the Boost representation
// without touching the rounding mode.
inline Raw raw(const Interval& x) noexcept { return Raw(x.lo(), x.hi(), true); }
inline Interval cook(const Raw& x) noexcept { return Interval::unchecked(x.lower(), x.upper()); }

}  // namespace interval_detail
}  // namespace genmod
