// Local search and constraint rewriting for the minimizer (see minimizer_detail.hpp).
#include "genmod/solvers/minimizer.hpp"
#include "minimizer_detail.hpp"

#include "genmod/kernel/expression.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace genmod {
namespace {

// Rewrites eq(a, b) -> |a - b| <= eta in the and / or skeleton of the scalar constraint c.
Fn relax(const Fn& c, double eta, std::unordered_map<NodeId, Fn>& memo) {
  if (auto it = memo.find(c.node(0)); it != memo.end()) return it->second;
  const Expression e = expression(c);
  Fn out = c;
  if (e.op == Op::Eq) out = abs(e.operands[0] - e.operands[1]) <= Fn(eta);
  else if (e.op == Op::And) out = relax(e.operands[0], eta, memo) && relax(e.operands[1], eta, memo);
  else if (e.op == Op::Or) out = relax(e.operands[0], eta, memo) || relax(e.operands[1], eta, memo);
  memo.emplace(c.node(0), out);
  return out;
}

// Appends the residuals of the and-skeleton of the scalar constraint c.
void collect_residuals(const Fn& c, std::vector<Fn>& out) {
  const Expression e = expression(c);
  auto excess = [](const Fn& a, const Fn& b) { return max(a - b, Fn(0.0)); };
  switch (e.op) {
    case Op::And:
      collect_residuals(e.operands[0], out);
      collect_residuals(e.operands[1], out);
      break;
    case Op::Eq:
      out.push_back(e.operands[0] - e.operands[1]);
      break;
    case Op::Lt:
    case Op::Le:
      out.push_back(excess(e.operands[0], e.operands[1]));
      break;
    case Op::Gt:
    case Op::Ge:
      out.push_back(excess(e.operands[1], e.operands[0]));
      break;
    default:
      break;  // or, not, select, ...: no residual (local search then relies on descent only)
  }
}

}  // namespace

Fn relax_equalities(const Fn& constraint, double eta) {
  if (!(eta >= 0.0) || !std::isfinite(eta))
    throw std::invalid_argument("genmod::relax_equalities: the tolerance must be finite and >= 0, got " +
                                std::to_string(eta));
  if (eta == 0.0) return constraint;
  std::unordered_map<NodeId, Fn> memo;
  std::vector<Fn> parts;
  for (std::size_t j = 0; j < constraint.dim(); ++j) parts.push_back(relax(constraint[j], eta, memo));
  return cat(parts);
}

namespace minimizer_detail {

std::optional<Fn> constraint_residuals(const Fn& constraint) {
  std::vector<Fn> residuals;
  for (std::size_t j = 0; j < constraint.dim(); ++j) collect_residuals(constraint[j], residuals);
  if (residuals.empty()) return std::nullopt;
  return cat(residuals);
}

LocalSearch::LocalSearch(const Tape& objective, const Tape& constraint, std::optional<Tape> residuals,
                         const Box& box)
    : f_(objective), c_(constraint), r_(std::move(residuals)), box_(box) {}

bool LocalSearch::feasible(std::span<const double> x) {
  const double c = pe_.eval(c_, x)[0];
  return c == c && c != 0.0 && std::isfinite(value(x));
}

double LocalSearch::value(std::span<const double> x) { return pe_.eval(f_, x)[0]; }

void LocalSearch::clamp(std::vector<double>& x) const {
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::clamp(x[i], box_[i].lo(), box_[i].hi());
}

// Levenberg-Marquardt steps on the residuals, projected onto the box.
void LocalSearch::restore_feasibility(std::vector<double>& x) {
  const std::size_t n = x.size();
  double lambda = 1e-6;
  for (int iter = 0; iter < 30 && !feasible(x); ++iter) {
    ge_.eval(*r_, x);
    const std::size_t m = ge_.values().size();
    Eigen::VectorXd r(static_cast<Eigen::Index>(m));
    Eigen::MatrixXd jac(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(n));
    for (std::size_t j = 0; j < m; ++j) {
      r(static_cast<Eigen::Index>(j)) = ge_.values()[j];
      for (std::size_t i = 0; i < n; ++i)
        jac(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(i)) = ge_.jacobian()[j * n + i];
    }
    if (!r.allFinite() || !jac.allFinite()) return;
    const double norm = r.squaredNorm();
    if (norm == 0.0) return;
    Eigen::MatrixXd normal = jac.transpose() * jac;
    normal.diagonal().array() += lambda * (1.0 + normal.diagonal().array());
    const Eigen::VectorXd step = normal.ldlt().solve(-jac.transpose() * r);
    if (!step.allFinite()) return;
    std::vector<double> next(x);
    for (std::size_t i = 0; i < n; ++i) next[i] += step(static_cast<Eigen::Index>(i));
    clamp(next);
    ge_.eval(*r_, next);
    double next_norm = 0.0;
    for (double v : ge_.values()) next_norm += v * v;
    if (next_norm == next_norm && next_norm < norm) {
      x = std::move(next);
      lambda = std::max(lambda * 0.1, 1e-12);
    } else {
      lambda *= 100.0;
      if (lambda > 1e8) return;
    }
  }
}

std::vector<double> LocalSearch::run(std::vector<double> x) {
  const std::size_t n = x.size();
  clamp(x);
  if (!feasible(x)) {
    if (!r_) return x;
    restore_feasibility(x);
    if (!feasible(x)) return x;
  }
  double fx = value(x);
  double step = 1.0;
  std::vector<double> g(n), trial(n);
  for (int iter = 0; iter < 40; ++iter) {
    ge_.eval(f_, x);
    bool finite = true;
    double gnorm = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      g[i] = ge_.jacobian()[i];
      finite = finite && std::isfinite(g[i]);
      gnorm += g[i] * g[i];
    }
    if (!finite || gnorm == 0.0) break;
    // Backtracking (Armijo) on the projected step; the first trial doubles the last step.
    step = std::min(step * 2.0, 1e6);
    bool moved = false;
    for (int k = 0; k < 40; ++k, step *= 0.5) {
      double decrease = 0.0;
      for (std::size_t i = 0; i < n; ++i) trial[i] = x[i] - step * g[i];
      clamp(trial);
      for (std::size_t i = 0; i < n; ++i) decrease += g[i] * (x[i] - trial[i]);
      if (decrease <= 0.0) break;  // projected step vanished
      const double ft = value(trial);
      if (ft == ft && ft <= fx - 1e-4 * decrease && feasible(trial)) {
        x = trial;
        fx = ft;
        moved = true;
        break;
      }
    }
    if (!moved) break;
  }
  return x;
}

}  // namespace minimizer_detail
}  // namespace genmod
