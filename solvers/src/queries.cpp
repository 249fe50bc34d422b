// Geometric queries: each one sets up equations or an objective over the shapes' parameters
// and hands them to solve() or minimize().
#include "genmod/solvers/queries.hpp"

#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/solvers/constraint_solver.hpp"
#include "genmod/solvers/minimizer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace genmod {
namespace {

// f with its parameters (its input coordinates, ascending) renamed to x(to[0]), x(to[1]), ...
Fn rename_parameters(const Fn& f, std::span<const int> to, const char* what) {
  const std::vector<int> from = f.inputs();
  if (from.size() > to.size())
    throw std::invalid_argument(std::string("genmod: ") + what + " depends on " + std::to_string(from.size()) +
                                " coordinates, expected at most " + std::to_string(to.size()));
  if (from.empty()) return f;
  std::vector<Fn> targets;
  for (std::size_t k = 0; k < from.size(); ++k) targets.push_back(x(to[k]));
  return compose_all(f, from, cat(targets));
}

void check_domain(const Interval& d, const char* what) {
  if (d.is_empty() || !d.is_bounded())
    throw std::invalid_argument(std::string("genmod: ") + what + " must be a bounded, nonempty interval");
}

void check_vector(std::span<const double> v, const char* what) {
  for (double c : v)
    if (!std::isfinite(c)) throw std::invalid_argument(std::string("genmod: ") + what + " has a non-finite coordinate");
}

SolveOptions solve_options(const QueryOptions& q) {
  SolveOptions o;
  o.epsilon = q.epsilon;
  o.limits = q.limits;
  return o;
}

std::vector<double> evaluate_at(const Fn& f, std::span<const double> coordinates) { return evaluate(f, coordinates); }

CurveIntersections hits_from(const SolveResult& r, const Fn& first_curve) {
  CurveIntersections out;
  out.complete = r.complete();
  for (const SolutionComponent& c : r.components) {
    CurveHit h;
    h.s = c.hull[0];
    h.t = c.hull[1];
    h.point = evaluate_at(first_curve, std::vector<double>{h.s.mid()});
    h.certified = c.unique;
    out.hits.push_back(std::move(h));
  }
  std::sort(out.hits.begin(), out.hits.end(), [](const CurveHit& a, const CurveHit& b) { return a.s.lo() < b.s.lo(); });
  return out;
}

// The first hit among the components of a solve over (..., t) with t the coordinate at
// position t_index of the hulls.
RayHit first_hit(const SolveResult& r, std::size_t t_index, bool parametric) {
  RayHit hit;
  hit.complete = r.complete();
  const SolutionComponent* first = nullptr;
  for (const SolutionComponent& c : r.components)
    if (!first || c.hull[t_index].lo() < first->hull[t_index].lo()) first = &c;
  if (!first) return hit;
  hit.hit = true;
  hit.t = first->hull[t_index];
  if (parametric) {
    hit.u = first->hull[0];
    hit.v = first->hull[1];
  }
  // Certified: one solution in this component and every other component lies beyond it.
  bool separated = true;
  for (const SolutionComponent& c : r.components)
    if (&c != first && c.hull[t_index].lo() <= hit.t.hi()) separated = false;
  hit.certified = first->unique && separated && hit.complete;
  return hit;
}

}  // namespace

CurveIntersections curve_intersections(const Fn& a, const Fn& b, Interval a_domain, Interval b_domain,
                                       const QueryOptions& options) {
  if (a.dim() != b.dim())
    throw std::invalid_argument("genmod: curve_intersections: curves of dimension " + std::to_string(a.dim()) +
                                " and " + std::to_string(b.dim()));
  check_domain(a_domain, "curve_intersections: the first curve's domain");
  check_domain(b_domain, "curve_intersections: the second curve's domain");
  const int s[] = {0}, t[] = {1};
  const Fn as = rename_parameters(a, s, "curve_intersections: the first curve");
  const Fn bt = rename_parameters(b, t, "curve_intersections: the second curve");
  const int unknowns[] = {0, 1};
  const SolveResult r = solve(eq(as, bt), unknowns, {a_domain, b_domain}, solve_options(options));
  return hits_from(r, as);
}

CurveIntersections curve_self_intersections(const Fn& c, Interval domain, double min_separation,
                                            const QueryOptions& options) {
  check_domain(domain, "curve_self_intersections: the domain");
  if (!(min_separation > 0.0))
    throw std::invalid_argument("genmod: curve_self_intersections: min_separation must be > 0");
  const int s[] = {0}, t[] = {1};
  const Fn cs = rename_parameters(c, s, "curve_self_intersections: the curve");
  const Fn ct = rename_parameters(c, t, "curve_self_intersections: the curve");
  const int unknowns[] = {0, 1};
  const Fn constraint = eq(cs, ct) && (x(1) - x(0) >= min_separation);
  const SolveResult r = solve(constraint, unknowns, {domain, domain}, solve_options(options));
  return hits_from(r, cs);
}

RayHit ray_hit(const Fn& surface, std::array<double, 3> origin, std::array<double, 3> direction, double t_max,
               Interval u_domain, Interval v_domain, const QueryOptions& options) {
  if (surface.dim() != 3)
    throw std::invalid_argument("genmod: ray_hit: the surface has dimension " + std::to_string(surface.dim()) +
                                ", expected 3");
  check_vector(origin, "ray_hit: the origin");
  check_vector(direction, "ray_hit: the direction");
  if (!(t_max > 0.0) || !std::isfinite(t_max)) throw std::invalid_argument("genmod: ray_hit: t_max must be finite and > 0");
  check_domain(u_domain, "ray_hit: the u domain");
  check_domain(v_domain, "ray_hit: the v domain");
  const int uv[] = {0, 1};
  const Fn s = rename_parameters(surface, uv, "ray_hit: the surface");
  const Fn t = x(2);
  const Fn ray = cat({origin[0] + t * direction[0], origin[1] + t * direction[1], origin[2] + t * direction[2]});
  const int unknowns[] = {0, 1, 2};
  const SolveResult r = solve(eq(ray, s), unknowns, {u_domain, v_domain, Interval(0.0, t_max)}, solve_options(options));
  return first_hit(r, 2, true);
}

RayHit ray_hit_implicit(const Fn& f, std::array<double, 3> origin, std::array<double, 3> direction, double t_max,
                        const QueryOptions& options) {
  if (f.dim() != 1) throw std::invalid_argument("genmod: ray_hit_implicit: f must be scalar");
  for (int i : f.inputs())
    if (i > 2) throw std::invalid_argument("genmod: ray_hit_implicit: f may depend on x(0), x(1), x(2) only");
  check_vector(origin, "ray_hit_implicit: the origin");
  check_vector(direction, "ray_hit_implicit: the direction");
  if (!(t_max > 0.0) || !std::isfinite(t_max))
    throw std::invalid_argument("genmod: ray_hit_implicit: t_max must be finite and > 0");
  const Fn t = x(0);
  const int xyz[] = {0, 1, 2};
  const Fn along = compose_all(f, xyz, cat({origin[0] + t * direction[0], origin[1] + t * direction[1],
                                             origin[2] + t * direction[2]}));
  const int unknowns[] = {0};
  const SolveResult r = solve(eq(along, 0.0), unknowns, {Interval(0.0, t_max)}, solve_options(options));
  return first_hit(r, 0, false);
}

SurfaceIntersection surface_intersection(const Fn& a, const Fn& b, std::span<const Interval> a_domain,
                                         std::span<const Interval> b_domain, const SurfaceIntersectionOptions& options) {
  if (a.dim() != 3 || b.dim() != 3)
    throw std::invalid_argument("genmod: surface_intersection: surfaces must have dimension 3, got " +
                                std::to_string(a.dim()) + " and " + std::to_string(b.dim()));
  Box box(a_domain.begin(), a_domain.end());
  if (box.empty()) box.assign(2, Interval(0, 1));
  check_search_box(box, 2, "surface_intersection (first domain)");
  Box second(b_domain.begin(), b_domain.end());
  if (second.empty()) second.assign(2, Interval(0, 1));
  check_search_box(second, 2, "surface_intersection (second domain)");
  box.insert(box.end(), second.begin(), second.end());
  const int uv[] = {0, 1}, st[] = {2, 3};
  const Fn au = rename_parameters(a, uv, "surface_intersection: the first surface");
  const Fn bs = rename_parameters(b, st, "surface_intersection: the second surface");
  const int coords[] = {0, 1, 2, 3};
  if (!options.curve.periodic.empty())
    throw std::invalid_argument(
        "genmod: surface_intersection: set periodic_u, periodic_v, periodic_s, periodic_t instead of curve.periodic");
  ImplicitCurveOptions curve = options.curve;
  const bool periodic[] = {options.periodic_u, options.periodic_v, options.periodic_s, options.periodic_t};
  for (int i = 0; i < 4; ++i)
    if (periodic[i]) curve.periodic.push_back(i);
  SurfaceIntersection out;
  out.curve = approximate_implicit_curve(au - bs, coords, box, curve);
  const Tape at(au, std::vector<int>{0, 1});
  PointEvaluator pe;
  for (const Polyline& line : out.curve.components) {
    std::vector<std::array<double, 3>> pts;
    for (const std::vector<double>& q : line.points) {
      const auto p = pe.eval(at, {q[0], q[1]});
      pts.push_back({p[0], p[1], p[2]});
    }
    out.components.push_back(std::move(pts));
  }
  return out;
}

ClosestPoint closest_point(const Fn& shape, std::span<const double> p, std::span<const Interval> domain,
                           const QueryOptions& options) {
  if (shape.dim() != p.size())
    throw std::invalid_argument("genmod: closest_point: the shape has dimension " + std::to_string(shape.dim()) +
                                " but the point has " + std::to_string(p.size()) + " coordinates");
  check_vector(p, "closest_point: the point");
  const std::size_t k = shape.inputs().size();
  if (k == 0) throw std::invalid_argument("genmod: closest_point: the shape has no parameters");
  Box box(domain.begin(), domain.end());
  if (box.empty()) box.assign(k, Interval(0, 1));
  check_search_box(box, k, "closest_point");
  std::vector<int> params(k);
  for (std::size_t i = 0; i < k; ++i) params[i] = static_cast<int>(i);
  const Fn s = rename_parameters(shape, params, "closest_point: the shape");
  Fn d2 = 0.0;
  for (std::size_t j = 0; j < p.size(); ++j) d2 = d2 + square(s[j] - p[j]);
  MinimizeOptions opt;
  opt.epsilon = std::max(options.epsilon, 1e-7);  // the squared distance is flat at its minimum
  opt.delta = 1e-12;
  opt.limits = options.limits;
  const MinimizeResult m = minimize(d2, Fn(1.0), params, box, opt);
  ClosestPoint out;
  out.complete = m.report.limit == LimitHit::None;
  out.epsilon = opt.epsilon;
  const Interval squared = intersect(m.minimum, Interval::unchecked(0.0, std::numeric_limits<double>::infinity()));
  out.distance = sqrt(squared);
  out.parameters = m.best_point;
  if (!m.best_point.empty()) out.point = evaluate_at(s, m.best_point);
  out.candidates = m.candidates;
  return out;
}

Classification classify_point(const Fn& surface, std::array<double, 3> p, Interval u_domain, Interval v_domain,
                              double on_surface, const QueryOptions& options) {
  if (surface.dim() != 3)
    throw std::invalid_argument("genmod: classify_point: the surface has dimension " + std::to_string(surface.dim()) +
                                ", expected 3");
  check_domain(u_domain, "classify_point: the u domain");
  check_domain(v_domain, "classify_point: the v domain");
  const int uv[] = {0, 1};
  const Fn s = rename_parameters(surface, uv, "classify_point: the surface");
  const Interval domain[] = {u_domain, v_domain};
  const ClosestPoint near = closest_point(s, p, domain, options);
  Classification out;
  out.distance = near.distance;
  if (near.distance.hi() <= on_surface) {
    out.where = PointClass::OnSurface;
    return out;
  }
  // N . (S - p) with N = S_u x S_v (outward): positive when p lies inside.
  const Fn su = derivative(s, 0), sv = derivative(s, 1);
  const Fn n = cat({su[1] * sv[2] - su[2] * sv[1], su[2] * sv[0] - su[0] * sv[2], su[0] * sv[1] - su[1] * sv[0]});
  const Fn side = n[0] * (s[0] - p[0]) + n[1] * (s[1] - p[1]) + n[2] * (s[2] - p[2]);
  const Tape tape(side, std::vector<int>{0, 1});
  IntervalEvaluator ev;
  bool all_positive = !near.candidates.empty(), all_negative = !near.candidates.empty();
  for (const Box& c : near.candidates) {
    const Interval g = ev.eval(tape, c)[0];
    if (ev.errors()[0] != kNoError || !(g.lo() > 0.0)) all_positive = false;
    if (ev.errors()[0] != kNoError || !(g.hi() < 0.0)) all_negative = false;
  }
  if (near.complete && all_positive) out.where = PointClass::Inside;
  else if (near.complete && all_negative) out.where = PointClass::Outside;
  return out;
}

}  // namespace genmod
