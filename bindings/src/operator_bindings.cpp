// The higher-order operators in Python: integration, tables, interpolation and concatenation,
// branching, and the operators built on the solvers (inverse, solve, minimize as functions of
// the remaining coordinates, GENMOD's m_inverse / m_solve / m_minimize); plus the skeletal
// fields beyond the elementary ones (cubic curves, ramiforms, culled sums, the convexity and
// grouped blends).
#include "arrays.hpp"
#include "bindings.hpp"

#include "genmod/kernel/fn.hpp"
#include "genmod/operators/blends.hpp"
#include "genmod/operators/branching.hpp"
#include "genmod/operators/culled_field.hpp"
#include "genmod/operators/higher_order.hpp"
#include "genmod/operators/integrate.hpp"
#include "genmod/operators/skeletal.hpp"
#include "genmod/operators/table.hpp"
#include "genmod/solvers/inverse_operator.hpp"
#include "genmod/solvers/minimize_operator.hpp"
#include "genmod/solvers/solve_operator.hpp"

#include <pybind11/stl.h>

#include <optional>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace genmod::python {
namespace {

void bind_higher_order(py::module_& m) {
  m.def("integrate", [](const Fn& integrand, const Fn& lower, const Fn& upper, int parameter, double tolerance) {
        IntegrateOptions o;
        o.tolerance = tolerance;
        return integrate(integrand, lower, upper, parameter, o);
      }, py::arg("integrand"), py::arg("lower"), py::arg("upper"), py::arg("parameter"), py::arg("tolerance") = 1e-11,
      "The integral of the integrand over x(parameter) from lower to upper (Romberg; a sound Riemann enclosure).");
  m.def("table", [](const std::vector<double>& samples, const std::vector<int>& dimen, const Fn& in) {
        return table(samples, dimen, in);
      }, py::arg("samples"), py::arg("dimen"), py::arg("in"),
      "Multilinear interpolation of a rectilinear table: dimen = (n0, n1, ..., ns), samples node by node, the "
      "lowest dimension fastest; in (dimension s) in [0, 1]^s.");
  m.def("interp", &interp, py::arg("t"), py::arg("a"), py::arg("b"), "a + t (b - a).");
  m.def("concat", [](int parm, const Fn& in, const std::vector<Fn>& fns) { return concat(parm, in, fns); },
        py::arg("parm"), py::arg("in"), py::arg("fns"),
        "Uniform concatenation: the i-th of n functions of x(parm) on [i/n, (i+1)/n], evaluated at in.");
  m.def("hermite_interp", &hermite_interp, py::arg("alpha"), py::arg("p1"), py::arg("p2"), py::arg("t1"), py::arg("t2"),
        "Cubic Hermite interpolation between p1 and p2 with end derivatives t1 and t2.");
  m.def("index", [](const std::vector<Fn>& fns, const Fn& q) { return index(std::span<const Fn>(fns), q); },
        py::arg("fns"), py::arg("q"), "fns[floor(q)], the index clamped to the list.");
  m.def("select_case", [](const std::vector<Fn>& guards, const std::vector<Fn>& evals) {
        return select_case(std::span<const Fn>(guards), std::span<const Fn>(evals));
      }, py::arg("guards"), py::arg("evals"), "The first eval whose guard is nonzero (an error where none is).");
  m.def("error_fn", &error_fn, py::arg("dim") = 1, "A function that is an error everywhere.");
}

void bind_solver_operators(py::module_& m) {
  m.def("inverse", [](const Fn& invert, const Fn& match, int parameter, std::pair<double, double> domain, double epsilon) {
        return inverse(invert, match, parameter, Interval(domain.first, domain.second), epsilon);
      }, py::arg("invert"), py::arg("match"), py::arg("parameter"), py::arg("domain") = std::pair<double, double>{0.0, 1.0},
      py::arg("epsilon") = 1e-12,
      "GENMOD's m_inverse: the t in domain where invert (monotone in x(parameter) = t) equals match, as a function.");
  m.def("solve_operator", [](const Fn& c, const std::vector<int>& unknowns, const DoubleArray& domain, double epsilon) {
        return solve_operator(c, unknowns, box_from_array(domain, "genmod.solve_operator: domain"), epsilon);
      }, py::arg("constraint"), py::arg("unknowns"), py::arg("domain"), py::arg("epsilon") = 1e-9,
      "GENMOD's m_solve: the solution of the constraint for the unknowns as a function of the other coordinates.");
  m.def("solve_all_operator", [](const Fn& c, const std::vector<int>& unknowns, const DoubleArray& domain,
                                 double epsilon, int max_solutions) {
        return solve_all_operator(c, unknowns, box_from_array(domain, "genmod.solve_all_operator: domain"), epsilon, max_solutions);
      }, py::arg("constraint"), py::arg("unknowns"), py::arg("domain"), py::arg("epsilon") = 1e-9,
      py::arg("max_solutions") = 4, "The count and up to max_solutions solution points, as one function.");
  m.def("minimize_operator", [](const Fn& f, const std::vector<int>& unknowns, const DoubleArray& domain,
                                const std::optional<Fn>& constraint, double epsilon) {
        return minimize_operator(f, constraint ? *constraint : Fn(1.0), unknowns,
                        box_from_array(domain, "genmod.minimize_operator: domain"), epsilon);
      }, py::arg("objective"), py::arg("unknowns"), py::arg("domain"), py::arg("constraint") = std::optional<Fn>{},
      py::arg("epsilon") = 1e-9, "GENMOD's m_minimize: the global minimizer as a function of the other coordinates.");
  m.def("minimum_value_operator", [](const Fn& f, const std::vector<int>& unknowns, const DoubleArray& domain,
                                     const std::optional<Fn>& constraint, double epsilon) {
        return minimum_value_operator(f, constraint ? *constraint : Fn(1.0), unknowns,
                             box_from_array(domain, "genmod.minimum_value_operator: domain"), epsilon);
      }, py::arg("objective"), py::arg("unknowns"), py::arg("domain"), py::arg("constraint") = std::optional<Fn>{},
      py::arg("epsilon") = 1e-9, "The minimum value as a function of the other coordinates.");
}

void bind_more_skeletal(py::module_& m) {
  const Fn p = skeleton_query_point();
  py::class_<CubicCurve>(m, "CubicCurve", "A skeleton cubic c1 t^3 + c2 t^2 + c3 t + c4, t in [0, 1].")
      .def(py::init([](Point3 c1, Point3 c2, Point3 c3, Point3 c4) { return CubicCurve{c1, c2, c3, c4}; }),
           py::arg("c1"), py::arg("c2"), py::arg("c3"), py::arg("c4"))
      .def("at", &CubicCurve::at, py::arg("t"), "The curve point at t.");
  m.def("distance2_to_cubic", &distance2_to_cubic, py::arg("c"), py::arg("p") = p,
        "min_t |p - C(t)|^2 (nearest point by the quintic of eq. 5.8), with a sound inclusion.");
  py::class_<SkeletonLimb>(m, "SkeletonLimb", "A ramiform limb: the segment a -> b with radius r.")
      .def(py::init([](Point3 a, Point3 b, double r) { return SkeletonLimb{a, b, r}; }), py::arg("a"), py::arg("b"),
           py::arg("radius"));
  m.def("ramiform_density", [](const SkeletonLimb& parent, const std::vector<SkeletonLimb>& children, const Fn& q) {
        return ramiform_density(parent, children, q);
      }, py::arg("parent"), py::arg("children"), py::arg("p") = p,
      "The ramiform density max(f(parent), sum f(child)) of eq. 5.36 (surface at 1; larger inside).");
  py::enum_<Falloff>(m, "Falloff", "How a culled field element's density falls off: gaussian, compact or none.")
      .value("gaussian", Falloff::gaussian)
      .value("compact", Falloff::compact)
      .value("none", Falloff::none);
  py::class_<FieldElement>(m, "FieldElement", R"doc(One element of a culled field: its density Fn, its skeleton segment a-b
(a point when a == b), weight and radius of its falloff bound, and the falloff kind. taper >= 0
declares a Gaussian point source or segment convolution (taper >= |r2 - r1| / |b - a|) whose
first derivatives may be culled too; the default -1 never culls them.)doc")
      .def(py::init([](const Fn& density, Point3 a, Point3 b, double weight, double radius, Falloff falloff,
                       double taper) {
             return FieldElement{density, a, b, weight, radius, falloff, taper};
           }), py::arg("density"), py::arg("a"), py::arg("b"), py::arg("weight"), py::arg("radius"), py::arg("falloff"),
           py::arg("taper") = -1.0)
      .def_readonly("weight", &FieldElement::weight)
      .def_readonly("radius", &FieldElement::radius)
      .def_readonly("taper", &FieldElement::taper);
  m.def("gaussian_segment_element", &gaussian_segment_element, py::arg("a"), py::arg("b"), py::arg("r1"),
        py::arg("r2"), "The element of segment_convolution(a, b, r1, r2) with every culling parameter set.");
  m.def("gaussian_point_element", &gaussian_point_element, py::arg("c"), py::arg("r"), py::arg("weight") = 1.0,
        "The element of point_source(c, r, weight) with every culling parameter set.");
  m.def("culled_field", [](const std::vector<FieldElement>& elements, double cull_below, bool hierarchy) {
        CulledFieldOptions o;
        o.cull_below = cull_below;
        o.hierarchy = hierarchy;
        return culled_field(elements, o);
      }, py::arg("elements"), py::arg("cull_below") = 1e-6, py::arg("hierarchy") = true,
      "The sum of the elements' densities, culling far elements per box with a sound remainder (through a "
      "bounding-volume hierarchy, or a linear scan with hierarchy=False).");
  m.def("convexity_blend", &convexity_blend, py::arg("blend"), py::arg("union_field"), py::arg("convexity"),
        "Interpolates a blend and a union field by a convexity in [0, 1] (eqs. 5.15, 5.17, 5.37).");
  m.def("grouped_blend", [](const std::vector<Fn>& densities, const std::vector<std::vector<int>>& blend_with, double iso) {
        return grouped_blend(std::span<const Fn>(densities), blend_with, iso);
      }, py::arg("densities"), py::arg("blend_with"), py::arg("iso") = 0.5,
      "Blend sets per limb (Fig. 6.18): each density blended only with those listed for it, the results united "
      "(an implicit function, negative inside).");
  m.def("decay", &decay, py::arg("x"), "1 - Ease(x): the decreasing profile of the product blend's primitives.");
}

}  // namespace

void bind_higher_order_operators(py::module_& m) {
  bind_higher_order(m);
  bind_solver_operators(m);
  bind_more_skeletal(m);
}

}  // namespace genmod::python
