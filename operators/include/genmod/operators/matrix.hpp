// Matrix operators of GENMOD (thesis App. A.3.5): GENMOD's MAN_MATRIX, one Fn of dimension
// rows * cols (row-major) plus its shape. Every operation scalarizes at construction, so a
// matrix product, determinant or inverse is an ordinary expression DAG (shared
// subexpressions are hash-consed) and gets the kernel's three methods for free.
//
// Example:
//   Fn a = x(0), b = x(1), c = x(2), d = x(3);
//   Matrix m = matrix(cat({a, b, c, d}), 2, 2);
//   Fn det = determinant(m);          // a d - b c
//   Fn row1 = m[1];                   // (c, d)
#pragma once

#include "genmod/kernel/fn.hpp"

namespace genmod {

class Matrix {
 public:
  // components.dim() must equal rows * cols (std::invalid_argument otherwise).
  Matrix(Fn components, int rows, int cols);
  static Matrix identity(int n);

  int rows() const noexcept { return rows_; }
  int cols() const noexcept { return cols_; }
  // The components, row-major (GENMOD's `.m`).
  const Fn& fn() const noexcept { return m_; }
  // Entry (r, c), 0-based; std::out_of_range outside the shape.
  Fn operator()(int r, int c) const;
  // Row projection M[r]: a function of dimension cols().
  Fn operator[](int r) const;
  Fn column(int c) const;

 private:
  Fn m_;
  int rows_, cols_;
};

// GENMOD's m_matrix.
inline Matrix matrix(const Fn& components, int rows, int cols) { return Matrix(components, rows, cols); }

Matrix transpose(const Matrix& m);
// Determinant of a square matrix by cofactor expansion (memoized on column subsets, so the
// DAG grows as n 2^n, not n!; no divisions, so it is defined everywhere).
Fn determinant(const Matrix& m);
// Inverse of a square matrix as adjugate / determinant (an error where det = 0).
Matrix inverse(const Matrix& m);

// Same shapes for + and -; cols(a) = rows(b) for *.
Matrix operator+(const Matrix& a, const Matrix& b);
Matrix operator-(const Matrix& a, const Matrix& b);
Matrix operator-(const Matrix& a);
Matrix operator*(const Matrix& a, const Matrix& b);
// A scalar function times every entry.
Matrix operator*(const Fn& s, const Matrix& m);
// Matrix times column vector: v.dim() must equal cols(m); the result has dimension rows(m).
Fn operator*(const Matrix& m, const Fn& v);

}  // namespace genmod
