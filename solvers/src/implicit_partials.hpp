// Private: derivatives of implicitly defined functions (snyder.md section 3.3), shared by the
// solve and minimize operators.
#pragma once

#include "genmod/kernel/fn.hpp"

#include <span>
#include <vector>

namespace genmod::detail {

// Largest system differentiated symbolically (Cramer's rule grows as n!).
inline constexpr std::size_t kMaxImplicitSize = 4;

// Determinant of the n x n matrix m (row major) by cofactor expansion.
Fn determinant(const std::vector<Fn>& m, std::size_t n);

// For a square system eqs(x, p) = 0 (n = unknowns.size() equations), the partial derivatives
// of the solution x(p) with respect to each free coordinate, dx/dp_k = -J_x^{-1} dh/dp_k, built
// by Cramer's rule: one Fn of dimension n per free coordinate, over the unknowns and free
// coordinates (substitute the solution for the unknowns to use it). Empty when
// n > kMaxImplicitSize or the system is not square.
std::vector<Fn> implicit_partials(const std::vector<Fn>& eqs, std::span<const int> unknowns,
                                  std::span<const int> free);

}  // namespace genmod::detail
