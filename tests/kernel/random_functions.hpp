// Shared property-test harness: random functions, random boxes and sample points.
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/interval.hpp"
#include "genmod/kernel/opcode.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod::testing {

// Every DAG opcode with its arity, so a test can loop over all of them.
struct OpInfo {
  Op op;
  int arity;
};
inline std::vector<OpInfo> all_dag_ops() {
  std::vector<OpInfo> ops;
  for (int i = static_cast<int>(Op::Neg); i <= static_cast<int>(Op::Select); ++i) {
    const Op op = static_cast<Op>(i);
    ops.push_back({op, arity(op)});
  }
  return ops;
}

// The opcode applied through the public Fn API (one function or operator per opcode).
inline Fn apply_op(Op op, const Fn& a, const Fn& b = Fn(), const Fn& c = Fn()) {
  switch (op) {
    case Op::Neg: return -a;
    case Op::Square: return square(a);
    case Op::Sqrt: return sqrt(a);
    case Op::Exp: return exp(a);
    case Op::Log: return log(a);
    case Op::Sin: return sin(a);
    case Op::Cos: return cos(a);
    case Op::Tan: return tan(a);
    case Op::Asin: return asin(a);
    case Op::Acos: return acos(a);
    case Op::Atan: return atan(a);
    case Op::Abs: return abs(a);
    case Op::Floor: return floor(a);
    case Op::Ceil: return ceil(a);
    case Op::Not: return !a;
    case Op::IsError: return is_error(a);
    case Op::Add: return a + b;
    case Op::Sub: return a - b;
    case Op::Mul: return a * b;
    case Op::Div: return a / b;
    case Op::Pow: return pow(a, b);
    case Op::Atan2: return atan2(a, b);
    case Op::Min: return min(a, b);
    case Op::Max: return max(a, b);
    case Op::Lt: return a < b;
    case Op::Le: return a <= b;
    case Op::Gt: return a > b;
    case Op::Ge: return a >= b;
    case Op::Eq: return eq(a, b);
    case Op::Ne: return ne(a, b);
    case Op::And: return a && b;
    case Op::Or: return a || b;
    case Op::Select: return select(a, b, c);
    default: throw std::invalid_argument("apply_op: not an arithmetic DAG opcode: " + std::string(op_name(op)));
  }
}

class RandomFunctions {
 public:
  explicit RandomFunctions(unsigned seed, int num_inputs = 3) : rng_(seed), num_inputs_(num_inputs) {}

  std::mt19937_64& rng() { return rng_; }
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }

  // A random scalar function of x(0) .. x(num_inputs-1) with depth <= max_depth, using
  // every opcode (smooth ones only when `smooth`, for derivative tests).
  Fn function(int max_depth, bool smooth = false) {
    if (max_depth <= 0 || integer(0, 5) == 0) {
      if (integer(0, 2) == 0) return Fn(std::round(uniform(-3, 3) * 4) / 4 + (integer(0, 3) == 0 ? 0.1 : 0.0));
      return x(integer(0, num_inputs_ - 1));
    }
    static const std::vector<OpInfo> all = all_dag_ops();
    static const std::vector<Op> smooth_ops = {Op::Neg, Op::Square, Op::Exp, Op::Sin, Op::Cos, Op::Atan,
                                               Op::Add, Op::Sub, Op::Mul, Op::Div, Op::Sqrt, Op::Log};
    const Op op = smooth ? smooth_ops[static_cast<std::size_t>(integer(0, static_cast<int>(smooth_ops.size()) - 1))]
                         : all[static_cast<std::size_t>(integer(0, static_cast<int>(all.size()) - 1))].op;
    const int n = arity(op);
    Fn a = function(max_depth - 1, smooth);
    Fn b = n >= 2 ? function(max_depth - 1, smooth) : Fn();
    Fn c = n >= 3 ? function(max_depth - 1, smooth) : Fn();
    if (smooth && (op == Op::Sqrt || op == Op::Log)) a = square(a) + 0.5;  // keep away from the domain edge
    if (smooth && op == Op::Div) b = square(b) + 0.5;
    if (smooth && op == Op::Exp) a = sin(a);  // bounded growth
    return apply_op(op, a, b, c);
  }

  // A random interval of one of several kinds: ordinary, degenerate, huge, unbounded.
  Interval interval() {
    const double inf = std::numeric_limits<double>::infinity();
    switch (integer(0, 9)) {
      case 0: {
        const double v = uniform(-4, 4);
        return Interval(v, v);
      }
      case 1: return Interval(-1e300, uniform(-1, 1e300));
      case 2: return Interval(uniform(-5, 5), inf);
      case 3: return Interval(-inf, uniform(-5, 5));
      case 4: return Interval::entire();
      case 5: {
        const double m = uniform(-1e6, 1e6);
        return Interval(m, m + uniform(0, 1e-3));
      }
      default: {
        const double a = uniform(-4, 4), b = uniform(-4, 4);
        return Interval(std::min(a, b), std::max(a, b));
      }
    }
  }
  // An ordinary bounded interval.
  Interval small_interval(double range = 3.0) {
    const double a = uniform(-range, range), w = uniform(0, 1) * uniform(0, 1) * range;
    return Interval(a, a + w);
  }

  // A random real in x: corners first, then uniform (a finite range stands in for an
  // unbounded side).
  double sample(const Interval& x, int k) {
    const double big = 1e6;
    const double lo = std::isfinite(x.lo()) ? x.lo() : -std::numeric_limits<double>::max();
    const double hi = std::isfinite(x.hi()) ? x.hi() : std::numeric_limits<double>::max();
    if (k == 0) return lo;
    if (k == 1) return hi;
    const double a = std::max(lo, -big), b = std::min(hi, big);
    if (a > b) return k % 2 ? lo : hi;
    const double u = uniform(0, 1);
    return a + u * (b - a) <= b ? std::min(b, a + u * (b - a)) : b;
  }

 private:
  std::mt19937_64 rng_;
  int num_inputs_;
};

// Does interval y (with error bits) account for the point value v?
inline bool accounts_for(const Interval& y, std::uint8_t err, double v) {
  if (std::isnan(v)) return (err & kMaybeError) != 0;
  return y.contains(v);
}

}  // namespace genmod::testing
