// m_inverse as a custom operator: Brent's method for points, the constraint solver for boxes,
// the implicit function theorem for derivatives (see inverse_operator.hpp).
#include "genmod/solvers/inverse_operator.hpp"

#include "genmod/kernel/custom_op.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/solvers/constraint_solver.hpp"

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

// Brent's method (Numerical Recipes' zbrent) for a root of f in [a, b]; NaN when the ends do not
// bracket a sign change or f is NaN at a visited point. Stops when the bracket is below `tol`.
template <class F>
double brent(F&& f, double a, double b, double tol) {
  double fa = f(a), fb = f(b);
  if (std::isnan(fa) || std::isnan(fb)) return kNaN;
  if (fa == 0.0) return a;
  if (fb == 0.0) return b;
  if ((fa > 0.0) == (fb > 0.0)) return kNaN;
  double c = b, fc = fb, d = b - a, e = d;
  for (int iter = 0; iter < 300; ++iter) {
    if ((fb > 0.0) == (fc > 0.0)) {
      c = a;
      fc = fa;
      e = d = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol1 = 2.0 * std::numeric_limits<double>::epsilon() * std::abs(b) + 0.5 * tol;
    const double xm = 0.5 * (c - b);
    if (std::abs(xm) <= tol1 || fb == 0.0) return b;
    if (std::abs(e) >= tol1 && std::abs(fa) > std::abs(fb)) {
      const double s = fb / fa;
      double p, q;
      if (a == c) {
        p = 2.0 * xm * s;
        q = 1.0 - s;
      } else {
        const double qq = fa / fc, r = fb / fc;
        p = s * (2.0 * xm * qq * (qq - r) - (b - a) * (r - 1.0));
        q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0) q = -q;
      p = std::abs(p);
      if (2.0 * p < std::min(3.0 * xm * q - std::abs(tol1 * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = xm;
        e = d;
      }
    } else {
      d = xm;
      e = d;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tol1 ? d : (xm > 0.0 ? tol1 : -tol1);
    fb = f(b);
    if (std::isnan(fb)) return kNaN;
  }
  return b;
}

class InverseOp : public CustomOp, public std::enable_shared_from_this<InverseOp> {
 public:
  // F = invert_t - match: invert_t is invert with x(parameter) := x(bound).
  InverseOp(const Fn& invert_t, const Fn& match, int bound, std::vector<int> free, Interval domain, double epsilon)
      : bound_(bound), free_(std::move(free)), domain_(domain), epsilon_(epsilon) {
    inputs_.push_back(bound_);
    inputs_.insert(inputs_.end(), free_.begin(), free_.end());
    const Fn f = invert_t - match;
    tape_ = std::make_shared<const Tape>(f, inputs_);
    invert_tape_ = std::make_shared<const Tape>(invert_t, inputs_);
    match_tape_ = std::make_shared<const Tape>(match, inputs_);
    const Fn dt = genmod::derivative(f, bound_);
    dt_tape_ = std::make_shared<const Tape>(dt, inputs_);
    for (int c : free_) partials_.push_back(-genmod::derivative(f, c) / dt);
    constraint_ = eq(f, 0.0);
  }

  std::string name() const override { return "inverse"; }
  int num_args() const override { return static_cast<int>(free_.size()); }
  int num_outputs() const override { return 1; }

  void eval(std::span<const double> args, std::span<double> out) const override {
    PointEvaluator ev;
    std::vector<double> point(inputs_.size());
    std::copy(args.begin(), args.end(), point.begin() + 1);
    // match does not depend on t: evaluate it once, not at every step of the root finder
    // (it may itself hold nested operators). F(t) is the same subtraction of the same two
    // values as in tape_, so the result is bitwise that of evaluating F.
    point[0] = domain_.lo();
    const double match = ev.eval(*match_tape_, point)[0];
    auto f = [&](double t) {
      point[0] = t;
      return ev.eval(*invert_tape_, point)[0] - match;
    };
    out[0] = brent(f, domain_.lo(), domain_.hi(), epsilon_);
  }

  void inclusion(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const override {
    enclose(args, out, err);
  }

  bool inclusion_continuous(std::span<const Interval> args, std::span<Interval> out,
                            std::span<std::uint8_t> err) const override {
    return enclose(args, out, err);
  }

  Fn derivative(std::span<const Fn> args, int k) const override {
    std::vector<Fn> at;
    at.push_back(apply_custom(shared_from_this(), args));
    at.insert(at.end(), args.begin(), args.end());
    return compose_all(partials_.at(static_cast<std::size_t>(k)), inputs_, cat(at));
  }

 private:
  // The inclusion; returns whether R is continuous on the box `args` (see the header): F is
  // continuous on domain x args, changes sign between the domain's ends for every parameter
  // value, and has exactly one root in the domain (F strictly monotone in t, or the solver's
  // one component certified to hold exactly one root for every parameter value).
  bool enclose(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const {
    for (const Interval& a : args) {
      if (a.is_empty()) {  // an argument certainly failed: so does the result
        out[0] = Interval::empty();
        err[0] |= kCertainError;
        return false;
      }
    }
    for (const Interval& a : args) {
      if (!a.is_bounded()) {
        out[0] = domain_;
        err[0] |= kMaybeError;
        return false;
      }
    }
    // Accept boxes a little narrower than the spread the parameters cause (not much tighter is
    // possible), so that a wide parameter box does not cost width / epsilon boxes.
    SolveOptions opt;
    opt.epsilon = std::max(epsilon_, 0.01 * width(args));
    opt.threads = 1;
    opt.limits.max_boxes = 20000;
    FreeParameters params{free_, Box(args.begin(), args.end())};
    const int unknown[] = {bound_};
    const SolveResult r = solve(constraint_, unknown, Box{domain_}, opt, params);
    if (r.boxes.empty()) {
      out[0] = Interval::empty();
      err[0] |= kCertainError;
      return false;
    }
    Interval h = Interval::empty();
    for (const SolutionBox& b : r.boxes) h = hull(h, b.box[0]);
    const Interval margin(-epsilon_, epsilon_);
    out[0] = intersect(h + margin, domain_);
    bool continuous = false;
    if (!r.complete() || !bracketed(args, &continuous)) {
      err[0] |= kMaybeError;
      return false;
    }
    const bool one_root = (r.components.size() == 1 && r.components[0].unique) || monotone(args);
    return continuous && one_root;
  }

  // True if F changes sign strictly between the domain's ends for every parameter value in
  // `args`, and F cannot fail anywhere on domain x args; *continuous says whether F is also
  // continuous there (no jump).
  bool bracketed(std::span<const Interval> args, bool* continuous) const {
    IntervalEvaluator ev;
    std::vector<Interval> box(inputs_.size());
    std::copy(args.begin(), args.end(), box.begin() + 1);
    box[0] = domain_;
    ev.eval(*tape_, box);
    if (ev.errors()[0] != kNoError) return false;
    *continuous = ev.continuous();
    box[0] = Interval(domain_.lo());
    const Interval lo = ev.eval(*tape_, box)[0];
    box[0] = Interval(domain_.hi());
    const Interval hi = ev.eval(*tape_, box)[0];
    return (lo.hi() < 0.0 && hi.lo() > 0.0) || (lo.lo() > 0.0 && hi.hi() < 0.0);
  }

  // True if dF/dt excludes 0 on domain x args (F strictly monotone in t: at most one root).
  bool monotone(std::span<const Interval> args) const {
    IntervalEvaluator ev;
    std::vector<Interval> box(inputs_.size());
    std::copy(args.begin(), args.end(), box.begin() + 1);
    box[0] = domain_;
    const Interval d = ev.eval(*dt_tape_, box)[0];
    return ev.errors()[0] == kNoError && !d.is_empty() && !d.contains_zero();
  }

  int bound_;               // the scratch coordinate standing for t inside F
  std::vector<int> free_;   // the free coordinates = the operator's arguments, ascending
  std::vector<int> inputs_; // {bound_, free_...}: the input order of tape_ and partials_
  Interval domain_;
  double epsilon_;
  std::shared_ptr<const Tape> tape_;  // F(t, free)
  std::shared_ptr<const Tape> invert_tape_, match_tape_;  // its two terms, for point evaluation
  std::shared_ptr<const Tape> dt_tape_;  // dF/dt(t, free): the monotonicity test
  std::vector<Fn> partials_;          // dR/d free_k as functions of (t, free)
  Fn constraint_;                     // F == 0
};

}  // namespace

Fn inverse(const Fn& invert, const Fn& match, int parameter, Interval domain, double epsilon) {
  const std::string who = "genmod: inverse: ";
  if (invert.dim() != 1)
    throw std::invalid_argument(who + "invert must be scalar, got dimension " + std::to_string(invert.dim()));
  if (match.dim() != 1)
    throw std::invalid_argument(who + "match must be scalar, got dimension " + std::to_string(match.dim()));
  if (parameter < 0 || parameter >= kMaxInputs)
    throw std::invalid_argument(who + "parameter " + std::to_string(parameter) + " is outside [0, " +
                                std::to_string(kMaxInputs) + ")");
  if (domain.is_empty() || !domain.is_bounded() || !(domain.lo() < domain.hi()))
    throw std::invalid_argument(who + "the domain must be a bounded interval with lo < hi");
  if (!(epsilon > 0.0) || !std::isfinite(epsilon))
    throw std::invalid_argument(who + "epsilon must be finite and > 0, got " + std::to_string(epsilon));
  const std::uint64_t pbit = std::uint64_t{1} << parameter;
  if (!(invert.input_mask() & pbit))
    throw std::invalid_argument(who + "invert does not depend on x(" + std::to_string(parameter) + ")");
  const std::uint64_t used = invert.input_mask() | match.input_mask();
  int scratch = -1;  // a coordinate no operand uses stands for the bound t inside F
  for (int i = kMaxInputs - 1; i >= 0 && scratch < 0; --i)
    if (!(used & (std::uint64_t{1} << i))) scratch = i;
  if (scratch < 0) throw std::invalid_argument(who + "all coordinates are in use; none is left for the bound variable");
  const std::uint64_t free_mask = (invert.input_mask() & ~pbit) | match.input_mask();
  std::vector<int> free;
  for (int i = 0; i < kMaxInputs; ++i)
    if (free_mask & (std::uint64_t{1} << i)) free.push_back(i);
  auto op = std::make_shared<const InverseOp>(compose(invert, parameter, x(scratch)), match, scratch, free, domain,
                                              epsilon);
  std::vector<Fn> args;
  for (int c : free) args.push_back(x(c));
  return apply_custom(op, args);
}

}  // namespace genmod
