// Vector operators of GENMOD (thesis App. A.3.4). They scalarize at construction: the
// result is an ordinary Fn of sums and products, so tapes stay scalar and the kernel's three
// methods (point, inclusion, derivative) apply unchanged. Cartesian product and projection
// are the kernel's cat() and Fn::operator[].
//
// Example:
//   Fn s = cat({x(0), x(1), square(x(0)) + square(x(1))});       // a paraboloid
//   Fn n = normalize(cross(derivative(s, 0), derivative(s, 1)));   // surface normal
#pragma once

#include "genmod/kernel/fn.hpp"

namespace genmod {

// Euclidean length ||f|| (for a scalar f, |f|).
Fn length(const Fn& f);
// f . g; equal dimensions required (std::invalid_argument otherwise).
Fn dot(const Fn& f, const Fn& g);
// f x g; both of dimension 3.
Fn cross(const Fn& f, const Fn& g);
// f / ||f|| (an error where f = 0).
Fn normalize(const Fn& f);

}  // namespace genmod
