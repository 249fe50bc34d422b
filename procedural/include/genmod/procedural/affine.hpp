// The affine placement passed in a procedure's context (Morkel's VRTransformation): a 3x3
// linear part and a translation. Procedures that want it apply it themselves (apply_affine).
#pragma once

#include "genmod/procedural/poly_mesh.hpp"

#include <array>

namespace genmod {

struct Affine {
  // Row-major 3x4: p' = L p + t with L = m[r][0..2], t = m[r][3].
  std::array<std::array<double, 4>, 3> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};

  static Affine translation(const Vec3& t);
  static Affine scaling(double s);
  Vec3 apply(const Vec3& p) const;
  // (a * b).apply(p) == a.apply(b.apply(p)).
  friend Affine operator*(const Affine& a, const Affine& b);
  bool operator==(const Affine&) const = default;
};

// Maps every vertex of `mesh` by `xf`.
void apply_affine(const Affine& xf, PolyMesh& mesh);
// Adds a copy of `part` mapped by `xf` to `mesh` (vertices, faces in order, labels).
void append_mesh(PolyMesh& mesh, const PolyMesh& part, const Affine& xf = {});

}  // namespace genmod
