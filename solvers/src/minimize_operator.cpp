// m_minimize as a custom operator (see minimize_operator.hpp). One operator computes both the
// minimizer point (outputs 0..n-1) and the minimum value (output n); minimize() and
// minimum_value() project it.
#include "genmod/solvers/minimize_operator.hpp"

#include "genmod/kernel/custom_op.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/solvers/aggregation.hpp"
#include "genmod/solvers/constraint_solver.hpp"
#include "genmod/solvers/minimizer.hpp"
#include "implicit_partials.hpp"
#include "minimizer_1d.hpp"
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

class MinimizeOp : public CustomOp, public std::enable_shared_from_this<MinimizeOp> {
 public:
  // max_solutions == 0: the minimizer and the minimum value (n + 1 outputs); K > 0: the number
  // of minimizers found (at most K), K minimizer points, then the minimum value (2 + K n).
  MinimizeOp(Fn objective, Fn constraint, std::vector<int> unknowns, std::vector<int> free, Box domain, double epsilon,
             int max_solutions)
      : objective_(std::move(objective)),
        constraint_(std::move(constraint)),
        unknowns_(std::move(unknowns)),
        free_(std::move(free)),
        domain_(std::move(domain)),
        epsilon_(epsilon),
        max_solutions_(max_solutions) {
    inputs_ = unknowns_;
    inputs_.insert(inputs_.end(), free_.begin(), free_.end());
    objective_tape_ = std::make_shared<const Tape>(objective_, inputs_);
    constraint_tape_ = std::make_shared<const Tape>(constraint_, inputs_);
    for (int p : free_) envelope_.push_back(genmod::derivative(objective_, p));
    // The minimizer's derivative: the implicit function theorem on grad_x f = 0 (an interior
    // minimum or inactive constraints).
    std::vector<Fn> gradient;
    for (int u : unknowns_) gradient.push_back(genmod::derivative(objective_, u));
    minimizer_partials_ = detail::implicit_partials(gradient, unknowns_, free_);
    const std::uint64_t used = objective_.input_mask() | constraint_.input_mask();
    for (int i = kMaxInputs - 1; i >= 0 && scratch_ < 0; --i)
      if (!(used & (std::uint64_t{1} << i))) scratch_ = i;
    if (scratch_ >= 0) level_set_ = (objective_ <= x(scratch_)) && constraint_;
    // One unknown and no constraint (a closest point): point values are polished to the root
    // of df/dx and boxes enclosed without a search (minimizer_1d.hpp).
    double always = 0.0;
    if (unknowns_.size() == 1 && max_solutions_ == 0 && constraint_.is_constant(&always) && always != 0.0) {
      fx_tape_ = std::make_shared<const Tape>(gradient[0], inputs_);
      fxx_tape_ = std::make_shared<const Tape>(genmod::derivative(gradient[0], unknowns_[0]), inputs_);
    }
  }

  std::string name() const override { return max_solutions_ ? "minimize-all" : "minimize"; }
  int num_args() const override { return static_cast<int>(free_.size()); }
  int num_outputs() const override { return static_cast<int>(slots() * unknowns_.size() + first_slot() + 1); }

  void eval(std::span<const double> args, std::span<double> out) const override {
    std::fill(out.begin(), out.end(), kNaN);
    if (fx_tape_ && std::all_of(args.begin(), args.end(), [](double a) { return std::isfinite(a); })) {
      if (const auto q = detail::minimizer_1d(objective_1d(), args, epsilon_)) {
        out[0] = *q;
        std::vector<double> at{*q};
        at.insert(at.end(), args.begin(), args.end());
        out[1] = PointEvaluator().eval(*objective_tape_, at)[0];
        return;
      }
    }
    Box box = domain_;
    for (double a : args) {
      if (!std::isfinite(a)) return;
      box.emplace_back(a);
    }
    const MinimizeResult r = genmod::minimize(objective_, constraint_, inputs_, box, options());
    const std::size_t n = unknowns_.size();
    if (r.infeasible || !r.feasible_found || !(r.minimum.width() <= epsilon_)) return;
    out[value_index()] = r.minimum.mid();
    if (fx_tape_) {
      out[0] = detail::polish_minimizer(objective_1d(), r.best_point[0], args);
      return;
    }
    if (!max_solutions_) {
      std::copy(r.best_point.begin(), r.best_point.begin() + static_cast<std::ptrdiff_t>(n), out.begin());
      return;
    }
    // Every minimizer lies in the candidates; each connected group of them is one minimizer
    // (up to epsilon), in lexicographic order of the groups' lower corners.
    std::vector<Box> xs;
    for (const Box& c : r.candidates) xs.emplace_back(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(n));
    std::vector<Aggregate> groups = aggregate(xs, epsilon_);
    std::sort(groups.begin(), groups.end(), [](const Aggregate& a, const Aggregate& b) {
      return std::lexicographical_compare(a.hull.begin(), a.hull.end(), b.hull.begin(), b.hull.end(),
                                          [](const Interval& u, const Interval& v) { return u.lo() < v.lo(); });
    });
    const std::size_t count = std::min(groups.size(), slots());
    out[0] = static_cast<double>(count);
    for (std::size_t j = 0; j < count; ++j) {
      const std::vector<double> m = midpoint(groups[j].hull);
      std::copy(m.begin(), m.end(), out.begin() + static_cast<std::ptrdiff_t>(1 + j * n));
    }
  }

  void inclusion(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const override {
    enclose(args, out, err);
  }

  // Continuous where the one-unknown enclosure proves the minimizer unique (minimizer_1d.hpp).
  bool inclusion_continuous(std::span<const Interval> args, std::span<Interval> out,
                            std::span<std::uint8_t> err) const override {
    return enclose(args, out, err);
  }

  // The inclusion; true when the outputs are continuous on the box (see inclusion_continuous).
  bool enclose(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const {
    const std::size_t n = unknowns_.size();
    for (const Interval& a : args) {
      if (a.is_empty()) {
        std::fill(out.begin(), out.end(), Interval::empty());
        for (auto& e : err) e |= kCertainError;
        return false;
      }
    }
    Box box = domain_;
    box.insert(box.end(), args.begin(), args.end());
    IntervalEvaluator ev;
    for (const Interval& a : args) {
      if (!a.is_bounded()) {  // the objective's natural bound; the minimizer lies in the domain
        for (std::size_t j = 0; j < slots(); ++j)
          std::copy(domain_.begin(), domain_.end(), out.begin() + static_cast<std::ptrdiff_t>(first_slot() + j * n));
        if (max_solutions_) out[0] = Interval(0.0, static_cast<double>(slots()));
        out[value_index()] = ev.eval(*objective_tape_, box)[0];
        for (auto& e : err) e |= kMaybeError;
        return false;
      }
    }
    const Interval margin(-epsilon_, epsilon_);
    if (fx_tape_) {
      // Point values are within delta = epsilon of the minimum (options()). The value has no
      // error (no constraint: every point is feasible); the minimizer has none where it is
      // unique (minimizer_1d finds it for every p), else a point value may fail.
      const auto e = detail::enclose_minimizer_1d(objective_1d(), args, epsilon_, std::max(epsilon_, 0.01 * width(args)));
      if (e) {
        out[0] = intersect(e->minimizer + margin, domain_[0]);
        if (!e->unique) err[0] |= kMaybeError;
        out[1] = e->minimum + margin;
        return e->unique;
      }
    }
    MinimizeOptions opt = options();
    opt.epsilon = std::max(epsilon_, 0.01 * width(args));
    opt.limits.max_boxes = 20000;
    const MinimizeResult r = genmod::minimize(objective_, constraint_, inputs_, box, opt);
    if (r.infeasible) {
      std::fill(out.begin(), out.end(), Interval::empty());
      for (auto& e : err) e |= kCertainError;
      return false;
    }
    // Minimum value.
    double upper = ev.eval(*objective_tape_, box)[0].hi();
    bool everywhere = false;
    if (r.feasible_found) {
      Box at = box;
      for (std::size_t k = 0; k < n; ++k) at[k] = Interval(r.best_point[k]);
      const Interval c = ev.eval(*constraint_tape_, at)[0];
      if (ev.errors()[0] == kNoError && !c.contains_zero()) {
        const Interval f = ev.eval(*objective_tape_, at)[0];
        if (ev.errors()[0] == kNoError) {
          upper = std::min(upper, f.hi());
          everywhere = true;
        }
      }
    }
    const Interval value = Interval::unchecked(r.minimum.lo(), std::max(upper, r.minimum.lo()));
    const std::size_t vi = value_index();
    out[vi] = value + margin;
    if (!everywhere) err[vi] |= kMaybeError;
    if (max_solutions_) {  // the count is not certified by the minimizer
      out[0] = Interval(0.0, static_cast<double>(slots()));
      err[0] |= kMaybeError;
    }
    // Minimizer point: a point value q at p is feasible with f(q, p) <= f*(p) + delta <= U, so
    // it lies in a box the constraint solver returns for f(x, p) <= U && constraint, p in P.
    for (std::size_t j = 0; j < slots(); ++j)
      for (std::size_t k = 0; k < n; ++k) {
        out[first_slot() + j * n + k] = domain_[k];
        err[first_slot() + j * n + k] |= kMaybeError;
      }
    if (!std::isfinite(out[vi].hi()) || scratch_ < 0) return false;
    SolveOptions sopt;
    sopt.epsilon = opt.epsilon;
    sopt.threads = 1;
    sopt.limits.max_boxes = 20000;
    FreeParameters params{free_, Box(args.begin(), args.end())};
    params.coords.push_back(scratch_);
    params.values.emplace_back(out[vi].hi());
    const SolveResult s = genmod::solve(level_set_, unknowns_, domain_, sopt, params);
    for (std::size_t k = 0; k < n; ++k) {
      Interval h = Interval::empty();
      for (const SolutionBox& b : s.boxes) h = hull(h, b.box[k]);
      const Interval slot = h.is_empty() ? Interval::empty() : intersect(h + margin, domain_[k]);
      for (std::size_t j = 0; j < slots(); ++j) out[first_slot() + j * n + k] = slot;
    }
    return false;
  }

  Fn derivative(std::span<const Fn> args, int k) const override {
    const std::size_t n = unknowns_.size();
    const Fn r = apply_custom(shared_from_this(), args);
    std::vector<Fn> at;  // the first minimizer and the free coordinates (for the envelope)
    for (std::size_t j = 0; j < n; ++j) at.push_back(r[first_slot() + j]);
    at.insert(at.end(), args.begin(), args.end());
    std::vector<Fn> d;
    if (max_solutions_) d.push_back(Fn(0.0));  // the count is piecewise constant
    for (std::size_t j = 0; j < slots(); ++j) {
      if (minimizer_partials_.empty()) {  // n > detail::kMaxImplicitSize
        for (std::size_t i = 0; i < n; ++i) d.push_back(Fn(kNaN));
        continue;
      }
      std::vector<Fn> at_j;
      for (std::size_t i = 0; i < n; ++i) at_j.push_back(r[first_slot() + j * n + i]);
      at_j.insert(at_j.end(), args.begin(), args.end());
      const Fn dx = compose_all(minimizer_partials_.at(static_cast<std::size_t>(k)), inputs_, cat(at_j));
      for (std::size_t i = 0; i < n; ++i) d.push_back(dx[i]);
    }
    d.push_back(compose_all(envelope_.at(static_cast<std::size_t>(k)), inputs_, cat(at)));
    return cat(d);
  }

 private:
  std::size_t slots() const noexcept { return max_solutions_ ? static_cast<std::size_t>(max_solutions_) : 1; }
  std::size_t first_slot() const noexcept { return max_solutions_ ? 1 : 0; }
  std::size_t value_index() const noexcept { return first_slot() + slots() * unknowns_.size(); }

  detail::Objective1d objective_1d() const { return {*objective_tape_, *fx_tape_, *fxx_tape_, domain_[0]}; }

  MinimizeOptions options() const {
    MinimizeOptions opt;
    opt.epsilon = epsilon_;
    opt.delta = epsilon_;
    return opt;
  }

  Fn objective_, constraint_;
  std::vector<int> unknowns_, free_;
  std::vector<int> inputs_;  // unknowns then free coordinates
  Box domain_;
  double epsilon_;
  int max_solutions_ = 0;
  std::shared_ptr<const Tape> objective_tape_, constraint_tape_;
  std::vector<Fn> envelope_;  // df/d free_k over inputs_
  std::vector<Fn> minimizer_partials_;  // dx*/d free_k (dimension n) over inputs_
  std::shared_ptr<const Tape> fx_tape_, fxx_tape_;  // df/dx, d2f/dx2: one unknown, no constraint only
  int scratch_ = -1;          // a coordinate holding the level U in level_set_
  Fn level_set_;              // objective <= x(scratch_) && constraint
};

Fn make(const Fn& objective, const Fn& constraint, std::span<const int> unknowns, const Box& domain, double epsilon,
        int max_solutions) {
  const std::string who = "genmod: minimize operator: ";
  if (objective.dim() != 1)
    throw std::invalid_argument(who + "the objective must be scalar, got dimension " + std::to_string(objective.dim()));
  if (constraint.dim() != 1)
    throw std::invalid_argument(who + "the constraint must be scalar, got dimension " + std::to_string(constraint.dim()));
  const std::uint64_t mask = detail::unknowns_mask(unknowns, who);
  check_search_box(domain, unknowns.size(), "minimize operator (domain)");
  if (!(epsilon > 0.0) || !std::isfinite(epsilon))
    throw std::invalid_argument(who + "epsilon must be finite and > 0, got " + std::to_string(epsilon));
  const std::uint64_t used = objective.input_mask() | constraint.input_mask();
  std::vector<int> free;
  for (int c = 0; c < kMaxInputs; ++c)
    if ((used & (std::uint64_t{1} << c)) && !(mask & (std::uint64_t{1} << c))) free.push_back(c);
  auto op = std::make_shared<const MinimizeOp>(objective, constraint, std::vector<int>(unknowns.begin(), unknowns.end()),
                                               free, domain, epsilon, max_solutions);
  std::vector<Fn> args;
  for (int c : free) args.push_back(x(c));
  return apply_custom(op, args);
}

}  // namespace

Fn minimize_operator(const Fn& objective, const Fn& constraint, Coordinates unknowns, const Box& domain,
            double epsilon) {
  const Fn all = make(objective, constraint, unknowns, domain, epsilon, 0);
  std::vector<Fn> point;
  for (std::size_t k = 0; k < unknowns.size(); ++k) point.push_back(all[k]);
  return cat(point);
}

Fn minimum_value_operator(const Fn& objective, const Fn& constraint, Coordinates unknowns, const Box& domain,
                 double epsilon) {
  return make(objective, constraint, unknowns, domain, epsilon, 0)[unknowns.size()];
}

Fn minimize_all_operator(const Fn& objective, const Fn& constraint, Coordinates unknowns, const Box& domain,
                double epsilon, int max_solutions) {
  if (max_solutions < 1) throw std::invalid_argument("genmod: minimize_all: max_solutions must be >= 1");
  const Fn all = make(objective, constraint, unknowns, domain, epsilon, max_solutions);
  std::vector<Fn> out;
  for (std::size_t k = 0; k + 1 < all.dim(); ++k) out.push_back(all[k]);  // without the value
  return cat(out);
}

}  // namespace genmod
