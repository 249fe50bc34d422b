#include "nonmanifold/face_follower.hpp"

#include <cmath>

namespace genmod::nonmanifold {

namespace {

Point sub(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Point add(const Point& a, const Point& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Point scale(const Point& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Point cross(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Point unit(const Point& a) {
  const double l = std::sqrt(dot(a, a));
  return l > 0.0 ? scale(a, 1.0 / l) : Point{0.0, 0.0, 0.0};
}

}  // namespace

std::optional<Point> follow_to_junction(RegionEvaluator& f, const std::array<Point, 3>& face, Point p1, Point p2, int a,
                                        int b, std::size_t max_steps) {
  const Point normal = cross(sub(face[1], face[0]), sub(face[2], face[0]));
  const Point centroid = scale(add(add(face[0], face[1]), face[2]), 1.0 / 3.0);
  // In-plane unit normals of the three edges, pointing into the face.
  std::array<Point, 3> inward;
  for (int e = 0; e < 3; ++e) {
    Point n = unit(cross(normal, sub(face[(e + 1) % 3], face[e])));
    if (dot(n, sub(centroid, face[e])) < 0.0) n = scale(n, -1.0);
    inward[static_cast<std::size_t>(e)] = n;
  }
  const Point d = sub(p2, p1);
  const double side = std::sqrt(dot(d, d));
  if (!(side > 0.0)) return std::nullopt;
  // The first apex: the equilateral triangle on p1-p2 on the side of the face's interior.
  const Point mid = scale(add(p1, p2), 0.5);
  Point toward = sub(centroid, mid);
  toward = unit(sub(toward, scale(d, dot(toward, d) / (side * side))));
  Point apex = add(mid, scale(toward, side * std::sqrt(3.0) / 2.0));
  for (std::size_t step = 0; step < max_steps; ++step) {
    for (int e = 0; e < 3; ++e)
      if (dot(sub(apex, face[e]), inward[static_cast<std::size_t>(e)]) < -side) return std::nullopt;
    const int r = f.region(apex);
    Point dropped;
    if (r == a) {
      dropped = p1;
      p1 = apex;
    } else if (r == b) {
      dropped = p2;
      p2 = apex;
    } else {
      return scale(add(add(p1, p2), apex), 1.0 / 3.0);
    }
    apex = sub(add(p1, p2), dropped);  // the triangle across the new segment
  }
  return std::nullopt;
}

}  // namespace genmod::nonmanifold
