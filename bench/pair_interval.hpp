// The baseline an interval evaluator is measured against: an interval as a bare pair of
// doubles, with textbook formulas in the current (round-to-nearest) mode. Not rigorous (the
// bounds are not rounded outward, errors are not tracked); it is the cost floor that genmod's
// "one rounding scope per tape" design aims to match.
#pragma once

#include <algorithm>
#include <cmath>

namespace genmod::bench {

struct PairInterval {
  double lo, hi;

  PairInterval() = default;
  PairInterval(double value) : lo(value), hi(value) {}  // NOLINT(google-explicit-constructor): like Boost's
  PairInterval(double l, double h) : lo(l), hi(h) {}
  double lower() const { return lo; }
  double upper() const { return hi; }
};

inline PairInterval operator+(PairInterval a, PairInterval b) { return {a.lo + b.lo, a.hi + b.hi}; }
inline PairInterval operator+(PairInterval a, double k) { return {a.lo + k, a.hi + k}; }
inline PairInterval operator-(PairInterval a, PairInterval b) { return {a.lo - b.hi, a.hi - b.lo}; }
inline PairInterval operator-(double k, PairInterval a) { return {k - a.hi, k - a.lo}; }
inline PairInterval operator-(PairInterval a) { return {-a.hi, -a.lo}; }

// Branch-free: all four products, then their extremes.
inline PairInterval operator*(PairInterval a, PairInterval b) {
  const double p = a.lo * b.lo, q = a.lo * b.hi, r = a.hi * b.lo, s = a.hi * b.hi;
  return {std::min(std::min(p, q), std::min(r, s)), std::max(std::max(p, q), std::max(r, s))};
}
inline PairInterval operator*(PairInterval a, double k) {
  return k >= 0.0 ? PairInterval{a.lo * k, a.hi * k} : PairInterval{a.hi * k, a.lo * k};
}

inline PairInterval square(PairInterval a) {
  const double l = a.lo * a.lo, h = a.hi * a.hi;
  if (a.lo >= 0.0) return {l, h};
  if (a.hi <= 0.0) return {h, l};
  return {0.0, std::max(l, h)};
}
// The part of the argument below zero is ignored (an error the baseline does not report).
inline PairInterval sqrt(PairInterval a) { return {std::sqrt(std::max(a.lo, 0.0)), std::sqrt(std::max(a.hi, 0.0))}; }

inline PairInterval min(PairInterval a, PairInterval b) { return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)}; }
inline PairInterval max(PairInterval a, PairInterval b) { return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)}; }
inline PairInterval min(PairInterval a, double k) { return {std::min(a.lo, k), std::min(a.hi, k)}; }
inline PairInterval max(PairInterval a, double k) { return {std::max(a.lo, k), std::max(a.hi, k)}; }

}  // namespace genmod::bench
