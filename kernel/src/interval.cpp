// Interval construction, set operations and protected arithmetic. The elementary
// enclosures live in interval_elementary.cpp.
#include "genmod/kernel/interval.hpp"

#include <algorithm>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace genmod {

using interval_detail::cook;
using interval_detail::raw;
using interval_detail::Raw;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMax = std::numeric_limits<double>::max();
}  // namespace

Interval::Interval(double lo, double hi) : lo_(lo), hi_(hi) {
  if (lo != lo || hi != hi || lo > hi || lo == kInf || hi == -kInf) {
    std::ostringstream msg;
    msg << "genmod::Interval: [" << lo << ", " << hi << "] is not a legal interval "
        << "(bounds must be numbers with lo <= hi, lo < +inf, hi > -inf)";
    throw std::invalid_argument(msg.str());
  }
}

double Interval::width() const noexcept {
  if (is_empty()) return 0.0;
  RoundingScope up;
  return hi_ - lo_;
}

double Interval::mid() const noexcept {
  if (is_empty()) return lo_;
  if (lo_ == -kInf) return hi_ == kInf ? 0.0 : (hi_ <= -kMax / 2 ? hi_ : std::min(0.0, hi_) - 1.0 - std::abs(hi_));
  if (hi_ == kInf) return lo_ >= kMax / 2 ? lo_ : std::max(0.0, lo_) + 1.0 + std::abs(lo_);
  const double m = 0.5 * lo_ + 0.5 * hi_;  // no overflow for huge bounds
  return std::clamp(m, lo_, hi_);
}

Interval hull(const Interval& a, const Interval& b) noexcept {
  if (a.is_empty()) return b;
  if (b.is_empty()) return a;
  return Interval::unchecked(std::min(a.lo(), b.lo()), std::max(a.hi(), b.hi()));
}

Interval intersect(const Interval& a, const Interval& b) noexcept {
  const double lo = std::max(a.lo(), b.lo()), hi = std::min(a.hi(), b.hi());
  if (a.is_empty() || b.is_empty() || lo > hi) return Interval::empty();
  return Interval::unchecked(lo, hi);
}

bool overlaps(const Interval& a, const Interval& b) noexcept {
  return !a.is_empty() && !b.is_empty() && a.lo() <= b.hi() && b.lo() <= a.hi();
}

std::ostream& operator<<(std::ostream& os, const Interval& x) {
  if (x.is_empty()) return os << "[empty]";
  const auto old = os.precision(17);
  os << '[' << x.lo() << ", " << x.hi() << ']';
  os.precision(old);
  return os;
}

Interval operator+(const Interval& a, const Interval& b) noexcept {
  RoundingScope up;
  return cook(raw(a) + raw(b));
}

Interval operator-(const Interval& a, const Interval& b) noexcept {
  RoundingScope up;
  return cook(raw(a) - raw(b));
}

Interval operator*(const Interval& a, const Interval& b) noexcept {
  RoundingScope up;
  return cook(raw(a) * raw(b));
}

Interval divide(const Interval& a, const Interval& b, std::uint8_t* err) noexcept {
  if (a.is_empty() || b.is_empty()) {
    if (err) *err |= kCertainError;
    return Interval::empty();
  }
  if (b.contains_zero() && err) *err |= (b.lo() == 0.0 && b.hi() == 0.0) ? kCertainError : kMaybeError;
  RoundingScope up;
  return cook(raw(a) / raw(b));
}

IntervalPair extended_divide(const Interval& a, const Interval& b) noexcept {
  const Interval none = Interval::empty();
  if (a.is_empty() || b.is_empty()) return {none, none};
  // Hansen's extended quotient {q : x = q y, x in a, y in b}: 0 in both means any q works
  // (also for b = [0,0]); b = [0,0] with 0 outside a admits no q.
  if (a.contains_zero() && b.contains_zero()) return {Interval::entire(), none};
  if (b.lo() == 0.0 && b.hi() == 0.0) return {none, none};
  if (!(b.lo() < 0.0 && b.hi() > 0.0)) return {divide(a, b), none};
  // b strictly contains 0 in its interior and a does not contain 0: two unbounded pieces.
  RoundingScope up;
  bool both = false;
  const Raw p1 = boost::numeric::interval_lib::division_part1(raw(a), raw(b), both);
  if (!both) return {cook(p1), none};
  const Raw p2 = boost::numeric::interval_lib::division_part2(raw(a), raw(b));
  return {cook(p1), cook(p2)};
}

}  // namespace genmod
