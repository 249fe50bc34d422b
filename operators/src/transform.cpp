#include "genmod/operators/transform.hpp"

#include "dims.hpp"

namespace genmod {

namespace {

Matrix affine(const Fn& a00, const Fn& a01, const Fn& a02, const Fn& t0,  //
              const Fn& a10, const Fn& a11, const Fn& a12, const Fn& t1,  //
              const Fn& a20, const Fn& a21, const Fn& a22, const Fn& t2) {
  for (const Fn* f : {&a00, &a01, &a02, &t0, &a10, &a11, &a12, &t1, &a20, &a21, &a22, &t2})
    if (f->dim() != 1) detail::dimension_error("transform", "matrix entries must be scalar functions");
  return Matrix(cat({a00, a01, a02, t0, a10, a11, a12, t1, a20, a21, a22, t2, 0.0, 0.0, 0.0, 1.0}), 4, 4);
}

}  // namespace

Matrix translate(const Fn& tx, const Fn& ty, const Fn& tz) {
  return affine(1.0, 0.0, 0.0, tx, 0.0, 1.0, 0.0, ty, 0.0, 0.0, 1.0, tz);
}

Matrix translate(const Fn& t) {
  if (t.dim() != 3) detail::dimension_error("translate", "the offset has dimension " + std::to_string(t.dim()) + ", expected 3");
  return translate(t[0], t[1], t[2]);
}

Matrix scale(const Fn& sx, const Fn& sy, const Fn& sz) {
  return affine(sx, 0.0, 0.0, 0.0, 0.0, sy, 0.0, 0.0, 0.0, 0.0, sz, 0.0);
}

Matrix scale(const Fn& s) { return scale(s, s, s); }

Matrix rotate_x(const Fn& angle) {
  const Fn c = cos(angle), s = sin(angle);
  return affine(1.0, 0.0, 0.0, 0.0, 0.0, c, -s, 0.0, 0.0, s, c, 0.0);
}

Matrix rotate_y(const Fn& angle) {
  const Fn c = cos(angle), s = sin(angle);
  return affine(c, 0.0, s, 0.0, 0.0, 1.0, 0.0, 0.0, -s, 0.0, c, 0.0);
}

Matrix rotate_z(const Fn& angle) {
  const Fn c = cos(angle), s = sin(angle);
  return affine(c, -s, 0.0, 0.0, s, c, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

Fn transform3d(const Fn& shape, const Matrix& m) {
  if (m.rows() != 4 || m.cols() != 4)
    detail::dimension_error("transform3d", "the matrix is " + std::to_string(m.rows()) + "x" +
                                               std::to_string(m.cols()) + ", expected 4x4");
  Fn p;
  if (shape.dim() == 3) p = cat({shape, 1.0});
  else if (shape.dim() == 2) p = cat({shape, 0.0, 1.0});
  else detail::dimension_error("transform3d", "the shape has dimension " + std::to_string(shape.dim()) + ", expected 2 or 3");
  const Fn h = m * p;
  // The last row of an affine matrix is (0 0 0 1), so the homogeneous w is 1 and needs no
  // division.
  return cat({h[0], h[1], h[2]});
}

}  // namespace genmod
