// Quadric error minimization (as in dual contouring): the point closest, in the least-squares
// sense, to the tangent planes through `points` with unit `normals`. Directions in which the
// planes do not constrain the point (eigenvalues of the normal matrix below a fraction of the
// largest) stay at the mass point, so smooth pieces give a point near the middle of the
// samples and two or three independent planes give their edge or corner.
#pragma once

#include "implicit/frame.hpp"

#include <span>

namespace genmod::implicit {

struct QefPoint {
  Vec3 point;
  int rank;  // independent planes: 1 smooth, 2 an edge, 3 a corner
};

QefPoint solve_qef(std::span<const Vec3> points, std::span<const Vec3> normals);

}  // namespace genmod::implicit
