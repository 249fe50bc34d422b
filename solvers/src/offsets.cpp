// s-offsets and b-offsets: an outer subdivision of space with inner global minimizations.
#include "genmod/solvers/offsets.hpp"

#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/solvers/minimizer.hpp"

#include <cmath>
#include <deque>
#include <stdexcept>
#include <string>

namespace genmod {
namespace {

struct Pending {
  Box box;
  int depth;
};

class OffsetSearch {
 public:
  OffsetSearch(const Fn& shape, double r, std::span<const Interval> region, std::span<const Interval> domain,
               const OffsetOptions& options, bool region_wanted)
      : options_(options), region_wanted_(region_wanted) {
    if (!(r > 0.0) || !std::isfinite(r)) throw std::invalid_argument("genmod: offset: the radius must be finite and > 0");
    if (!(options.epsilon > 0.0)) throw std::invalid_argument("genmod: offset: epsilon must be > 0");
    n_ = shape.dim();
    const std::vector<int> params = shape.inputs();
    k_ = params.size();
    if (k_ == 0) throw std::invalid_argument("genmod: offset: the shape has no parameters");
    check_search_box(region, n_, "offset (the region of space)");
    domain_.assign(domain.begin(), domain.end());
    if (domain_.empty()) domain_.assign(k_, Interval(0, 1));
    check_search_box(domain_, k_, "offset (the parameter domain)");
    // Parameters become x(0 .. k-1), space coordinates x(k .. k+n-1).
    std::vector<Fn> renamed;
    for (std::size_t i = 0; i < k_; ++i) renamed.push_back(x(static_cast<int>(i)));
    const Fn s = compose_all(shape, params, cat(renamed));
    Fn d2 = 0.0;
    for (std::size_t j = 0; j < n_; ++j) d2 = d2 + square(x(static_cast<int>(k_ + j)) - s[j]);
    distance2_ = d2;
    for (std::size_t i = 0; i < k_ + n_; ++i) all_.push_back(static_cast<int>(i));
    tape_ = std::make_unique<Tape>(distance2_, all_);
    r2_ = Interval(r) * Interval(r);
    region_.assign(region.begin(), region.end());
  }

  OffsetResult run() {
    const LimitWatch watch(options_.limits);
    OffsetResult out;
    std::deque<Pending> work{{region_, 0}};
    while (!work.empty()) {
      const LimitHit hit = watch.reached(out.report.boxes_processed);
      if (hit != LimitHit::None) {
        out.report.limit = hit;
        for (Pending& p : work) out.boxes.push_back({std::move(p.box), OffsetBoxStatus::Boundary});
        break;
      }
      Pending p = std::move(work.front());
      work.pop_front();
      ++out.report.boxes_processed;
      out.report.deepest = std::max(out.report.deepest, p.depth);
      const Interval d2 = bracket(p.box);
      if (d2.lo() > r2_.hi()) continue;  // farther than r everywhere in the box
      if (d2.hi() < r2_.lo()) {          // nearer than r everywhere
        if (region_wanted_) out.boxes.push_back({std::move(p.box), OffsetBoxStatus::Inside});
        continue;
      }
      if (width(p.box) <= options_.epsilon || p.depth >= options_.limits.max_depth) {
        if (p.depth >= options_.limits.max_depth && out.report.limit == LimitHit::None)
          out.report.limit = LimitHit::MaxDepth;
        out.boxes.push_back({std::move(p.box), OffsetBoxStatus::Boundary});
        continue;
      }
      auto [lo, hi] = bisect(p.box, widest_side(p.box));
      work.push_back({std::move(lo), p.depth + 1});
      work.push_back({std::move(hi), p.depth + 1});
    }
    out.report.seconds = watch.seconds();
    return out;
  }

 private:
  // A guaranteed bracket of min over x of |z - S(x)|^2 for z in the box Z.
  Interval bracket(const Box& z) {
    Box joint = domain_;
    joint.insert(joint.end(), z.begin(), z.end());
    // Inner tolerance proportional to the box (section 5.1): the bracket cannot be narrower
    // than the variation of the distance over Z anyway.
    const double w = width(z);
    MinimizeOptions mo;
    mo.epsilon = std::max(0.1 * w, 1e-9);
    mo.delta = std::max(0.1 * w * std::max(w, std::sqrt(r2_.lo())), 1e-12);
    mo.limits = options_.inner_limits;
    const MinimizeResult m = minimize_value(distance2_, Fn(1.0), all_, joint, mo);
    const double lower = std::max(0.0, m.minimum.lo());
    // Upper: any fixed parameter x* bounds the minimum over x from above, for every z at once.
    Box at = z;
    std::vector<Interval> point(domain_.size());
    for (std::size_t i = 0; i < k_; ++i)
      point[i] = Interval(m.feasible_found ? m.best_point[i] : domain_[i].mid());
    point.insert(point.end(), z.begin(), z.end());
    const Interval upper = ev_.eval(*tape_, point)[0];
    return Interval::unchecked(lower, std::max(lower, upper.hi()));
  }

  OffsetOptions options_;
  bool region_wanted_;
  std::size_t n_ = 0, k_ = 0;
  Box domain_, region_;
  Fn distance2_;
  std::vector<int> all_;
  std::unique_ptr<Tape> tape_;
  IntervalEvaluator ev_;
  Interval r2_;
};

}  // namespace

OffsetResult b_offset(const Fn& shape, double r, std::span<const Interval> region, std::span<const Interval> domain,
                      const OffsetOptions& options) {
  return OffsetSearch(shape, r, region, domain, options, false).run();
}

OffsetResult s_offset(const Fn& shape, double r, std::span<const Interval> region, std::span<const Interval> domain,
                      const OffsetOptions& options) {
  return OffsetSearch(shape, r, region, domain, options, true).run();
}

}  // namespace genmod
