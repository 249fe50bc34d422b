// Algorithm 5.2 of snyder.md section 4.13: best-first branch and bound with a verified upper
// bound, the monotonicity test of section 4.15 and the termination rules of section 4.14.
#include "genmod/solvers/minimizer.hpp"
#include "minimizer_detail.hpp"

#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/solvers/constraint_system.hpp"
#include "genmod/solvers/contractor.hpp"

#include <Eigen/Dense>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace genmod {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

enum class Feasibility { No, Yes, Maybe };

// The evaluators a box's bounds need; one per child of a split, so that the two children of
// a box are bounded in parallel.
struct Worker {
  IntervalEvaluator ev;
  InclusionFunction inclusion;                 // the objective
  std::optional<Hc4Contractor> hc4;            // the constraint's contractor
  std::optional<InclusionFunction> lagrangian;
  std::optional<minimizer_detail::FeasiblePointCertifier> certifier;
};

// A child box bounded (by a Worker) but not yet in the list: committing it in a fixed order
// applies the u updates exactly as bounding the children one after the other would.
struct Child {
  bool alive = false;   // survived contraction, feasibility and the objective's bounds
  Box box;
  Interval f;
  std::vector<Interval> grad;
  double key = 0.0;
  Feasibility feasible = Feasibility::Maybe;
  bool no_error = false;
  std::optional<double> point_value;      // rule 1 at the midpoint: sup f there, if feasible
  bool certified = false;                 // rule 3: a certified feasible sub-box was found
  std::vector<double> certified_point;
  std::optional<double> certified_value;  // sup f over that sub-box, if defined
};

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
  if (opt.threads < 0) throw std::invalid_argument(who + ": threads must be >= 0 (0 = oneTBB's default), got " +
                                                   std::to_string(opt.threads));
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
    if (!trivially_feasible_) {
      system_.emplace(opt.equality_tolerance > 0.0 ? relax_equalities(constraint, opt.equality_tolerance) : constraint,
                      unknowns);
      build_lagrangian(objective, unknowns);
    }
    Worker w{IntervalEvaluator(), inclusion_, {}, lagrangian_, {}};
    if (system_) w.hc4.emplace(*system_);
    // Exact equalities (no relaxation): certified boxes holding feasible points give u.
    if (opt.equality_tolerance == 0.0 && !trivially_feasible_) {
      w.certifier.emplace(constraint, unknowns);
      if (!w.certifier->active()) w.certifier.reset();
    }
    workers_.assign(2, w);
    if (opt_.local_search) {
      std::optional<Tape> residual_tape;
      if (auto r = minimizer_detail::constraint_residuals(constraint)) residual_tape.emplace(*r, unknowns);
      local_.emplace(inclusion_.tape(), c_, std::move(residual_tape), box);
    }
    if (opt.threads != 1) {
      // (Not a conditional expression: that would bind a reference to task_arena::automatic,
      // which oneTBB declares but does not define out of line.)
      int concurrency = opt.threads;
      if (concurrency == 0) concurrency = tbb::task_arena::automatic;
      arena_.emplace(concurrency);
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

  Feasibility constraint_on(Worker& w, std::span<const Interval> box);
  // The Lagrangian lower bound: for multipliers lambda (>= 0 for inequalities g <= 0, any
  // sign for equalities g = 0), f(x) >= L(x) = f(x) + sum lambda_i g_i(x) at every feasible x,
  // so inf L over a box bounds f over its feasible points from below, whatever lambda is.
  // With lambda near the KKT multipliers of the best point, L is flat there and its mean
  // value form is second order: boxes at the minimizer need not shrink to width delta.
  void build_lagrangian(const Fn& objective, std::span<const int> unknowns);
  void update_multipliers();
  // The constraints active at a point (equalities, and inequalities within 1e-3 of 0), from
  // the kkt_ values there, and least-squares multipliers for them (inequalities clipped at 0).
  std::vector<std::size_t> active_constraints(std::span<const double> kkt_values) const;
  std::vector<double> multipliers_for(std::span<const double> kkt_values, std::span<const std::size_t> active) const;
  // Newton's method on the KKT conditions of the constraints active at q (see the definition).
  std::optional<std::vector<double>> kkt_point(std::span<const double> q);
  // Offers verified points at and just inside the KKT point near q.
  void try_kkt_point(std::span<const double> q);
  double lagrangian_bound(Worker& w, std::span<const Interval> box);
  Bounds bound_objective(Worker& w, std::span<const Interval> box);
  // sup f at q when q is proven feasible and f is defined there.
  std::optional<double> point_value(Worker& w, std::span<const double> q);
  void try_point(std::span<const double> q);
  // Rule 3 for exact equalities: a sub-box of `box` certified to hold a feasible point.
  void certify_in(Worker& w, std::span<const Interval> box, Child& c);
  void try_certified(std::span<const Interval> box);
  // try_certified on a small box around q (exact equalities).
  void try_certified_around(std::span<const double> q);
  void offer(double value, std::vector<double> point);
  // Bounds a child of a box; u_before is u at the start of the split (u only decreases).
  Child bound_child(Worker& w, Box box, double parent_key, const Interval& parent_f, double u_before);
  void commit(Child&& c, int depth);
  void push(Box box, int depth, double parent_key, const Interval& parent_f);
  void push_children(Box a, Box b, int depth, double parent_key, const Interval& parent_f);
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
  std::vector<Worker> workers_;   // [0] for the serial steps; [0] and [1] bound split children
  std::optional<tbb::task_arena> arena_;
  std::optional<minimizer_detail::LocalSearch> local_;
  std::optional<ConstraintSystem> system_;  // the constraint (relaxed if eta > 0); the workers' HC4 refers to it
  // Lagrangian: g_i of the top-level conjuncts (g <= 0 or g = 0), multipliers as extra inputs.
  std::vector<Fn> g_;
  std::vector<std::uint8_t> g_equality_;
  std::optional<InclusionFunction> lagrangian_;
  std::optional<Tape> kkt_;       // g_i, grad f, grad g_i at a point (over the unknowns)
  std::optional<Tape> kkt_system_;  // grad_x L, g_i over (unknowns, multipliers): Newton's system
  GradientEvaluator kkt_jacobian_;
  std::vector<double> lambda_;    // current multipliers (all 0: no bound)
  bool multipliers_stale_ = false;
  PointEvaluator pe_;

  std::vector<Entry> heap_;
  std::vector<Entry> candidates_;
  double candidate_min_ = kInf;
  std::uint64_t seq_ = 0;
  double u_ = kInf;
  std::vector<double> best_;
  MinimizeResult result_;
  LimitWatch watch_{opt_.limits};
};

Feasibility Search::constraint_on(Worker& w, std::span<const Interval> box) {
  if (trivially_feasible_) return Feasibility::Yes;
  const Interval c = w.ev.eval(c_, box)[0];
  const std::uint8_t err = w.ev.errors()[0];
  if (c.is_empty() || err == kCertainError || (c.lo() == 0.0 && c.hi() == 0.0)) return Feasibility::No;
  if (err == kNoError && !c.contains_zero()) return Feasibility::Yes;
  return Feasibility::Maybe;
}

void Search::build_lagrangian(const Fn& objective, std::span<const int> unknowns) {
  if (!system_->is_conjunction()) return;
  for (const ConstraintSystem::Conjunct& c : system_->conjuncts()) {
    const Fn& h = system_->atoms()[c.atom].h;
    switch (c.rel) {
      case Relation::Le:
      case Relation::Lt: g_.push_back(h), g_equality_.push_back(0); break;
      case Relation::Ge:
      case Relation::Gt: g_.push_back(-h), g_equality_.push_back(0); break;
      case Relation::Eq: g_.push_back(h), g_equality_.push_back(1); break;
      default: break;  // != and "nonzero" give no bound
    }
  }
  if (g_.empty()) return;
  // Multipliers live in coordinates the problem does not use.
  std::uint64_t used = objective.input_mask() | system_->atoms()[0].h.input_mask();
  for (int u : unknowns) used |= std::uint64_t{1} << u;
  for (const Fn& g : g_) used |= g.input_mask();
  std::vector<int> inputs(unknowns.begin(), unknowns.end());
  Fn l = objective;
  for (int i = kMaxInputs - 1; i >= 0 && inputs.size() < unknowns.size() + g_.size(); --i) {
    if (used & (std::uint64_t{1} << i)) continue;
    l = l + x(i) * g_[inputs.size() - unknowns.size()];
    inputs.push_back(i);
  }
  if (inputs.size() != unknowns.size() + g_.size()) {
    g_.clear();
    return;
  }
  try {
    std::vector<Fn> parts(g_.begin(), g_.end());
    for (int u : unknowns) parts.push_back(derivative(objective, u));
    for (const Fn& g : g_)
      for (int u : unknowns) parts.push_back(derivative(g, u));
    kkt_.emplace(cat(parts), unknowns);
    lagrangian_.emplace(l, inputs);
    std::vector<Fn> system;
    for (int u : unknowns) system.push_back(derivative(l, u));
    system.insert(system.end(), g_.begin(), g_.end());
    kkt_system_.emplace(cat(system), inputs);
  } catch (const std::exception&) {  // no derivative: no Lagrangian bound
    g_.clear();
    kkt_.reset();
    kkt_system_.reset();
    lagrangian_.reset();
    return;
  }
  lambda_.assign(g_.size(), 0.0);
}

// Least squares grad f + sum lambda_i grad g_i = 0 over the constraints active at the best
// point (inequality multipliers clipped at 0). Not rigorous, and it need not be: any lambda of
// the right signs gives a valid bound.
void Search::update_multipliers() {
  multipliers_stale_ = false;
  if (!lagrangian_ || best_.empty()) return;
  const auto v = pe_.eval(*kkt_, best_);
  lambda_ = multipliers_for(v, active_constraints(v));
}

std::vector<std::size_t> Search::active_constraints(std::span<const double> v) const {
  std::vector<std::size_t> active;
  for (std::size_t i = 0; i < g_.size(); ++i)
    if (g_equality_[i] || (std::isfinite(v[i]) && v[i] >= -1e-3)) active.push_back(i);
  return active;
}

std::vector<double> Search::multipliers_for(std::span<const double> v, std::span<const std::size_t> active) const {
  const std::size_t n = root_.size(), m = g_.size();
  std::vector<double> lambda(m, 0.0);
  if (active.empty()) return lambda;
  Eigen::MatrixXd a(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(active.size()));
  Eigen::VectorXd b(static_cast<Eigen::Index>(n));
  for (std::size_t j = 0; j < n; ++j) {
    b(static_cast<Eigen::Index>(j)) = -v[m + j];
    for (std::size_t k = 0; k < active.size(); ++k)
      a(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(k)) = v[m + n + active[k] * n + j];
  }
  if (!a.allFinite() || !b.allFinite()) return lambda;
  const Eigen::VectorXd lam = a.colPivHouseholderQr().solve(b);
  for (std::size_t k = 0; k < active.size(); ++k) {
    const double l = lam(static_cast<Eigen::Index>(k));
    if (!std::isfinite(l)) return std::vector<double>(m, 0.0);
    lambda[active[k]] = g_equality_[active[k]] ? l : std::max(l, 0.0);
  }
  return lambda;
}

// Projected descent crawls along active constraints, so the point it returns near a
// constrained minimum can be 1e-3 away, and u that far above f*: every box around the
// minimizer whose bound is below u - delta must then be split. Newton's method on
// grad f + sum_{i in A} lambda_i grad g_i = 0, g_A = 0 (A: the constraints active at q) goes
// from there to the KKT point to machine precision, quadratically. Not rigorous, and it need
// not be: the caller verifies what it offers. Nothing when Newton does not converge, leaves
// the box, or ends with a negative inequality multiplier (then A was wrong).
std::optional<std::vector<double>> Search::kkt_point(std::span<const double> q) {
  if (!kkt_system_ || q.size() != root_.size()) return std::nullopt;
  const std::size_t n = q.size(), m = g_.size();
  const auto v = pe_.eval(*kkt_, q);
  const std::vector<std::size_t> active = active_constraints(v);
  std::vector<double> z(q.begin(), q.end());
  const std::vector<double> lambda = multipliers_for(v, active);
  z.insert(z.end(), lambda.begin(), lambda.end());
  // Unknowns: x and the multipliers of A; equations: grad_x L (n) and g_A.
  std::vector<std::size_t> columns(n), rows(n);
  for (std::size_t j = 0; j < n; ++j) columns[j] = rows[j] = j;
  for (std::size_t i : active) {
    columns.push_back(n + i);
    rows.push_back(n + i);
  }
  const auto k = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXd jac(k, k);
  Eigen::VectorXd r(k);
  for (int iter = 0; iter < 30; ++iter) {
    kkt_jacobian_.eval(*kkt_system_, z);
    const auto values = kkt_jacobian_.values();
    const auto jv = kkt_jacobian_.jacobian();
    for (Eigen::Index a = 0; a < k; ++a) {
      r(a) = values[rows[static_cast<std::size_t>(a)]];
      for (Eigen::Index b = 0; b < k; ++b)
        jac(a, b) = jv[rows[static_cast<std::size_t>(a)] * (n + m) + columns[static_cast<std::size_t>(b)]];
    }
    if (!r.allFinite() || !jac.allFinite()) return std::nullopt;
    const Eigen::VectorXd step = jac.fullPivLu().solve(-r);
    if (!step.allFinite()) return std::nullopt;
    double size = 0.0, scale = 1.0;
    for (Eigen::Index b = 0; b < k; ++b) {
      double& zb = z[columns[static_cast<std::size_t>(b)]];
      zb += step(b);
      size = std::max(size, std::abs(step(b)));
      scale = std::max(scale, std::abs(zb));
    }
    if (size > 1e-14 * scale) continue;
    for (std::size_t i : active)
      if (!g_equality_[i] && z[n + i] < 0.0) return std::nullopt;
    z.resize(n);
    for (std::size_t j = 0; j < n; ++j)
      if (!root_[j].contains(z[j])) return std::nullopt;
    return z;
  }
  return std::nullopt;
}

// The KKT point itself is on its active inequalities, where no interval evaluation can prove
// g <= 0 (or g < 0) true; points a few ulps to 1e-7 inside, along -grad g of the active
// inequalities, can be, at a cost of that distance times |grad f| in u.
void Search::try_kkt_point(std::span<const double> q) {
  const std::optional<std::vector<double>> p = kkt_point(q);
  if (!p) return;
  const std::size_t n = p->size(), m = g_.size();
  const auto v = pe_.eval(*kkt_, *p);
  std::vector<double> inward(n, 0.0);
  double scale = 1.0;
  for (std::size_t j = 0; j < n; ++j) scale = std::max(scale, std::abs((*p)[j]));
  for (std::size_t i : active_constraints(v)) {
    if (g_equality_[i]) continue;
    double norm = 0.0;
    for (std::size_t j = 0; j < n; ++j) norm += v[m + n + i * n + j] * v[m + n + i * n + j];
    norm = std::sqrt(norm);
    if (!(norm > 0.0) || !std::isfinite(norm)) continue;
    for (std::size_t j = 0; j < n; ++j) inward[j] -= v[m + n + i * n + j] / norm;
  }
  try_point(*p);
  for (double t : {1e-14, 1e-12, 1e-10, 1e-8, 1e-7}) {
    std::vector<double> inside(*p);
    for (std::size_t j = 0; j < n; ++j) inside[j] += t * scale * inward[j];
    const std::optional<double> value = point_value(workers_[0], inside);
    if (!value) continue;
    offer(*value, std::move(inside));
    break;
  }
  if (workers_[0].certifier) try_certified_around(*p);
}

double Search::lagrangian_bound(Worker& w, std::span<const Interval> box) {
  if (!w.lagrangian || std::all_of(lambda_.begin(), lambda_.end(), [](double l) { return l == 0.0; })) return -kInf;
  std::vector<Interval> in(box.begin(), box.end());
  for (double l : lambda_) in.emplace_back(l);
  const Interval v = w.lagrangian->eval(in, opt_.inclusion_forms)[0];
  // Points where L fails are points where f or some g_i fails: not feasible.
  if (v.is_empty()) return -kInf;
  return v.lo();
}

Search::Bounds Search::bound_objective(Worker& w, std::span<const Interval> box) {
  Bounds b;
  // The gradient enclosure is wanted by the monotonicity test even when the forms are off.
  const bool want_grad = (opt_.inclusion_forms & (kMeanValueForm | kMonotonicityForm)) || opt_.monotonicity_test;
  b.f = w.inclusion.eval(box, opt_.inclusion_forms, want_grad ? &b.grad : nullptr)[0];
  const std::uint8_t err = w.inclusion.errors()[0];
  if (b.f.is_empty() || err == kCertainError) {
    b.empty = true;
    b.grad.clear();
    return b;
  }
  b.no_error = err == kNoError;
  return b;
}

// Rule 1 of the u update: a point proven feasible, with the objective bounded rigorously there.
std::optional<double> Search::point_value(Worker& w, std::span<const double> q) {
  std::vector<Interval> point(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (!std::isfinite(q[i]) || !root_[i].contains(q[i])) return std::nullopt;
    point[i] = Interval(q[i]);
  }
  if (constraint_on(w, point) != Feasibility::Yes) return std::nullopt;
  const Interval fq = w.ev.eval(inclusion_.tape(), point)[0];
  if (w.ev.errors()[0] != kNoError || fq.is_empty()) return std::nullopt;
  return fq.hi();
}

void Search::offer(double value, std::vector<double> point) {
  if (value < u_) {
    u_ = value;
    best_ = std::move(point);
    multipliers_stale_ = true;
  }
}

void Search::try_point(std::span<const double> q) {
  if (const std::optional<double> v = point_value(workers_[0], q)) offer(*v, {q.begin(), q.end()});
}

// B holds a point x with constraint(x) true (FeasiblePointCertifier), so f* <= f(x) <= sup f(B).
void Search::certify_in(Worker& w, std::span<const Interval> box, Child& c) {
  const std::optional<Box> b = w.certifier->find(box);
  if (!b) return;
  c.certified = true;
  c.certified_point = midpoint(*b);
  const Interval fb = w.ev.eval(inclusion_.tape(), *b)[0];
  if (w.ev.errors()[0] == kNoError && !fb.is_empty()) c.certified_value = fb.hi();
}

void Search::try_certified(std::span<const Interval> box) {
  Child c;
  certify_in(workers_[0], box, c);
  if (!c.certified) return;
  ++result_.certified_points;
  if (c.certified_value) offer(*c.certified_value, std::move(c.certified_point));
}

void Search::try_certified_around(std::span<const double> q) {
  if (q.size() != root_.size()) return;
  Box around(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (!std::isfinite(q[i])) return;
    const double r = 1e-7 * (1.0 + std::abs(q[i]));
    around[i] = intersect(Interval(q[i] - r, q[i] + r), root_[i]);
    if (around[i].is_empty()) return;
  }
  try_certified(around);
}

Child Search::bound_child(Worker& w, Box box, double parent_key, const Interval& parent_f, double u_before) {
  Child c;
  // Contract with the constraint first (HC4 removes only infeasible points, so every minimizer
  // stays in the box): tighter objective bounds, and infeasible boxes die early.
  if (w.hc4) {
    for (int pass = 0; pass < 4; ++pass) {
      const double w0 = width(box);
      if (!w.hc4->contract(box)) return c;
      if (!(width(box) < 0.9 * w0)) break;
    }
  }
  c.feasible = constraint_on(w, box);
  if (c.feasible == Feasibility::No) return c;
  Bounds b = bound_objective(w, box);
  if (b.empty) return c;
  c.f = intersect(b.f, parent_f);
  if (c.f.is_empty()) c.f = b.f;
  c.key = std::max({c.f.lo(), parent_key, lagrangian_bound(w, box)});
  c.alive = true;
  c.no_error = b.no_error;
  c.grad = std::move(b.grad);
  if (c.key <= u_before) {  // else commit() drops it: u never grows
    c.point_value = point_value(w, midpoint(box));
    if (w.certifier && c.feasible == Feasibility::Maybe) certify_in(w, box, c);
  }
  c.box = std::move(box);
  return c;
}

void Search::commit(Child&& c, int depth) {
  if (!c.alive || c.key > u_) return;
  // Rule 2: the whole box is feasible, so any of its points bounds the minimum by ub f(box).
  if (c.feasible == Feasibility::Yes && c.no_error) offer(c.f.hi(), midpoint(c.box));
  if (c.point_value) offer(*c.point_value, midpoint(c.box));
  if (c.certified) {
    ++result_.certified_points;
    if (c.certified_value) offer(*c.certified_value, std::move(c.certified_point));
  }
  Entry e{c.key, seq_++, depth, std::move(c.box), c.f, std::move(c.grad), false};
  heap_.push_back(std::move(e));
  std::push_heap(heap_.begin(), heap_.end(), Later{});
}

void Search::push(Box box, int depth, double parent_key, const Interval& parent_f) {
  commit(bound_child(workers_[0], std::move(box), parent_key, parent_f, u_), depth);
}

// Both children bounded at once (one Worker each), then committed in order: the result is
// the same as pushing them one after the other, for any thread count.
void Search::push_children(Box a, Box b, int depth, double parent_key, const Interval& parent_f) {
  const double u_before = u_;
  Child ca, cb;
  auto both = [&] {
    tbb::parallel_invoke([&] { ca = bound_child(workers_[0], std::move(a), parent_key, parent_f, u_before); },
                         [&] { cb = bound_child(workers_[1], std::move(b), parent_key, parent_f, u_before); });
  };
  if (arena_) arena_->execute(both);
  else {
    ca = bound_child(workers_[0], std::move(a), parent_key, parent_f, u_before);
    cb = bound_child(workers_[1], std::move(b), parent_key, parent_f, u_before);
  }
  commit(std::move(ca), depth);
  commit(std::move(cb), depth);
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
  const LimitHit hit = watch_.reached(r.boxes_processed);
  if (hit == LimitHit::None) return false;
  if (r.limit == LimitHit::None) r.limit = hit;
  return true;
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
    if (constraint_on(workers_[0], wide) != Feasibility::Yes) return true;
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
      if (multipliers_stale_) update_multipliers();
      Entry e = pop();
      if (e.key > u_) continue;  // purged: its lower bound exceeds a verified value
      ++report.boxes_processed;
      report.deepest = std::max(report.deepest, e.depth);
      if (local_ && (report.boxes_processed <= 4 || report.boxes_processed % 32 == 0)) {
        ++result_.local_searches;
        const std::vector<double> q = local_->run(midpoint(e.box));
        try_point(q);
        if (workers_[0].certifier) try_certified_around(q);
        try_kkt_point(q);
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
        push_children(std::move(a), std::move(b), e.depth + 1, e.key, e.f);
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
  report.seconds = watch_.seconds();
  return std::move(result_);
}

}  // namespace

MinimizeResult minimize(const Fn& objective, const Fn& constraint, Coordinates unknowns, const Box& box,
                        const MinimizeOptions& options) {
  validate(objective, constraint, unknowns, box, options);
  return Search(objective, constraint, unknowns, box, options, false).run();
}

MinimizeResult minimize_value(const Fn& objective, const Fn& constraint, Coordinates unknowns,
                              const Box& box, const MinimizeOptions& options) {
  validate(objective, constraint, unknowns, box, options);
  return Search(objective, constraint, unknowns, box, options, true).run();
}

Interval minimum_value(const Fn& objective, const Fn& constraint, Coordinates unknowns, const Box& box,
                       const MinimizeOptions& options) {
  return minimize_value(objective, constraint, unknowns, box, options).minimum;
}

}  // namespace genmod
