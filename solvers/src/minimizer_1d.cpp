#include "minimizer_1d.hpp"

#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace genmod::detail {
namespace {

constexpr int kFirstCells = 32;  // the first grid on the domain
constexpr int kMaxLevels = 10;   // bisections of the candidates (cells down to 1/32768 of it)
constexpr std::size_t kMaxCells = 48;  // more candidates than this: stop refining

// Interval evaluations of one tape at (x, P) with x varying.
class AtFree {
 public:
  AtFree(const Tape& tape, std::span<const Interval> P) : tape_(tape), box_(1 + P.size()) {
    std::copy(P.begin(), P.end(), box_.begin() + 1);
  }
  // The enclosure over x, or nullopt when the function may fail there.
  std::optional<Interval> operator()(const Interval& x) {
    box_[0] = x;
    const Interval v = ev_.eval(tape_, box_)[0];
    if (ev_.errors()[0] != kNoError || v.is_empty()) return std::nullopt;
    return v;
  }

 private:
  const Tape& tape_;
  std::vector<Interval> box_;
  IntervalEvaluator ev_;
};

// Candidate cells of a grid on the domain, merged into runs of adjacent cells, with the bounds
// U >= f*(p) and lower <= f*(p) for every p in P (steps 1 and 2 of minimizer_1d.hpp).
struct Run1d {
  double lo, hi;
  bool at_end = false;  // touches an end of the domain
  bool convex = false;  // d2f/dx2 > 0 on the run x P
};
struct Candidates1d {
  std::vector<Run1d> runs;
  double lower = 0.0, upper = 0.0;
};

std::optional<Candidates1d> minimizer_candidates_1d(const Objective1d& obj, std::span<const Interval> P, double delta,
                                                    bool ends_convex);

}  // namespace

double polish_minimizer(const Objective1d& obj, double q, std::span<const double> p) {
  PointEvaluator ev;
  std::vector<double> point(1 + p.size());
  std::copy(p.begin(), p.end(), point.begin() + 1);
  auto at = [&](const Tape& tape, double x) {
    point[0] = x;
    return ev.eval(tape, point)[0];
  };
  const double g0 = at(obj.fx, q);
  if (!(g0 != 0.0) || std::isnan(g0)) return q;
  // Descend: toward larger x where df/dx < 0, smaller where > 0.
  const double dir = g0 < 0.0 ? 1.0 : -1.0;
  const double end = dir > 0 ? obj.domain.hi() : obj.domain.lo();
  const double scale = obj.domain.hi() - obj.domain.lo();
  double before = q, after = q;  // df/dx has g0's sign at `before`; the other sign at `after`
  bool found = false;
  for (double step = 1e-12 * scale; !found; step *= 2.0) {
    double t = q + dir * step;
    if (dir > 0 ? t >= end : t <= end) t = end;
    const double g = at(obj.fx, t);
    if (std::isnan(g)) return q;
    if ((g < 0.0) != (g0 < 0.0) || g == 0.0) {
      after = t;
      found = true;
    } else if (t == end) {
      return q;  // no sign change before the end: the minimum is there (q is in its level set)
    } else {
      before = t;
    }
  }
  // Bisection down to adjacent doubles; the end on the descending side of the root.
  for (;;) {
    const double mid = 0.5 * (before + after);
    if (mid == before || mid == after) break;
    const double g = at(obj.fx, mid);
    if (std::isnan(g)) return q;
    if (g != 0.0 && (g < 0.0) == (g0 < 0.0)) before = mid;
    else after = mid;
  }
  return before;  // f decreased from q to here (df/dx kept its sign): still in q's level set
}

namespace {

// Refines until every run off the ends (every run, with ends_convex) is convex, or a limit.
std::optional<Candidates1d> minimizer_candidates_1d(const Objective1d& obj, std::span<const Interval> P, double delta,
                                                    bool ends_convex) {
  AtFree f(obj.f, P), fxx(obj.fxx, P);
  const Interval dom = obj.domain;
  std::vector<Interval> cells;
  for (int i = 0; i < kFirstCells; ++i) {
    const double a = i == 0 ? dom.lo() : dom.lo() + (dom.hi() - dom.lo()) * i / kFirstCells;
    const double b = i + 1 == kFirstCells ? dom.hi() : dom.lo() + (dom.hi() - dom.lo()) * (i + 1) / kFirstCells;
    cells.emplace_back(a, b);
  }
  Candidates1d out;
  out.upper = std::numeric_limits<double>::infinity();  // U >= f*(p) for every p in P
  for (int level = 0;; ++level) {
    for (const Interval& c : cells) {
      const auto v = f(Interval(c.mid()));
      if (!v) return std::nullopt;
      out.upper = std::min(out.upper, v->hi());
    }
    // Every point value q at p has f(q, p) <= f*(p) + delta <= U + delta; 2 delta leaves room
    // for the rounding of the point evaluation that found q.
    const double level_set = out.upper + 2.0 * delta;
    std::vector<Interval> kept;
    out.lower = std::numeric_limits<double>::infinity();
    for (const Interval& c : cells) {
      const auto v = f(c);
      if (!v) return std::nullopt;
      if (v->lo() <= level_set) {
        kept.push_back(c);
        out.lower = std::min(out.lower, v->lo());
      }
    }
    cells = std::move(kept);
    if (cells.empty()) return std::nullopt;  // cannot happen for a sound enclosure; stay general
    // Runs of adjacent cells (cells stay in domain order).
    out.runs.clear();
    for (const Interval& c : cells) {
      if (!out.runs.empty() && out.runs.back().hi == c.lo()) out.runs.back().hi = c.hi();
      else out.runs.push_back({c.lo(), c.hi()});
    }
    // Done when every run (off the domain's ends, unless ends_convex) is convex for all of P,
    // or when refining would cost too much.
    bool all_convex = true;
    for (Run1d& r : out.runs) {
      r.at_end = r.lo == dom.lo() || r.hi == dom.hi();
      const auto c = fxx(Interval(r.lo, r.hi));
      r.convex = c && c->lo() > 0.0;
      if (!r.convex && (ends_convex || !r.at_end)) all_convex = false;
    }
    if (all_convex || level == kMaxLevels || 2 * cells.size() > kMaxCells) return out;
    std::vector<Interval> halves;
    for (const Interval& c : cells) {
      const double m = c.mid();
      halves.emplace_back(c.lo(), m);
      halves.emplace_back(m, c.hi());
    }
    cells = std::move(halves);
  }
}

}  // namespace

std::optional<Enclosure1d> enclose_minimizer_1d(const Objective1d& obj, std::span<const Interval> P, double delta,
                                                double tolerance) {
  const auto candidates = minimizer_candidates_1d(obj, P, delta, false);
  if (!candidates) return std::nullopt;
  AtFree fx(obj.fx, P);
  const std::vector<Run1d>& runs = candidates->runs;
  const double lower = candidates->lower, upper = candidates->upper;
  Interval hull_of_runs = Interval::empty();
  for (const Run1d& r : runs) {
    Interval part(r.lo, r.hi);
    if (r.convex && !r.at_end) {
      // df/dx increases on the run for every p: its root lies above every x where df/dx < 0
      // for all of P and below every x where it is > 0 for all of P.
      auto certainly = [&](double x, int sign) -> std::optional<bool> {
        const auto g = fx(Interval(x));
        if (!g) return std::nullopt;
        return sign < 0 ? g->hi() < 0.0 : g->lo() > 0.0;
      };
      double lo = r.lo, hi = r.hi;
      const auto neg_at_lo = certainly(r.lo, -1), pos_at_hi = certainly(r.hi, 1);
      if (!neg_at_lo || !pos_at_hi) return std::nullopt;
      if (*neg_at_lo) {  // the largest x found with df/dx < 0 on all of P
        double ok = r.lo, fail = r.hi;
        while (fail - ok > tolerance) {
          const double mid = 0.5 * (ok + fail);
          if (mid == ok || mid == fail) break;
          const auto s = certainly(mid, -1);
          if (!s) return std::nullopt;
          (*s ? ok : fail) = mid;
        }
        lo = ok;
      }
      if (*pos_at_hi) {  // the smallest x found with df/dx > 0 on all of P
        double ok = r.hi, fail = lo;
        while (ok - fail > tolerance) {
          const double mid = 0.5 * (ok + fail);
          if (mid == ok || mid == fail) break;
          const auto s = certainly(mid, 1);
          if (!s) return std::nullopt;
          (*s ? ok : fail) = mid;
        }
        hi = ok;
      }
      part = Interval(lo, hi);
    }
    hull_of_runs = hull(hull_of_runs, part);
  }
  // One convex run off the ends: every p in P has one minimizer, the root of df/dx there, a
  // continuous function of p (implicit function theorem), which the point value finds.
  const bool unique = runs.size() == 1 && runs[0].convex && !runs[0].at_end;
  return Enclosure1d{hull_of_runs, Interval(lower, std::max(lower, upper)), unique};
}

std::optional<double> minimizer_1d(const Objective1d& obj, std::span<const double> p, double delta) {
  std::vector<Interval> P(p.begin(), p.end());
  const auto candidates = minimizer_candidates_1d(obj, P, delta, true);
  if (!candidates) return std::nullopt;
  PointEvaluator ev;
  std::vector<double> point(1 + p.size());
  std::copy(p.begin(), p.end(), point.begin() + 1);
  double best = std::numeric_limits<double>::quiet_NaN(), best_f = std::numeric_limits<double>::infinity();
  auto consider = [&](double q) {
    point[0] = q;
    const double fq = ev.eval(obj.f, point)[0];
    if (fq < best_f) {
      best = q;
      best_f = fq;
    }
  };
  for (const Run1d& r : candidates->runs) {
    if (!r.convex) return std::nullopt;
    // f is convex on the run: descending from its middle ends at its minimum there (a root
    // of df/dx), or runs to the domain's end, which is then a candidate; the global minimum is
    // the least of these.
    consider(polish_minimizer(obj, 0.5 * (r.lo + r.hi), p));
    if (r.lo == obj.domain.lo()) consider(r.lo);
    if (r.hi == obj.domain.hi()) consider(r.hi);
  }
  if (std::isnan(best)) return std::nullopt;
  return best;
}

}  // namespace genmod::detail
