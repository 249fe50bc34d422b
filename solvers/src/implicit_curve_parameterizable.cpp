// The robust global parameterizability test (snyder.md section 5.2.3, Theorem 5.5): the
// interval Jacobian minor J_k (column k removed) is regular.
#include "genmod/kernel/inclusion.hpp"
#include "genmod/solvers/implicit_curve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace genmod {
namespace {

// Determinant of the square interval matrix a (row-major, m x m) by cofactor expansion along
// the first row. Each term is an interval product, so the result encloses the determinant of
// every real matrix in a (with the usual overestimation).
Interval cofactor_determinant(const std::vector<Interval>& a, std::size_t m) {
  if (m == 1) return a[0];
  if (m == 2) return a[0] * a[3] - a[1] * a[2];
  Interval det(0.0);
  std::vector<Interval> minor((m - 1) * (m - 1));
  for (std::size_t c = 0; c < m; ++c) {
    std::size_t p = 0;
    for (std::size_t r = 1; r < m; ++r)
      for (std::size_t cc = 0; cc < m; ++cc)
        if (cc != c) minor[p++] = a[r * m + cc];
    const Interval term = a[c] * cofactor_determinant(minor, m - 1);
    det = (c % 2 == 0) ? det + term : det - term;
  }
  return det;
}

std::vector<Interval> minor_of(std::span<const Interval> jacobian, std::size_t m, std::size_t skip) {
  if (jacobian.size() != m * (m + 1) || skip > m)
    throw std::invalid_argument("genmod: jacobian minor: expected an m x (m + 1) matrix and a column index <= m");
  std::vector<Interval> a;
  a.reserve(m * m);
  for (std::size_t r = 0; r < m; ++r)
    for (std::size_t c = 0; c <= m; ++c)
      if (c != skip) a.push_back(jacobian[r * (m + 1) + c]);
  return a;
}

double magnitude(const Interval& x) { return std::max(std::abs(x.lo()), std::abs(x.hi())); }
double mignitude(const Interval& x) { return x.contains_zero() ? 0.0 : std::min(std::abs(x.lo()), std::abs(x.hi())); }

// Y = mid(a)^-1 by Gauss-Jordan elimination with partial pivoting; false if (nearly) singular.
// Y need not be an exact inverse: it only preconditions, the test below is rigorous for any Y.
bool midpoint_inverse(const std::vector<Interval>& a, std::size_t m, std::vector<double>& y) {
  std::vector<double> w(m * 2 * m, 0.0);
  for (std::size_t r = 0; r < m; ++r) {
    for (std::size_t c = 0; c < m; ++c) w[r * 2 * m + c] = a[r * m + c].mid();
    w[r * 2 * m + m + r] = 1.0;
  }
  for (std::size_t c = 0; c < m; ++c) {
    std::size_t piv = c;
    for (std::size_t r = c + 1; r < m; ++r)
      if (std::abs(w[r * 2 * m + c]) > std::abs(w[piv * 2 * m + c])) piv = r;
    const double p = w[piv * 2 * m + c];
    if (!(std::abs(p) > 1e-300) || !std::isfinite(p)) return false;
    if (piv != c)
      for (std::size_t k = 0; k < 2 * m; ++k) std::swap(w[c * 2 * m + k], w[piv * 2 * m + k]);
    for (std::size_t k = 0; k < 2 * m; ++k) w[c * 2 * m + k] /= p;
    for (std::size_t r = 0; r < m; ++r) {
      if (r == c) continue;
      const double f = w[r * 2 * m + c];
      if (f == 0.0) continue;
      for (std::size_t k = 0; k < 2 * m; ++k) w[r * 2 * m + k] -= f * w[c * 2 * m + k];
    }
  }
  y.assign(m * m, 0.0);
  for (std::size_t r = 0; r < m; ++r)
    for (std::size_t c = 0; c < m; ++c) y[r * m + c] = w[r * 2 * m + m + c];
  return std::all_of(y.begin(), y.end(), [](double v) { return std::isfinite(v); });
}

// Y a strictly diagonally dominant (computed in interval arithmetic) implies every real matrix
// in a is nonsingular: Y A is then nonsingular for each A in a.
bool preconditioned_dominant(const std::vector<Interval>& a, std::size_t m) {
  std::vector<double> y;
  if (!midpoint_inverse(a, m, y)) return false;
  for (std::size_t i = 0; i < m; ++i) {
    Interval off(0.0);
    Interval diag(0.0);
    for (std::size_t j = 0; j < m; ++j) {
      Interval s(0.0);
      for (std::size_t l = 0; l < m; ++l) s += Interval(y[i * m + l]) * a[l * m + j];
      if (s.is_empty() || !std::isfinite(s.lo()) || !std::isfinite(s.hi())) return false;
      if (j == i)
        diag = s;
      else
        off += Interval(magnitude(s));
    }
    if (!(mignitude(diag) > off.hi())) return false;
  }
  return true;
}

}  // namespace

Interval jacobian_minor_determinant(std::span<const Interval> jacobian, std::size_t m, std::size_t skip) {
  if (m == 0) throw std::invalid_argument("genmod: jacobian minor: m must be >= 1");
  return cofactor_determinant(minor_of(jacobian, m, skip), m);
}

bool jacobian_minor_regular(std::span<const Interval> jacobian, std::size_t m, std::size_t skip) {
  if (m == 0) throw std::invalid_argument("genmod: jacobian minor: m must be >= 1");
  for (const Interval& v : jacobian)
    if (v.is_empty() || !std::isfinite(v.lo()) || !std::isfinite(v.hi())) return false;
  const std::vector<Interval> a = minor_of(jacobian, m, skip);
  const Interval det = cofactor_determinant(a, m);
  if (!det.is_empty() && !det.contains_zero()) return true;
  return m > 1 && preconditioned_dominant(a, m);
}

std::vector<int> parameterizable_coordinates(const Fn& F, Coordinates coords, const Box& box) {
  const std::size_t n = coords.size();
  if (n < 2 || F.dim() != n - 1)
    throw std::invalid_argument("genmod: parameterizable_coordinates: F must have coords.size() - 1 components");
  check_search_box(box, n, "parameterizable_coordinates");
  InclusionFunction incl(F, coords);
  std::vector<Interval> jac;
  incl.eval(box, kAllForms, &jac);
  std::vector<int> out;
  if (jac.size() != (n - 1) * n) return out;
  for (std::size_t k = 0; k < n; ++k)
    if (jacobian_minor_regular(jac, n - 1, k)) out.push_back(static_cast<int>(k));
  return out;
}

}  // namespace genmod
