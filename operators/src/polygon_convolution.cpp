// Polygonal skeletal elements: the polygon's frame, its filtered image and the density Fns
// (polygon_convolution.hpp).
#include "genmod/operators/polygon_convolution.hpp"

#include "genmod/operators/convolution.hpp"
#include "polygon_image_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace genmod {

namespace {

using Vec2 = std::array<double, 2>;

constexpr int kMaxResolution = 4096;
constexpr int kMaxSupersampling = 16;

[[noreturn]] void bad(const std::string& what) { throw std::invalid_argument("polygon_convolution: " + what); }

Point3 sub(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Point3 cross(const Point3& a, const Point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Point3 scaled(const Point3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double norm(const Point3& a) { return std::sqrt(dot(a, a)); }

// The B-spline kernel h_B(x) of convolution.hpp (support |x| < 2) on doubles, for the filter.
double bspline(double x) {
  const double t = std::abs(x);
  if (t >= 2) return 0;
  if (t >= 1) return (2 - t) * (2 - t) * (2 - t) / 6;
  return (t * t * (3 * t - 6) + 4) / 6;
}

// Even-odd point-in-polygon test.
bool inside(const std::vector<Vec2>& poly, const Vec2& q) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 &a = poly[i], &b = poly[j];
    if ((a[1] > q[1]) != (b[1] > q[1]) && q[0] < (b[0] - a[0]) * (q[1] - a[1]) / (b[1] - a[1]) + a[0]) in = !in;
  }
  return in;
}

// The mean value coordinates of q (Floater's tangent form) applied to the values w.
double mean_value_interpolation(const std::vector<Vec2>& poly, const std::vector<double>& w, const Vec2& q) {
  const std::size_t n = poly.size();
  std::vector<Vec2> d(n);
  std::vector<double> r(n);
  for (std::size_t i = 0; i < n; ++i) {
    d[i] = {poly[i][0] - q[0], poly[i][1] - q[1]};
    r[i] = std::hypot(d[i][0], d[i][1]);
    if (r[i] == 0) return w[i];
  }
  std::vector<double> t(n);  // tan(alpha_i / 2), alpha_i the signed angle from d_i to d_i+1
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = (i + 1) % n;
    const double c = d[i][0] * d[k][1] - d[i][1] * d[k][0];
    const double s = r[i] * r[k] + d[i][0] * d[k][0] + d[i][1] * d[k][1];
    if (c == 0 && s <= 0) return (r[k] * w[i] + r[i] * w[k]) / (r[i] + r[k]);  // q on edge i
    t[i] = c / s;
  }
  double sum = 0, total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double lambda = (t[(i + n - 1) % n] + t[i]) / r[i];
    sum += lambda * w[i];
    total += lambda;
  }
  return sum / total;
}

// The per-vertex weights interpolated at q by mean value coordinates (defined inside any
// simple polygon; exact on the edges and at the vertices). In a concave polygon some
// coordinates are negative and the value can overshoot the weights, so it is clamped to
// their range (and a self-intersecting polygon, where the coordinates can cancel, gets the
// clamp's lower end instead of a NaN).
double interpolate_weights(const std::vector<Vec2>& poly, const std::vector<double>& w, const Vec2& q) {
  const auto [lo, hi] = std::minmax_element(w.begin(), w.end());
  const double v = mean_value_interpolation(poly, w, q);
  return std::isfinite(v) ? std::clamp(v, *lo, *hi) : *lo;
}

// True if no two non-adjacent edges meet and no two adjacent ones overlap (orientation tests;
// O(n^2), run once per image).
bool is_simple(const std::vector<Vec2>& poly) {
  const std::size_t n = poly.size();
  auto orient = [](const Vec2& a, const Vec2& b, const Vec2& c) {
    const double v = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    return (v > 0) - (v < 0);
  };
  auto on_segment = [](const Vec2& a, const Vec2& b, const Vec2& c) {  // c collinear with ab
    return std::min(a[0], b[0]) <= c[0] && c[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= c[1] &&
           c[1] <= std::max(a[1], b[1]);
  };
  auto meet = [&](const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
    const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;  // a proper crossing
    return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) || (o3 == 0 && on_segment(c, d, a)) ||
           (o4 == 0 && on_segment(c, d, b));
  };
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &a = poly[i], &b = poly[(i + 1) % n];
    if (a == b) return false;
    for (std::size_t j = i + 1; j < n; ++j) {
      const Vec2 &c = poly[j], &d = poly[(j + 1) % n];
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (!adjacent && meet(a, b, c, d)) return false;
      // Adjacent edges share one vertex; they must not fold back onto each other.
      if (adjacent) {
        const Vec2& shared = j == i + 1 ? b : a;
        const Vec2& p = j == i + 1 ? a : b;
        const Vec2& q = j == i + 1 ? d : c;
        if (orient(p, shared, q) == 0 &&
            (q[0] - shared[0]) * (p[0] - shared[0]) + (q[1] - shared[1]) * (p[1] - shared[1]) > 0)
          return false;
      }
    }
  }
  return true;
}

// The area and centroid of the part of the simple polygon inside the axis-aligned square
// [x0, x1] x [y0, y1]: Sutherland-Hodgman clipping against the square's four sides (exact for
// a convex window, leaving only zero-area bridges where a concave polygon is cut), then the
// shoelace formula. Returns the unsigned area; centroid is set when the area is positive.
double clipped_area(const std::vector<Vec2>& poly, double x0, double x1, double y0, double y1, Vec2& centroid,
                    std::vector<Vec2>& a, std::vector<Vec2>& b) {
  a = poly;
  for (int side = 0; side < 4 && !a.empty(); ++side) {
    const int axis = side / 2;
    const double bound = side == 0 ? x0 : side == 1 ? x1 : side == 2 ? y0 : y1;
    const bool keep_above = side % 2 == 0;
    auto in = [&](const Vec2& p) { return keep_above ? p[axis] >= bound : p[axis] <= bound; };
    b.clear();
    for (std::size_t i = 0; i < a.size(); ++i) {
      const Vec2 &p = a[i], &q = a[(i + 1) % a.size()];
      const bool pin = in(p), qin = in(q);
      if (pin) b.push_back(p);
      if (pin != qin) {
        const double t = (bound - p[axis]) / (q[axis] - p[axis]);
        Vec2 r{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])};
        r[axis] = bound;
        b.push_back(r);
      }
    }
    std::swap(a, b);
  }
  double area2 = 0, cx = 0, cy = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2 &p = a[i], &q = a[(i + 1) % a.size()];
    const double c = p[0] * q[1] - q[0] * p[1];
    area2 += c;
    cx += (p[0] + q[0]) * c;
    cy += (p[1] + q[1]) * c;
  }
  if (area2 != 0) centroid = {cx / (3 * area2), cy / (3 * area2)};
  return std::abs(area2) / 2;
}

}  // namespace

ConvolutionImage::ConvolutionImage(const SkeletalPolygon& polygon, double radius, const PolygonImageOptions& options) {
  const std::vector<Point3>& vs = polygon.vertices;
  const std::size_t n = vs.size();
  if (n < 3) bad("a polygon needs at least 3 vertices, got " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i)
    for (double c : vs[i])
      if (!std::isfinite(c)) bad("vertex " + std::to_string(i) + " is not finite");
  if (!polygon.weights.empty() && polygon.weights.size() != n)
    bad(std::to_string(n) + " vertices need 0 or " + std::to_string(n) + " weights, got " +
        std::to_string(polygon.weights.size()));
  for (std::size_t i = 0; i < polygon.weights.size(); ++i)
    if (!(polygon.weights[i] >= 0 && std::isfinite(polygon.weights[i])))
      bad("weight " + std::to_string(i) + " must be finite and >= 0");
  if (!(radius > 0 && std::isfinite(radius)))
    bad("radius (the kernel's extent / 2.769) must be finite and > 0, got " + std::to_string(radius));
  if (options.resolution < 2 || options.resolution > kMaxResolution)
    bad("resolution must be in [2, " + std::to_string(kMaxResolution) + "], got " + std::to_string(options.resolution));
  if (options.supersampling < 1 || options.supersampling > kMaxSupersampling)
    bad("supersampling must be in [1, " + std::to_string(kMaxSupersampling) + "], got " +
        std::to_string(options.supersampling));
  if (!(options.planarity_tolerance >= 0 && std::isfinite(options.planarity_tolerance)))
    bad("planarity tolerance must be finite and >= 0");

  // Newell's normal (twice the area vector) and the polygon's size (its bounding diagonal).
  Point3 newell{0, 0, 0}, centroid{0, 0, 0}, lo = vs[0], hi = vs[0];
  for (std::size_t i = 0; i < n; ++i) {
    const Point3 &a = vs[i], &b = vs[(i + 1) % n];
    newell[0] += (a[1] - b[1]) * (a[2] + b[2]);
    newell[1] += (a[2] - b[2]) * (a[0] + b[0]);
    newell[2] += (a[0] - b[0]) * (a[1] + b[1]);
    for (int k = 0; k < 3; ++k) centroid[k] += a[k] / static_cast<double>(n), lo[k] = std::min(lo[k], a[k]), hi[k] = std::max(hi[k], a[k]);
  }
  const double size = norm(sub(hi, lo));
  const double area2 = norm(newell);
  if (!(size > 0) || !(area2 > 1e-12 * size * size)) bad("the polygon is degenerate (no area)");
  normal_ = scaled(newell, 1 / area2);
  plane_offset_ = -dot(normal_, centroid);
  double off = 0;
  for (const Point3& v : vs) off = std::max(off, std::abs(dot(normal_, v) + plane_offset_));
  if (off > options.planarity_tolerance * size)
    bad("the polygon is not planar: a vertex is " + std::to_string(off) + " from its plane, more than " +
        std::to_string(options.planarity_tolerance) + " times its size " + std::to_string(size));

  // The x axis: given, or the first edge, projected into the plane.
  auto in_plane = [&](const Point3& d) { return sub(d, scaled(normal_, dot(d, normal_))); };
  Point3 x{0, 0, 0};
  if (options.x_axis) {
    x = in_plane(*options.x_axis);
    if (!(norm(x) > 1e-9 * norm(*options.x_axis)) || !std::isfinite(norm(x))) bad("x_axis is zero, not finite or parallel to the normal");
  } else {
    for (std::size_t i = 0; i < n && !(norm(x) > 1e-9 * size); ++i) x = in_plane(sub(vs[(i + 1) % n], vs[i]));
  }
  x_axis_ = scaled(x, 1 / norm(x));
  y_axis_ = cross(normal_, x_axis_);

  // Plane coordinates relative to the plane's origin -plane_offset * normal (App. A.3).
  const Point3 plane_origin = scaled(normal_, -plane_offset_);
  std::vector<Vec2> poly(n);
  Vec2 mn{HUGE_VAL, HUGE_VAL}, mx{-HUGE_VAL, -HUGE_VAL};
  for (std::size_t i = 0; i < n; ++i) {
    const Point3 d = sub(vs[i], plane_origin);
    poly[i] = {dot(d, x_axis_), dot(d, y_axis_)};
    for (int k = 0; k < 2; ++k) mn[k] = std::min(mn[k], poly[i][k]), mx[k] = std::max(mx[k], poly[i][k]);
  }
  radius_ = radius;
  extent_ = radius * kernel_support(Kernel::bspline);  // the normalized B-spline's support
  const Vec2 corner{mn[0] - 2 * extent_, mn[1] - 2 * extent_};
  const Vec2 span{mx[0] - mn[0] + 4 * extent_, mx[1] - mn[1] + 4 * extent_};
  scale_ = std::min(options.resolution / span[0], options.resolution / span[1]);
  origin_ = {plane_origin[0] + corner[0] * x_axis_[0] + corner[1] * y_axis_[0],
             plane_origin[1] + corner[0] * x_axis_[1] + corner[1] * y_axis_[1],
             plane_origin[2] + corner[0] * x_axis_[2] + corner[1] * y_axis_[2]};
  // Nodes at integer image coordinates covering the span (the longer side has resolution + 1).
  bounds_lo_ = lo;
  bounds_hi_ = hi;
  // Rounded up generously (1e-9 relative, far above the rounding of the frame's arithmetic).
  support_distance_ = (std::hypot(extent_, std::sqrt(2.0) * (extent_ + 1.5 / scale_)) + off) * (1 + 1e-9) + 1e-12 * size;
  const int w = static_cast<int>(std::ceil(span[0] * scale_ - 1e-9)) + 1;
  const int h = static_cast<int>(std::ceil(span[1] * scale_ - 1e-9)) + 1;

  // Coverage of the pixel centred on each node: for a simple polygon the exact area of the
  // polygon inside the pixel (so edges fall where they are, not where subsamples are),
  // times the interpolated weight at the centroid of that area; otherwise the fraction of
  // s x s subsamples inside by the even-odd rule, times the weight at each.
  std::vector<double> image(static_cast<std::size_t>(w) * h, 0.0);
  const bool simple = is_simple(poly);
  const int s = options.supersampling;
  const int i0 = std::max(0, static_cast<int>(std::floor((mn[0] - corner[0]) * scale_)) - 1);
  const int i1 = std::min(w - 1, static_cast<int>(std::ceil((mx[0] - corner[0]) * scale_)) + 1);
  const int j0 = std::max(0, static_cast<int>(std::floor((mn[1] - corner[1]) * scale_)) - 1);
  const int j1 = std::min(h - 1, static_cast<int>(std::ceil((mx[1] - corner[1]) * scale_)) + 1);
  const double pixel = 1 / scale_;
  std::vector<Vec2> work_a, work_b;
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const double cx = corner[0] + i * pixel, cy = corner[1] + j * pixel;
      double value = 0;
      if (simple) {
        Vec2 piece{cx, cy};
        const double area = clipped_area(poly, cx - pixel / 2, cx + pixel / 2, cy - pixel / 2, cy + pixel / 2, piece, work_a, work_b);
        value = std::min(area / (pixel * pixel), 1.0);
        if (value > 0 && !polygon.weights.empty()) value *= interpolate_weights(poly, polygon.weights, piece);
      } else {
        for (int b = 0; b < s; ++b)
          for (int a = 0; a < s; ++a) {
            const Vec2 q{cx + ((a + 0.5) / s - 0.5) * pixel, cy + ((b + 0.5) / s - 0.5) * pixel};
            if (inside(poly, q)) value += polygon.weights.empty() ? 1.0 : interpolate_weights(poly, polygon.weights, q);
          }
        value /= s * s;
      }
      image[static_cast<std::size_t>(j) * w + i] = value;
    }

  // The separable filter: the B-spline over its support in pixels, normalized to unit sum so
  // that a region far inside a polygon of weight 1 filters to 1.
  const double support = support_pixels();
  const int reach = static_cast<int>(std::ceil(support)) - 1 < 0 ? 0 : static_cast<int>(std::ceil(support)) - 1;
  std::vector<double> taps(static_cast<std::size_t>(2 * reach + 1));
  double total = 0;
  for (int k = -reach; k <= reach; ++k) total += taps[static_cast<std::size_t>(k + reach)] = bspline(2.0 * k / support);
  for (double& t : taps) t /= total;
  std::vector<double> tmp(image.size(), 0.0);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      double acc = 0;
      for (int k = std::max(-reach, -i); k <= std::min(reach, w - 1 - i); ++k)
        acc += taps[static_cast<std::size_t>(k + reach)] * image[static_cast<std::size_t>(j) * w + i + k];
      tmp[static_cast<std::size_t>(j) * w + i] = acc;
    }
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      double acc = 0;
      for (int k = std::max(-reach, -j); k <= std::min(reach, h - 1 - j); ++k)
        acc += taps[static_cast<std::size_t>(k + reach)] * tmp[static_cast<std::size_t>(j + k) * w + i];
      image[static_cast<std::size_t>(j) * w + i] = acc;
    }
  grid_ = std::make_shared<const Grid>(std::array<int, 2>{w, h}, std::array<bool, 2>{false, false}, std::move(image));
  op_ = make_image_lookup_op(grid_);
}

int ConvolutionImage::width() const noexcept { return grid_->n[0]; }
int ConvolutionImage::height() const noexcept { return grid_->n[1]; }
double ConvolutionImage::sample(int i, int j) const {
  if (i < 0 || i >= width() || j < 0 || j >= height()) throw std::out_of_range("ConvolutionImage::sample: index outside the image");
  return grid_->at(i, j);
}
double ConvolutionImage::at(double u, double v) const { return grid_->eval(u, v); }
Interval ConvolutionImage::range(const Interval& u, const Interval& v) const { return grid_->range(u, v); }

Fn ConvolutionImage::lookup(const Fn& p) const {
  if (p.dim() != 3) bad("the query point must have dimension 3");
  // (p - origin) . axis, each coordinate once, so the box's image-coordinate interval is tight.
  auto coordinate = [&](const Point3& axis) {
    return scale_ * ((p[0] - origin_[0]) * axis[0] + (p[1] - origin_[1]) * axis[1] + (p[2] - origin_[2]) * axis[2]);
  };
  return apply_custom(op_, {coordinate(x_axis_), coordinate(y_axis_)});
}

Fn ConvolutionImage::density(const Fn& p, double k) const {
  if (!std::isfinite(k)) bad("the scale k must be finite");
  const Fn image = lookup(p);
  const Fn qz = p[0] * normal_[0] + p[1] * normal_[1] + p[2] * normal_[2] + plane_offset_;
  // The distance filter h(q_z) = 1.5 h_B(0.72235 q_z / r): the normalized B-spline of
  // convolution.hpp, written on q_z itself (not its square) so that its derivative is smooth
  // on the plane.
  const double half = 2.0 / kernel_support(Kernel::bspline);
  return k * (1.5 * bspline_kernel((half / radius_) * qz)) * image;
}

Fn polygon_convolution(std::span<const SkeletalPolygon> polygons, double radius, const PolygonImageOptions& options,
                       double k, const Fn& p) {
  if (polygons.empty()) bad("no polygons");
  Fn sum;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const Fn d = ConvolutionImage(polygons[i], radius, options).density(p, k);
    sum = i == 0 ? d : sum + d;
  }
  return sum;
}

FieldElement polygon_element(const SkeletalPolygon& polygon, double radius, const PolygonImageOptions& options, double k) {
  if (!(k >= 0 && std::isfinite(k))) bad("the scale k of an element must be finite and >= 0");
  const ConvolutionImage image(polygon, radius, options);
  FieldElement e{image.density(skeleton_query_point(), k), image.bounds_lo(), image.bounds_hi(), 1.0, image.support_distance(),
                 Falloff::compact};
  return e;
}

Fn polygon_convolution_surface(std::span<const SkeletalPolygon> polygons, double radius,
                               const PolygonImageOptions& options, double iso, double k, const Fn& p) {
  return density_to_implicit(polygon_convolution(polygons, radius, options, k, p), iso);
}

}  // namespace genmod
