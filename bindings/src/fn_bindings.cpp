// Fn in Python: the shape language with Python's operators. Comparisons build relations
// (0/1-valued functions), & | ~ build logical functions, and an Fn refuses to be used as a
// Python truth value, so `if f == g:` is an error instead of a silent identity test.
#include "bindings.hpp"

#include "genmod/kernel/expression.hpp"
#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/kernel/vm_format.hpp"

#include <pybind11/operators.h>
#include <pybind11/stl.h>

#include <sstream>

namespace py = pybind11;

namespace genmod::python {
namespace {

std::string describe(const Fn& f) {
  std::ostringstream os;
  os << "<genmod.Fn dim=" << f.dim() << " inputs=[";
  const std::vector<int> in = f.inputs();
  for (std::size_t k = 0; k < in.size(); ++k) os << (k ? ", " : "") << in[k];
  os << "]";
  double v;
  if (f.is_constant(&v)) os << " constant=" << v;
  os << ">";
  return os.str();
}

}  // namespace

void bind_fn(py::module_& m) {
  py::class_<Fn> fn(m, "Fn", R"doc(A function R^n -> R^m over parametric coordinates x(i) (GENMOD's MAN).

Build one from x(i), numbers and the operators: + - * / ** and unary -, comparisons
(< <= > >= == != give 0/1-valued relations), & | ~ (logical and, or, not on scalars),
indexing f[j] (component j), and the module functions (sqrt, sin, min, select, cat,
derivative, compose, ...). Scalars broadcast over vectors. Errors (sqrt of a negative, x/0)
are NaN at points and flagged in bounds.)doc");
  fn.def(py::init<double>(), py::arg("value"), "A constant scalar function.")
      .def_property_readonly("dim", &Fn::dim, "The number of components m.")
      .def_property_readonly("inputs", &Fn::inputs, "The coordinates the function depends on, ascending.")
      .def("is_constant", [](const Fn& f) { return f.is_constant(); }, "True for a constant scalar.")
      .def("__getitem__", [](const Fn& f, long j) {
        if (j < 0) j += static_cast<long>(f.dim());
        if (j < 0) throw std::out_of_range("genmod: negative component index");
        return f[static_cast<std::size_t>(j)];
      }, py::arg("j"), "Component j (negative counts from the end).")
      .def("__len__", &Fn::dim)
      .def("__repr__", &describe)
      .def("__bool__", [](const Fn&) -> bool {
        throw py::type_error(
            "genmod.Fn has no truth value: comparisons build relations (use genmod.identical to compare handles)");
      })
      .def("__hash__", [](const Fn& f) {
        std::size_t h = f.dim();
        for (NodeId n : f.nodes()) h = h * 1000003u ^ n;
        return h;
      })
      .def(py::self + py::self).def(py::self + double()).def(double() + py::self)
      .def(py::self - py::self).def(py::self - double()).def(double() - py::self)
      .def(py::self * py::self).def(py::self * double()).def(double() * py::self)
      .def(py::self / py::self).def(py::self / double()).def(double() / py::self)
      .def(-py::self)
      .def("__pow__", [](const Fn& a, const Fn& b) { return pow(a, b); }, py::is_operator())
      .def("__pow__", [](const Fn& a, double b) { return b == 2.0 ? square(a) : pow(a, Fn(b)); }, py::is_operator())
      .def("__rpow__", [](const Fn& b, double a) { return pow(Fn(a), b); }, py::is_operator())
      .def("__lt__", [](const Fn& a, const Fn& b) { return a < b; }, py::is_operator())
      .def("__lt__", [](const Fn& a, double b) { return a < Fn(b); }, py::is_operator())
      .def("__le__", [](const Fn& a, const Fn& b) { return a <= b; }, py::is_operator())
      .def("__le__", [](const Fn& a, double b) { return a <= Fn(b); }, py::is_operator())
      .def("__gt__", [](const Fn& a, const Fn& b) { return a > b; }, py::is_operator())
      .def("__gt__", [](const Fn& a, double b) { return a > Fn(b); }, py::is_operator())
      .def("__ge__", [](const Fn& a, const Fn& b) { return a >= b; }, py::is_operator())
      .def("__ge__", [](const Fn& a, double b) { return a >= Fn(b); }, py::is_operator())
      .def("__eq__", [](const Fn& a, const Fn& b) { return eq(a, b); }, py::is_operator())
      .def("__eq__", [](const Fn& a, double b) { return eq(a, Fn(b)); }, py::is_operator())
      .def("__ne__", [](const Fn& a, const Fn& b) { return ne(a, b); }, py::is_operator())
      .def("__ne__", [](const Fn& a, double b) { return ne(a, Fn(b)); }, py::is_operator())
      .def("__and__", [](const Fn& a, const Fn& b) { return a && b; }, py::is_operator())
      .def("__or__", [](const Fn& a, const Fn& b) { return a || b; }, py::is_operator())
      .def("__invert__", [](const Fn& a) { return !a; }, py::is_operator())
      .def("__abs__", [](const Fn& a) { return abs(a); });
  py::implicitly_convertible<double, Fn>();
  py::implicitly_convertible<int, Fn>();

  // A malformed or unreadable model file: a ValueError (genmod.VmFormatError) naming the line.
  py::register_exception<VmFormatError>(m, "VmFormatError", PyExc_ValueError).doc() =
      "A malformed or unreadable .vm model file; the message names the line.";
  m.def("load_vm", [](const std::string& path) { return load_vm(path); }, py::arg("path"),
        "Reads a .vm model file (x, y, z are x(0), x(1), x(2)); genmod.VmFormatError (a ValueError) names the line of a malformed file.");
  m.def("save_vm", [](const Fn& f, const std::string& path) { save_vm(path, f); }, py::arg("f"), py::arg("path"),
        "Writes a scalar function as a .vm model file (x(i) as var-N; ValueError for a vector or a custom operator).");
  fn.def("to_vm", [](const Fn& f) {
    std::ostringstream os;
    write_vm(os, f);
    return os.str();
  }, "The scalar function as .vm text (what save_vm writes).");
  m.def("live_nodes", &live_nodes, "The number of live expression nodes (the store reclaims what nothing holds).");
  m.def("live_custom_operators", &live_custom_operators, "The number of live custom operators.");
  m.def("x", &x, py::arg("i"), "The parametric coordinate x(i), 0 <= i < 64.");
  m.def("identical", [](const Fn& a, const Fn& b) { return identical(a, b); }, py::arg("a"), py::arg("b"),
        "True when both handles hold the same nodes (structurally equal functions are identical).");
  m.def("cat", [](const std::vector<Fn>& parts) {
    if (parts.empty()) throw std::invalid_argument("genmod.cat: needs at least one part");
    return cat(std::span<const Fn>(parts));
  }, py::arg("parts"), "The Cartesian product: the components of all parts, in order.");

  using Unary = Fn (*)(const Fn&);
  const std::pair<const char*, Unary> unary[] = {
      {"square", &square}, {"sqrt", &sqrt}, {"exp", &exp}, {"log", &log}, {"sin", &sin},
      {"cos", &cos}, {"tan", &tan}, {"asin", &asin}, {"acos", &acos}, {"atan", &atan},
      {"abs", &abs}, {"floor", &floor}, {"ceil", &ceil}, {"is_error", &is_error}};
  for (const auto& [name, f] : unary)
    m.def(name, f, py::arg("f"), (std::string(name) + "(f), componentwise.").c_str());
  m.def("pow", [](const Fn& a, const Fn& b) { return pow(a, b); }, py::arg("a"), py::arg("b"), "a ** b.");
  m.def("atan2", [](const Fn& y, const Fn& x) { return atan2(y, x); }, py::arg("y"), py::arg("x"), "The angle of (x, y), in (-pi, pi].");
  m.def("min", [](const Fn& a, const Fn& b) { return min(a, b); }, py::arg("a"), py::arg("b"), "The smaller of a and b (CSG union of implicit shapes).");
  m.def("max", [](const Fn& a, const Fn& b) { return max(a, b); }, py::arg("a"), py::arg("b"), "The larger of a and b (CSG intersection of implicit shapes).");
  m.def("select", [](const Fn& c, const Fn& t, const Fn& e) { return select(c, t, e); }, py::arg("cond"),
        py::arg("then"), py::arg("otherwise"), "if-then-else: cond is scalar (nonzero is true).");
  m.def("derivative", [](const Fn& f, int i) { return derivative(f, i); }, py::arg("f"), py::arg("i"),
        "d f / d x(i), built symbolically.");
  m.def("compose", [](const Fn& f, int i, const Fn& g) { return compose(f, i, g); }, py::arg("f"), py::arg("i"),
        py::arg("g"), "f with x(i) replaced by the scalar function g.");
}

}  // namespace genmod::python
