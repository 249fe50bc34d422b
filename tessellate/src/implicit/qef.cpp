#include "implicit/qef.hpp"

#include <Eigen/Eigenvalues>

namespace genmod::implicit {

QefPoint solve_qef(std::span<const Vec3> points, std::span<const Vec3> normals) {
  Eigen::Vector3d mass = Eigen::Vector3d::Zero();
  for (const Vec3& p : points) mass += Eigen::Vector3d(p[0], p[1], p[2]);
  mass /= static_cast<double>(points.size());
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d n(normals[i][0], normals[i][1], normals[i][2]);
    const Eigen::Vector3d p(points[i][0], points[i][1], points[i][2]);
    a += n * n.transpose();
    b += n * n.dot(p - mass);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(a);
  const Eigen::Vector3d lambda = eig.eigenvalues();
  const double largest = lambda.cwiseAbs().maxCoeff();
  Eigen::Vector3d x = mass;
  int rank = 0;
  if (largest > 0.0) {
    // Truncated pseudo-inverse: a direction is constrained when its eigenvalue is at least
    // 10% of the largest (about 18 degrees between two planes).
    const Eigen::Vector3d rhs = eig.eigenvectors().transpose() * b;
    Eigen::Vector3d y = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
      if (lambda[k] >= 0.1 * largest) {
        y[k] = rhs[k] / lambda[k];
        ++rank;
      }
    x += eig.eigenvectors() * y;
  }
  return {{x[0], x[1], x[2]}, rank};
}

}  // namespace genmod::implicit
