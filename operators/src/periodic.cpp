#include "genmod/operators/periodic.hpp"

#include "genmod/kernel/custom_op.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod {
namespace {

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("genmod: periodic: " + what); }

// An evaluator of this thread's, lent for one call: evaluators keep their buffers, so reusing
// them saves the allocations a fresh one makes on every call (they were a third of the time
// of meshing a surface through this operator). One per nesting level: c may itself contain a
// periodic operator, which borrows another while this one is lent.
template <class Evaluator>
class Borrowed {
 public:
  Borrowed() {
    std::vector<std::unique_ptr<Evaluator>>& spare = pool();
    if (spare.empty()) {
      ev_ = std::make_unique<Evaluator>();
    } else {
      ev_ = std::move(spare.back());
      spare.pop_back();
    }
  }
  ~Borrowed() { pool().push_back(std::move(ev_)); }
  Borrowed(const Borrowed&) = delete;
  Borrowed& operator=(const Borrowed&) = delete;
  Evaluator* operator->() const noexcept { return ev_.get(); }

 private:
  static std::vector<std::unique_ptr<Evaluator>>& pool() {
    thread_local std::vector<std::unique_ptr<Evaluator>> spare;
    return spare;
  }
  std::unique_ptr<Evaluator> ev_;
};

class PeriodicOp final : public CustomOp, public std::enable_shared_from_this<PeriodicOp> {
 public:
  PeriodicOp(Fn curve, int parm) : curve_(std::move(curve)), parm_(parm), tape_(curve_, std::vector<int>{parm}) {
    PointEvaluator ev;
    const std::span<const double> at0 = ev.eval(tape_, {0.0});
    const std::vector<double> start(at0.begin(), at0.end());
    const std::span<const double> end = ev.eval(tape_, {1.0});
    seamless_ = std::equal(start.begin(), start.end(), end.begin());
  }

  std::string name() const override { return "periodic"; }
  int num_args() const override { return 1; }
  int num_outputs() const override { return static_cast<int>(curve_.dim()); }

  void eval(std::span<const double> args, std::span<double> out) const override {
    const double s = args[0];
    if (!std::isfinite(s)) {
      std::fill(out.begin(), out.end(), std::numeric_limits<double>::quiet_NaN());
      return;
    }
    const double t = s - std::floor(s);  // exact, in [0, 1)
    const Borrowed<PointEvaluator> ev;
    const std::span<const double> c = ev->eval(tape_, {t});
    std::copy(c.begin(), c.end(), out.begin());
  }

  void inclusion(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const override {
    enclose(args[0], out, err);
  }

  bool inclusion_continuous(std::span<const Interval> args, std::span<Interval> out,
                            std::span<std::uint8_t> err) const override {
    return enclose(args[0], out, err);
  }

  // d/ds c(s - floor(s)) = c'(s - floor(s)) away from the integers, and c' is closed where c
  // is smooth across its seam; where it is not, the hull of the pieces still encloses both
  // one-sided derivatives, which is what mean-value forms need of a continuous function.
  Fn derivative(std::span<const Fn> args, int) const override {
    std::call_once(derivative_once_, [&] {
      derivative_op_ = std::make_shared<const PeriodicOp>(genmod::derivative(curve_, parm_), parm_);
    });
    return apply_custom(derivative_op_, args);
  }

 private:
  // Encloses c(s - floor(s)) over s, splitting at the integers inside; true when the result is
  // continuous on s: c's tape is continuous on every piece and, where s crosses an integer,
  // c(0) and c(1) evaluate to the same doubles (a curve closed only to rounding jumps there).
  bool enclose(const Interval& s, std::span<Interval> out, std::span<std::uint8_t> err) const {
    if (s.is_empty()) {
      std::fill(out.begin(), out.end(), Interval::empty());
      return true;
    }
    // The pieces of [0, 1] that s - floor(s) covers. x - floor(x) is exact for every double,
    // and so are the pieces' ends.
    std::array<Interval, 2> pieces;
    std::size_t count = 1;
    const double k = std::floor(s.lo());
    if (!s.is_bounded() || s.hi() - k >= 2.0) {
      pieces[0] = Interval(0.0, 1.0);
    } else if (s.hi() < k + 1.0) {  // at s = k + 1 the value is c(0), the next period's
      pieces[0] = Interval(s.lo() - k, s.hi() - k);
    } else {
      pieces[0] = Interval(s.lo() - k, 1.0);
      pieces[1] = Interval(0.0, s.hi() - (k + 1.0));
      count = 2;
    }
    const std::uint8_t error = s.is_bounded() ? kNoError : kMaybeError;  // no value at s = +-inf
    const bool crosses_seam = !s.is_bounded() || s.hi() >= k + 1.0;
    bool continuous = !crosses_seam || seamless_;
    const Borrowed<IntervalEvaluator> ev;
    for (std::size_t p = 0; p < count; ++p) {
      const std::span<const Interval> c = ev->eval(tape_, {pieces[p]});
      for (std::size_t j = 0; j < out.size(); ++j) {
        out[j] = p == 0 ? c[j] : hull(out[j], c[j]);
        err[j] |= ev->errors()[j] | error;
      }
      continuous = continuous && ev->continuous();
    }
    return continuous && error == kNoError;
  }

  Fn curve_;
  int parm_;
  Tape tape_;
  bool seamless_ = false;  // c(0) == c(1) as evaluated: continuous across the integers
  mutable std::once_flag derivative_once_;
  mutable std::shared_ptr<const PeriodicOp> derivative_op_;
};

}  // namespace

Fn periodic(const Fn& c, int parm, const Fn& s) {
  if (parm < 0 || parm >= kMaxInputs)
    fail("parameter " + std::to_string(parm) + " is outside [0, " + std::to_string(kMaxInputs) + ")");
  if (s.dim() != 1) fail("the argument s must be scalar, got dimension " + std::to_string(s.dim()));
  if (c.input_mask() != (std::uint64_t{1} << parm))
    fail("the curve must depend on x(" + std::to_string(parm) + ") and on no other coordinate");
  if (!is_closed_curve(c, parm)) fail("the curve is not closed: c(0) and c(1) differ (or are not finite)");
  return apply_custom(std::make_shared<const PeriodicOp>(c, parm), {s});
}

bool is_closed_curve(const Fn& c, int parm) {
  if (parm < 0 || parm >= kMaxInputs || c.input_mask() != (std::uint64_t{1} << parm)) return false;
  const Tape tape(c, std::vector<int>{parm});
  PointEvaluator ev;
  const std::span<const double> at0 = ev.eval(tape, {0.0});
  const std::vector<double> a(at0.begin(), at0.end());
  const std::span<const double> b = ev.eval(tape, {1.0});
  double size = 1.0, gap = 0.0;
  for (std::size_t j = 0; j < a.size(); ++j) {
    if (!std::isfinite(a[j]) || !std::isfinite(b[j])) return false;
    size = std::max({size, std::abs(a[j]), std::abs(b[j])});
    gap = std::max(gap, std::abs(a[j] - b[j]));
  }
  return gap <= 1e-12 * size;
}

}  // namespace genmod
