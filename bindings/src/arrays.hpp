// numpy conversions shared by the binding files: boxes and intervals as (..., 2) arrays of
// [lo, hi] (an empty interval is [nan, nan]), points and parameter vectors as 1-D arrays.
#pragma once

#include "genmod/kernel/interval.hpp"

#include <pybind11/numpy.h>

#include <array>
#include <span>
#include <string>
#include <vector>

namespace genmod::python {

using DoubleArray = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

// An (n, 2) array of [lo, hi] rows; std::invalid_argument naming `what` for another shape or a
// row that is not an interval (lo > hi, NaN).
std::vector<Interval> box_from_array(const DoubleArray& a, const std::string& what);
// One interval from a (2,) array [lo, hi], with the same checks.
Interval interval_from_array(const DoubleArray& a, const std::string& what);
// A (n,) array of finite numbers; `n` = 0 accepts any length.
std::vector<double> vector_from_array(const DoubleArray& a, std::size_t n, const std::string& what);
std::array<double, 3> point3_from_array(const DoubleArray& a, const std::string& what);

pybind11::array_t<double> to_array(const Interval& x);                  // (2,)
pybind11::array_t<double> to_array(std::span<const Interval> box);      // (n, 2)
pybind11::array_t<double> to_array(std::span<const double> values);     // (n,)
// (K, n, 2): K boxes of n sides each.
pybind11::array_t<double> boxes_to_array(const std::vector<std::vector<Interval>>& boxes, std::size_t n);

}  // namespace genmod::python
