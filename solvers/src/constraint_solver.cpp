#include "genmod/solvers/constraint_solver.hpp"

#include "genmod/solvers/constraint_system.hpp"
#include "genmod/solvers/contractor.hpp"
#include "genmod/solvers/interval_newton.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

namespace genmod {

std::string_view status_name(SolutionStatus s) noexcept {
  switch (s) {
    case SolutionStatus::CertifiedUnique: return "certified_unique";
    case SolutionStatus::Possible: return "possible";
    case SolutionStatus::Feasible: return "feasible";
    case SolutionStatus::Boundary: return "boundary";
    case SolutionStatus::Unexplored: return "unexplored";
  }
  return "?";
}

std::size_t SolveResult::box_count(SolutionStatus s) const noexcept {
  return static_cast<std::size_t>(
      std::count_if(boxes.begin(), boxes.end(), [s](const SolutionBox& b) { return b.status == s; }));
}

std::size_t SolveResult::unique_components() const noexcept {
  return static_cast<std::size_t>(
      std::count_if(components.begin(), components.end(), [](const SolutionComponent& c) { return c.unique; }));
}

std::size_t cyclic_next(std::size_t last, std::size_t n) noexcept { return n == 0 ? 0 : (last + 1) % n; }

namespace {

// The problem, shared read-only by all workers.
struct Problem {
  Problem(const Fn& constraint, std::span<const int> unknowns, const FreeParameters& p, const SolveOptions& o)
      : sys(constraint, unknowns, p.coords), params(p.values), opt(o), n(unknowns.size()) {
    // Newton on the top-level equalities when there are at least as many as unknowns.
    std::vector<NodeId> eqs;
    for (const ConstraintSystem::Conjunct& c : sys.conjuncts())
      if (c.rel == Relation::Eq && eqs.size() < n) {
        newton_atoms.push_back(c.atom);
        eqs.push_back(sys.atoms()[c.atom].h.node(0));
      }
    if (o.use_newton && eqs.size() == n) newton.emplace(Fn(eqs), unknowns, p.coords);
    if (o.rule == Subdivision::Smear) {
      std::vector<Fn> parts;
      try {
        for (const ConstraintAtom& a : sys.atoms())
          for (int u : unknowns) parts.push_back(derivative(a.h, u));
        smear.emplace(cat(parts), sys.inputs());
      } catch (const std::exception&) {
        smear.reset();  // no derivative: split the widest side instead
      }
    }
    is_newton_atom.assign(sys.num_atoms(), 0);
    for (std::size_t a : newton_atoms) is_newton_atom[a] = 1;
  }

  ConstraintSystem sys;
  Box params;
  SolveOptions opt;
  std::size_t n;
  std::vector<std::size_t> newton_atoms;
  std::vector<std::uint8_t> is_newton_atom;
  std::optional<IntervalNewton> newton;
  std::optional<Tape> smear;
};

struct Item {
  Box box;  // unknowns only
  std::vector<std::uint8_t> tags;
  int depth = 0;
  std::size_t last_dim = 0;
};

struct Outcome {
  enum Kind : std::uint8_t { Discard, Output, Split } kind = Discard;
  SolutionBox out;
  Item kids[2];
  SolveStats stats;
  bool depth_limited = false;
};

struct Worker {
  explicit Worker(const Problem& p) : hc4(p.sys), newton(p.newton) {}
  IntervalEvaluator ev;
  AtomValues vals;
  Hc4Contractor hc4;
  std::optional<IntervalNewton> newton;
  std::vector<Interval> full;
  std::vector<Truth> forced;
};

void add_stats(SolveStats& a, const SolveStats& b) {
  a.atom_evaluations += b.atom_evaluations;
  a.contractions += b.contractions;
  a.newton_steps += b.newton_steps;
  a.splits += b.splits;
}

// Whether every atom except the Newton equalities is known true (without error), so that a
// unique zero of the equalities is a unique solution of the whole constraint.
bool others_true(const Problem& p, Worker& w) {
  w.forced = w.vals.value;
  for (std::size_t a = 0; a < w.forced.size(); ++a) {
    if (p.is_newton_atom[a])
      w.forced[a] = Truth::True;
    else if (w.vals.error[a] != kNoError)
      return false;
  }
  return p.sys.combine(w.forced) == Truth::True;
}

bool splittable(const Interval& x) {
  const double m = x.mid();
  return x.lo() < m && m < x.hi();
}

std::size_t choose_dim(const Problem& p, Worker& w, const Item& it, std::span<const Interval> box) {
  const std::size_t n = p.n;
  std::size_t dim = widest_side(box);
  if (p.opt.rule == Subdivision::Cyclic) {
    dim = cyclic_next(it.last_dim, n);
    for (std::size_t k = 0; k < n && !splittable(box[dim]); ++k) dim = cyclic_next(dim, n);
  } else if (p.opt.rule == Subdivision::Smear && p.smear) {
    const auto j = w.ev.eval(*p.smear, w.full);
    double best = -1.0;
    std::size_t arg = dim;
    for (std::size_t d = 0; d < n; ++d) {
      if (!splittable(box[d])) continue;
      double s = 0.0;
      for (std::size_t a = 0; a < p.sys.num_atoms(); ++a) {
        if (w.vals.value[a] != Truth::Unknown) continue;
        const Interval& g = j[a * n + d];
        const double mag = g.is_empty() ? 0.0 : std::max(std::abs(g.lo()), std::abs(g.hi()));
        s += mag * box[d].width();
      }
      if (std::isfinite(s) && s > best) {
        best = s;
        arg = d;
      }
    }
    if (best > 0.0) dim = arg;
  }
  return dim;
}

Outcome process(const Problem& p, Worker& w, Item it) {
  Outcome o;
  const SolveOptions& opt = p.opt;
  const std::size_t n = p.n;
  w.full.assign(it.box.begin(), it.box.end());
  w.full.insert(w.full.end(), p.params.begin(), p.params.end());
  std::span<Interval> unknowns(w.full.data(), n);
  bool certified = false;
  auto output = [&](SolutionStatus s) {
    o.kind = Outcome::Output;
    o.out = SolutionBox{Box(unknowns.begin(), unknowns.end()), s, it.depth};
    return o;
  };
  for (int pass = 0;; ++pass) {
    if (!opt.use_tags) std::fill(it.tags.begin(), it.tags.end(), kTagUnknown);
    const Truth t = p.sys.evaluate(w.full, it.tags, w.vals, w.ev, &o.stats.atom_evaluations);
    if (t == Truth::False) return o;
    if (t == Truth::True) {
      // A point that satisfies the constraint is an exact solution, alone in its box.
      const bool point = std::all_of(unknowns.begin(), unknowns.end(), [](const Interval& v) { return v.is_point(); });
      return output(point ? SolutionStatus::CertifiedUnique : SolutionStatus::Feasible);
    }
    if (pass >= opt.max_contractions) break;
    const double w0 = width(unknowns);
    if (opt.use_hc4) {
      ++o.stats.contractions;
      if (!w.hc4.contract(w.full, w.vals.value)) return o;
    }
    certified = false;
    if (w.newton) {
      const NewtonStatus s = w.newton->contract(w.full);
      if (s == NewtonStatus::Empty) return o;
      if (s == NewtonStatus::Contracted) {
        ++o.stats.newton_steps;
        certified = others_true(p, w) && w.newton->certify(w.full);
      }
    }
    const double w1 = width(unknowns);
    if (certified && w1 < opt.epsilon) break;
    if (!(w1 < 0.9 * w0)) break;
  }
  if (certified) return output(SolutionStatus::CertifiedUnique);

  bool equality_open = false, delta_ok = true;
  for (std::size_t a = 0; a < p.sys.num_atoms(); ++a) {
    if (w.vals.value[a] != Truth::Unknown) continue;
    const Relation r = p.sys.atoms()[a].rel;
    if (r == Relation::Eq || r == Relation::Ne || r == Relation::Nonzero) {
      equality_open = true;
      if (r == Relation::Eq && !(w.vals.range[a].width() <= opt.delta)) delta_ok = false;
    }
  }
  const SolutionStatus small = equality_open ? SolutionStatus::Possible : SolutionStatus::Boundary;
  if (width(unknowns) < opt.epsilon && delta_ok) return output(small);
  if (it.depth >= opt.limits.max_depth) {
    // Not accepted, and the limit forbids a split: the box was not explored to the end, like
    // the boxes left on the work list by the other limits.
    o.depth_limited = true;
    return output(SolutionStatus::Unexplored);
  }
  const std::size_t dim = choose_dim(p, w, it, unknowns);
  if (!splittable(unknowns[dim])) return output(small);  // at machine precision
  auto halves = bisect(unknowns, dim);
  ++o.stats.splits;
  o.kind = Outcome::Split;
  o.kids[0] = Item{std::move(halves.first), it.tags, it.depth + 1, dim};
  o.kids[1] = Item{std::move(halves.second), std::move(it.tags), it.depth + 1, dim};
  return o;
}

// The work list in the chosen discipline.
class WorkList {
 public:
  explicit WorkList(Discipline d) : d_(d) {}
  bool empty() const { return items_.empty(); }
  std::size_t size() const { return items_.size(); }
  void push(Item it) {
    if (d_ == Discipline::Priority) {
      heap_.push_back({width(it.box), seq_++, std::move(it)});
      std::push_heap(heap_.begin(), heap_.end(), Less{});
      items_.emplace_back();  // size bookkeeping only
      return;
    }
    items_.push_back(std::move(it));
  }
  Item pop() {
    Item it;
    if (d_ == Discipline::Priority) {
      std::pop_heap(heap_.begin(), heap_.end(), Less{});
      it = std::move(heap_.back().item);
      heap_.pop_back();
      items_.pop_back();
    } else if (d_ == Discipline::Fifo) {
      it = std::move(items_.front());
      items_.pop_front();
    } else {
      it = std::move(items_.back());
      items_.pop_back();
    }
    return it;
  }

 private:
  struct Entry {
    double width;
    std::uint64_t seq;
    Item item;
  };
  struct Less {  // the top is the widest, then the oldest
    bool operator()(const Entry& a, const Entry& b) const {
      return a.width < b.width || (a.width == b.width && a.seq > b.seq);
    }
  };
  Discipline d_;
  std::deque<Item> items_;
  std::vector<Entry> heap_;
  std::uint64_t seq_ = 0;
};

bool lower_corner_less(const SolutionBox& a, const SolutionBox& b) {
  for (std::size_t i = 0; i < a.box.size(); ++i) {
    if (a.box[i].lo() != b.box[i].lo()) return a.box[i].lo() < b.box[i].lo();
  }
  for (std::size_t i = 0; i < a.box.size(); ++i) {
    if (a.box[i].hi() != b.box[i].hi()) return a.box[i].hi() < b.box[i].hi();
  }
  return a.status < b.status;
}

void validate(const Box& box, std::span<const int> unknowns, const SolveOptions& opt, const FreeParameters& params) {
  if (box.size() != unknowns.size())
    throw std::invalid_argument("genmod: solve: the box has " + std::to_string(box.size()) + " sides for " +
                                std::to_string(unknowns.size()) + " unknowns");
  check_search_box(box, unknowns.size(), "solve");
  if (!(opt.epsilon > 0.0))
    throw std::invalid_argument("genmod: solve: epsilon must be > 0, got " + std::to_string(opt.epsilon));
  if (!(opt.delta > 0.0))
    throw std::invalid_argument("genmod: solve: delta must be > 0, got " + std::to_string(opt.delta));
  if (opt.threads < 0) throw std::invalid_argument("genmod: solve: threads must be >= 0");
  if (opt.batch == 0) throw std::invalid_argument("genmod: solve: batch must be >= 1");
  if (opt.max_contractions < 0) throw std::invalid_argument("genmod: solve: max_contractions must be >= 0");
  if (!(opt.limits.time_limit >= 0.0)) throw std::invalid_argument("genmod: solve: time_limit must be >= 0");
  if (params.values.size() != params.coords.size())
    throw std::invalid_argument("genmod: solve: " + std::to_string(params.coords.size()) + " parameter coordinates but " +
                                std::to_string(params.values.size()) + " parameter intervals");
  check_search_box(params.values, params.coords.size(), "solve (parameter values)");
}

// Krawczyk on the component's hull with epsilon-inflation (Rump): a solution may sit on a
// member's face, and a stalled Newton leaves boxes about as wide as their Krawczyk image.
// The trial box is clipped to the search box and must touch no other component: its unique
// zero then lies in a returned box (no solution is lost), which can only be this component's.
bool certify_component(const Problem& p, Worker& w, const Box& search, const std::vector<Aggregate>& groups,
                       std::size_t g) {
  std::vector<std::uint8_t> tags(p.sys.num_atoms(), kTagUnknown);
  Box h = groups[g].hull;
  for (int attempt = 0; attempt < 6; ++attempt) {
    for (std::size_t i = 0; i < h.size(); ++i) {
      const double mag = std::max(std::abs(h[i].lo()), std::abs(h[i].hi()));
      const double r0 = 0.1 * h[i].width() + std::ldexp(mag, -40) + 1e-300;
      h[i] = intersect(Interval(h[i].lo() - r0, h[i].hi() + r0), search[i]);
      if (h[i].is_empty()) return false;
    }
    for (std::size_t o = 0; o < groups.size(); ++o)
      if (o != g && touches(h, groups[o].hull)) return false;
    w.full.assign(h.begin(), h.end());
    w.full.insert(w.full.end(), p.params.begin(), p.params.end());
    std::fill(tags.begin(), tags.end(), kTagUnknown);
    if (p.sys.evaluate(w.full, tags, w.vals, w.ev) == Truth::False) return false;
    if (!others_true(p, w)) return false;
    if (w.newton->certify(w.full)) return true;
    const Box k = w.newton->krawczyk(w.full);
    if (k.empty()) return false;
    // Next trial: the Krawczyk image joined with the component (then inflated again).
    for (std::size_t i = 0; i < h.size(); ++i) {
      if (k[i].is_empty() || !k[i].is_bounded()) return false;
      h[i] = hull(groups[g].hull[i], intersect(k[i], search[i]).is_empty() ? groups[g].hull[i] : intersect(k[i], search[i]));
    }
  }
  return false;
}

// Components (section 4.9) and their uniqueness certificates.
void build_components(const Problem& p, const Box& search, SolveResult& r) {
  std::vector<Box> boxes;
  boxes.reserve(r.boxes.size());
  for (const SolutionBox& b : r.boxes) boxes.push_back(b.box);
  std::vector<Aggregate> groups = aggregate(boxes, p.opt.epsilon);
  Worker w(p);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    SolutionComponent c;
    c.hull = groups[g].hull;
    c.members = groups[g].members;
    bool unexplored = false;
    for (std::size_t m : c.members) {
      c.certified += r.boxes[m].status == SolutionStatus::CertifiedUnique;
      c.feasible += r.boxes[m].status == SolutionStatus::Feasible;
      unexplored = unexplored || r.boxes[m].status == SolutionStatus::Unexplored;
    }
    if (c.members.size() == 1 && c.certified == 1) c.unique = true;
    if (!c.unique && w.newton && c.feasible == 0 && !unexplored) c.unique = certify_component(p, w, search, groups, g);
    r.components.push_back(std::move(c));
  }
}

}  // namespace

SolveResult solve(const Fn& constraint, Coordinates unknowns, const Box& box, const SolveOptions& options,
                  const FreeParameters& parameters) {
  const LimitWatch watch(options.limits);
  validate(box, unknowns, options, parameters);
  const Problem problem(constraint, unknowns, parameters, options);
  const SearchLimits& lim = options.limits;
  SolveResult result;
  SearchReport& rep = result.report;

  WorkList work(options.order);
  work.push(Item{box, std::vector<std::uint8_t>(problem.sys.num_atoms(), kTagUnknown), 0,
                 unknowns.size() - 1});
  std::optional<tbb::task_arena> arena;
  if (options.threads != 1) {
    // (Not a conditional expression: that would bind a reference to task_arena::automatic,
    // which oneTBB declares but does not define out of line.)
    int concurrency = options.threads;
    if (concurrency == 0) concurrency = tbb::task_arena::automatic;
    arena.emplace(concurrency);
  }
  tbb::enumerable_thread_specific<Worker> workers([&] { return Worker(problem); });
  std::vector<Item> batch;
  std::vector<Outcome> outcomes;
  bool depth_hit = false;

  while (!work.empty()) {
    rep.limit = watch.reached(rep.boxes_processed);
    if (rep.limit != LimitHit::None) break;
    const std::size_t k = std::min({options.batch, work.size(), lim.max_boxes - rep.boxes_processed});
    batch.clear();
    for (std::size_t i = 0; i < k; ++i) batch.push_back(work.pop());
    outcomes.assign(k, Outcome{});
    auto body = [&](std::size_t i) { outcomes[i] = process(problem, workers.local(), std::move(batch[i])); };
    if (!arena || k == 1) {
      for (std::size_t i = 0; i < k; ++i) body(i);
    } else {
      arena->execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, k, 1), [&](const tbb::blocked_range<std::size_t>& r) {
          for (std::size_t i = r.begin(); i != r.end(); ++i) body(i);
        });
      });
    }
    // Merge in work-list order: the result does not depend on the thread count.
    rep.boxes_processed += k;
    for (Outcome& o : outcomes) {
      add_stats(result.stats, o.stats);
      depth_hit = depth_hit || o.depth_limited;
      if (o.kind == Outcome::Output) {
        rep.deepest = std::max(rep.deepest, o.out.depth);
        result.boxes.push_back(std::move(o.out));
      } else if (o.kind == Outcome::Split) {
        rep.deepest = std::max(rep.deepest, o.kids[0].depth);
        if (options.order == Discipline::Lifo) {
          work.push(std::move(o.kids[1]));
          work.push(std::move(o.kids[0]));
        } else {
          work.push(std::move(o.kids[0]));
          work.push(std::move(o.kids[1]));
        }
      }
    }
  }
  // A stopped search returns what it did not explore: no solution is lost.
  while (!work.empty()) {
    Item it = work.pop();
    result.boxes.push_back(SolutionBox{std::move(it.box), SolutionStatus::Unexplored, it.depth});
  }
  if (rep.limit == LimitHit::None && depth_hit) rep.limit = LimitHit::MaxDepth;
  std::sort(result.boxes.begin(), result.boxes.end(), lower_corner_less);
  // The same box (typically a point solution on a split face) found from two sides is
  // returned once.
  result.boxes.erase(std::unique(result.boxes.begin(), result.boxes.end(),
                                 [](const SolutionBox& a, const SolutionBox& b) {
                                   return a.status == b.status && a.box == b.box;
                                 }),
                     result.boxes.end());
  build_components(problem, box, result);
  rep.seconds = watch.seconds();
  return result;
}

}  // namespace genmod
