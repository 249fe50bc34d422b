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
// fa and fb are f(a) and f(b) when the caller knows them, else NaN.
template <class F>
double brent(F&& f, double a, double b, double tol, double fa = kNaN, double fb = kNaN) {
  if (std::isnan(fa)) fa = f(a);
  if (std::isnan(fb)) fb = f(b);
  if (std::isnan(fa) || std::isnan(fb)) return kNaN;
  if (fa == 0.0) return a;
  if (fb == 0.0) return b;
  if ((fa > 0.0) == (fb > 0.0)) return kNaN;
  double c = b, fc = fb, d = b - a, e = d;
  for (int iter = 0; iter < 2000; ++iter) {  // converges in at most ~log2(width / tol)^2 steps
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
    if (invert_t.input_mask() == (std::uint64_t{1} << bound_)) describe_invert_on_domain();
  }

  std::string name() const override { return "inverse"; }
  int num_args() const override { return static_cast<int>(free_.size()); }
  int num_outputs() const override { return 1; }

  void eval(std::span<const double> args, std::span<double> out) const override { out[0] = root(args); }

  // Brent's root of F at one parameter value (NaN when not bracketed).
  double root(std::span<const double> args) const {
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
    const Bracket br = bracket(match);
    return brent(f, br.a, br.b, epsilon_, br.fa, br.fb);
  }

  // Where Brent's method starts for the value m: with a table of invert's values (invert
  // depends on t alone), the table cell whose end values straddle m, found by bisection of the
  // table, with F's values there (the same evaluation as Brent's, bitwise: they have opposite
  // signs, as Brent requires); else the whole domain. A value outside the table's range is
  // left to Brent on the whole domain (no bracket: NaN).
  struct Bracket {
    double a, b;
    double fa = kNaN, fb = kNaN;  // F(a) and F(b) if known
  };
  Bracket bracket(double m) const {
    const std::size_t n = table_t_.size();
    if (n < 2) return {domain_.lo(), domain_.hi()};
    // below(k): F(t_k) < 0 for increasing values, > 0 for decreasing ones.
    const bool increasing = table_g_.back() > table_g_.front();
    auto below = [&](std::size_t k) { return increasing ? table_g_[k] < m : table_g_[k] > m; };
    if (!below(0) || below(n - 1)) return {domain_.lo(), domain_.hi()};
    std::size_t lo = 0, hi = n - 1;  // below(lo), !below(hi)
    while (hi - lo > 1) {
      const std::size_t mid = lo + (hi - lo) / 2;
      (below(mid) ? lo : hi) = mid;
    }
    return {table_t_[lo], table_t_[hi], table_g_[lo] - m, table_g_[hi] - m};
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
    // Accept enclosures a little narrower than the spread the parameters cause (not much
    // tighter is possible), so that a wide parameter box does not cost width / epsilon boxes.
    const double tolerance = std::max(epsilon_, 0.01 * width(args));
    if (separable_direction_ != 0) return enclose_separable(args, out, err);
    if (const int direction = monotone(args)) return enclose_monotone(args, direction, tolerance, out, err);
    SolveOptions opt;
    opt.epsilon = tolerance;
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
    out[0] = widen_to_point_values(h);
    bool continuous = false;
    if (!r.complete() || !bracketed(args, &continuous)) {
      err[0] |= kMaybeError;
      return false;
    }
    const bool one_root = r.components.size() == 1 && r.components[0].unique;
    return continuous && one_root;
  }

  // F strictly monotone in t on domain x args (direction +1 increasing, -1 decreasing): for
  // every parameter value the root, if any, lies between the last t where F is certainly below
  // zero for the whole box and the first t where it is certainly above (for increasing F),
  // found with interval evaluations at single values of t. match does
  // not depend on t, so its enclosure over the box is computed once and subtracted (sound:
  // F(t, p) = invert(t, p) - match(p) lies in invert(t, P) - match(P)). This replaces a
  // constraint solve per box by a few evaluations of invert.
  bool enclose_monotone(std::span<const Interval> args, int direction, double tolerance, std::span<Interval> out,
                        std::span<std::uint8_t> err) const {
    IntervalEvaluator ev;
    std::vector<Interval> box(inputs_.size());
    std::copy(args.begin(), args.end(), box.begin() + 1);
    box[0] = domain_;
    const Interval match = ev.eval(*match_tape_, box)[0];
    const bool match_ok = ev.errors()[0] == kNoError && !match.is_empty();
    const bool match_continuous = ev.continuous();
    // G(t) = direction * F(t, P), increasing in t; sign(t) is -1 (certainly < 0), +1
    // (certainly > 0) or 0 (unknown, or F may fail).
    auto sign = [&](double t) {
      if (!match_ok) return 0;
      box[0] = Interval(t);
      const Interval v = ev.eval(*invert_tape_, box)[0];
      if (ev.errors()[0] != kNoError || v.is_empty()) return 0;
      const Interval g = (v - match) * static_cast<double>(direction);
      return g.hi() < 0.0 ? -1 : (g.lo() > 0.0 ? 1 : 0);
    };
    const int at_lo = sign(domain_.lo()), at_hi = sign(domain_.hi());
    if (at_hi == -1 || at_lo == 1) {  // G has one sign on the whole domain: no root anywhere
      out[0] = Interval::empty();
      err[0] |= kCertainError;
      return false;
    }
    // Search outward from the root at the box's centre (the roots of the other parameter
    // values lie around it): steps that double from the tolerance until G has the wanted sign,
    // then bisection back to within the tolerance. A point box costs two evaluations.
    std::vector<double> centre(args.size());
    for (std::size_t i = 0; i < args.size(); ++i) centre[i] = args[i].mid();
    double guess = root(centre);
    if (!(guess >= domain_.lo() && guess <= domain_.hi())) guess = domain_.mid();
    // The nearest t found beyond the roots in direction dir (-1 down, +1 up) where G has the
    // sign `want` for the whole box, or the domain's end there (which has it).
    auto bound = [&](int want, double dir) {
      const double end = dir < 0 ? domain_.lo() : domain_.hi();
      double ok = end, fail = guess;
      for (double step = tolerance;; step *= 2.0) {
        const double t = guess + dir * step;
        if (dir < 0 ? t <= end : t >= end) break;
        if (sign(t) == want) {
          ok = t;
          break;
        }
        fail = t;
      }
      while (std::abs(fail - ok) > tolerance) {
        const double mid = 0.5 * (ok + fail);
        if (mid == ok || mid == fail) break;
        (sign(mid) == want ? ok : fail) = mid;
      }
      return ok;
    };
    const double below = at_lo == -1 ? bound(-1, -1.0) : domain_.lo();
    const double above = at_hi == 1 ? bound(1, 1.0) : domain_.hi();
    out[0] = widen_to_point_values(Interval(below, above));
    // Every parameter value is bracketed (one root, hence a point value) when G is certainly
    // negative at the domain's start and positive at its end, and F cannot fail on the box.
    box[0] = domain_;
    ev.eval(*invert_tape_, box);
    if (!(at_lo == -1 && at_hi == 1 && ev.errors()[0] == kNoError)) {
      err[0] |= kMaybeError;
      return false;
    }
    return match_continuous && ev.continuous();
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

  // invert depends on t alone (every schedule: a curve component matched against a value):
  // its monotonicity, its values at the domain's ends and whether it can fail or jump on the
  // domain do not depend on the box, so they are found once, here. Leaves
  // separable_direction_ at 0 (the general paths) unless dg/dt is certainly nonzero.
  void describe_invert_on_domain() {
    IntervalEvaluator ev;
    std::vector<Interval> box(inputs_.size(), Interval(0.0));
    box[0] = domain_;
    ev.eval(*invert_tape_, box);
    if (ev.errors()[0] != kNoError) return;
    invert_continuous_ = ev.continuous();
    box[0] = Interval(domain_.lo());
    invert_at_lo_ = ev.eval(*invert_tape_, box)[0];
    box[0] = Interval(domain_.hi());
    invert_at_hi_ = ev.eval(*invert_tape_, box)[0];
    box[0] = domain_;
    const Interval d = ev.eval(*dt_tape_, box)[0];
    if (ev.errors()[0] != kNoError || d.is_empty()) return;
    separable_direction_ = d.lo() > 0.0 ? 1 : (d.hi() < 0.0 ? -1 : 0);
    if (separable_direction_ == 0) return;
    // invert's point values at evenly spaced t: Brent then starts from one cell of the table
    // (a few steps) instead of the whole domain (a dozen or more), at every point and box.
    PointEvaluator pev;
    std::vector<double> point(inputs_.size(), 0.0);
    for (int k = 0; k <= kTableCells; ++k) {
      point[0] = k == kTableCells ? domain_.hi() : domain_.lo() + (domain_.hi() - domain_.lo()) * k / kTableCells;
      const double g = pev.eval(*invert_tape_, point)[0];
      if (std::isnan(g)) {  // cannot happen for a certified monotone invert; stay general
        table_t_.clear();
        table_g_.clear();
        return;
      }
      table_t_.push_back(point[0]);
      table_g_.push_back(g);
    }
  }

  // F = g(t) - match with g strictly monotone on the domain: the roots for match values in
  // M = match(P) run from g^-1 of M's one end to g^-1 of its other. Each is found by Brent's
  // method at that value and certified by an interval evaluation of g a little beyond it (the
  // step doubles from epsilon until g is certainly past the end of M): two point solves and
  // about two interval evaluations of g per box, however wide the box.
  bool enclose_separable(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const {
    const int direction = separable_direction_;
    IntervalEvaluator ev;
    std::vector<Interval> box(inputs_.size());
    std::copy(args.begin(), args.end(), box.begin() + 1);
    box[0] = domain_;
    const Interval match = ev.eval(*match_tape_, box)[0];
    const bool match_continuous = ev.continuous();
    if (match.is_empty()) {  // match certainly fails: so does F
      out[0] = Interval::empty();
      err[0] |= kCertainError;
      return false;
    }
    if (ev.errors()[0] != kNoError || !match.is_bounded()) {
      out[0] = domain_;
      err[0] |= kMaybeError;
      return false;
    }
    // G(t) = direction (g(t) - M), increasing; its sign for the whole box (0: unknown).
    auto sign_of = [&](const Interval& g) {
      const Interval v = (g - match) * static_cast<double>(direction);
      return v.hi() < 0.0 ? -1 : (v.lo() > 0.0 ? 1 : 0);
    };
    auto sign = [&](double t) {
      box[0] = Interval(t);
      const Interval g = ev.eval(*invert_tape_, box)[0];
      return ev.errors()[0] != kNoError || g.is_empty() ? 0 : sign_of(g);
    };
    const int at_lo = sign_of(invert_at_lo_), at_hi = sign_of(invert_at_hi_);
    if (at_hi == -1 || at_lo == 1) {  // G has one sign on the whole domain: no root anywhere
      out[0] = Interval::empty();
      err[0] |= kCertainError;
      return false;
    }
    PointEvaluator pev;
    std::vector<double> point(inputs_.size(), 0.0);
    // The root for match value m, then the nearest t beyond it in direction dir where G has
    // the sign `want` (or the domain's end there, where it has).
    auto bound = [&](double m, int want, double dir) {
      const double end = dir < 0 ? domain_.lo() : domain_.hi();
      auto f = [&](double t) {
        point[0] = t;
        return pev.eval(*invert_tape_, point)[0] - m;
      };
      const Bracket br = bracket(m);
      double start = brent(f, br.a, br.b, epsilon_, br.fa, br.fb);
      if (std::isnan(start)) return end;
      for (double step = epsilon_;; step *= 2.0) {
        const double t = start + dir * step;
        if (dir < 0 ? t <= end : t >= end) return end;
        if (sign(t) == want) return t;
      }
    };
    // For increasing g the smallest root is g^-1(M.lo); for decreasing g, g^-1(M.hi).
    const double m_first = direction > 0 ? match.lo() : match.hi();
    const double m_last = direction > 0 ? match.hi() : match.lo();
    const double below = at_lo == -1 ? bound(m_first, -1, -1.0) : domain_.lo();
    const double above = at_hi == 1 ? bound(m_last, 1, 1.0) : domain_.hi();
    out[0] = widen_to_point_values(Interval(below, above));
    if (!(at_lo == -1 && at_hi == 1)) {  // some parameter values may not be bracketed
      err[0] |= kMaybeError;
      return false;
    }
    return invert_continuous_ && match_continuous;
  }

  // Roots -> the point values near them: Brent's result b ends within its final bracket of a
  // root, of width at most epsilon + 4 DBL_EPSILON |b|; clipped to the domain it stays in.
  Interval widen_to_point_values(const Interval& roots) const {
    const double reach = std::max(std::abs(domain_.lo()), std::abs(domain_.hi()));
    const double margin = epsilon_ + 8.0 * std::numeric_limits<double>::epsilon() * reach;
    return intersect(roots + Interval(-margin, margin), domain_);
  }

  // +1 or -1 if dF/dt is certainly positive or negative on domain x args (F strictly monotone
  // in t: at most one root), else 0.
  int monotone(std::span<const Interval> args) const {
    IntervalEvaluator ev;
    std::vector<Interval> box(inputs_.size());
    std::copy(args.begin(), args.end(), box.begin() + 1);
    box[0] = domain_;
    const Interval d = ev.eval(*dt_tape_, box)[0];
    if (ev.errors()[0] != kNoError || d.is_empty()) return 0;
    return d.lo() > 0.0 ? 1 : (d.hi() < 0.0 ? -1 : 0);
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
  // When invert depends on t alone (describe_invert_on_domain): +1 / -1 if it is certainly
  // increasing / decreasing on the domain, else 0; its enclosures at the domain's ends; and
  // whether it is continuous there (it cannot fail there, or the direction stays 0).
  int separable_direction_ = 0;
  static constexpr int kTableCells = 256;
  std::vector<double> table_t_, table_g_;  // invert's point values at t_k (separable only)
  Interval invert_at_lo_, invert_at_hi_;
  bool invert_continuous_ = false;
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
  if (invert.input_mask() == pbit) {
    // invert depends on t alone: the operator takes match's value as its one argument, so
    // the surrounding tape computes match once (shared with the rest of the function)
    // instead of the operator evaluating a copy of it on every call. Inside the operator,
    // x(0) stands for t and x(1) for the value to match.
    auto op = std::make_shared<const InverseOp>(compose(invert, parameter, x(0)), x(1), 0, std::vector<int>{1},
                                                domain, epsilon);
    return apply_custom(op, {match});
  }
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
