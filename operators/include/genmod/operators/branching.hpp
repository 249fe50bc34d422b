// Branching operators of GENMOD (thesis App. A.3.10) beyond the kernel's select():
//
//  * index(fns, q): f_i with i = floor(q), clamped to [0, n-1] (so q = n, e.g. u = 1 in a
//    concatenation, selects the last function). Built as a chain of selects, so the
//    inclusion is the hull of the functions whose index the box of q can reach, and the
//    derivative is index(D fns, q).
//  * select_case(guards, evals): the value of the first eval whose guard is nonzero (GENMOD's
//    m_case; `case` is a C++ keyword). Where no guard is true the result is an error (NaN).
//
// All functions in one call must have the same dimension (std::invalid_argument otherwise).
#pragma once

#include "genmod/kernel/fn.hpp"

#include <initializer_list>
#include <span>

namespace genmod {

Fn index(std::span<const Fn> fns, const Fn& q);
Fn index(std::initializer_list<Fn> fns, const Fn& q);

Fn select_case(std::span<const Fn> guards, std::span<const Fn> evals);
Fn select_case(std::initializer_list<Fn> guards, std::initializer_list<Fn> evals);

// A function that is an error everywhere (NaN at points, certain error over boxes), of the
// given dimension.
Fn error_fn(std::size_t dim = 1);

}  // namespace genmod
