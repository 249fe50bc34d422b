// numpy in and out: an Fn or a compiled Tape evaluated on an (N, n) array of points (column k is
// the coordinate x(k)) to (N, m) with the batch evaluator (no per-point Python work, the GIL
// released), and bounded over a box given as an (n, 2) array of [lo, hi] rows.
#include "arrays.hpp"
#include "bindings.hpp"

#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/tape.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <numeric>
#include <string>

namespace py = pybind11;

namespace genmod::python {
namespace {

using Array = DoubleArray;

// A tape over the coordinates x(0) .. x(columns - 1), in that order.
struct ColumnTape {
  ColumnTape(const Fn& f, std::size_t n) : tape(f, coordinates(f, n)), columns(n) {}

  static std::vector<int> coordinates(const Fn& f, std::size_t n) {
    const std::vector<int> in = f.inputs();
    if (!in.empty() && static_cast<std::size_t>(in.back()) >= n)
      throw std::invalid_argument("genmod: the function depends on x(" + std::to_string(in.back()) + ") but the points have " +
                                  std::to_string(n) + " column" + (n == 1 ? "" : "s"));
    std::vector<int> all(n);
    std::iota(all.begin(), all.end(), 0);
    return all;
  }

  Tape tape;
  std::size_t columns;
};

// A 2-D view of doubles: element (i, k) at data[i * row + k * col] (strides in elements).
struct View {
  double* data;
  std::ptrdiff_t row, col;
};

View view_of(const py::array& a, bool single) {
  const auto step = [&](int axis) { return static_cast<std::ptrdiff_t>(a.strides(axis) / static_cast<py::ssize_t>(sizeof(double))); };
  return {static_cast<double*>(const_cast<void*>(a.data())), single ? 1 : step(0), step(single ? 0 : 1)};
}

// Strides the batch evaluator reads in place: whole elements, forward.
bool usable_strides(const py::array& a) {
  for (py::ssize_t axis = 0; axis < a.ndim(); ++axis)
    if (a.strides(axis) <= 0 || a.strides(axis) % static_cast<py::ssize_t>(sizeof(double)) != 0) return false;
  return true;
}

// Points as doubles, in their own layout when they already are doubles with forward strides
// (C- or Fortran-ordered, or a strided view), otherwise converted to a C-ordered copy.
py::array points_array(const py::object& points) {
  if (py::isinstance<py::array>(points)) {
    py::array a = py::reinterpret_borrow<py::array>(points);
    if (a.dtype().is(py::dtype::of<double>()) && usable_strides(a)) return a;
  }
  Array converted = Array::ensure(points);
  if (!converted) throw std::invalid_argument("genmod: points must be an array of numbers");
  return converted;
}

// Evaluates the rows of `in` (count x n) into the rows of `out` (count x m) in place: column k
// of the input starts at in.data + k * in.col and steps by in.row (1 for a Fortran-ordered
// array, n for a C-ordered one), and likewise for the output.
void evaluate_into(const Tape& tape, View in, std::size_t n, View out, std::size_t m, std::size_t count) {
  std::vector<const double*> ins(n);
  std::vector<double*> outs(m);
  for (std::size_t k = 0; k < n; ++k) ins[k] = in.data + static_cast<std::ptrdiff_t>(k) * in.col;
  for (std::size_t j = 0; j < m; ++j) outs[j] = out.data + static_cast<std::ptrdiff_t>(j) * out.col;
  BatchEvaluator().eval(tape, ins, count, outs, static_cast<std::size_t>(in.row), static_cast<std::size_t>(out.row));
}

py::array evaluate(const ColumnTape& t, const py::object& points_object, const py::object& out_object) {
  const py::array points = points_array(points_object);
  if (points.ndim() != 1 && points.ndim() != 2)
    throw std::invalid_argument("genmod: points must be an array of shape (n,) or (N, n), got " +
                                std::to_string(points.ndim()) + " dimensions");
  const bool single = points.ndim() == 1;
  const std::size_t count = single ? 1 : static_cast<std::size_t>(points.shape(0));
  const std::size_t n = static_cast<std::size_t>(points.shape(single ? 0 : 1));
  if (n != t.columns)
    throw std::invalid_argument("genmod: the points have " + std::to_string(n) + " columns, the tape " +
                                std::to_string(t.columns));
  const std::size_t m = t.tape.num_outputs();
  const auto N = static_cast<py::ssize_t>(count), M = static_cast<py::ssize_t>(m);
  py::array result;
  if (!out_object.is_none()) {
    // The caller's array (no allocation: a loop over many batches reuses one).
    if (!py::isinstance<py::array>(out_object)) throw std::invalid_argument("genmod: out must be a numpy array");
    result = py::reinterpret_borrow<py::array>(out_object);
    const bool shape_ok = single ? result.ndim() == 1 && result.shape(0) == M
                                 : result.ndim() == 2 && result.shape(0) == N && result.shape(1) == M;
    if (!shape_ok)
      throw std::invalid_argument("genmod: out must have shape " + (single ? "(" + std::to_string(m) + ",)"
                                  : "(" + std::to_string(count) + ", " + std::to_string(m) + ")"));
    if (!result.dtype().is(py::dtype::of<double>()) || !result.writeable() || !usable_strides(result))
      throw std::invalid_argument("genmod: out must be a writeable array of float64 with forward strides");
  } else if (single) {
    result = py::array_t<double>(M);
  } else if (points.flags() & py::array::f_style) {
    result = py::array_t<double, py::array::f_style>({N, M});  // columns in, columns out
  } else {
    result = py::array_t<double>({N, M});
  }
  const View in = view_of(points, single), out = view_of(result, single);
  if (count > 0) {
    py::gil_scoped_release unlocked;
    evaluate_into(t.tape, in, n, out, m, count);
  }
  return result;
}

py::array bound(const ColumnTape& t, const Array& box) {
  const std::vector<Interval> b = box_from_array(box, "genmod: a box");
  if (b.size() != t.columns)
    throw std::invalid_argument("genmod: the box has " + std::to_string(b.size()) + " rows, the tape " +
                                std::to_string(t.columns));
  IntervalEvaluator ev;
  return to_array(ev.eval(t.tape, b));
}

}  // namespace

void bind_evaluation(py::module_& m) {
  py::class_<ColumnTape>(m, "Tape", R"doc(A function compiled once for evaluation over the coordinates x(0) .. x(n-1).

tape(points) evaluates an (N, n) array (column k is x(k)) to an (N, m) array, or an (n,)
point to (m,); tape(points, out=a) writes into a float64 array a of that shape instead of a new
one. Any float64 layout with forward strides is read in place (no copy); a Fortran-ordered
input gives a Fortran-ordered result. tape.bound(box) encloses every value over an (n, 2)
box to an (m, 2) array.)doc")
      .def(py::init<const Fn&, std::size_t>(), py::arg("f"), py::arg("n"))
      .def_property_readonly("n", [](const ColumnTape& t) { return t.columns; })
      .def_property_readonly("m", [](const ColumnTape& t) { return t.tape.num_outputs(); })
      .def_property_readonly("size", [](const ColumnTape& t) { return t.tape.size(); }, "The number of clauses.")
      .def("__call__", &evaluate, py::arg("points"), py::arg("out") = py::none())
      .def("bound", &bound, py::arg("box"));

  auto fn = py::reinterpret_borrow<py::class_<Fn>>(m.attr("Fn"));
  // The number of coordinates a points array (last axis) or a box (rows) gives.
  auto columns_of = [](const py::array& a, bool is_box) -> std::size_t {
    if (is_box) return a.ndim() >= 1 ? static_cast<std::size_t>(a.shape(0)) : 0;
    return static_cast<std::size_t>(a.ndim() == 1 ? a.shape(0) : a.ndim() == 2 ? a.shape(1) : 0);
  };
  fn.def("__call__", [columns_of](const Fn& f, const py::object& points, const py::object& out) {
        const py::array a = points_array(points);
        return evaluate(ColumnTape(f, columns_of(a, false)), a, out);
      }, py::arg("points"), py::arg("out") = py::none(),
      "Values at an (N, n) array of points (column k is x(k)) as (N, m); compiles a tape each call (use genmod.Tape for repeated calls).")
      .def("bound", [columns_of](const Fn& f, const Array& box) {
        return bound(ColumnTape(f, columns_of(box, true)), box);
      }, py::arg("box"), "An enclosure of every value over an (n, 2) box, as (m, 2) [lo, hi] rows.");
}

}  // namespace genmod::python
