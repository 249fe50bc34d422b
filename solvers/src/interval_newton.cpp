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
  m_.assign(n * n, Interval(0.0));
  b_.assign(n, Interval(0.0));
  for (std::size_t r = 0; r < n; ++r) {
    for (std::size_t k = 0; k < n; ++k) {
      const Interval y(y_[r * n + k]);
      b_[r] = b_[r] + y * fc_[k];
      for (std::size_t col = 0; col < n; ++col) m_[r * n + col] = m_[r * n + col] + y * jx_[k * n + col];
    }
  }
  return all_bounded(m_) && all_bounded(b_);
}

NewtonStatus IntervalNewton::contract(std::span<Interval> box) {
  if (!prepare(box)) return NewtonStatus::Skipped;
  const std::size_t n = n_;
  for (std::size_t i = 0; i < n; ++i) {
    Interval s = b_[i];
    for (std::size_t j = 0; j < n; ++j)
      if (j != i) s = s + m_[i * n + j] * (box[j] - Interval(c_[j]));
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
  for (std::size_t i = 0; i < n; ++i) {
    Interval s = Interval(c_[i]) - b_[i];
    for (std::size_t j = 0; j < n; ++j) {
      const Interval ij = Interval(i == j ? 1.0 : 0.0) - m_[i * n + j];
      s = s + ij * (box[j] - Interval(c_[j]));
    }
    if (s.is_empty()) return {};
    k[i] = s;
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
