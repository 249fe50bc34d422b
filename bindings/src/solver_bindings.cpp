// The interval solvers and queries in Python, results as numpy arrays with their statuses and
// the limit that stopped a search: solve (constraint solution), minimize (global
// minimization), ray hits, closest points, point classification and curve intersections.
// Each call releases the GIL while it searches, and Ctrl-C stops it (KeyboardInterrupt).
#include "arrays.hpp"
#include "bindings.hpp"
#include "interruptible.hpp"

#include "genmod/kernel/fn.hpp"
#include "genmod/solvers/constraint_solver.hpp"
#include "genmod/solvers/minimizer.hpp"
#include "genmod/solvers/queries.hpp"

#include <pybind11/stl.h>

#include <limits>
#include <map>
#include <optional>

namespace py = pybind11;

namespace genmod::python {
namespace {

SearchLimits limits_of(std::size_t max_boxes, int max_depth, double time_limit) {
  SearchLimits limits;
  limits.max_boxes = max_boxes;
  limits.max_depth = max_depth;
  limits.time_limit = time_limit;
  return limits;
}

QueryOptions query_options(double epsilon, std::size_t max_boxes, int max_depth, double time_limit) {
  QueryOptions o;
  o.epsilon = epsilon;
  o.limits = limits_of(max_boxes, max_depth, time_limit);
  return o;
}

// The search report's fields every result shares.
template <class Class>
void def_report(Class& c, SearchReport (*report)(const typename Class::type&)) {
  c.def_property_readonly("limit", [report](const typename Class::type& r) { return std::string(limit_name(report(r).limit)); },
                          "The first limit that stopped the search ('none' when it finished).")
      .def_property_readonly("boxes_processed", [report](const typename Class::type& r) { return report(r).boxes_processed; })
      .def_property_readonly("seconds", [report](const typename Class::type& r) { return report(r).seconds; });
}

// A solve result with the number of unknowns (an empty result still has shape (0, n, 2)).
struct SolveAnswer {
  SolveResult result;
  std::size_t unknowns;
};

SolveAnswer run_solve(const Fn& constraint, const std::vector<int>& unknowns, const DoubleArray& box, double epsilon,
                      double delta, std::size_t max_boxes, int max_depth, double time_limit, int threads,
                      const std::map<int, DoubleArray>& parameters) {
  SolveOptions o;
  o.epsilon = epsilon;
  o.delta = delta;
  o.limits = limits_of(max_boxes, max_depth, time_limit);
  o.threads = threads;
  FreeParameters free;
  for (const auto& [coord, range] : parameters) {
    free.coords.push_back(coord);
    free.values.push_back(interval_from_array(range, "genmod.solve: parameter x(" + std::to_string(coord) + ")"));
  }
  const Box b = box_from_array(box, "genmod.solve: box");
  std::atomic<bool> cancel{false};
  o.limits.cancel = &cancel;
  return run_interruptible(cancel, [&] { return SolveAnswer{solve(constraint, unknowns, b, o, free), unknowns.size()}; });
}

py::array_t<double> solution_boxes(const SolveAnswer& a) {
  std::vector<Box> boxes;
  for (const SolutionBox& s : a.result.boxes) boxes.push_back(s.box);
  return boxes_to_array(boxes, a.unknowns);
}

MinimizeResult run_minimize(const Fn& objective, const std::vector<int>& unknowns, const DoubleArray& box,
                            const std::optional<Fn>& constraint, double epsilon, double delta, std::size_t max_boxes,
                            int max_depth, double time_limit, double equality_tolerance, bool value_only,
                            int threads) {
  MinimizeOptions o;
  o.threads = threads;
  o.epsilon = epsilon;
  o.delta = delta;
  o.limits = limits_of(max_boxes, max_depth, time_limit);
  o.equality_tolerance = equality_tolerance;
  const Box b = box_from_array(box, "genmod.minimize: box");
  const Fn c = constraint ? *constraint : Fn(1.0);
  std::atomic<bool> cancel{false};
  o.limits.cancel = &cancel;
  return run_interruptible(cancel, [&] {
    return value_only ? minimize_value(objective, c, unknowns, b, o) : minimize(objective, c, unknowns, b, o);
  });
}

using Point3 = std::array<double, 3>;
using Range = std::pair<double, double>;

Interval interval_of(const Range& r, const std::string& what) {
  if (!(r.first <= r.second)) throw std::invalid_argument(what + " is not an interval lo <= hi");
  return Interval(r.first, r.second);
}

std::string class_name(PointClass c) {
  switch (c) {
    case PointClass::Inside: return "inside";
    case PointClass::Outside: return "outside";
    case PointClass::OnSurface: return "on_surface";
    case PointClass::Unknown: break;
  }
  return "unknown";
}

// The keyword arguments of every query: the parameter tolerance and the search limits.
#define QUERY_LIMIT_ARGS                                                                               \
  py::arg("epsilon") = 1e-9, py::arg("max_boxes") = SearchLimits{}.max_boxes,                          \
      py::arg("max_depth") = SearchLimits{}.max_depth, py::arg("time_limit") = 0.0

}  // namespace

void bind_solvers(py::module_& m) {
  py::class_<SolveAnswer> solve_result(m, "SolveResult", R"doc(The answer of genmod.solve.

boxes (K, n, 2): boxes of the unknowns holding every solution; status: their statuses
('certified_unique', 'possible', 'feasible', 'boundary', 'unexplored'); depth (K,);
components: connected groups (hull, members, certified, feasible, unique); complete is False
when a limit stopped the search (limit names it; the unexplored boxes are returned).)doc");
  solve_result.def_property_readonly("boxes", &solution_boxes)
      .def_property_readonly("status", [](const SolveAnswer& a) {
        std::vector<std::string> s;
        for (const SolutionBox& b : a.result.boxes) s.emplace_back(status_name(b.status));
        return s;
      })
      .def_property_readonly("depth", [](const SolveAnswer& a) {
        py::array_t<int> d(static_cast<py::ssize_t>(a.result.boxes.size()));
        for (std::size_t k = 0; k < a.result.boxes.size(); ++k) d.mutable_at(k) = a.result.boxes[k].depth;
        return d;
      })
      .def_property_readonly("components", [](const SolveAnswer& a) {
        py::list out;
        for (const SolutionComponent& c : a.result.components) {
          py::dict d;
          d["hull"] = to_array(std::span<const Interval>(c.hull));
          d["members"] = c.members;
          d["certified"] = c.certified;
          d["feasible"] = c.feasible;
          d["unique"] = c.unique;
          out.append(d);
        }
        return out;
      })
      .def_property_readonly("complete", [](const SolveAnswer& a) { return a.result.complete(); })
      .def_property_readonly("unique_components", [](const SolveAnswer& a) { return a.result.unique_components(); },
                             "The number of certified solutions (components holding exactly one each).")
      .def("__len__", [](const SolveAnswer& a) { return a.result.boxes.size(); });
  def_report(solve_result, +[](const SolveAnswer& a) { return a.result.report; });

  m.def("solve", &run_solve, py::arg("constraint"), py::arg("unknowns"), py::arg("box"), py::kw_only(),
        py::arg("epsilon") = 1e-6, py::arg("delta") = std::numeric_limits<double>::infinity(),
        py::arg("max_boxes") = SearchLimits{}.max_boxes, py::arg("max_depth") = SearchLimits{}.max_depth,
        py::arg("time_limit") = 0.0, py::arg("threads") = 0, py::arg("parameters") = std::map<int, DoubleArray>{},
        R"doc(Every solution of a constraint (built with == != < <= > >= & | ~) for the coordinates
`unknowns` over `box` ((n, 2), one row per unknown), by branch and prune with HC4, interval
Newton and Krawczyk certificates. No solution is lost, also when a limit stops the search.
`parameters` maps further coordinates the constraint depends on to their [lo, hi] ranges.)doc");

  py::class_<MinimizeResult> min_result(m, "MinimizeResult", R"doc(The answer of genmod.minimize.

minimum (2,): a guaranteed bracket [lo, hi] of the minimum value (hi is inf without a verified
feasible point, [nan, nan] when the problem is proven infeasible); candidates (K, n, 2): boxes
holding every global minimizer, with their lower bounds; best_point (n,): a verified feasible
point with f <= hi (empty if none).)doc");
  min_result.def_property_readonly("minimum", [](const MinimizeResult& r) { return to_array(r.minimum); })
      .def_property_readonly("candidates", [](const MinimizeResult& r) {
        return boxes_to_array(r.candidates, r.candidates.empty() ? 0 : r.candidates.front().size());
      })
      .def_property_readonly("candidate_lower_bounds", [](const MinimizeResult& r) {
        return to_array(std::span<const double>(r.candidate_lower_bounds));
      })
      .def_property_readonly("best_point", [](const MinimizeResult& r) { return to_array(std::span<const double>(r.best_point)); })
      .def_readonly("feasible_found", &MinimizeResult::feasible_found)
      .def_readonly("infeasible", &MinimizeResult::infeasible)
      .def_readonly("delta_reached", &MinimizeResult::delta_reached)
      .def_property_readonly("complete", [](const MinimizeResult& r) { return r.report.limit == LimitHit::None; });
  def_report(min_result, +[](const MinimizeResult& r) { return r.report; });

  m.def("minimize", &run_minimize, py::arg("objective"), py::arg("unknowns"), py::arg("box"), py::kw_only(),
        py::arg("constraint") = std::optional<Fn>{}, py::arg("epsilon") = 1e-4, py::arg("delta") = 1e-6,
        py::arg("max_boxes") = SearchLimits{}.max_boxes, py::arg("max_depth") = SearchLimits{}.max_depth,
        py::arg("time_limit") = 0.0, py::arg("equality_tolerance") = 0.0, py::arg("value_only") = false,
        py::arg("threads") = 1,
        R"doc(The global minimum of a scalar objective over the points of `box` where `constraint` is
nonzero (default: everywhere), by interval branch and bound. value_only stops as soon as the
bracket is delta wide (faster; candidates are then the boxes still open). threads: 1 (default),
0 for oneTBB's default or a count; the result is the same for any count.)doc");

  py::class_<RayHit>(m, "RayHit", "The first hit of a ray: hit, t (2,) the ray parameter ([nan, nan] on a miss), "
                                  "u, v (parametric surfaces), certified (one hit in the box and none before), complete.")
      .def_readonly("hit", &RayHit::hit)
      .def_property_readonly("t", [](const RayHit& h) { return to_array(h.t); })
      .def_property_readonly("u", [](const RayHit& h) { return to_array(h.u); })
      .def_property_readonly("v", [](const RayHit& h) { return to_array(h.v); })
      .def_readonly("certified", &RayHit::certified)
      .def_readonly("complete", &RayHit::complete);

  m.def("ray_hit", [](const Fn& surface, Point3 origin, Point3 direction, double t_max, Range u, Range v, double epsilon,
                      std::size_t max_boxes, int max_depth, double time_limit) {
        const Interval ud = interval_of(u, "genmod.ray_hit: u"), vd = interval_of(v, "genmod.ray_hit: v");
        std::atomic<bool> cancel{false};
        QueryOptions o = query_options(epsilon, max_boxes, max_depth, time_limit);
        o.limits.cancel = &cancel;
        return run_interruptible(cancel, [&] { return ray_hit(surface, origin, direction, t_max, ud, vd, o); });
      }, py::arg("surface"), py::arg("origin"), py::arg("direction"), py::arg("t_max"), py::kw_only(),
      py::arg("u") = Range{0.0, 1.0}, py::arg("v") = Range{0.0, 1.0}, QUERY_LIMIT_ARGS,
      "The first hit, for t in [0, t_max], of origin + t direction on the parametric surface S(u, v) over u x v.");
  m.def("ray_hit_implicit", [](const Fn& f, Point3 origin, Point3 direction, double t_max, double epsilon,
                               std::size_t max_boxes, int max_depth, double time_limit) {
        std::atomic<bool> cancel{false};
        QueryOptions o = query_options(epsilon, max_boxes, max_depth, time_limit);
        o.limits.cancel = &cancel;
        return run_interruptible(cancel, [&] { return ray_hit_implicit(f, origin, direction, t_max, o); });
      }, py::arg("f"), py::arg("origin"), py::arg("direction"), py::arg("t_max"), py::kw_only(), QUERY_LIMIT_ARGS,
      "The first hit, for t in [0, t_max], of origin + t direction on the implicit surface f(x, y, z) = 0.");

  py::class_<ClosestPoint>(m, "ClosestPoint", R"doc(The answer of genmod.closest_point.

distance (2,): a guaranteed bracket of the distance; parameters and point: a point of the shape
at a distance <= distance[1]; candidates (K, n, 2): parameter boxes holding every closest point;
epsilon: the parameter tolerance used.)doc")
      .def_property_readonly("distance", [](const ClosestPoint& c) { return to_array(c.distance); })
      .def_property_readonly("parameters", [](const ClosestPoint& c) { return to_array(std::span<const double>(c.parameters)); })
      .def_property_readonly("point", [](const ClosestPoint& c) { return to_array(std::span<const double>(c.point)); })
      .def_property_readonly("candidates", [](const ClosestPoint& c) {
        return boxes_to_array(c.candidates, c.parameters.size());
      })
      .def_readonly("complete", &ClosestPoint::complete)
      .def_readonly("epsilon", &ClosestPoint::epsilon);

  m.def("closest_point", [](const Fn& shape, const DoubleArray& p, std::optional<DoubleArray> domain, double epsilon,
                            std::size_t max_boxes, int max_depth, double time_limit) {
        const std::vector<double> q = vector_from_array(p, 0, "genmod.closest_point: p");
        const Box d = domain ? box_from_array(*domain, "genmod.closest_point: domain") : Box{};
        std::atomic<bool> cancel{false};
        QueryOptions o = query_options(epsilon, max_boxes, max_depth, time_limit);
        o.limits.cancel = &cancel;
        return run_interruptible(cancel, [&] { return closest_point(shape, q, d, o); });
      }, py::arg("shape"), py::arg("p"), py::kw_only(), py::arg("domain") = std::optional<DoubleArray>{}, QUERY_LIMIT_ARGS,
      "The distance from p to a parametric curve or surface (dimension len(p)) over its parameter domain "
      "((n, 2), default [0, 1] per parameter).");

  py::class_<Classification>(m, "Classification", "where: 'inside', 'outside', 'on_surface' or 'unknown' (not certified); "
                                                   "distance (2,): a bracket of the distance to the surface.")
      .def_property_readonly("where", [](const Classification& c) { return class_name(c.where); })
      .def_property_readonly("distance", [](const Classification& c) { return to_array(c.distance); });

  m.def("classify_point", [](const Fn& surface, Point3 p, Range u, Range v, double on_surface, double epsilon,
                             std::size_t max_boxes, int max_depth, double time_limit) {
        const Interval ud = interval_of(u, "genmod.classify_point: u"), vd = interval_of(v, "genmod.classify_point: v");
        std::atomic<bool> cancel{false};
        QueryOptions o = query_options(epsilon, max_boxes, max_depth, time_limit);
        o.limits.cancel = &cancel;
        return run_interruptible(cancel, [&] { return classify_point(surface, p, ud, vd, on_surface, o); });
      }, py::arg("surface"), py::arg("p"), py::kw_only(), py::arg("u") = Range{0.0, 1.0}, py::arg("v") = Range{0.0, 1.0},
      py::arg("on_surface") = 1e-9, QUERY_LIMIT_ARGS,
      "Inside or outside of a closed parametric surface whose normal S_u x S_v points outward.");

  py::class_<CurveIntersections>(m, "CurveIntersections", R"doc(Where two curves meet.

s, t (K, 2): parameter intervals on the first and second curve; points (K, d): the first
curve at the middle of s; certified (K,): exactly one intersection in s x t; complete.)doc")
      .def_property_readonly("s", [](const CurveIntersections& c) {
        Box s;
        for (const CurveHit& h : c.hits) s.push_back(h.s);
        return to_array(std::span<const Interval>(s));
      })
      .def_property_readonly("t", [](const CurveIntersections& c) {
        Box t;
        for (const CurveHit& h : c.hits) t.push_back(h.t);
        return to_array(std::span<const Interval>(t));
      })
      .def_property_readonly("points", [](const CurveIntersections& c) {
        const std::size_t d = c.hits.empty() ? 0 : c.hits.front().point.size();
        py::array_t<double> r({static_cast<py::ssize_t>(c.hits.size()), static_cast<py::ssize_t>(d)});
        for (std::size_t k = 0; k < c.hits.size(); ++k)
          for (std::size_t j = 0; j < d; ++j) r.mutable_at(k, j) = c.hits[k].point[j];
        return r;
      })
      .def_property_readonly("certified", [](const CurveIntersections& c) {
        py::array_t<bool> r(static_cast<py::ssize_t>(c.hits.size()));
        for (std::size_t k = 0; k < c.hits.size(); ++k) r.mutable_at(k) = c.hits[k].certified;
        return r;
      })
      .def_readonly("complete", &CurveIntersections::complete)
      .def("__len__", [](const CurveIntersections& c) { return c.hits.size(); });

  m.def("curve_intersections", [](const Fn& a, const Fn& b, Range a_domain, Range b_domain, double epsilon,
                                  std::size_t max_boxes, int max_depth, double time_limit) {
        const Interval ad = interval_of(a_domain, "genmod.curve_intersections: a_domain");
        const Interval bd = interval_of(b_domain, "genmod.curve_intersections: b_domain");
        std::atomic<bool> cancel{false};
        QueryOptions o = query_options(epsilon, max_boxes, max_depth, time_limit);
        o.limits.cancel = &cancel;
        return run_interruptible(cancel, [&] { return curve_intersections(a, b, ad, bd, o); });
      }, py::arg("a"), py::arg("b"), py::kw_only(), py::arg("a_domain") = Range{0.0, 1.0},
      py::arg("b_domain") = Range{0.0, 1.0}, QUERY_LIMIT_ARGS,
      "Every intersection of the curves a(s), s in a_domain, and b(t), t in b_domain (of equal dimension).");
}

}  // namespace genmod::python

#undef QUERY_LIMIT_ARGS
