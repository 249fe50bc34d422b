// Vector, matrix and transform operators: closed-form values, the shared properties
// (containment, derivatives, batch = scalar) and dimension errors.
#include "genmod/operators/matrix.hpp"
#include "genmod/operators/transform.hpp"
#include "genmod/operators/vector.hpp"
#include "operators/operator_properties.hpp"

#include <gtest/gtest.h>

namespace genmod {
namespace {

using testing::check_operator_properties;
using testing::unit_domain;

const Fn u = x(0), v = x(1), w = x(2);
// Smooth, nonconstant vectors of (u, v, w).
const Fn a = cat({u + 0.5, sin(v) * 2.0 + w, u * w - 1.0});
const Fn b = cat({cos(u + v), w * w + 0.3, v - 2.0 * u});

double at(const Fn& f, std::vector<double> p, std::size_t j = 0) { return evaluate(f, p)[j]; }

TEST(Vector, ValuesMatchClosedForms) {
  const std::vector<double> p = {0.2, 0.7, 0.4};
  const auto av = evaluate(a, p), bv = evaluate(b, p);
  EXPECT_NEAR(at(dot(a, b), p), av[0] * bv[0] + av[1] * bv[1] + av[2] * bv[2], 1e-14);
  EXPECT_NEAR(at(length(a), p), std::sqrt(av[0] * av[0] + av[1] * av[1] + av[2] * av[2]), 1e-14);
  EXPECT_NEAR(at(cross(a, b), p, 2), av[0] * bv[1] - av[1] * bv[0], 1e-14);
  EXPECT_NEAR(at(length(normalize(a)), p), 1.0, 1e-15);
  EXPECT_NEAR(at(dot(cross(a, b), a), p), 0.0, 1e-14);
  EXPECT_EQ(at(length(Fn(-3.0) * u), {0.5}), 1.5);
}

TEST(Vector, Properties) {
  for (const Fn& f : {dot(a, b), length(a), cross(a, b), normalize(b), cat({a, b})[4]})
    check_operator_properties(f, unit_domain(3), 11);
}

TEST(Vector, DimensionErrors) {
  EXPECT_THROW(dot(a, cat({u, v})), std::invalid_argument);
  EXPECT_THROW(cross(cat({u, v}), cat({u, v})), std::invalid_argument);
}

TEST(Matrix, ShapeRowsColumnsAndTranspose) {
  const Matrix m = matrix(cat({u, v, w, 1.0, 2.0, 3.0}), 2, 3);
  EXPECT_EQ(m.rows(), 2);
  EXPECT_EQ(m.cols(), 3);
  EXPECT_EQ(m[1].dim(), 3u);
  EXPECT_EQ(at(m[1], {}, 2), 3.0);
  EXPECT_TRUE(identical(m(0, 1), v));
  const Matrix t = transpose(m);
  EXPECT_EQ(t.rows(), 3);
  EXPECT_TRUE(identical(t(1, 0), v));
  EXPECT_TRUE(identical(m.column(2), cat({w, 3.0})));
  EXPECT_THROW(matrix(cat({u, v, w}), 2, 2), std::invalid_argument);
  EXPECT_THROW(m(2, 0), std::out_of_range);
  EXPECT_THROW(m * m, std::invalid_argument);
  EXPECT_THROW(m + transpose(m), std::invalid_argument);
  EXPECT_THROW(determinant(m), std::invalid_argument);
  EXPECT_THROW(inverse(m), std::invalid_argument);
}

// A well-conditioned parametric 3x3 matrix (diagonally dominant on the unit box).
Matrix sample_matrix() {
  return matrix(cat({3.0 + u, v, w * u, sin(w), 4.0 - v, u, 0.5 * v, cos(u), 5.0 + w}), 3, 3);
}

TEST(Matrix, DeterminantAndInverse) {
  const Matrix m = sample_matrix();
  const Matrix product = m * inverse(m);
  const std::vector<double> p = {0.3, 0.6, 0.9};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(at(product(r, c), p), r == c ? 1.0 : 0.0, 1e-14);
  // det(A B) = det A det B; det of a 2x2 by hand; det(A^T) = det A.
  const Matrix n = matrix(cat({1.0, u, v, 2.0, 0.0, w, 1.0, 1.0, 1.0}), 3, 3);
  EXPECT_NEAR(at(determinant(m * n), p), at(determinant(m), p) * at(determinant(n), p), 1e-12);
  EXPECT_NEAR(at(determinant(transpose(m)), p), at(determinant(m), p), 1e-12);
  EXPECT_NEAR(at(determinant(matrix(cat({u, v, w, 2.0}), 2, 2)), p), 0.3 * 2 - 0.6 * 0.9, 1e-15);
  // 5x5: the memoized expansion agrees with the product of a triangular matrix's diagonal.
  std::vector<Fn> e;
  for (int r = 0; r < 5; ++r)
    for (int c = 0; c < 5; ++c) e.push_back(c < r ? Fn(0.0) : (r == c ? 1.0 + u * (r + 1) : Fn(v + c)));
  EXPECT_NEAR(at(determinant(matrix(cat(e), 5, 5)), p), 1.3 * 1.6 * 1.9 * 2.2 * 2.5, 1e-12);
  // A singular matrix: the inverse is an error (NaN), not an infinity.
  EXPECT_TRUE(std::isnan(at(inverse(matrix(cat({u, u, u, u}), 2, 2)).fn(), p)));
}

TEST(Matrix, Properties) {
  const Matrix m = sample_matrix();
  const Fn vec = cat({u, v - w, 1.0});
  for (const Fn& f : {determinant(m), inverse(m).fn(), (m * transpose(m) - m).fn(), m * vec, (Fn(u) * m)[2]})
    check_operator_properties(f, unit_domain(3), 12);
}

TEST(Transform, ComposesRightToLeftAndActsOnShapes) {
  const double pi = std::acos(-1.0);
  // Translate then rotate a quarter turn about z: (1, 0, 0) -> (2, 0, 0) -> (0, 2, 0).
  const Matrix m = rotate_z(pi / 2) * translate(1.0, 0.0, 0.0);
  const auto q = evaluate(transform3d(cat({1.0, 0.0, 0.0}), m), std::vector<double>{});
  EXPECT_NEAR(q[0], 0.0, 1e-15);
  EXPECT_NEAR(q[1], 2.0, 1e-15);
  EXPECT_NEAR(q[2], 0.0, 1e-15);
  const auto r = evaluate(transform3d(cat({0.0, 1.0, 0.0}), rotate_x(pi / 2) * scale(2.0)), std::vector<double>{});
  EXPECT_NEAR(r[2], 2.0, 1e-15);
  const auto s = evaluate(transform3d(cat({0.0, 0.0, 1.0}), rotate_y(pi / 2)), std::vector<double>{});
  EXPECT_NEAR(s[0], 1.0, 1e-15);
  // A 2D shape is taken at z = 0; rotations preserve length.
  const Fn circle = cat({cos(2 * pi * u), sin(2 * pi * u)});
  const Fn swept = transform3d(circle, translate(cat({0.0, 0.0, v})) * rotate_x(v * 3.0) * scale(1.0 + w));
  EXPECT_NEAR(at(swept, {0.3, 0.0, 1.0}, 0), 2 * std::cos(2 * pi * 0.3), 1e-14);
  check_operator_properties(swept, unit_domain(3), 13);
  EXPECT_THROW(transform3d(cat({u, v, w, u}), m), std::invalid_argument);
  EXPECT_THROW(transform3d(circle, sample_matrix()), std::invalid_argument);
}

}  // namespace
}  // namespace genmod
