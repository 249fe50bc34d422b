// Algorithm 5.2 of snyder.md section 4.13: best-first branch and bound with a verified upper
// bound, the monotonicity test of section 4.15 and the termination rules of section 4.14.
#include "genmod/solvers/minimizer.hpp"
#include "genmod/solvers/minimizer_detail.hpp"

#include "genmod/kernel/interval_evaluator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace genmod {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

enum class Feasibility { No, Yes, Maybe };

struct Entry {
  double key;          // lower bound of the objective over the box (never below the parent's)
  std::uint64_t seq;   // insertion order: ties are broken deterministically
  int depth;
  Box box;
  Interval f;                   // enclosure of the objective over the box
  std::vector<Interval> grad;   // enclosure of the gradient (empty if unavailable)
  bool accepted_by_width = false;
};

// Min-heap order on (key, seq).
struct Later {
  bool operator()(const Entry& a, const Entry& b) const noexcept {
    return a.key > b.key || (a.key == b.key && a.seq > b.seq);
  }
};

void validate(const Fn& objective, const Fn& constraint, std::span<const int> unknowns, const Box& box,
              const MinimizeOptions& opt) {
  const std::string who = "genmod::minimize";
  if (objective.dim() != 1)
    throw std::invalid_argument(who + ": the objective must be scalar, it has dimension " +
                                std::to_string(objective.dim()));
  if (constraint.dim() != 1)
    throw std::invalid_argument(who + ": the constraint must be scalar (0/1 valued), it has dimension " +
                                std::to_string(constraint.dim()));
  if (unknowns.empty()) throw std::invalid_argument(who + ": no unknowns");
  std::uint64_t mask = 0;
  for (int u : unknowns) {
    if (u < 0 || u >= kMaxInputs)
      throw std::invalid_argument(who + ": unknown x(" + std::to_string(u) + ") is out of range [0, " +
                                  std::to_string(kMaxInputs) + ")");
    const std::uint64_t bit = std::uint64_t{1} << u;
    if (mask & bit) throw std::invalid_argument(who + ": unknown x(" + std::to_string(u) + ") is listed twice");
    mask |= bit;
  }
  for (int i : objective.inputs())
    if (!(mask & (std::uint64_t{1} << i)))
      throw std::invalid_argument(who + ": the objective depends on x(" + std::to_string(i) +
                                  "), which is not among the unknowns");
  for (int i : constraint.inputs())
    if (!(mask & (std::uint64_t{1} << i)))
      throw std::invalid_argument(who + ": the constraint depends on x(" + std::to_string(i) +
                                  "), which is not among the unknowns");
  check_search_box(box, unknowns.size(), "minimize");
  if (!(opt.epsilon > 0.0) || !std::isfinite(opt.epsilon))
    throw std::invalid_argument(who + ": epsilon (box width tolerance) must be finite and > 0, got " +
                                std::to_string(opt.epsilon));
  if (!(opt.delta > 0.0) || !std::isfinite(opt.delta))
    throw std::invalid_argument(who + ": delta (bracket width target) must be finite and > 0, got " +
                                std::to_string(opt.delta));
  if (!(opt.equality_tolerance >= 0.0) || !std::isfinite(opt.equality_tolerance))
    throw std::invalid_argument(who + ": equality_tolerance must be finite and >= 0, got " +
                                std::to_string(opt.equality_tolerance));
  if (opt.limits.max_depth < 0) throw std::invalid_argument(who + ": limits.max_depth must be >= 0");
  if (!(opt.limits.time_limit >= 0.0))
    throw std::invalid_argument(who + ": limits.time_limit must be >= 0 (0 = none)");
}

class Search {
 public:
  Search(const Fn& objective, const Fn& constraint, std::span<const int> unknowns, const Box& box,
         const MinimizeOptions& opt, bool value_only)
      : opt_(opt),
        value_only_(value_only),
        root_(box),
        inclusion_(objective, unknowns),
        c_(opt.equality_tolerance > 0.0 ? relax_equalities(constraint, opt.equality_tolerance) : constraint,
           unknowns),
        trivially_feasible_(constraint.is_constant(&constant_) && constant_ != 0.0 && constant_ == constant_) {
    // Exact equalities (no relaxation): certified boxes holding feasible points give u.
    if (opt.equality_tolerance == 0.0 && !trivially_feasible_) {
      certifier_.emplace(constraint, unknowns);
      if (!certifier_->active()) certifier_.reset();
    }
    if (opt_.local_search) {
      std::optional<Tape> residual_tape;
      if (auto r = minimizer_detail::constraint_residuals(constraint)) residual_tape.emplace(*r, unknowns);
      local_.emplace(inclusion_.tape(), c_, std::move(residual_tape), box);
    }
  }

  MinimizeResult run();

 private:
  struct Bounds {
    Interval f;
    std::vector<Interval> grad;
    bool empty = false;     // the objective fails everywhere on the box
    bool no_error = false;  // the objective is defined everywhere on the box
  };

  Feasibility constraint_on(std::span<const Interval> box);
  Bounds bound_objective(std::span<const Interval> box);
  void try_point(std::span<const double> q);
  // Rule 1 for exact equalities: a sub-box of `box` certified to hold a feasible point.
  void try_certified(std::span<const Interval> box);
  void push(Box box, int depth, double parent_key, const Interval& parent_f);
  Entry pop();
  double lower_bound() const;
  bool limit_reached();
  void step_callback();
  bool splittable(const Entry& e) const;
  // The monotonicity test; returns false if the entry is discarded (reduced entries are
  // pushed back and also return false).
  bool monotonicity_test(Entry& e);

  const MinimizeOptions& opt_;
  const bool value_only_;
  const Box root_;
  InclusionFunction inclusion_;
  Tape c_;
  double constant_ = 0.0;
  const bool trivially_feasible_;
  IntervalEvaluator ev_;
  std::optional<minimizer_detail::LocalSearch> local_;
  std::optional<minimizer_detail::FeasiblePointCertifier> certifier_;

  std::vector<Entry> heap_;
  std::vector<Entry> candidates_;
  double candidate_min_ = kInf;
  std::uint64_t seq_ = 0;
  double u_ = kInf;
  std::vector<double> best_;
  MinimizeResult result_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

Feasibility Search::constraint_on(std::span<const Interval> box) {
  if (trivially_feasible_) return Feasibility::Yes;
  const Interval c = ev_.eval(c_, box)[0];
  const std::uint8_t err = ev_.errors()[0];
  if (c.is_empty() || err == kCertainError || (c.lo() == 0.0 && c.hi() == 0.0)) return Feasibility::No;
  if (err == kNoError && !c.contains_zero()) return Feasibility::Yes;
  return Feasibility::Maybe;
}

Search::Bounds Search::bound_objective(std::span<const Interval> box) {
  Bounds b;
  // The gradient enclosure is wanted by the monotonicity test even when the forms are off.
  const bool want_grad = (opt_.inclusion_forms & (kMeanValueForm | kMonotonicityForm)) || opt_.monotonicity_test;
  b.f = inclusion_.eval(box, opt_.inclusion_forms, want_grad ? &b.grad : nullptr)[0];
  const std::uint8_t err = inclusion_.errors()[0];
  if (b.f.is_empty() || err == kCertainError) {
    b.empty = true;
    b.grad.clear();
    return b;
  }
  b.no_error = err == kNoError;
  return b;
}

// Rule 1 of the u update: a point proven feasible, with the objective bounded rigorously there.
void Search::try_point(std::span<const double> q) {
  std::vector<Interval> point(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (!std::isfinite(q[i]) || !root_[i].contains(q[i])) return;
    point[i] = Interval(q[i]);
  }
  if (constraint_on(point) != Feasibility::Yes) return;
  const Interval fq = ev_.eval(inclusion_.tape(), point)[0];
  if (ev_.errors()[0] != kNoError || fq.is_empty()) return;
  if (fq.hi() < u_) {
    u_ = fq.hi();
    best_.assign(q.begin(), q.end());
  }
}

// B holds a point x with constraint(x) true (FeasiblePointCertifier), so f* <= f(x) <= sup f(B).
void Search::try_certified(std::span<const Interval> box) {
  const std::optional<Box> b = certifier_->find(box);
  if (!b) return;
  ++result_.certified_points;
  const Interval fb = ev_.eval(inclusion_.tape(), *b)[0];
  if (ev_.errors()[0] != kNoError || fb.is_empty()) return;
  if (fb.hi() < u_) {
    u_ = fb.hi();
    best_ = midpoint(*b);
  }
}

void Search::push(Box box, int depth, double parent_key, const Interval& parent_f) {
  const Feasibility feasible = constraint_on(box);
  if (feasible == Feasibility::No) return;
  Bounds b = bound_objective(box);
  if (b.empty) return;
  Interval f = intersect(b.f, parent_f);
  if (f.is_empty()) f = b.f;
  const double key = std::max(f.lo(), parent_key);
  if (key > u_) return;
  // Rule 2: the whole box is feasible, so any of its points bounds the minimum by ub f(box).
  if (feasible == Feasibility::Yes && b.no_error && f.hi() < u_) {
    u_ = f.hi();
    best_ = midpoint(box);
  }
  try_point(midpoint(box));
  if (certifier_ && feasible == Feasibility::Maybe) try_certified(box);
  Entry e{key, seq_++, depth, std::move(box), f, std::move(b.grad), false};
  heap_.push_back(std::move(e));
  std::push_heap(heap_.begin(), heap_.end(), Later{});
}

Entry Search::pop() {
  std::pop_heap(heap_.begin(), heap_.end(), Later{});
  Entry e = std::move(heap_.back());
  heap_.pop_back();
  return e;
}

double Search::lower_bound() const {
  double l = candidate_min_;
  if (!heap_.empty()) l = std::min(l, heap_.front().key);
  return l;
}

bool Search::limit_reached() {
  SearchReport& r = result_.report;
  if (r.boxes_processed >= opt_.limits.max_boxes) {
    if (r.limit == LimitHit::None) r.limit = LimitHit::MaxBoxes;
    return true;
  }
  if (opt_.limits.time_limit > 0.0 && (r.boxes_processed % 16 == 0)) {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (s >= opt_.limits.time_limit) {
      if (r.limit == LimitHit::None) r.limit = LimitHit::TimeLimit;
      return true;
    }
  }
  return false;
}

void Search::step_callback() {
  if (!opt_.on_step) return;
  MinimizeStep s;
  s.iteration = result_.report.boxes_processed;
  s.lower = lower_bound();
  s.upper = u_;
  s.list_size = heap_.size();
  s.candidates = candidates_.size();
  opt_.on_step(s);
}

bool Search::splittable(const Entry& e) const {
  const std::size_t j = widest_side(e.box);
  const Interval& side = e.box[j];
  const double m = side.mid();
  return side.lo() < m && m < side.hi();
}

bool Search::monotonicity_test(Entry& e) {
  if (e.grad.empty()) return true;
  const std::size_t n = e.box.size();
  bool any = false;
  for (std::size_t j = 0; j < n; ++j)
    if (!e.box[j].is_point() && !e.grad[j].contains_zero()) any = true;
  if (!any) return true;
  // The constraint must hold on a neighbourhood of the box (strict satisfaction, so no
  // constraint is active on the box's faces): check it on the box widened by one ulp.
  if (!trivially_feasible_) {
    Box wide(e.box);
    for (Interval& s : wide)
      s = Interval::unchecked(interval_detail::next_down(s.lo()), interval_detail::next_up(s.hi()));
    if (constraint_on(wide) != Feasibility::Yes) return true;
  }
  bool reduced = false;
  for (std::size_t j = 0; j < n; ++j) {
    const Interval& d = e.grad[j];
    if (e.box[j].is_point() || d.contains_zero()) continue;
    const bool increasing = d.lo() > 0.0;
    const double face = increasing ? e.box[j].lo() : e.box[j].hi();
    const double edge = increasing ? root_[j].lo() : root_[j].hi();
    if (face != edge) {  // the smaller face is inside the search box: no minimizer in the box
      ++result_.monotone_discards;
      return false;
    }
    e.box[j] = Interval(face);
    reduced = true;
  }
  if (reduced) {
    ++result_.monotone_reductions;
    push(std::move(e.box), e.depth, e.key, e.f);
    return false;
  }
  return true;
}

MinimizeResult Search::run() {
  push(root_, 0, -kInf, Interval::entire());
  SearchReport& report = result_.report;
  bool stopped = false;
  while (true) {
    while (!heap_.empty()) {
      if (value_only_ && u_ - lower_bound() <= opt_.delta) {
        stopped = true;
        break;
      }
      if (limit_reached()) {
        stopped = true;
        break;
      }
      Entry e = pop();
      if (e.key > u_) continue;  // purged: its lower bound exceeds a verified value
      ++report.boxes_processed;
      report.deepest = std::max(report.deepest, e.depth);
      if (local_ && (report.boxes_processed <= 4 || report.boxes_processed % 32 == 0)) {
        ++result_.local_searches;
        const std::vector<double> q = local_->run(midpoint(e.box));
        try_point(q);
        if (certifier_ && q.size() == root_.size()) {  // a small box around the local minimum
          Box around(q.size());
          bool inside = true;
          for (std::size_t i = 0; i < q.size(); ++i) {
            const double r = 1e-7 * (1.0 + std::abs(q[i]));
            around[i] = intersect(Interval(q[i] - r, q[i] + r), root_[i]);
            inside = inside && std::isfinite(q[i]) && !around[i].is_empty();
          }
          if (inside) try_certified(around);
        }
      }
      if (opt_.monotonicity_test && !monotonicity_test(e)) {
        step_callback();
        continue;
      }
      const bool small = width(e.box) <= opt_.epsilon;
      if (small && (!std::isfinite(u_) || e.key >= u_ - opt_.delta)) {
        e.accepted_by_width = true;
      } else if (!splittable(e)) {
        e.accepted_by_width = false;
      } else if (e.depth >= opt_.limits.max_depth) {
        if (report.limit == LimitHit::None) report.limit = LimitHit::MaxDepth;
      } else {
        auto [a, b] = bisect(e.box, widest_side(e.box));
        push(std::move(a), e.depth + 1, e.key, e.f);
        push(std::move(b), e.depth + 1, e.key, e.f);
        step_callback();
        continue;
      }
      candidate_min_ = std::min(candidate_min_, e.key);
      candidates_.push_back(std::move(e));
      step_callback();
    }
    if (stopped) break;
    // Candidates accepted before u was known may keep the bracket wider than delta: split
    // them further now that u is finite.
    if (!std::isfinite(u_) || value_only_) break;
    bool requeued = false;
    std::vector<Entry> keep;
    for (Entry& c : candidates_) {
      if (c.accepted_by_width && c.key < u_ - opt_.delta && c.key <= u_ && splittable(c) &&
          c.depth < opt_.limits.max_depth) {
        c.accepted_by_width = false;
        heap_.push_back(std::move(c));
        std::push_heap(heap_.begin(), heap_.end(), Later{});
        requeued = true;
      } else {
        c.accepted_by_width = false;  // never requeue twice: it passed the test with the current u
        keep.push_back(std::move(c));
      }
    }
    candidates_ = std::move(keep);
    if (!requeued) break;
  }
  // Boxes still waiting (a limit, or the value-only stop) stay candidates: nothing is dropped.
  for (Entry& e : heap_) candidates_.push_back(std::move(e));
  heap_.clear();
  std::erase_if(candidates_, [&](const Entry& c) { return c.key > u_; });
  std::sort(candidates_.begin(), candidates_.end(),
            [](const Entry& a, const Entry& b) { return a.key < b.key || (a.key == b.key && a.seq < b.seq); });

  double lo = kInf;
  for (const Entry& c : candidates_) lo = std::min(lo, c.key);
  if (candidates_.empty()) {
    result_.infeasible = !std::isfinite(u_);
    // A verified feasible point exists but every box was purged: cannot happen with sound
    // bounds; keep the point's value as a degenerate bracket rather than lose it.
    result_.minimum = std::isfinite(u_) ? Interval(u_, u_) : Interval::empty();
  } else {
    lo = std::min(lo, u_);
    result_.minimum = Interval::unchecked(lo, u_);
  }
  for (Entry& c : candidates_) {
    result_.candidate_lower_bounds.push_back(c.key);
    result_.candidates.push_back(std::move(c.box));
  }
  result_.feasible_found = std::isfinite(u_);
  result_.best_point = best_;
  result_.delta_reached = result_.feasible_found && !result_.minimum.is_empty() &&
                          result_.minimum.hi() - result_.minimum.lo() <= opt_.delta;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return std::move(result_);
}

}  // namespace

MinimizeResult minimize(const Fn& objective, const Fn& constraint, std::span<const int> unknowns, const Box& box,
                        const MinimizeOptions& options) {
  validate(objective, constraint, unknowns, box, options);
  return Search(objective, constraint, unknowns, box, options, false).run();
}

MinimizeResult minimize_value(const Fn& objective, const Fn& constraint, std::span<const int> unknowns,
                              const Box& box, const MinimizeOptions& options) {
  validate(objective, constraint, unknowns, box, options);
  return Search(objective, constraint, unknowns, box, options, true).run();
}

Interval minimum_value(const Fn& objective, const Fn& constraint, std::span<const int> unknowns, const Box& box,
                       const MinimizeOptions& options) {
  return minimize_value(objective, constraint, unknowns, box, options).minimum;
}

}  // namespace genmod
