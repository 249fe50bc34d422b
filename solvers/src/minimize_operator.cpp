// m_minimize as a custom operator (see minimize_operator.hpp). One operator computes both the
// minimizer point (outputs 0..n-1) and the minimum value (output n); minimize() and
// minimum_value() project it.
#include "genmod/solvers/minimize_operator.hpp"

#include "genmod/kernel/custom_op.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/solvers/constraint_solver.hpp"
#include "genmod/solvers/minimizer.hpp"
#include "implicit_partials.hpp"

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
  MinimizeOp(Fn objective, Fn constraint, std::vector<int> unknowns, std::vector<int> free, Box domain, double epsilon)
      : objective_(std::move(objective)),
        constraint_(std::move(constraint)),
        unknowns_(std::move(unknowns)),
        free_(std::move(free)),
        domain_(std::move(domain)),
        epsilon_(epsilon) {
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
  }

  std::string name() const override { return "minimize"; }
  int num_args() const override { return static_cast<int>(free_.size()); }
  int num_outputs() const override { return static_cast<int>(unknowns_.size()) + 1; }

  void eval(std::span<const double> args, std::span<double> out) const override {
    std::fill(out.begin(), out.end(), kNaN);
    Box box = domain_;
    for (double a : args) {
      if (!std::isfinite(a)) return;
      box.emplace_back(a);
    }
    const MinimizeResult r = genmod::minimize(objective_, constraint_, inputs_, box, options());
    const std::size_t n = unknowns_.size();
    if (r.infeasible || !r.feasible_found || !(r.minimum.width() <= epsilon_)) return;
    std::copy(r.best_point.begin(), r.best_point.begin() + static_cast<std::ptrdiff_t>(n), out.begin());
    out[n] = r.minimum.mid();
  }

  void inclusion(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const override {
    const std::size_t n = unknowns_.size();
    for (const Interval& a : args) {
      if (a.is_empty()) {
        std::fill(out.begin(), out.end(), Interval::empty());
        for (auto& e : err) e |= kCertainError;
        return;
      }
    }
    Box box = domain_;
    box.insert(box.end(), args.begin(), args.end());
    IntervalEvaluator ev;
    for (const Interval& a : args) {
      if (!a.is_bounded()) {  // the objective's natural bound; the minimizer lies in the domain
        std::copy(domain_.begin(), domain_.end(), out.begin());
        out[n] = ev.eval(*objective_tape_, box)[0];
        for (auto& e : err) e |= kMaybeError;
        return;
      }
    }
    MinimizeOptions opt = options();
    opt.epsilon = std::max(epsilon_, 0.01 * width(args));
    opt.limits.max_boxes = 20000;
    const MinimizeResult r = genmod::minimize(objective_, constraint_, inputs_, box, opt);
    if (r.infeasible) {
      std::fill(out.begin(), out.end(), Interval::empty());
      for (auto& e : err) e |= kCertainError;
      return;
    }
    const Interval margin(-epsilon_, epsilon_);
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
    out[n] = value + margin;
    if (!everywhere) err[n] |= kMaybeError;
    // Minimizer point: a point value q at p is feasible with f(q, p) <= f*(p) + delta <= U, so
    // it lies in a box the constraint solver returns for f(x, p) <= U && constraint, p in P.
    for (std::size_t k = 0; k < n; ++k) {
      out[k] = domain_[k];
      err[k] |= kMaybeError;
    }
    if (!std::isfinite(out[n].hi()) || scratch_ < 0) return;
    SolveOptions sopt;
    sopt.epsilon = opt.epsilon;
    sopt.threads = 1;
    sopt.limits.max_boxes = 20000;
    FreeParameters params{free_, Box(args.begin(), args.end())};
    params.coords.push_back(scratch_);
    params.values.emplace_back(out[n].hi());
    const SolveResult s = genmod::solve(level_set_, unknowns_, domain_, sopt, params);
    for (std::size_t k = 0; k < n; ++k) {
      Interval h = Interval::empty();
      for (const SolutionBox& b : s.boxes) h = hull(h, b.box[k]);
      out[k] = h.is_empty() ? Interval::empty() : intersect(h + margin, domain_[k]);
    }
  }

  Fn derivative(std::span<const Fn> args, int k) const override {
    const std::size_t n = unknowns_.size();
    const Fn r = apply_custom(shared_from_this(), args);
    std::vector<Fn> at;
    for (std::size_t j = 0; j < n; ++j) at.push_back(r[j]);
    at.insert(at.end(), args.begin(), args.end());
    std::vector<Fn> d;
    if (minimizer_partials_.empty()) {
      d.assign(n, Fn(kNaN));  // n > detail::kMaxImplicitSize
    } else {
      const Fn dx = compose_all(minimizer_partials_.at(static_cast<std::size_t>(k)), inputs_, cat(at));
      for (std::size_t j = 0; j < n; ++j) d.push_back(dx[j]);
    }
    d.push_back(compose_all(envelope_.at(static_cast<std::size_t>(k)), inputs_, cat(at)));
    return cat(d);
  }

 private:
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
  std::shared_ptr<const Tape> objective_tape_, constraint_tape_;
  std::vector<Fn> envelope_;  // df/d free_k over inputs_
  std::vector<Fn> minimizer_partials_;  // dx*/d free_k (dimension n) over inputs_
  int scratch_ = -1;          // a coordinate holding the level U in level_set_
  Fn level_set_;              // objective <= x(scratch_) && constraint
};

Fn make(const Fn& objective, const Fn& constraint, std::span<const int> unknowns, const Box& domain, double epsilon) {
  const std::string who = "genmod: minimize operator: ";
  if (objective.dim() != 1)
    throw std::invalid_argument(who + "the objective must be scalar, got dimension " + std::to_string(objective.dim()));
  if (constraint.dim() != 1)
    throw std::invalid_argument(who + "the constraint must be scalar, got dimension " + std::to_string(constraint.dim()));
  if (unknowns.empty()) throw std::invalid_argument(who + "no unknowns");
  std::uint64_t mask = 0;
  for (int u : unknowns) {
    if (u < 0 || u >= kMaxInputs)
      throw std::invalid_argument(who + "unknown " + std::to_string(u) + " is outside [0, " + std::to_string(kMaxInputs) + ")");
    if (mask & (std::uint64_t{1} << u)) throw std::invalid_argument(who + "unknown x(" + std::to_string(u) + ") is listed twice");
    mask |= std::uint64_t{1} << u;
  }
  check_search_box(domain, unknowns.size(), "minimize operator (domain)");
  if (!(epsilon > 0.0) || !std::isfinite(epsilon))
    throw std::invalid_argument(who + "epsilon must be finite and > 0, got " + std::to_string(epsilon));
  const std::uint64_t used = objective.input_mask() | constraint.input_mask();
  std::vector<int> free;
  for (int c = 0; c < kMaxInputs; ++c)
    if ((used & (std::uint64_t{1} << c)) && !(mask & (std::uint64_t{1} << c))) free.push_back(c);
  auto op = std::make_shared<const MinimizeOp>(objective, constraint, std::vector<int>(unknowns.begin(), unknowns.end()),
                                               free, domain, epsilon);
  std::vector<Fn> args;
  for (int c : free) args.push_back(x(c));
  return apply_custom(op, args);
}

}  // namespace

Fn minimize(const Fn& objective, const Fn& constraint, std::span<const int> unknowns, const Box& domain,
            double epsilon) {
  const Fn all = make(objective, constraint, unknowns, domain, epsilon);
  std::vector<Fn> point;
  for (std::size_t k = 0; k < unknowns.size(); ++k) point.push_back(all[k]);
  return cat(point);
}

Fn minimum_value(const Fn& objective, const Fn& constraint, std::span<const int> unknowns, const Box& domain,
                 double epsilon) {
  return make(objective, constraint, unknowns, domain, epsilon)[unknowns.size()];
}

}  // namespace genmod
