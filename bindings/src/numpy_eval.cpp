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

py::array evaluate(const ColumnTape& t, const Array& points) {
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
  py::array_t<double> result = single ? py::array_t<double>({static_cast<py::ssize_t>(m)})
                                      : py::array_t<double>({static_cast<py::ssize_t>(count), static_cast<py::ssize_t>(m)});
  const double* p = points.data();
  double* r = result.mutable_data();
  {
    // Blocks of points go through small structure-of-arrays buffers that stay in cache, so
    // the rows are read once and the results written once (a whole-array transpose each way
    // cost as much as the evaluation of a cheap function).
    py::gil_scoped_release unlocked;
    constexpr std::size_t kBlock = 4096;
    std::vector<double> in(n * kBlock), out(m * kBlock);
    std::vector<const double*> ins(n);
    std::vector<double*> outs(m);
    BatchEvaluator ev;
    for (std::size_t start = 0; start < count; start += kBlock) {
      const std::size_t b = std::min(kBlock, count - start);
      for (std::size_t i = 0; i < b; ++i)
        for (std::size_t k = 0; k < n; ++k) in[k * kBlock + i] = p[(start + i) * n + k];
      for (std::size_t k = 0; k < n; ++k) ins[k] = in.data() + k * kBlock;
      // One output: its row-major result is already a column, so write it in place.
      for (std::size_t j = 0; j < m; ++j) outs[j] = m == 1 ? r + start : out.data() + j * kBlock;
      ev.eval(t.tape, ins, b, outs);
      if (m != 1)
        for (std::size_t i = 0; i < b; ++i)
          for (std::size_t j = 0; j < m; ++j) r[(start + i) * m + j] = out[j * kBlock + i];
    }
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
point to (m,); tape.bound(box) encloses every value over an (n, 2) box to an (m, 2) array.)doc")
      .def(py::init<const Fn&, std::size_t>(), py::arg("f"), py::arg("n"))
      .def_property_readonly("n", [](const ColumnTape& t) { return t.columns; })
      .def_property_readonly("m", [](const ColumnTape& t) { return t.tape.num_outputs(); })
      .def_property_readonly("size", [](const ColumnTape& t) { return t.tape.size(); }, "The number of clauses.")
      .def("__call__", &evaluate, py::arg("points"))
      .def("bound", &bound, py::arg("box"));

  auto fn = py::reinterpret_borrow<py::class_<Fn>>(m.attr("Fn"));
  // The number of coordinates a points array (last axis) or a box (rows) gives.
  auto columns_of = [](const Array& a, bool is_box) -> std::size_t {
    if (is_box) return a.ndim() >= 1 ? static_cast<std::size_t>(a.shape(0)) : 0;
    return static_cast<std::size_t>(a.ndim() == 1 ? a.shape(0) : a.ndim() == 2 ? a.shape(1) : 0);
  };
  fn.def("__call__", [columns_of](const Fn& f, const Array& points) {
        return evaluate(ColumnTape(f, columns_of(points, false)), points);
      }, py::arg("points"),
      "Values at an (N, n) array of points (column k is x(k)) as (N, m); compiles a tape each call (use genmod.Tape for repeated calls).")
      .def("bound", [columns_of](const Fn& f, const Array& box) {
        return bound(ColumnTape(f, columns_of(box, true)), box);
      }, py::arg("box"), "An enclosure of every value over an (n, 2) box, as (m, 2) [lo, hi] rows.");
}

}  // namespace genmod::python
