#include "genmod/operators/integrate.hpp"

#include "genmod/kernel/custom_op.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Arguments: (lower, upper, x(free[0]), x(free[1]), ...). The integrand is compiled with
// inputs (parameter, free...), so the bound variable is input 0.
class IntegrateOp final : public CustomOp {
 public:
  IntegrateOp(Fn integrand, int parameter, std::vector<int> free, IntegrateOptions options)
      : integrand_(std::move(integrand)), parameter_(parameter), free_(std::move(free)), options_(options),
        tape_(integrand_, inputs()), partials_(free_.size()) {}

  std::string name() const override { return "integrate"; }
  int num_args() const override { return static_cast<int>(free_.size()) + 2; }
  int num_outputs() const override { return static_cast<int>(integrand_.dim()); }

  void eval(std::span<const double> args, std::span<double> out) const override {
    const std::size_t m = out.size();
    std::fill(out.begin(), out.end(), kNaN);
    for (double a : args)
      if (std::isnan(a)) return;
    const double a = args[0], b = args[1];
    if (a == b) {
      std::fill(out.begin(), out.end(), 0.0);
      return;
    }
    PointEvaluator ev;
    std::vector<double> point(args.size() - 1);
    std::copy(args.begin() + 2, args.end(), point.begin() + 1);
    double scale = 0.0;  // max |f| over the samples so far
    bool error = false;
    auto f = [&](double t, std::vector<double>& sum, double weight) {
      point[0] = t;
      const auto v = ev.eval(tape_, point);
      for (std::size_t j = 0; j < m; ++j) {
        if (std::isnan(v[j])) error = true;
        scale = std::max(scale, std::abs(v[j]));
        sum[j] += weight * v[j];
      }
    };
    const int levels = options_.max_levels;
    // rows[i][j] = R(i, j): trapezoid with 2^i intervals, j Richardson steps; kept two rows.
    std::vector<std::vector<double>> prev(static_cast<std::size_t>(levels) + 1, std::vector<double>(m)),
        cur = prev;
    const double h0 = b - a;
    std::vector<double> ends(m, 0.0);
    f(a, ends, 1.0);
    f(b, ends, 1.0);
    for (std::size_t j = 0; j < m; ++j) prev[0][j] = 0.5 * h0 * ends[j];
    std::vector<double> mids(m);
    int done = 0;  // the last completed level: prev holds its row
    for (int i = 1; i <= levels; ++i) {
      const double count = std::ldexp(1.0, i - 1);  // new midpoints at this level
      const double h = h0 / std::ldexp(1.0, i);
      std::fill(mids.begin(), mids.end(), 0.0);
      for (double k = 0; k < count; k += 1.0) f(a + (2.0 * k + 1.0) * h, mids, 1.0);
      if (error) return;
      for (std::size_t j = 0; j < m; ++j) cur[0][j] = 0.5 * prev[0][j] + h * mids[j];
      double factor = 1.0;
      for (int r = 1; r <= i; ++r) {
        factor *= 4.0;
        const std::size_t ru = static_cast<std::size_t>(r);
        for (std::size_t j = 0; j < m; ++j)
          cur[ru][j] = cur[ru - 1][j] + (cur[ru - 1][j] - prev[ru - 1][j]) / (factor - 1.0);
      }
      const std::size_t iu = static_cast<std::size_t>(i);
      double change = 0.0;
      for (std::size_t j = 0; j < m; ++j) change = std::max(change, std::abs(cur[iu][j] - prev[iu - 1][j]));
      std::swap(prev, cur);
      done = i;
      if (i >= options_.min_levels && change <= options_.tolerance * std::abs(h0) * scale) break;
    }
    for (std::size_t j = 0; j < m; ++j) out[j] = prev[static_cast<std::size_t>(done)][j];
  }

  void inclusion(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const override {
    enclose(args, out, err);
  }

  // Continuous where the integrand is: if f is continuous on [a, b] x P (the pieces below
  // cover it), the integral is continuous in the limits (|f| is bounded) and in P (f is
  // uniformly continuous there). An integrand that may jump gives no claim.
  bool inclusion_continuous(std::span<const Interval> args, std::span<Interval> out,
                            std::span<std::uint8_t> err) const override {
    return enclose(args, out, err);
  }

  Fn derivative(std::span<const Fn> args, int k) const override { return leibniz(args, k); }

 private:
  // The inclusion; returns whether the integrand was continuous on every piece.
  bool enclose(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const {
    const std::size_t m = out.size();
    for (const Interval& a : args)
      if (a.is_empty()) {
        std::fill(out.begin(), out.end(), Interval::empty());
        return false;
      }
    const Interval lower = args[0], upper = args[1];
    if (!lower.is_bounded() || !upper.is_bounded()) {
      std::fill(out.begin(), out.end(), Interval::entire());
      return false;
    }
    bool continuous = true;
    IntervalEvaluator ev;
    std::vector<Interval> box(args.size() - 1);
    std::copy(args.begin() + 2, args.end(), box.begin() + 1);
    double magnitude = 0.0;
    // F over [lo, hi] of the bound variable, or-ing the error bits into err.
    auto f = [&](double lo, double hi, std::vector<Interval>& value) {
      box[0] = Interval(lo, hi);
      const auto v = ev.eval(tape_, box);
      continuous = continuous && ev.continuous();
      for (std::size_t j = 0; j < m; ++j) {
        value[j] = v[j];
        err[j] |= ev.errors()[j];
        magnitude = std::max({magnitude, std::abs(v[j].lo()), std::abs(v[j].hi())});
      }
    };
    const double a = std::min(lower.lo(), upper.lo());
    std::vector<Interval> g_upper(m), g_lower(m), value(m);
    // G(Y) for Y with lo Y >= a, accumulated into g.
    auto enclose_g = [&](const Interval& y, std::vector<Interval>& g) {
      std::fill(g.begin(), g.end(), Interval(0.0));
      const double end = y.lo();
      if (end > a) {
        const int n = options_.pieces;
        double t0 = a;
        for (int i = 1; i <= n; ++i) {
          const double t1 = i == n ? end : std::min(end, a + (end - a) * (static_cast<double>(i) / n));
          if (t1 > t0) {
            f(t0, t1, value);
            const Interval width = Interval(t1) - Interval(t0);
            for (std::size_t j = 0; j < m; ++j) g[j] = g[j] + width * value[j];
          }
          t0 = std::max(t0, t1);
        }
      }
      if (y.hi() > y.lo()) {
        f(y.lo(), y.hi(), value);
        const Interval tail(0.0, (Interval(y.hi()) - Interval(y.lo())).hi());
        for (std::size_t j = 0; j < m; ++j) g[j] = g[j] + tail * value[j];
      }
    };
    enclose_g(upper, g_upper);
    enclose_g(lower, g_lower);
    const double span = std::max(upper.hi(), lower.hi()) - a;
    const double pad = 4.0 * options_.tolerance * span * magnitude + std::numeric_limits<double>::denorm_min();
    for (std::size_t j = 0; j < m; ++j) {
      const Interval r = g_upper[j] - g_lower[j];
      if (r.is_empty() || !r.is_bounded() || !std::isfinite(pad)) {
        out[j] = r.is_empty() ? r : Interval::entire();
        continuous = false;
        continue;
      }
      out[j] = r + Interval(-pad, pad);
    }
    return continuous;
  }

  // The Leibniz rule (see the header).
  Fn leibniz(std::span<const Fn> args, int k) const {
    if (k < 2) {
      // Leibniz: the integrand at the limit, with the other arguments substituted.
      std::vector<Fn> at;
      at.push_back(args[static_cast<std::size_t>(k)]);
      for (std::size_t i = 2; i < args.size(); ++i) at.push_back(args[i]);
      const std::vector<int> in = inputs();
      const Fn value = compose_all(integrand_, in, cat(at));
      return k == 0 ? -value : value;
    }
    const std::size_t j = static_cast<std::size_t>(k - 2);
    std::shared_ptr<const IntegrateOp> partial;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!partials_[j])
        partials_[j] = std::make_shared<IntegrateOp>(genmod::derivative(integrand_, free_[j]), parameter_, free_, options_);
      partial = partials_[j];
    }
    return genmod::apply_custom(std::shared_ptr<const CustomOp>(partial), args);
  }

 private:
  std::vector<int> inputs() const {
    std::vector<int> in{parameter_};
    in.insert(in.end(), free_.begin(), free_.end());
    return in;
  }

  Fn integrand_;
  int parameter_;
  std::vector<int> free_;
  IntegrateOptions options_;
  Tape tape_;
  mutable std::mutex mutex_;
  mutable std::vector<std::shared_ptr<const IntegrateOp>> partials_;
};

}  // namespace

Fn integrate(const Fn& integrand, const Fn& lower, const Fn& upper, int parameter, const IntegrateOptions& options) {
  if (parameter < 0 || parameter >= kMaxInputs)
    throw std::invalid_argument("genmod: integrate: parameter " + std::to_string(parameter) + " is not a coordinate");
  if (lower.dim() != 1 || upper.dim() != 1)
    throw std::invalid_argument("genmod: integrate: the limits must be scalar (dimensions " + std::to_string(lower.dim()) +
                                " and " + std::to_string(upper.dim()) + ")");
  if (!(options.tolerance > 0.0) || options.min_levels < 1 || options.max_levels < options.min_levels ||
      options.max_levels > 30 || options.pieces < 1)
    throw std::invalid_argument("genmod: integrate: bad options");
  std::vector<int> free;
  for (int i : integrand.inputs())
    if (i != parameter) free.push_back(i);
  auto op = std::make_shared<IntegrateOp>(integrand, parameter, free, options);
  std::vector<Fn> args{lower, upper};
  for (int i : free) args.push_back(x(i));
  return genmod::apply_custom(std::shared_ptr<const CustomOp>(op), args);
}

}  // namespace genmod
