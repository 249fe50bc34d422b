// The compiled part of the Python package: genmod._genmod. Each binding file adds one part of
// the API; C++ exceptions become Python exceptions with the same messages (pybind11 maps
// std::invalid_argument to ValueError, std::out_of_range to IndexError, std::runtime_error to
// RuntimeError).
#include "bindings.hpp"

PYBIND11_MODULE(_genmod, m) {
  m.doc() = "genmod: generative modeling with interval arithmetic (the compiled core)";
  genmod::python::bind_fn(m);
  genmod::python::bind_evaluation(m);
  genmod::python::bind_operators(m);
  genmod::python::bind_curves_and_sweeps(m);
  genmod::python::bind_higher_order_operators(m);
  genmod::python::bind_solvers(m);
  genmod::python::bind_mesh(m);
  genmod::python::bind_gallery(m);
  genmod::python::bind_batch(m);
  genmod::python::bind_procedural(m);
  genmod::python::bind_procedure_tools(m);
}
