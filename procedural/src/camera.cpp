#include "genmod/procedural/camera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace genmod {
namespace {

[[noreturn]] void refuse_field(const char* field, const std::string& problem) {
  throw std::invalid_argument(std::string("camera field '") + field + "' " + problem);
}

bool finite(const Vec3& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

// The camera's orthonormal frame: right, true up, forward.
struct Frame {
  Vec3 right, up, forward;
};
Frame frame_of(const Camera& c) {
  Frame f;
  f.forward = c.direction / c.direction.norm();
  f.right = OpenMesh::cross(f.forward, c.up);
  f.right /= f.right.norm();
  f.up = OpenMesh::cross(f.right, f.forward);
  return f;
}

}  // namespace

void check_camera(const Camera& c) {
  if (!finite(c.position)) refuse_field("position", "must be finite");
  if (!finite(c.direction)) refuse_field("direction", "must be finite");
  if (!(c.direction.norm() > 0)) refuse_field("direction", "must not be zero");
  if (!finite(c.up)) refuse_field("up", "must be finite");
  // Parallel (or zero) up: no frame. The sine of the angle between them, scale free.
  const double s = OpenMesh::cross(c.direction, c.up).norm() / (c.direction.norm() * c.up.norm());
  if (!(s > 1e-9)) refuse_field("up", "must not be zero or parallel to the direction");
  if (!std::isfinite(c.fov_y)) refuse_field("fov_y", "must be finite");
  if (!(c.fov_y > 0 && c.fov_y < std::numbers::pi))
    refuse_field("fov_y", "must be in (0, pi) radians, given " + std::to_string(c.fov_y));
  if (c.image_width <= 0) refuse_field("image_width", "must be positive, given " + std::to_string(c.image_width));
  if (c.image_height <= 0) refuse_field("image_height", "must be positive, given " + std::to_string(c.image_height));
  if (!std::isfinite(c.near)) refuse_field("near", "must be finite");
  if (!(c.near > 0)) refuse_field("near", "must be positive");
  if (c.min_lod > c.max_lod) refuse_field("min_lod", "must be at most max_lod");
}

BoxView view_of_box(const Camera& c, const std::array<Vec3, 2>& box, const Affine& xf) {
  const Frame f = frame_of(c);
  const double ty = std::tan(0.5 * c.fov_y);
  const double tx = ty * static_cast<double>(c.image_width) / static_cast<double>(c.image_height);
  // The corners in camera coordinates (x right, y up, z depth along the view direction).
  std::array<Vec3, 8> p;
  for (int i = 0; i < 8; ++i) {
    const Vec3 local(box[i & 1][0], box[(i >> 1) & 1][1], box[(i >> 2) & 1][2]);
    const Vec3 d = xf.apply(local) - c.position;
    p[i] = Vec3(OpenMesh::dot(d, f.right), OpenMesh::dot(d, f.up), OpenMesh::dot(d, f.forward));
  }
  // Each plane as a function >= 0 inside; all corners outside one plane: culled.
  const auto outside_all = [&](auto inside) {
    return std::none_of(p.begin(), p.end(), [&](const Vec3& q) { return inside(q) >= 0; });
  };
  if (outside_all([&](const Vec3& q) { return q[2] - c.near; }) ||
      outside_all([&](const Vec3& q) { return q[2] * tx - q[0]; }) ||
      outside_all([&](const Vec3& q) { return q[2] * tx + q[0]; }) ||
      outside_all([&](const Vec3& q) { return q[2] * ty - q[1]; }) ||
      outside_all([&](const Vec3& q) { return q[2] * ty + q[1]; }))
    return {};

  const double width = c.image_width, height = c.image_height;
  double pixels = width * height;  // a box reaching behind the near plane fills the view
  if (std::all_of(p.begin(), p.end(), [&](const Vec3& q) { return q[2] >= c.near; })) {
    // Pixel coordinates of the corners: x from the left, y from the bottom.
    double x0 = width, x1 = 0, y0 = height, y1 = 0;
    for (const Vec3& q : p) {
      const double sx = 0.5 * width * (1.0 + q[0] / (q[2] * tx)), sy = 0.5 * height * (1.0 + q[1] / (q[2] * ty));
      x0 = std::min(x0, sx), x1 = std::max(x1, sx), y0 = std::min(y0, sy), y1 = std::max(y1, sy);
    }
    x0 = std::max(x0, 0.0), y0 = std::max(y0, 0.0), x1 = std::min(x1, width), y1 = std::min(y1, height);
    pixels = std::max(x1 - x0, 0.0) * std::max(y1 - y0, 0.0);
  }
  const int level = static_cast<int>(std::floor(0.5 * std::log2(std::max(pixels, 1.0)))) + c.lod_bias;
  return {true, pixels, std::clamp(level, c.min_lod, c.max_lod)};
}

}  // namespace genmod
