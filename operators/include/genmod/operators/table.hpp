// Tables (GENMOD's m_table, thesis App. A.3.7): multilinear interpolation of an
// s-dimensional rectilinear array of n0-dimensional samples.
//
// `dimen` = (n0, n1, ..., ns): the table has n1 x ... x ns grid nodes of n0 values each,
// stored with the lowest-index dimension varying fastest (the n0 values of a node, then
// along n1, ...). `in` has dimension s; coordinate k in [0, 1] maps node j of dimension k to
// in_k = j / (n_k - 1). Outside [0, 1] the table is an error (NaN), not a clamp.
//
//  * inclusion: for each overlapped cell, the interpolant at the corners of the part of the
//    box inside the cell (a multilinear function takes its extremes at the corners of a
//    box), so the enclosure is the exact range up to a rounding allowance;
//  * derivative: d/d in_k is again a table: piecewise constant in dimension k (the cell
//    differences times n_k - 1), multilinear in the others.
//
// Bad input (n_k < 2 for k >= 1, n0 < 1, a sample count that is not the product, non-finite
// samples, `in` of the wrong dimension) throws std::invalid_argument.
//
// Example:
//   const double heights[] = {0, 1, 1, 2};                       // 2 x 2 nodes, scalar
//   Fn h = table(heights, std::vector<int>{1, 2, 2}, cat({x(0), x(1)}));   // = x(0) + x(1)
#pragma once

#include "genmod/kernel/fn.hpp"

#include <span>

namespace genmod {

Fn table(std::span<const double> samples, std::span<const int> dimen, const Fn& in);

}  // namespace genmod
