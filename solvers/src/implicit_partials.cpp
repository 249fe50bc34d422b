#include "implicit_partials.hpp"

namespace genmod::detail {

Fn determinant(const std::vector<Fn>& m, std::size_t n) {
  if (n == 1) return m[0];
  if (n == 2) return m[0] * m[3] - m[1] * m[2];
  Fn det(0.0);
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<Fn> minor;
    for (std::size_t r = 1; r < n; ++r)
      for (std::size_t c = 0; c < n; ++c)
        if (c != j) minor.push_back(m[r * n + c]);
    const Fn term = m[j] * determinant(minor, n - 1);
    det = (j % 2 == 0) ? det + term : det - term;
  }
  return det;
}

std::vector<Fn> implicit_partials(const std::vector<Fn>& eqs, std::span<const int> unknowns,
                                  std::span<const int> free) {
  const std::size_t n = unknowns.size();
  if (eqs.size() != n || n == 0 || n > kMaxImplicitSize) return {};
  std::vector<Fn> jx;
  for (const Fn& h : eqs)
    for (int u : unknowns) jx.push_back(derivative(h, u));
  // dx_j/dp = -det(J_x with column j replaced by dh/dp) / det(J_x).
  const Fn det = determinant(jx, n);
  std::vector<Fn> partials;
  for (int p : free) {
    std::vector<Fn> col;
    for (const Fn& h : eqs) col.push_back(derivative(h, p));
    std::vector<Fn> dk;
    for (std::size_t j = 0; j < n; ++j) {
      std::vector<Fn> m = jx;
      for (std::size_t i = 0; i < n; ++i) m[i * n + j] = col[i];
      dk.push_back(-determinant(m, n) / det);
    }
    partials.push_back(cat(dk));
  }
  return partials;
}

}  // namespace genmod::detail
