// The parts of the Python module, one function per binding file.
#pragma once

#include <pybind11/pybind11.h>

namespace genmod::python {

void bind_fn(pybind11::module_& m);          // Fn and the language (fn_bindings.cpp)
void bind_evaluation(pybind11::module_& m);  // numpy evaluation, bounds (numpy_eval.cpp)

}  // namespace genmod::python
