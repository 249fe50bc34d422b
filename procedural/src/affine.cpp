#include "genmod/procedural/affine.hpp"


namespace genmod {

Affine Affine::translation(const Vec3& t) {
  Affine a;
  for (int r = 0; r < 3; ++r) a.m[r][3] = t[r];
  return a;
}

Affine Affine::scaling(double s) {
  Affine a;
  for (int r = 0; r < 3; ++r) a.m[r][r] = s;
  return a;
}

Vec3 Affine::apply(const Vec3& p) const {
  Vec3 q;
  for (int r = 0; r < 3; ++r) q[r] = m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + m[r][3];
  return q;
}

Affine operator*(const Affine& a, const Affine& b) {
  Affine c;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 4; ++k) {
      double s = k == 3 ? a.m[r][3] : 0.0;
      for (int j = 0; j < 3; ++j) s += a.m[r][j] * b.m[j][k];
      c.m[r][k] = s;
    }
  return c;
}

void apply_affine(const Affine& xf, PolyMesh& mesh) {
  for (PolyMesh::VertexHandle v : mesh.vertices()) mesh.set_point(v, xf.apply(mesh.point(v)));
}

}  // namespace genmod
