// The parts of the Python module, one function per binding file.
#pragma once

#include <pybind11/pybind11.h>

namespace genmod::python {

void bind_fn(pybind11::module_& m);          // Fn and the language (fn_bindings.cpp)
void bind_evaluation(pybind11::module_& m);  // numpy evaluation, bounds (numpy_eval.cpp)
void bind_mesh(pybind11::module_& m);        // meshes, validation, previews, implicit meshing
void bind_gallery(pybind11::module_& m);     // the model gallery (gallery_bindings.cpp)
void bind_batch(pybind11::module_& m);       // the batch engine (batch_bindings.cpp)
void bind_procedural(pybind11::module_& m);  // the procedural models and caches (procedural_bindings.cpp)
void bind_procedure_tools(pybind11::module_& m);  // PolyMesh, mesh tools, Python procedures (procedure_tool_bindings.cpp)
void bind_curves_and_sweeps(pybind11::module_& m);  // vectors, curves, sweeps, offsets, paths (curve_bindings.cpp)
void bind_higher_order_operators(pybind11::module_& m);  // integrate, tables, solver operators, more skeletal (operator_bindings.cpp)
void bind_operators(pybind11::module_& m);   // matrices, transforms, shapes, skeletal fields (shape_bindings.cpp)
void bind_solvers(pybind11::module_& m);     // solve, minimize and the queries (solver_bindings.cpp)

}  // namespace genmod::python
