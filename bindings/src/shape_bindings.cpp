// The operator families of the shape language in Python: matrices and affine transforms,
// the standard parametric and implicit shapes with CSG, and Bloomenthal's skeletal fields
// (skeleton distances, distance and convolution surfaces, blends). Points are 3-sequences;
// every size argument may be a number or an Fn, as in C++.
#include "bindings.hpp"

#include "genmod/kernel/fn.hpp"
#include "genmod/operators/blends.hpp"
#include "genmod/operators/convolution.hpp"
#include "genmod/operators/matrix.hpp"
#include "genmod/operators/shapes.hpp"
#include "genmod/operators/skeletal.hpp"
#include "genmod/operators/transform.hpp"

#include <pybind11/operators.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

namespace py = pybind11;

namespace genmod::python {
namespace {

void bind_matrices(py::module_& m) {
  py::class_<Matrix>(m, "Matrix", R"doc(A matrix of functions: an Fn of rows * cols components (row-major) and its shape.

Matrix(f, rows, cols); m @ n multiplies matrices, m @ v applies m to a column vector Fn;
m[r, c] is an entry; the transforms (translate, scale, rotate_x/y/z) are 4x4 affine matrices.)doc")
      .def(py::init<Fn, int, int>(), py::arg("components"), py::arg("rows"), py::arg("cols"))
      .def_static("identity", &Matrix::identity, py::arg("n"))
      .def_property_readonly("rows", &Matrix::rows)
      .def_property_readonly("cols", &Matrix::cols)
      .def_property_readonly("fn", &Matrix::fn, "The components, row-major.")
      .def("__getitem__", [](const Matrix& a, std::pair<int, int> rc) { return a(rc.first, rc.second); })
      .def("row", [](const Matrix& a, int r) { return a[r]; }, py::arg("r"))
      .def("column", &Matrix::column, py::arg("c"))
      .def("__matmul__", [](const Matrix& a, const Matrix& b) { return a * b; }, py::is_operator())
      .def("__matmul__", [](const Matrix& a, const Fn& v) { return a * v; }, py::is_operator())
      .def(py::self + py::self).def(py::self - py::self).def(-py::self)
      .def("__rmul__", [](const Matrix& a, const Fn& s) { return s * a; }, py::is_operator())
      .def("__repr__", [](const Matrix& a) {
        return "<genmod.Matrix " + std::to_string(a.rows()) + "x" + std::to_string(a.cols()) + ">";
      });
  m.def("transpose", &transpose, py::arg("m"), "The transposed matrix.");
  m.def("determinant", &determinant, py::arg("m"), "The determinant of a square matrix (cofactor expansion, no divisions).");
  m.def("inverse", &inverse, py::arg("m"), "Adjugate / determinant (an error value where det = 0).");
  m.def("translate", py::overload_cast<const Fn&, const Fn&, const Fn&>(&translate), py::arg("tx"), py::arg("ty"), py::arg("tz"),
        "The 4x4 translation by (tx, ty, tz).");
  m.def("translate", py::overload_cast<const Fn&>(&translate), py::arg("t"), "Translation by a 3-vector Fn.");
  m.def("scale", py::overload_cast<const Fn&, const Fn&, const Fn&>(&scale), py::arg("sx"), py::arg("sy"), py::arg("sz"),
        "The 4x4 scaling by (sx, sy, sz).");
  m.def("scale", py::overload_cast<const Fn&>(&scale), py::arg("s"), "Uniform scaling.");
  m.def("rotate_x", &rotate_x, py::arg("angle"), "The 4x4 rotation by angle (radians) about the x axis.");
  m.def("rotate_y", &rotate_y, py::arg("angle"), "The 4x4 rotation by angle (radians) about the y axis.");
  m.def("rotate_z", &rotate_z, py::arg("angle"), "The 4x4 rotation by angle (radians) about the z axis.");
  m.def("transform3d", &transform3d, py::arg("shape"), py::arg("m"), "A 3-D shape (points) moved by an affine 4x4 matrix.");
}

void bind_shapes(py::module_& m) {
  m.def("sphere_surface", &sphere_surface, py::arg("radius") = Fn(1.0),
        "The sphere as a parametric surface of (u, v) over [0, 1]^2, normal outward.");
  m.def("torus_surface", &torus_surface, py::arg("major_radius"), py::arg("minor_radius"),
        "The torus about the z axis as a parametric surface of (u, v), normal outward.");
  m.def("cylinder_surface", &cylinder_surface, py::arg("radius"), py::arg("height"),
        "The side of a cylinder about the z axis from z = 0 to height, a parametric surface of (u, v).");
  m.def("cone_surface", &cone_surface, py::arg("radius"), py::arg("height"),
        "The side of a cone about the z axis (base radius at z = 0, apex at height), a parametric surface.");
  m.def("disk_surface", &disk_surface, py::arg("radius"), "A disk in the plane z = 0, a parametric surface of (u, v).");
  m.def("superquadric_surface", &superquadric_surface, py::arg("e1"), py::arg("e2"), py::arg("radii") = Fn(1.0),
        "Barr's superquadric with exponents e1 (latitude) and e2 (longitude), a parametric surface.");
  m.def("implicit_sphere", &implicit_sphere, py::arg("radius"), py::arg("center") = Fn(0.0),
        "Signed distance to a sphere of p = (x(0), x(1), x(2)): negative inside.");
  m.def("implicit_box", &implicit_box, py::arg("half_extents"), "Signed distance to a centred box (half extents: a 3-vector Fn).");
  m.def("implicit_cylinder", &implicit_cylinder, py::arg("radius"), py::arg("half_height"),
        "Signed distance to a capped cylinder about the z axis with |z| <= half_height.");
  m.def("implicit_torus", &implicit_torus, py::arg("major_radius"), py::arg("minor_radius"),
        "Signed distance to a torus about the z axis.");
  m.def("implicit_gyroid", &implicit_gyroid, py::arg("frequency") = Fn(1.0), py::arg("thickness") = Fn(0.0),
        "The gyroid g < 0 (thickness 0) or the sheet |g| - thickness < 0.");
  m.def("csg_union", &csg_union, py::arg("a"), py::arg("b"), "min(a, b).");
  m.def("csg_intersection", &csg_intersection, py::arg("a"), py::arg("b"), "max(a, b).");
  m.def("csg_difference", &csg_difference, py::arg("a"), py::arg("b"), "a minus b: max(a, -b).");
  m.def("smooth_union", &smooth_union, py::arg("a"), py::arg("b"), py::arg("k"),
        "The polynomial smooth minimum with blend radius k > 0 (a fillet of size about k).");
  m.def("transform_implicit", &transform_implicit, py::arg("f"), py::arg("m"), "The implicit shape moved by an affine matrix.");
  m.def("translate_implicit", &translate_implicit, py::arg("f"), py::arg("offset"), "f(p - offset).");
  m.def("scale_implicit", &scale_implicit, py::arg("f"), py::arg("s"), "f(p / s).");
}

void bind_skeletal(py::module_& m) {
  const Fn p = skeleton_query_point();
  m.def("skeleton_query_point", &skeleton_query_point, "(x(0), x(1), x(2)).");
  m.def("distance2_to_point", &distance2_to_point, py::arg("c"), py::arg("p") = p, "|p - c|^2.");
  m.def("distance2_to_segment", &distance2_to_segment, py::arg("a"), py::arg("b"), py::arg("p") = p,
        "The squared distance from p to the segment a-b.");
  m.def("distance2_to_line", &distance2_to_line, py::arg("a"), py::arg("b"), py::arg("p") = p,
        "The squared distance from p to the line through a and b.");
  m.def("distance2_to_polyline", [](const std::vector<Point3>& v, const Fn& q) { return distance2_to_polyline(v, q); },
        py::arg("vertices"), py::arg("p") = p, "The squared distance from p to the polyline through the vertices.");
  m.def("distance2_to_triangle", &distance2_to_triangle, py::arg("a"), py::arg("b"), py::arg("c"), py::arg("p") = p,
        "The squared distance from p to the filled triangle abc.");
  m.def("distance_surface", [](const std::vector<Fn>& d2, const std::vector<double>& radii) {
        return distance_surface(std::span<const Fn>(d2), std::span<const double>(radii));
      }, py::arg("distances2"), py::arg("radii"),
      "min_i d2_i / r_i^2 - 1: the union of spheres / capsules of radius r_i around the elements (negative inside).");
  m.def("tapered_segment_surface", &tapered_segment_surface, py::arg("a"), py::arg("b"), py::arg("r1"), py::arg("r2"),
        py::arg("p") = p, "A tapered limb: d^2 / r^2 - 1 with the radius going from r1 at a to r2 at b.");

  py::enum_<Kernel>(m, "Kernel", "Convolution kernels: gaussian, bspline, wyvill.")
      .value("gaussian", Kernel::gaussian)
      .value("bspline", Kernel::bspline)
      .value("wyvill", Kernel::wyvill);
  m.def("point_source", &point_source, py::arg("c"), py::arg("r"), py::arg("w") = 1.0,
        py::arg("kernel") = Kernel::gaussian, py::arg("p") = p, "A point source's density w h(|p - c| / r).");
  m.def("segment_convolution",
        py::overload_cast<const Point3&, const Point3&, double, double, Kernel, const Fn&>(&segment_convolution),
        py::arg("a"), py::arg("b"), py::arg("r1"), py::arg("r2"), py::arg("kernel") = Kernel::gaussian, py::arg("p") = p,
        "The convolution density of the segment a -> b (closed form, sound bounds); a DENSITY, larger inside.");
  m.def("density_to_implicit", &density_to_implicit, py::arg("density"), py::arg("iso") = 0.5,
        "iso - D: a density field in genmod's convention (negative inside).");
  m.def("erf", &erf, py::arg("x"), "The error function, with an outward-rounded enclosure.");

  m.def("average_blend", [](const std::vector<Fn>& f) { return average_blend(std::span<const Fn>(f)); }, py::arg("fields"),
        "The mean of the fields: a smooth global blend.");
  m.def("range_blend", [](const std::vector<Fn>& f, const std::vector<double>& r, int t) {
        return range_blend(std::span<const Fn>(f), std::span<const double>(r), t);
      }, py::arg("primitives"), py::arg("ranges"), py::arg("thumbweight") = 2,
      "Rockwood's range-controlled blend of implicit primitives (elliptic for thumbweight 2).");
  m.def("rolling_ball_blend", &rolling_ball_blend, py::arg("a"), py::arg("b"), py::arg("rho"),
        "The rolling-ball fillet of radius rho between two signed distances.");
  m.def("product_blend", &product_blend, py::arg("p1"), py::arg("p2"), "1 - (1 - P1)(1 - P2) of two densities.");
}

}  // namespace

void bind_operators(py::module_& m) {
  bind_matrices(m);
  bind_shapes(m);
  bind_skeletal(m);
}

}  // namespace genmod::python
