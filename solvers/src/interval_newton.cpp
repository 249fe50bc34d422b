#include "genmod/solvers/interval_newton.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>
#include <string>

namespace genmod {


namespace {

std::vector<int> all_inputs(std::span<const int> unknowns, std::span<const int> parameters) {
  std::vector<int> in(unknowns.begin(), unknowns.end());
  in.insert(in.end(), parameters.begin(), parameters.end());
  return in;
}

Fn jacobian_fn(const Fn& f, std::span<const int> unknowns) {
  std::vector<Fn> parts;
  for (std::size_t j = 0; j < f.dim(); ++j)
    for (int u : unknowns) parts.push_back(derivative(f[j], u));
  return cat(parts);
}

bool all_bounded(std::span<const Interval> v) {
  for (const Interval& x : v)
    if (x.is_empty() || !x.is_bounded()) return false;
  return true;
}

bool no_errors(std::span<const std::uint8_t> e) {
  for (std::uint8_t x : e)
    if (x != kNoError) return false;
  return true;
}

Interval hull_of(const Interval& a, const Interval& b) {
  if (a.is_empty()) return b;
  if (b.is_empty()) return a;
  return hull(a, b);
}

// The products below run inside one RoundingScope on raw intervals: a protected operation
// switches the rounding mode twice, and these loops make O(n^3) of them per box, which cost
// more than evaluating the system and its Jacobian. Every operand is bounded (prepare()
// checks), so the raw operations meet no 0 * inf.
using Raw = interval_detail::Raw;
Raw raw(const Interval& x) { return interval_detail::raw(x); }
Raw raw(double x) { return Raw(x, x, true); }

}  // namespace

IntervalNewton::IntervalNewton(const Fn& system, Coordinates unknowns, Coordinates parameters)
    : n_(unknowns.size()),
      inputs_(unknowns.size() + parameters.size()),
      f_([&] {
        if (system.dim() != unknowns.size())
          throw std::invalid_argument("genmod: interval Newton needs a square system: " +
                                      std::to_string(system.dim()) + " equations in " +
                                      std::to_string(unknowns.size()) + " unknowns");
        return Tape(system, all_inputs(unknowns, parameters));
      }()),
      j_(jacobian_fn(system, unknowns), all_inputs(unknowns, parameters)) {}

bool IntervalNewton::prepare(std::span<const Interval> box) {
  if (box.size() != inputs_)
    throw std::invalid_argument("genmod: interval Newton: the box has " + std::to_string(box.size()) +
                                " sides, expected " + std::to_string(inputs_));
  const std::size_t n = n_;
  if (!all_bounded(box)) return false;
  // F must be continuous on X and J must enclose its derivatives there.
  ev_.eval(f_, box);
  if (!ev_.continuous()) return false;
  const auto jv = ev_.eval(j_, box);
  if (!ev_.continuous() || !no_errors(ev_.errors()) || !all_bounded(jv)) return false;
  jx_.assign(jv.begin(), jv.end());
  c_.resize(n);
  point_.assign(box.begin(), box.end());
  for (std::size_t i = 0; i < n; ++i) {
    c_[i] = box[i].mid();
    point_[i] = Interval(c_[i]);
  }
  const auto fv = ev_.eval(f_, point_);
  if (!no_errors(ev_.errors()) || !all_bounded(fv)) return false;
  fc_.assign(fv.begin(), fv.end());

  // Preconditioner: inverse of the midpoint Jacobian (identity when singular).
  Eigen::MatrixXd mid(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t col = 0; col < n; ++col)
      mid(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(col)) = jx_[r * n + col].mid();
  Eigen::MatrixXd inv = Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  Eigen::FullPivLU<Eigen::MatrixXd> lu(mid);
  if (lu.isInvertible()) {
    Eigen::MatrixXd candidate = lu.inverse();
    if (candidate.allFinite()) inv = candidate;
  }
  y_.resize(n * n);
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t col = 0; col < n; ++col)
      y_[r * n + col] = inv(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(col));

  // M = Y J, b = Y F(c), outward rounded.
  m_.resize(n * n);
  b_.resize(n);
  RoundingScope upward;
  for (std::size_t r = 0; r < n; ++r) {
    Raw b = raw(0.0);
    for (std::size_t k = 0; k < n; ++k) b += raw(y_[r * n + k]) * raw(fc_[k]);
    b_[r] = interval_detail::cook(b);
    for (std::size_t col = 0; col < n; ++col) {
      Raw m = raw(0.0);
      for (std::size_t k = 0; k < n; ++k) m += raw(y_[r * n + k]) * raw(jx_[k * n + col]);
      m_[r * n + col] = interval_detail::cook(m);
    }
  }
  return all_bounded(m_) && all_bounded(b_);
}

NewtonStatus IntervalNewton::contract(std::span<Interval> box) {
  if (!prepare(box)) return NewtonStatus::Skipped;
  const std::size_t n = n_;
  RoundingScope upward;
  for (std::size_t i = 0; i < n; ++i) {
    Raw sum = raw(b_[i]);
    for (std::size_t j = 0; j < n; ++j)
      if (j != i) sum += raw(m_[i * n + j]) * (raw(box[j]) - raw(c_[j]));
    const Interval s = interval_detail::cook(sum);
    if (s.is_empty() || !s.is_bounded()) continue;  // no information (never shrink on NaN)
    const IntervalPair q = extended_divide(-s, m_[i * n + i]);
    const Interval ci(c_[i]);
    const Interval p1 = q.first.is_empty() ? q.first : ci + q.first;
    const Interval p2 = q.second.is_empty() ? q.second : ci + q.second;
    const Interval next = hull_of(intersect(box[i], p1), intersect(box[i], p2));
    if (next.is_empty()) return NewtonStatus::Empty;
    box[i] = next;
  }
  return NewtonStatus::Contracted;
}

Box IntervalNewton::krawczyk(std::span<const Interval> box) {
  if (!prepare(box)) return {};
  const std::size_t n = n_;
  Box k(n);
  RoundingScope upward;
  for (std::size_t i = 0; i < n; ++i) {
    Raw s = raw(c_[i]) - raw(b_[i]);
    for (std::size_t j = 0; j < n; ++j)
      s += (raw(i == j ? 1.0 : 0.0) - raw(m_[i * n + j])) * (raw(box[j]) - raw(c_[j]));
    k[i] = interval_detail::cook(s);
    if (k[i].is_empty()) return {};
  }
  return k;
}

bool IntervalNewton::certify(std::span<const Interval> box) {
  const Box k = krawczyk(box);
  if (k.empty()) return false;
  for (std::size_t i = 0; i < n_; ++i)
    if (!(k[i].lo() > box[i].lo() && k[i].hi() < box[i].hi())) return false;
  return true;
}

}  // namespace genmod
