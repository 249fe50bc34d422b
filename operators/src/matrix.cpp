#include "genmod/operators/matrix.hpp"

#include "dims.hpp"

#include <bit>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace genmod {

Matrix::Matrix(Fn components, int rows, int cols) : m_(std::move(components)), rows_(rows), cols_(cols) {
  if (rows < 1 || cols < 1)
    detail::dimension_error("matrix", "shape " + std::to_string(rows) + "x" + std::to_string(cols) + " is empty");
  if (m_.dim() != static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols))
    detail::dimension_error("matrix", "a " + std::to_string(rows) + "x" + std::to_string(cols) +
                                          " matrix needs " + std::to_string(rows * cols) + " components, got " +
                                          std::to_string(m_.dim()));
}

Matrix Matrix::identity(int n) {
  std::vector<Fn> e;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) e.push_back(Fn(r == c ? 1.0 : 0.0));
  return Matrix(cat(e), n, n);
}

Fn Matrix::operator()(int r, int c) const {
  if (r < 0 || r >= rows_ || c < 0 || c >= cols_)
    throw std::out_of_range("genmod: matrix entry (" + std::to_string(r) + ", " + std::to_string(c) +
                            ") outside a " + std::to_string(rows_) + "x" + std::to_string(cols_) + " matrix");
  return m_[static_cast<std::size_t>(r * cols_ + c)];
}

Fn Matrix::operator[](int r) const {
  std::vector<Fn> row;
  for (int c = 0; c < cols_; ++c) row.push_back((*this)(r, c));
  return cat(row);
}

Fn Matrix::column(int c) const {
  std::vector<Fn> col;
  for (int r = 0; r < rows_; ++r) col.push_back((*this)(r, c));
  return cat(col);
}

Matrix transpose(const Matrix& m) {
  std::vector<Fn> e;
  for (int c = 0; c < m.cols(); ++c)
    for (int r = 0; r < m.rows(); ++r) e.push_back(m(r, c));
  return Matrix(cat(e), m.cols(), m.rows());
}

namespace {

void require_square(const char* op, const Matrix& m) {
  if (m.rows() != m.cols())
    detail::dimension_error(op, "the matrix is " + std::to_string(m.rows()) + "x" + std::to_string(m.cols()) +
                                    ", expected a square matrix");
}

// Determinant of the minor made of rows [n - |cols|, n) and the columns in the bit set
// `cols`, by expansion along its first row; memoized on the column set.
class MinorDeterminants {
 public:
  explicit MinorDeterminants(const Matrix& m) : m_(m) {
    if (m.rows() > 20) detail::dimension_error("determinant", "matrices larger than 20x20 are not supported");
  }

  Fn det(std::uint32_t cols) {
    if (auto it = memo_.find(cols); it != memo_.end()) return it->second;
    const int size = std::popcount(cols);
    const int row = m_.rows() - size;
    Fn sum;
    if (size == 1) {
      sum = m_(row, std::countr_zero(cols));
    } else {
      bool first = true;
      int sign_index = 0;  // position of the column inside the minor gives the cofactor sign
      for (int c = 0; c < m_.cols(); ++c) {
        if (!(cols >> c & 1u)) continue;
        const Fn term = m_(row, c) * det(cols & ~(1u << c));
        sum = first ? (sign_index % 2 ? -term : term) : (sign_index % 2 ? sum - term : sum + term);
        first = false;
        ++sign_index;
      }
    }
    memo_.emplace(cols, sum);
    return sum;
  }

 private:
  const Matrix& m_;
  std::unordered_map<std::uint32_t, Fn> memo_;
};

Matrix without(const Matrix& m, int skip_row, int skip_col) {
  std::vector<Fn> e;
  for (int r = 0; r < m.rows(); ++r)
    for (int c = 0; c < m.cols(); ++c)
      if (r != skip_row && c != skip_col) e.push_back(m(r, c));
  return Matrix(cat(e), m.rows() - 1, m.cols() - 1);
}

}  // namespace

Fn determinant(const Matrix& m) {
  require_square("determinant", m);
  MinorDeterminants d(m);
  return d.det((m.cols() == 32 ? 0u : (1u << m.cols())) - 1u);
}

Matrix inverse(const Matrix& m) {
  require_square("inverse", m);
  const int n = m.rows();
  const Fn det = determinant(m);
  if (n == 1) return Matrix(1.0 / m(0, 0), 1, 1);
  std::vector<Fn> e;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      const Fn cofactor = determinant(without(m, c, r));  // adjugate = transposed cofactors
      e.push_back(((r + c) % 2 ? -cofactor : cofactor) / det);
    }
  return Matrix(cat(e), n, n);
}

Matrix operator+(const Matrix& a, const Matrix& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols())
    detail::dimension_error("matrix +", "shapes differ");
  return Matrix(a.fn() + b.fn(), a.rows(), a.cols());
}

Matrix operator-(const Matrix& a, const Matrix& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols())
    detail::dimension_error("matrix -", "shapes differ");
  return Matrix(a.fn() - b.fn(), a.rows(), a.cols());
}

Matrix operator-(const Matrix& a) { return Matrix(-a.fn(), a.rows(), a.cols()); }

Matrix operator*(const Matrix& a, const Matrix& b) {
  if (a.cols() != b.rows())
    detail::dimension_error("matrix *", "a " + std::to_string(a.rows()) + "x" + std::to_string(a.cols()) +
                                            " matrix cannot multiply a " + std::to_string(b.rows()) + "x" +
                                            std::to_string(b.cols()) + " matrix");
  std::vector<Fn> e;
  for (int r = 0; r < a.rows(); ++r)
    for (int c = 0; c < b.cols(); ++c) {
      Fn sum = a(r, 0) * b(0, c);
      for (int k = 1; k < a.cols(); ++k) sum = sum + a(r, k) * b(k, c);
      e.push_back(sum);
    }
  return Matrix(cat(e), a.rows(), b.cols());
}

Matrix operator*(const Fn& s, const Matrix& m) {
  if (s.dim() != 1) detail::dimension_error("scalar * matrix", "the scalar has dimension " + std::to_string(s.dim()));
  return Matrix(s * m.fn(), m.rows(), m.cols());
}

Fn operator*(const Matrix& m, const Fn& v) {
  if (v.dim() != static_cast<std::size_t>(m.cols()))
    detail::dimension_error("matrix * vector", "a matrix with " + std::to_string(m.cols()) +
                                                   " columns cannot multiply a vector of dimension " +
                                                   std::to_string(v.dim()));
  return (m * Matrix(v, m.cols(), 1)).fn();
}

}  // namespace genmod
