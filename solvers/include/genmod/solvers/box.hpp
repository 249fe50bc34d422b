// Boxes: the search space of the interval solvers, one interval per unknown.
#pragma once

#include "genmod/kernel/interval.hpp"

#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace genmod {

using Box = std::vector<Interval>;

// The largest width of the box's sides, rounded up (w(X) of snyder.md section 4.1).
double width(std::span<const Interval> box) noexcept;
// The index of the widest side (the first one on ties).
std::size_t widest_side(std::span<const Interval> box) noexcept;
// The midpoint of every side.
std::vector<double> midpoint(std::span<const Interval> box);
bool contains(std::span<const Interval> outer, std::span<const Interval> inner) noexcept;
bool contains(std::span<const Interval> box, std::span<const double> point) noexcept;
Box hull(std::span<const Interval> a, std::span<const Interval> b);
// Splits side `dim` at its midpoint: the two halves share the midpoint face and their union
// is the box (snyder.md section 4.8).
std::pair<Box, Box> bisect(std::span<const Interval> box, std::size_t dim);

// Throws std::invalid_argument naming `who` and the side if the box is not a search space:
// a wrong number of sides, or a side that is empty or unbounded.
void check_search_box(std::span<const Interval> box, std::size_t dims, const std::string& who);

}  // namespace genmod
