// The shared property-test harness of the operator library: one function checks, for any
// operator expression f of x(0) .. x(n-1), the properties every operator must have:
//
//  * containment: f(p) lies in the inclusion of every box holding p (or the inclusion
//    flags a possible error where f(p) is NaN), over random boxes of several kinds: small,
//    degenerate, the whole domain, boxes crossing a break (knot, cell edge, branch switch)
//    and boxes starting exactly on one; samples include the corners and the breaks;
//  * derivatives: the symbolic derivative d f / d x(i) agrees with Richardson-extrapolated
//    central differences (relative error below `derivative_tol`) at points away from the
//    breaks, and with the kernel's forward-mode gradient evaluator;
//  * batch = scalar: the batch evaluator reproduces the scalar evaluator bit for bit.
#pragma once

#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/kernel/gradient_evaluator.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "kernel/random_functions.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod::testing {

struct PropertySpec {
  std::vector<Interval> domain;              // the range of x(i), one per input
  std::vector<std::vector<double>> breaks;   // per input: where f may be non-smooth (optional)
  int boxes = 120;                           // containment boxes
  int samples = 10;                          // points per box
  int derivative_points = 25;
  double derivative_tol = 1e-6;
  double step = 1e-3;                        // finite-difference step, relative to the domain width
  bool check_derivative = true;
};

namespace detail {

inline bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b) || (std::isnan(a) && std::isnan(b));
}

inline const std::vector<double>& breaks_of(const PropertySpec& spec, std::size_t i) {
  static const std::vector<double> none;
  return i < spec.breaks.size() ? spec.breaks[i] : none;
}

// A random sub-box of the domain in coordinate i, of one of several kinds.
inline Interval random_box(RandomFunctions& rnd, const PropertySpec& spec, std::size_t i) {
  const Interval d = spec.domain[i];
  const std::vector<double>& br = breaks_of(spec, i);
  const double w = d.hi() - d.lo();
  auto clip = [&](double a, double b) { return Interval(std::max(d.lo(), a), std::min(d.hi(), b)); };
  switch (rnd.integer(0, 6)) {
    case 0: {
      const double p = rnd.uniform(d.lo(), d.hi());
      return Interval(p);
    }
    case 1: return d;
    case 2:
      if (!br.empty()) {  // crossing a break
        const double b = br[static_cast<std::size_t>(rnd.integer(0, static_cast<int>(br.size()) - 1))];
        return clip(b - rnd.uniform(0, 0.1) * w, b + rnd.uniform(0, 0.1) * w);
      }
      [[fallthrough]];
    case 3:
      if (!br.empty()) {  // starting or ending exactly on a break, or the break itself
        const double b = br[static_cast<std::size_t>(rnd.integer(0, static_cast<int>(br.size()) - 1))];
        const int side = rnd.integer(0, 2);
        if (side == 0) return Interval(b);
        return side == 1 ? clip(b, b + rnd.uniform(0, 0.2) * w) : clip(b - rnd.uniform(0, 0.2) * w, b);
      }
      [[fallthrough]];
    default: {
      const double a = rnd.uniform(d.lo(), d.hi());
      const double len = rnd.uniform(0, 1) * rnd.uniform(0, 1) * w;
      return clip(a, a + len);
    }
  }
}

}  // namespace detail

inline void check_containment(const Fn& f, const PropertySpec& spec, RandomFunctions& rnd) {
  const std::size_t n = spec.domain.size();
  std::vector<int> inputs(n);
  std::iota(inputs.begin(), inputs.end(), 0);
  const Tape tape(f, inputs);
  IntervalEvaluator iv;
  PointEvaluator pv;
  int checked = 0;
  for (int b = 0; b < spec.boxes; ++b) {
    std::vector<Interval> box(n);
    for (std::size_t i = 0; i < n; ++i) box[i] = detail::random_box(rnd, spec, i);
    const auto y = iv.eval(tape, box);
    const std::vector<Interval> ys(y.begin(), y.end());
    const std::vector<std::uint8_t> errs(iv.errors().begin(), iv.errors().end());
    for (int s = 0; s < spec.samples; ++s) {
      std::vector<double> p(n);
      for (std::size_t i = 0; i < n; ++i) {
        p[i] = rnd.sample(box[i], (s + static_cast<int>(i)) % 4);
        const std::vector<double>& br = detail::breaks_of(spec, i);
        if (s == 2)  // a break inside the box, if any
          for (double k : br)
            if (box[i].contains(k)) p[i] = k;
      }
      const auto v = pv.eval(tape, p);
      for (std::size_t j = 0; j < v.size(); ++j) {
        ++checked;
        if (!accounts_for(ys[j], errs[j], v[j])) {
          std::string where;
          for (std::size_t i = 0; i < n; ++i)
            where += " x" + std::to_string(i) + "=" + std::to_string(p[i]) + " in [" + std::to_string(box[i].lo()) + ", " +
                     std::to_string(box[i].hi()) + "]";
          ADD_FAILURE() << "containment: output " << j << " = " << v[j] << " outside " << ys[j] << " at" << where;
          return;
        }
      }
    }
  }
  EXPECT_GT(checked, spec.boxes);
}

inline void check_derivatives(const Fn& f, const PropertySpec& spec, RandomFunctions& rnd) {
  const std::size_t n = spec.domain.size();
  std::vector<int> inputs(n);
  std::iota(inputs.begin(), inputs.end(), 0);
  const Tape tape(f, inputs);
  std::vector<Tape> partials;
  for (std::size_t i = 0; i < n; ++i) partials.emplace_back(derivative(f, static_cast<int>(i)), inputs);
  PointEvaluator pv;
  GradientEvaluator gv;
  int checked = 0;
  for (int t = 0; t < spec.derivative_points * 4 && checked < spec.derivative_points; ++t) {
    std::vector<double> p(n);
    std::vector<double> h(n);
    bool near_break = false;
    for (std::size_t i = 0; i < n; ++i) {
      const Interval d = spec.domain[i];
      h[i] = spec.step * (d.hi() - d.lo());
      p[i] = rnd.uniform(d.lo() + 3 * h[i], d.hi() - 3 * h[i]);
      for (double b : detail::breaks_of(spec, i)) near_break |= std::abs(p[i] - b) < 3 * h[i];
    }
    if (near_break) continue;
    gv.eval(tape, p);
    const std::vector<double> jac(gv.jacobian().begin(), gv.jacobian().end());
    bool any = false;
    for (std::size_t i = 0; i < n; ++i) {
      const auto sym = pv.eval(partials[i], p);
      const std::vector<double> d(sym.begin(), sym.end());
      // Richardson: (4 D(h/2) - D(h)) / 3 has error O(h^4).
      auto central = [&](double step, std::size_t j) {
        std::vector<double> q = p;
        q[i] = p[i] + step;
        const double up = pv.eval(tape, q)[j];
        q[i] = p[i] - step;
        const double down = pv.eval(tape, q)[j];
        return (up - down) / (2 * step);
      };
      for (std::size_t j = 0; j < d.size(); ++j) {
        if (std::isnan(d[j])) continue;
        const double fd = (4 * central(h[i] / 2, j) - central(h[i], j)) / 3;
        if (std::isnan(fd)) continue;
        any = true;
        const double scale = std::max(1.0, std::abs(d[j]));
        EXPECT_LE(std::abs(d[j] - fd), spec.derivative_tol * scale)
            << "d output " << j << " / d x" << i << ": symbolic " << d[j] << ", differences " << fd;
        EXPECT_LE(std::abs(d[j] - jac[j * n + i]), 1e-9 * scale)
            << "d output " << j << " / d x" << i << ": symbolic " << d[j] << ", forward mode " << jac[j * n + i];
      }
    }
    checked += any;
  }
  EXPECT_GE(checked, spec.derivative_points / 2) << "too few derivative checks";
}

inline void check_batch_equals_scalar(const Fn& f, const PropertySpec& spec, RandomFunctions& rnd) {
  const std::size_t n = spec.domain.size(), count = 300;
  std::vector<int> inputs(n);
  std::iota(inputs.begin(), inputs.end(), 0);
  const Tape tape(f, inputs);
  std::vector<std::vector<double>> in(n, std::vector<double>(count));
  for (std::size_t i = 0; i < n; ++i) {
    const std::vector<double>& br = detail::breaks_of(spec, i);
    for (std::size_t k = 0; k < count; ++k)
      in[i][k] = (!br.empty() && k % 7 == 0) ? br[k % br.size()] : rnd.sample(spec.domain[i], static_cast<int>(k % 5));
  }
  std::vector<const double*> in_ptrs;
  for (const auto& v : in) in_ptrs.push_back(v.data());
  std::vector<std::vector<double>> out(tape.num_outputs(), std::vector<double>(count));
  std::vector<double*> out_ptrs;
  for (auto& v : out) out_ptrs.push_back(v.data());
  BatchEvaluator batch;
  batch.eval(tape, in_ptrs, count, out_ptrs);
  PointEvaluator pv;
  std::vector<double> p(n);
  for (std::size_t k = 0; k < count; ++k) {
    for (std::size_t i = 0; i < n; ++i) p[i] = in[i][k];
    const auto v = pv.eval(tape, p);
    for (std::size_t j = 0; j < v.size(); ++j)
      ASSERT_TRUE(detail::same_bits(v[j], out[j][k])) << "point " << k << " output " << j << ": " << v[j] << " vs " << out[j][k];
  }
}

// All three properties.
inline void check_operator_properties(const Fn& f, const PropertySpec& given, unsigned seed = 1) {
  PropertySpec spec = given;  // breaks outside the domain (e.g. end knots) do not matter
  for (std::size_t i = 0; i < spec.breaks.size() && i < spec.domain.size(); ++i)
    std::erase_if(spec.breaks[i], [&](double b) { return !spec.domain[i].contains(b); });
  RandomFunctions rnd(seed, static_cast<int>(spec.domain.size()));
  check_containment(f, spec, rnd);
  if (spec.check_derivative) check_derivatives(f, spec, rnd);
  check_batch_equals_scalar(f, spec, rnd);
}

// The unit box [0, 1]^n.
inline PropertySpec unit_domain(std::size_t n) {
  PropertySpec spec;
  spec.domain.assign(n, Interval(0.0, 1.0));
  return spec;
}

// Bad input: f() throws std::invalid_argument whose message names `name` (the operator).
template <typename F>
void expect_throw_naming(F&& f, const std::string& name) {
  try {
    f();
    ADD_FAILURE() << name << " did not throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
  }
}

}  // namespace genmod::testing
