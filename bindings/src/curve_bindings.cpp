// Curves and the operators built on them in Python: vector operations, the curve types and
// curve files, sweeps (profile, wire and rail products, interpolated cross sections), offsets,
// arcs, the CPG path builder and the warps. Control points are sequences of points (lists or
// (n, d) arrays).
#include "bindings.hpp"

#include "genmod/kernel/fn.hpp"
#include "genmod/operators/curve.hpp"
#include "genmod/operators/curve_file.hpp"
#include "genmod/operators/matrix.hpp"
#include "genmod/operators/offset.hpp"
#include "genmod/operators/path.hpp"
#include "genmod/operators/sweep.hpp"
#include "genmod/operators/vector.hpp"
#include "genmod/operators/warp.hpp"

#include <pybind11/stl.h>

#include <string>
#include <vector>

namespace py = pybind11;

namespace genmod::python {
namespace {

void bind_vectors(py::module_& m) {
  m.def("length", &length, py::arg("f"), "The Euclidean length of a vector function.");
  m.def("dot", &dot, py::arg("f"), py::arg("g"), "The dot product of two vector functions of equal dimension.");
  m.def("cross", &cross, py::arg("f"), py::arg("g"), "The cross product of two 3-vectors.");
  m.def("normalize", &normalize, py::arg("f"), "f / |f| (an error value where f = 0).");
}

void bind_curves(py::module_& m) {
  py::class_<Curve>(m, "Curve", R"doc(A curve (polyline, Bezier, B-spline, NURBS, Hermite, Catmull-Rom): one custom
operator with exact point values, a tight inclusion function (the convex hull of the Bezier
control points of each sub-span) and an exact derivative. curve(t) is the curve at the scalar
function t; outside its domain the value is an error (NaN), never a clamp.)doc")
      .def_static("polyline", &Curve::polyline, py::arg("points"))
      .def_static("bezier", &Curve::bezier, py::arg("points"))
      .def_static("bspline", &Curve::bspline, py::arg("points"), py::arg("degree"), py::arg("knots"))
      .def_static("uniform_bspline", &Curve::uniform_bspline, py::arg("points"), py::arg("degree"),
                  py::arg("clamped") = true)
      .def_static("nurbs", &Curve::nurbs, py::arg("points"), py::arg("weights"), py::arg("degree"),
                  py::arg("knots") = std::vector<double>{})
      .def_static("hermite", &Curve::hermite, py::arg("points"), py::arg("tangents"))
      .def_static("catmull_rom", &Curve::catmull_rom, py::arg("points"))
      .def_property_readonly("dimension", &Curve::dimension)
      .def_property_readonly("degree", &Curve::degree)
      .def_property_readonly("knots", &Curve::knots)
      .def_property_readonly("control_points", &Curve::control_points)
      .def_property_readonly("weights", &Curve::weights)
      .def_property_readonly("domain", &Curve::domain)
      .def("__call__", &Curve::operator(), py::arg("t"));
  m.def("parse_curve", [](const std::string& text) { return parse_curve(text); }, py::arg("text"),
        "A curve from curve-file text (ValueError names the line of malformed text).");
  m.def("load_curve", [](const std::string& path) { return load_curve(path); }, py::arg("path"),
        "A curve from a .crv file (streamed; ValueError names the line of a malformed file).");
  m.def("crv", &crv, py::arg("path"), py::arg("t"), "GENMOD's m_crv: the curve in the file at the scalar function t.");
}

void bind_sweeps(py::module_& m) {
  m.def("curve_in", &curve_in, py::arg("curve"), py::arg("parm"), "A curve of x(0) with x(0) replaced by x(parm).");
  m.def("profile_product", &profile_product, py::arg("cross"), py::arg("profile"),
        "(g1 d1, g2 d1, d2): a circular cross section gives a surface of revolution.");
  m.def("wire_product", &wire_product, py::arg("cross"), py::arg("wire"), py::arg("wire_parm") = 1,
        "A cross section swept along a planar wire, its x axis along the wire's normal and y along z.");
  m.def("rail_product", &rail_product, py::arg("cross"), py::arg("rail1"), py::arg("rail2"),
        "A cross section stretched between two planar rails (g1 = -1 on rail1, +1 on rail2).");
  m.def("quasi_linear", &quasi_linear, py::arg("cross"), py::arg("m"), py::arg("t"), "M g + T (M 3x3, T a 3-vector).");
  m.def("homogeneous", &homogeneous, py::arg("m"), py::arg("t"), "The 4x4 affine matrix [M T; 0 0 0 1].");
  m.def("interp_cross_sections", &interp_cross_sections, py::arg("alpha"), py::arg("c1"), py::arg("c2"),
        "Linear interpolation c1 + alpha (c2 - c1) of two cross sections.");
  m.def("hermite_cross_sections", &hermite_cross_sections, py::arg("alpha"), py::arg("p1"), py::arg("p2"),
        py::arg("t1"), py::arg("t2"), "Hermite interpolation of cross sections: H(0) = p1, H(1) = p2, H'(0) = t1, H'(1) = t2.");
  const char* curve_style = "Curve style: every argument is a curve of x(0); the result is a surface of (u, v) = (x(0), x(1)).";
  m.def("profile_surface", &profile_surface, py::arg("cross"), py::arg("profile"), curve_style);
  m.def("wire_surface", &wire_surface, py::arg("cross"), py::arg("wire"), curve_style);
  m.def("rail_surface", &rail_surface, py::arg("cross"), py::arg("rail1"), py::arg("rail2"), curve_style);
  m.def("interp_surface", &interp_surface, py::arg("c1"), py::arg("c2"), py::arg("height"), curve_style);
  m.def("warp_z_by_x", &warp_z_by_x, py::arg("cross"), py::arg("a"), py::arg("b"),
        "GENMOD's parabolic warp of a 3-D cross section: (x, y, z + a x^2 + b).");
}

void bind_offsets_and_paths(py::module_& m) {
  m.def("normal2d", &normal2d, py::arg("curve"), py::arg("parm") = 0, "(-c1', c0'), unnormalized.");
  m.def("offset_curve", &offset_curve, py::arg("curve"), py::arg("r"), py::arg("parm") = 0,
        "c + r normalize(normal2d(c)).");
  m.def("offset_product", static_cast<Fn (*)(const Fn&, const Fn&, int)>(&offset_product), py::arg("cross"), py::arg("profile"), py::arg("cross_parm") = 0,
        "(c(u) + d1(v) n(u), d2(v)): a closed cross section offset by d1 and lifted to height d2.");
  m.def("closed_offset", &closed_offset, py::arg("curve"), py::arg("r"), py::arg("parm") = 0,
        "The boundary of the points within r of an open planar curve, counter-clockwise.");
  m.def("arc_2pt_height", &arc_2pt_height, py::arg("p1"), py::arg("p2"), py::arg("height"), py::arg("t"),
        "The circular arc from p1 to p2 whose midpoint lies `height` left of the chord.");
  m.def("mirror_x", &mirror_x, py::arg("half"), py::arg("parm") = 0,
        "A half path on x >= 0 completed by its mirror image into a closed curve.");

  py::class_<Path>(m, "Path", R"doc(The CPG path builder: planar paths of segments and circular arcs (with fillets)
whose points may be functions, finished into one curve of x(coord) by path.curve(t).)doc")
      .def(py::init<int>(), py::arg("coord") = 0)
      .def("move_to", &Path::move_to, py::arg("p"))
      .def("line_to", &Path::line_to, py::arg("p"))
      .def("line_to_arc", &Path::line_to_arc, py::arg("p"), py::arg("center"), py::arg("radius"), py::arg("second"),
           py::arg("ccw"), py::arg("fillet") = Fn(0.0))
      .def("arc_to_line", &Path::arc_to_line, py::arg("center"), py::arg("radius"), py::arg("p1"), py::arg("p2"),
           py::arg("second"), py::arg("ccw"), py::arg("fillet") = Fn(0.0))
      .def("close", &Path::close)
      .def("curve", &Path::curve, py::arg("t"))
      .def_property_readonly("pieces", &Path::pieces);
}

}  // namespace

void bind_curves_and_sweeps(py::module_& m) {
  bind_vectors(m);
  bind_curves(m);
  bind_sweeps(m);
  bind_offsets_and_paths(m);
}

}  // namespace genmod::python
