// Certified feasible points for exact equality constraints (see minimizer_detail.hpp).
#include "minimizer_detail.hpp"

#include <algorithm>
#include <cmath>

namespace genmod::minimizer_detail {

FeasiblePointCertifier::FeasiblePointCertifier(const Fn& constraint, std::span<const int> unknowns)
    : unknowns_(unknowns.begin(), unknowns.end()), sys_(constraint, unknowns) {
  std::vector<NodeId> g;
  for (const ConstraintSystem::Conjunct& c : sys_.conjuncts()) {
    // Only atoms that are themselves equalities (not a negated !=): forcing them true below
    // is then what a zero of g means.
    if (c.rel != Relation::Eq || sys_.atoms()[c.atom].rel != Relation::Eq) continue;
    if (std::find(equalities_.begin(), equalities_.end(), c.atom) != equalities_.end()) continue;
    equalities_.push_back(c.atom);
    g.push_back(sys_.atoms()[c.atom].h.node(0));
  }
  if (equalities_.size() > unknowns_.size()) equalities_.clear();
  if (equalities_.empty()) return;
  is_equality_.assign(sys_.num_atoms(), 0);
  for (std::size_t a : equalities_) is_equality_[a] = 1;
  system_ = Fn(g);
  std::vector<Fn> parts;
  try {
    for (std::size_t i = 0; i < g.size(); ++i)
      for (int u : unknowns_) parts.push_back(derivative(system_[i], u));
  } catch (const std::exception&) {
    equalities_.clear();  // no derivative: no Newton
    return;
  }
  jacobian_.emplace(cat(parts), unknowns_);
}

IntervalNewton& FeasiblePointCertifier::newton_for(std::uint64_t chosen) {
  auto it = newton_.find(chosen);
  if (it != newton_.end()) return it->second;
  std::vector<int> solved, fixed;
  for (std::size_t j = 0; j < unknowns_.size(); ++j)
    ((chosen >> j) & 1 ? solved : fixed).push_back(unknowns_[j]);
  return newton_.emplace(chosen, IntervalNewton(system_, solved, fixed)).first->second;
}

std::optional<Box> FeasiblePointCertifier::find(std::span<const Interval> box) {
  if (!active()) return std::nullopt;
  const std::size_t n = unknowns_.size(), m = equalities_.size();
  const std::vector<double> q = midpoint(box);
  // The m columns of the midpoint Jacobian with the largest pivots (complete pivoting).
  const auto jv = pe_.eval(*jacobian_, q);
  std::vector<double> a(jv.begin(), jv.end());
  std::vector<std::size_t> rows(m);
  for (std::size_t i = 0; i < m; ++i) rows[i] = i;
  std::uint64_t chosen = 0;
  std::vector<std::size_t> cols;
  for (std::size_t k = 0; k < m; ++k) {
    double best = 0.0;
    std::size_t br = k, bc = n;
    for (std::size_t r = k; r < m; ++r)
      for (std::size_t c = 0; c < n; ++c) {
        if ((chosen >> c) & 1 || box[c].is_point()) continue;
        const double v = std::abs(a[rows[r] * n + c]);
        if (v > best) best = v, br = r, bc = c;
      }
    if (!(best > 0.0) || !std::isfinite(best)) return std::nullopt;
    std::swap(rows[k], rows[br]);
    chosen |= std::uint64_t{1} << bc;
    cols.push_back(bc);
    const double p = a[rows[k] * n + bc];
    for (std::size_t r = k + 1; r < m; ++r) {
      const double f = a[rows[r] * n + bc] / p;
      for (std::size_t c = 0; c < n; ++c) a[rows[r] * n + c] -= f * a[rows[k] * n + c];
    }
  }
  // Newton's box: the chosen sides of `box`, then the other coordinates fixed at q.
  std::vector<std::size_t> order;
  for (std::size_t j = 0; j < n; ++j)
    if ((chosen >> j) & 1) order.push_back(j);
  const std::size_t solved = order.size();
  for (std::size_t j = 0; j < n; ++j)
    if (!((chosen >> j) & 1)) order.push_back(j);
  std::vector<Interval> x(n);
  for (std::size_t k = 0; k < n; ++k) x[k] = k < solved ? box[order[k]] : Interval(q[order[k]]);
  IntervalNewton& newton = newton_for(chosen);
  for (int iter = 0; iter < 30; ++iter) {
    const double w0 = width(std::span<const Interval>(x).first(solved));
    const NewtonStatus s = newton.contract(x);
    if (s != NewtonStatus::Contracted) return std::nullopt;
    const double w1 = width(std::span<const Interval>(x).first(solved));
    if (!(w1 < 0.5 * w0)) break;
  }
  // Krawczyk with epsilon inflation (Rump), inside the box.
  bool certified = false;
  std::vector<Interval> y = x;
  for (int attempt = 0; attempt < 4 && !certified; ++attempt) {
    for (std::size_t k = 0; k < solved; ++k) {
      const double mag = std::max(std::abs(y[k].lo()), std::abs(y[k].hi()));
      const double r = 0.1 * y[k].width() + std::ldexp(mag, -44) + 1e-300;
      y[k] = intersect(Interval(y[k].lo() - r, y[k].hi() + r), box[order[k]]);
      if (y[k].is_empty()) return std::nullopt;
    }
    certified = newton.certify(y);
  }
  if (!certified) return std::nullopt;
  Box b(n);
  for (std::size_t k = 0; k < n; ++k) b[order[k]] = y[k];
  // The other atoms must hold on all of B (the zero's position in B is not known).
  std::vector<std::uint8_t> tags(sys_.num_atoms(), kTagUnknown);
  sys_.evaluate(b, tags, values_, ev_);
  forced_ = values_.value;
  for (std::size_t at = 0; at < forced_.size(); ++at) {
    if (is_equality_[at])
      forced_[at] = Truth::True;
    else if (values_.error[at] != kNoError)
      return std::nullopt;
  }
  if (sys_.combine(forced_) != Truth::True) return std::nullopt;
  return b;
}

}  // namespace genmod::minimizer_detail
