// preview(): orthographic z-buffer rasterization of a triangle mesh (see preview.hpp).
#include "genmod/tessellate/preview.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod {
namespace {

using Vec3 = std::array<double, 3>;

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 normalized(const Vec3& a) { return scaled(a, 1.0 / std::sqrt(dot(a, a))); }

// A right-handed frame: right x up = toward (the unit vector from the scene to the eye).
struct Camera {
  Vec3 right, up, toward;
};

Camera camera_from(const Vec3& view) {
  Camera c;
  c.toward = normalized(view);
  const Vec3 world_up = std::abs(c.toward[2]) > 0.999 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  c.right = normalized(cross(world_up, c.toward));
  c.up = cross(c.toward, c.right);
  return c;
}

// A projected vertex: X to the right and Y up in pixel units (pixel (i, j) has its centre at
// X = i + 0.5, Y = height - j - 0.5); depth grows toward the eye.
struct ScreenPoint {
  double x = 0, y = 0, depth = 0;
};

// The edge function of a -> b at p (positive left of the edge), evaluated with the endpoints
// in a fixed order so that the edge shared by two triangles gives exactly opposite values and
// no pixel centre on it is lost or drawn twice.
double edge(const ScreenPoint& a, const ScreenPoint& b, double px, double py) {
  if (a.x < b.x || (a.x == b.x && a.y < b.y)) return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
  return -((a.x - b.x) * (py - b.y) - (a.y - b.y) * (px - b.x));
}

// A pixel centre exactly on an edge belongs to the triangle on one fixed side of it.
bool owns_zero(const ScreenPoint& a, const ScreenPoint& b) { return b.y > a.y || (b.y == a.y && b.x < a.x); }

bool covers(double e, const ScreenPoint& a, const ScreenPoint& b) { return e > 0 || (e == 0 && owns_zero(a, b)); }

void check(const Mesh& mesh, const PreviewOptions& o) {
  auto bad = [](const std::string& what) { throw std::invalid_argument("genmod: preview: " + what); };
  if (o.width < 1 || o.width > 8192 || o.height < 1 || o.height > 8192)
    bad("the image size must be 1..8192 pixels per side, got " + std::to_string(o.width) + " x " +
        std::to_string(o.height));
  if (!(o.margin >= 0 && o.margin <= 0.45)) bad("margin must be in [0, 0.45], got " + std::to_string(o.margin));
  if (!std::isfinite(dot(o.view, o.view)) || dot(o.view, o.view) == 0)
    bad("the view direction must be a finite, non-zero vector");
  if (mesh.triangles.empty()) bad("the mesh has no triangles (nothing to show)");
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::uint32_t k : mesh.triangles[t]) {
      if (k >= mesh.vertices.size())
        bad("triangle " + std::to_string(t) + " uses vertex " + std::to_string(k) + " of " +
            std::to_string(mesh.vertices.size()));
      for (double c : mesh.vertices[k])
        if (!std::isfinite(c)) bad("vertex " + std::to_string(k) + " has a coordinate that is not finite");
    }
}

// The gray level of a face: Lambert plus ambient, in the front or the back range.
std::uint8_t shade(const Vec3& normal, const Vec3& light, bool front) {
  constexpr double kAmbient = 0.15;
  const double lambert = std::max(0.0, front ? dot(normal, light) : -dot(normal, light));
  const double brightness = kAmbient + (1 - kAmbient) * lambert;
  const double level = front ? 60 + 170 * brightness : 20 + 60 * brightness;
  return static_cast<std::uint8_t>(std::lround(level));
}

}  // namespace

Image preview(const Mesh& mesh, const PreviewOptions& options) {
  check(mesh, options);
  const Camera cam = camera_from(options.view);
  const Vec3 light = normalized(add(add(cam.toward, scaled(cam.up, 0.5)), scaled(cam.right, -0.35)));

  // Projected bounding rectangle of the used vertices, then the pixel transform.
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for (const auto& t : mesh.triangles)
    for (std::uint32_t k : t) {
      const double s[2] = {dot(mesh.vertices[k], cam.right), dot(mesh.vertices[k], cam.up)};
      for (int a = 0; a < 2; ++a) {
        lo[a] = std::min(lo[a], s[a]);
        hi[a] = std::max(hi[a], s[a]);
      }
    }
  const double free = 1 - 2 * options.margin;
  double scale = std::numeric_limits<double>::infinity();
  if (hi[0] > lo[0]) scale = std::min(scale, free * options.width / (hi[0] - lo[0]));
  if (hi[1] > lo[1]) scale = std::min(scale, free * options.height / (hi[1] - lo[1]));
  if (!std::isfinite(scale)) scale = 1;  // every vertex projects to one point
  const double mid[2] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
  auto project = [&](const Vec3& p) {
    return ScreenPoint{(dot(p, cam.right) - mid[0]) * scale + 0.5 * options.width,
                       (dot(p, cam.up) - mid[1]) * scale + 0.5 * options.height, dot(p, cam.toward)};
  };

  Image image(options.width, options.height, 255);
  std::vector<double> depth(image.pixels.size(), -std::numeric_limits<double>::infinity());
  for (const auto& t : mesh.triangles) {
    const Vec3 &pa = mesh.vertices[t[0]], &pb = mesh.vertices[t[1]], &pc = mesh.vertices[t[2]];
    ScreenPoint a = project(pa), b = project(pb), c = project(pc);
    double area = edge(a, b, c.x, c.y);
    if (!(area != 0)) continue;  // seen edge-on, or degenerate
    const bool front = area > 0;
    if (!front) {
      std::swap(b, c);
      area = -area;
    }
    const Vec3 n3 = cross(sub(pb, pa), sub(pc, pa));
    const double n_length = std::sqrt(dot(n3, n3));
    const std::uint8_t level = shade(n_length > 0 ? scaled(n3, 1 / n_length) : cam.toward, light, front);
    const double min_x = std::min({a.x, b.x, c.x}), max_x = std::max({a.x, b.x, c.x});
    const double min_y = std::min({a.y, b.y, c.y}), max_y = std::max({a.y, b.y, c.y});
    const int i0 = std::max(0, static_cast<int>(std::floor(min_x - 0.5)));
    const int i1 = std::min(options.width - 1, static_cast<int>(std::ceil(max_x)));
    const int j0 = std::max(0, static_cast<int>(std::floor(options.height - 0.5 - max_y)));
    const int j1 = std::min(options.height - 1, static_cast<int>(std::ceil(options.height - 0.5 - min_y)));
    for (int j = j0; j <= j1; ++j) {
      const double py = options.height - j - 0.5;
      for (int i = i0; i <= i1; ++i) {
        const double px = i + 0.5;
        const double ea = edge(b, c, px, py), eb = edge(c, a, px, py), ec = edge(a, b, px, py);
        if (!covers(ea, b, c) || !covers(eb, c, a) || !covers(ec, a, b)) continue;
        const double z = (ea * a.depth + eb * b.depth + ec * c.depth) / area;
        const std::size_t at = static_cast<std::size_t>(j) * static_cast<std::size_t>(options.width) +
                               static_cast<std::size_t>(i);
        if (z > depth[at]) {
          depth[at] = z;
          image.pixels[at] = level;
        }
      }
    }
  }
  return image;
}

}  // namespace genmod
