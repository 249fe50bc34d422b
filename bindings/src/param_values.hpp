// Procedure parameter values between Python and C++ (procedural_bindings.cpp): float, int,
// bool, str and 3-sequences become Double, Integer, Boolean, String and Vector values (a bool
// before an int: a Python bool is an int); anything else is refused naming the procedure and
// the parameter.
#pragma once

#include "genmod/procedural/param_value.hpp"

#include <pybind11/pybind11.h>

#include <string>

namespace genmod::python {

ParamValue param_from_python(const std::string& procedure, const std::string& name, const pybind11::handle& v);
pybind11::object param_to_python(const ParamValue& v);

}  // namespace genmod::python
