// m_solve as a custom operator (see solve_operator.hpp): the constraint solver for points and
// boxes, Newton refinement of the chosen solution, the implicit function theorem (Cramer's rule
// on kernel Fn expressions) for derivatives.
#include "genmod/solvers/solve_operator.hpp"

#include "genmod/kernel/custom_op.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/solvers/constraint_solver.hpp"
#include "genmod/solvers/constraint_system.hpp"
#include "implicit_partials.hpp"
#include "operator_arguments.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace genmod {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Solves a x = b (n x n, row major) by Gaussian elimination with partial pivoting; false if
// singular.
bool linear_solve(std::vector<double> a, std::vector<double>& b, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t piv = k;
    for (std::size_t r = k + 1; r < n; ++r)
      if (std::abs(a[r * n + k]) > std::abs(a[piv * n + k])) piv = r;
    if (!(std::abs(a[piv * n + k]) > 0.0)) return false;
    if (piv != k) {
      for (std::size_t c = 0; c < n; ++c) std::swap(a[k * n + c], a[piv * n + c]);
      std::swap(b[k], b[piv]);
    }
    for (std::size_t r = k + 1; r < n; ++r) {
      const double f = a[r * n + k] / a[k * n + k];
      for (std::size_t c = k; c < n; ++c) a[r * n + c] -= f * a[k * n + c];
      b[r] -= f * b[k];
    }
  }
  for (std::size_t k = n; k-- > 0;) {
    double s = b[k];
    for (std::size_t c = k + 1; c < n; ++c) s -= a[k * n + c] * b[c];
    b[k] = s / a[k * n + k];
  }
  return std::all_of(b.begin(), b.end(), [](double v) { return std::isfinite(v); });
}

class SolveOp : public CustomOp, public std::enable_shared_from_this<SolveOp> {
 public:
  // max_solutions == 0: the first solution (n outputs); K > 0: the count and up to K solutions
  // (1 + K n outputs).
  SolveOp(Fn constraint, std::vector<int> unknowns, std::vector<int> free, Box domain, double epsilon,
          int max_solutions)
      : constraint_(std::move(constraint)),
        unknowns_(std::move(unknowns)),
        free_(std::move(free)),
        domain_(std::move(domain)),
        epsilon_(epsilon),
        max_solutions_(max_solutions) {
    const std::size_t n = unknowns_.size();
    inputs_ = unknowns_;
    inputs_.insert(inputs_.end(), free_.begin(), free_.end());
    const ConstraintSystem sys(constraint_, unknowns_, free_);
    std::vector<Fn> eqs;
    for (const ConstraintSystem::Conjunct& c : sys.conjuncts())
      if (c.rel == Relation::Eq) eqs.push_back(sys.atoms()[c.atom].h);
    if (eqs.size() != n) return;  // not a square equality system: no Newton, NaN derivative
    square_ = true;
    // Newton tape: h (n outputs), then J_x row major (n * n outputs).
    std::vector<Fn> parts = eqs;
    std::vector<Fn> jx;
    for (const Fn& h : eqs)
      for (int u : unknowns_) jx.push_back(genmod::derivative(h, u));
    parts.insert(parts.end(), jx.begin(), jx.end());
    newton_ = std::make_shared<const Tape>(cat(parts), inputs_);
    partials_ = detail::implicit_partials(eqs, unknowns_, free_);
  }

  std::string name() const override { return max_solutions_ ? "solve-all" : "solve"; }
  int num_args() const override { return static_cast<int>(free_.size()); }
  int num_outputs() const override {
    const int n = static_cast<int>(unknowns_.size());
    return max_solutions_ ? 1 + max_solutions_ * n : n;
  }

  void eval(std::span<const double> args, std::span<double> out) const override {
    std::fill(out.begin(), out.end(), kNaN);
    FreeParameters params{free_, {}};
    for (double a : args) {
      if (!std::isfinite(a)) return;
      params.values.emplace_back(a);
    }
    SolveOptions opt;
    opt.epsilon = epsilon_;
    opt.threads = 1;
    const SolveResult r = genmod::solve(constraint_, unknowns_, domain_, opt, params);
    if (!r.complete() || r.components.empty()) {
      if (max_solutions_ && r.complete()) out[0] = 0.0;  // proven: no solution
      return;
    }
    // Components in lexicographic order of their lower corners (x(unknowns[0]) first).
    std::vector<const Box*> order;
    for (const SolutionComponent& c : r.components) order.push_back(&c.hull);
    std::sort(order.begin(), order.end(), [](const Box* a, const Box* b) {
      return std::lexicographical_compare(a->begin(), a->end(), b->begin(), b->end(),
                                          [](const Interval& u, const Interval& v) { return u.lo() < v.lo(); });
    });
    const std::size_t n = unknowns_.size();
    const std::size_t count = max_solutions_ ? std::min<std::size_t>(order.size(), static_cast<std::size_t>(max_solutions_)) : 1;
    const std::size_t first_slot = max_solutions_ ? 1 : 0;
    if (max_solutions_) out[0] = static_cast<double>(count);
    for (std::size_t j = 0; j < count; ++j) {
      std::vector<double> xs = midpoint(*order[j]);
      refine(xs, args, *order[j]);
      std::copy(xs.begin(), xs.end(), out.begin() + static_cast<std::ptrdiff_t>(first_slot + j * n));
    }
  }

  void inclusion(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const override {
    enclose(args, out, err);
  }

  bool inclusion_continuous(std::span<const Interval> args, std::span<Interval> out,
                            std::span<std::uint8_t> err) const override {
    return enclose(args, out, err);
  }

  Fn derivative(std::span<const Fn> args, int k) const override {
    const std::size_t n = unknowns_.size();
    const std::size_t slots = max_solutions_ ? static_cast<std::size_t>(max_solutions_) : 1;
    const std::size_t first_slot = max_solutions_ ? 1 : 0;
    std::vector<Fn> out;
    if (max_solutions_) out.push_back(Fn(0.0));  // the count is piecewise constant
    const Fn r = apply_custom(shared_from_this(), args);
    for (std::size_t j = 0; j < slots; ++j) {
      if (partials_.empty()) {
        for (std::size_t i = 0; i < n; ++i) out.push_back(Fn(kNaN));
        continue;
      }
      // The implicit-function-theorem partials at solution j.
      std::vector<Fn> at;
      for (std::size_t i = 0; i < n; ++i) at.push_back(r[first_slot + j * n + i]);
      at.insert(at.end(), args.begin(), args.end());
      const Fn d = compose_all(partials_.at(static_cast<std::size_t>(k)), inputs_, cat(at));
      for (std::size_t i = 0; i < n; ++i) out.push_back(d[i]);
    }
    return cat(out);
  }

 private:
  // The inclusion; returns whether the solution map is continuous on the box `args`: the
  // first-solution operator, a complete search, and one component certified to hold exactly
  // one solution for every parameter value (see the header).
  bool enclose(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const {
    auto all = [&](const Interval& v, std::uint8_t e) {
      std::fill(out.begin(), out.end(), v);
      for (auto& b : err) b |= e;
      return false;
    };
    for (const Interval& a : args)
      if (a.is_empty()) return all(Interval::empty(), kCertainError);
    for (const Interval& a : args) {
      if (!a.is_bounded()) {
        std::copy(domain_.begin(), domain_.end(), out.begin());
        for (auto& b : err) b |= kMaybeError;
        return false;
      }
    }
    SolveOptions opt;
    opt.epsilon = std::max(epsilon_, 0.01 * width(args));
    opt.threads = 1;
    opt.limits.max_boxes = 20000;
    const SolveResult r = genmod::solve(constraint_, unknowns_, domain_, opt, FreeParameters{free_, Box(args.begin(), args.end())});
    if (r.boxes.empty()) return all(Interval::empty(), kCertainError);
    const Interval margin(-epsilon_, epsilon_);
    const std::size_t n = unknowns_.size();
    Box h(n, Interval::empty());
    for (std::size_t k = 0; k < n; ++k) {
      for (const SolutionBox& b : r.boxes) h[k] = hull(h[k], b.box[k]);
      h[k] = intersect(h[k] + margin, domain_[k]);
    }
    // A solution exists for every parameter value in a certified box, an inner box or a
    // component certified unique (Krawczyk on its hull: its members may all be Possible).
    bool exists = r.unique_components() > 0;
    for (const SolutionBox& b : r.boxes)
      exists = exists || b.status == SolutionStatus::CertifiedUnique || b.status == SolutionStatus::Feasible;
    if (!max_solutions_) {
      std::copy(h.begin(), h.end(), out.begin());
      if (!exists || !r.complete()) {
        for (auto& b : err) b |= kMaybeError;
        return false;
      }
      // One solution for every parameter value, in the component's hull (where the
      // equalities are continuous and the other atoms true): a limit of solutions is a
      // solution, hence the solution. Several components: the first one may change.
      return r.components.size() == 1 && r.components[0].unique;
    }
    // Solution slot j holds some solution (any of them may come j-th for some parameter value),
    // and is certainly present when j < the number of components certified to hold exactly one
    // solution for every parameter value (they are disjoint).
    const std::size_t k_max = static_cast<std::size_t>(max_solutions_);
    const std::size_t sure = r.complete() ? std::min(k_max, r.unique_components()) : 0;
    const bool all_unique = r.complete() && r.unique_components() == r.components.size();
    const std::size_t most = all_unique ? std::min(k_max, r.components.size()) : k_max;
    out[0] = Interval(static_cast<double>(sure), static_cast<double>(most));
    for (std::size_t j = 0; j < k_max; ++j)
      for (std::size_t k = 0; k < n; ++k) {
        out[1 + j * n + k] = h[k];
        if (j >= sure) err[1 + j * n + k] |= kMaybeError;
      }
    if (!r.complete()) err[0] |= kMaybeError;
    return false;  // the count is a step function, and solutions may swap slots
  }

  // Newton steps on the square equality system from xs, kept while they stay in `hull` and
  // reduce the residual's max norm.
  void refine(std::vector<double>& xs, std::span<const double> args, const Box& hull) const {
    if (!square_) return;
    const std::size_t n = unknowns_.size();
    PointEvaluator ev;
    std::vector<double> point(inputs_.size());
    std::copy(args.begin(), args.end(), point.begin() + static_cast<std::ptrdiff_t>(n));
    auto residual = [&](std::span<const double> y) {
      double m = 0.0;
      for (std::size_t i = 0; i < n; ++i) m = std::isnan(y[i]) ? kNaN : std::max(m, std::abs(y[i]));
      return m;
    };
    std::copy(xs.begin(), xs.end(), point.begin());
    const auto y0 = ev.eval(*newton_, point);
    std::vector<double> y(y0.begin(), y0.end());
    double res = residual(y);
    for (int iter = 0; iter < 30 && res > 0.0; ++iter) {
      std::vector<double> step(y.begin(), y.begin() + static_cast<std::ptrdiff_t>(n));
      if (!linear_solve(std::vector<double>(y.begin() + static_cast<std::ptrdiff_t>(n), y.end()), step, n)) return;
      std::vector<double> next(n);
      for (std::size_t i = 0; i < n; ++i) {
        next[i] = xs[i] - step[i];
        if (!hull[i].contains(next[i])) return;
      }
      std::copy(next.begin(), next.end(), point.begin());
      const auto yn = ev.eval(*newton_, point);
      const double rn = residual(yn);
      if (!(rn < res)) return;
      xs = next;
      y.assign(yn.begin(), yn.end());
      res = rn;
    }
  }

  Fn constraint_;
  std::vector<int> unknowns_, free_;
  std::vector<int> inputs_;  // unknowns then free coordinates: the order of the tapes and partials
  Box domain_;
  double epsilon_;
  int max_solutions_ = 0;
  bool square_ = false;
  std::shared_ptr<const Tape> newton_;  // h and J_x over inputs_ (square systems only)
  std::vector<Fn> partials_;            // dR/d free_k (dimension n) over inputs_
};

}  // namespace

namespace {

std::shared_ptr<const SolveOp> make_solve_op(const Fn& constraint, std::span<const int> unknowns, const Box& domain,
                                             double epsilon, int max_solutions, std::vector<int>* free) {
  const std::string who = "genmod: solve operator: ";
  if (constraint.dim() != 1)
    throw std::invalid_argument(who + "the constraint must be scalar, got dimension " + std::to_string(constraint.dim()));
  const std::uint64_t mask = detail::unknowns_mask(unknowns, who);
  check_search_box(domain, unknowns.size(), "solve operator (domain)");
  if (!(epsilon > 0.0) || !std::isfinite(epsilon))
    throw std::invalid_argument(who + "epsilon must be finite and > 0, got " + std::to_string(epsilon));
  if (max_solutions < 0) throw std::invalid_argument(who + "max_solutions must be >= 1");
  for (int c : constraint.inputs())
    if (!(mask & (std::uint64_t{1} << c))) free->push_back(c);
  return std::make_shared<const SolveOp>(constraint, std::vector<int>(unknowns.begin(), unknowns.end()), *free, domain,
                                         epsilon, max_solutions);
}

Fn apply_to_free(const std::shared_ptr<const SolveOp>& op, const std::vector<int>& free) {
  std::vector<Fn> args;
  for (int c : free) args.push_back(x(c));
  return apply_custom(op, args);
}

}  // namespace

Fn solve_operator(const Fn& constraint, Coordinates unknowns, const Box& domain, double epsilon) {
  std::vector<int> free;
  const auto op = make_solve_op(constraint, unknowns, domain, epsilon, 0, &free);
  return apply_to_free(op, free);
}

Fn solve_all_operator(const Fn& constraint, Coordinates unknowns, const Box& domain, double epsilon, int max_solutions) {
  if (max_solutions < 1) throw std::invalid_argument("genmod: solve_all: max_solutions must be >= 1");
  std::vector<int> free;
  const auto op = make_solve_op(constraint, unknowns, domain, epsilon, max_solutions, &free);
  return apply_to_free(op, free);
}

}  // namespace genmod
