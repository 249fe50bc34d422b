// Polygonal skeletal elements: convolution of a planar polygon with the separable cubic
// B-spline kernel through a precomputed "convolution image" (Bloomenthal, research/
// bloomenthal.md §3.9, App. A.3).
//
// A polygon of radius r contributes the density
//
//   D(p) = k * h(q_z) * I(q_xy),   h(z) = 1.5 h_B(0.72235 z / r)  (h(0) = 1, h(r) = 1/2)
//
// with q = p in the polygon's frame: q_z the signed distance to its plane, q_xy the image
// coordinates. I is the polygon rasterized into a real-valued image (the area of each pixel
// it covers, times the per-vertex weights interpolated with mean value coordinates when
// given) and filtered with the same B-spline at the same scale, normalized to unit total
// weight, so the image of a large polygon is 1 in its interior and 1/2 on a long straight
// edge; far from the edges D -> k h(q_z), and the iso-surface D = 1/2 lies at distance r from
// a wide polygon. At 80 x 80 pixels the density of a square of side 6 r is within 0.6% of
// the exact convolution (the separable kernel's closed form; tested).
// I is the bilinear interpolant of the four nearest samples and 0 outside the image.
// Polygons superpose by summing their densities.
//
// Frame (as App. A.3): the normal by Newell's method; the x axis is `x_axis` projected into
// the plane if given, else the direction of the first edge (so the edges of rectangles run
// along pixel rows: less rasterization error than an arbitrary orthogonal vector); the y axis
// completes the right-handed frame (x, y, normal); the image spans the polygon's 2-D bounds
// plus a margin of 2 extents on each side, where extent = 2.769 r is the kernel's support
// radius; `resolution` pixels cover the longer side of that rectangle, and the filter's
// support is world_to_image_scale * extent pixels.
//
// Density convention: D is a density (positive, larger inside). `polygon_convolution_surface`
// is the one place it enters genmod's implicit convention, f = iso - D (negative inside);
// iso = 1/2 puts the surface at distance r above a wide polygon and through its edges.
//
// The image lookup is a custom operator: point value by bilinear interpolation; derivative
// the piecewise gradient of the interpolant (again image lookups: the cell differences,
// piecewise constant along the differentiated axis and linear along the other); inclusion
// the hull of every sample the box's pixels can touch, plus 0 if the box can leave the image.
// Bilinear interpolation is a convex combination of its four samples, so that hull is sound.
// The hull over a pixel rectangle comes from a pyramid of per-block minima and maxima over
// blocks of 2^a x 2^b samples, so a query reads O(log^2 n) blocks, never every pixel.
//
// Bad input (fewer than 3 vertices, non-finite coordinates or weights, a degenerate polygon,
// one that is not planar within the tolerance, resolution < 2, a radius that is not finite
// and > 0)
// throws std::invalid_argument naming the problem.
//
// Example:
//   const SkeletalPolygon square{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
//   Fn f = polygon_convolution_surface({square}, 0.1, {.resolution = 40});  // a slab, f < 0 inside
//   Fn many = density_to_implicit(culled_field({polygon_element(square, 0.1), polygon_element(
//       {{{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}}}, 0.1)}));         // abutting: one plateau
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/interval.hpp"
#include "genmod/operators/convolution.hpp"
#include "genmod/operators/culled_field.hpp"
#include "genmod/operators/skeletal.hpp"

#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace genmod {

class CustomOp;

// A planar polygon (a closed loop of vertices; the even-odd rule decides inside) with
// optional per-vertex weights (empty: weight 1 everywhere; else one finite weight >= 0 per
// vertex, interpolated over the polygon by mean value coordinates, clamped to the weights'
// range).
struct SkeletalPolygon {
  std::vector<Point3> vertices{};
  std::vector<double> weights{};
};

struct PolygonImageOptions {
  // Pixels across the longer side of the image (App. A.3's res); >= 2. At 80 the surface is
  // within about 2% of r of its high-resolution limit; below 40 it shifts by a fifth of r and
  // more (measured in tests/operators/polygon_convolution_test.cpp).
  int resolution = 80;
  // The largest distance of a vertex from the best plane, relative to the polygon's
  // diameter; beyond it the polygon is refused as non-planar. Smaller deviations are
  // flattened by the projection into the plane.
  double planarity_tolerance = 1e-3;
  // The image's x axis (projected into the plane); default: the first edge's direction.
  std::optional<Point3> x_axis{};
  // Subsamples per pixel side of the coverage of a self-intersecting polygon (1 = point
  // sampling); a simple polygon's coverage is the exact area inside each pixel.
  int supersampling = 4;
};

// The filtered image of one polygon and its frame. Immutable once built; shared by the Fns
// that look it up.
class ConvolutionImage {
 public:
  ConvolutionImage(const SkeletalPolygon& polygon, double radius, const PolygonImageOptions& options = {});

  // Samples sit at integer image coordinates (i, j), 0 <= i < width(), 0 <= j < height().
  int width() const noexcept;
  int height() const noexcept;
  double sample(int i, int j) const;
  // The bilinear interpolant at image coordinates (u, v); 0 outside [0, width-1] x [0, height-1].
  double at(double u, double v) const;
  // A sound enclosure of the interpolant over the image-coordinate box u x v (the pyramid).
  Interval range(const Interval& u, const Interval& v) const;

  // Frame: q_z = dot(normal, p) + plane_offset; image coordinates (u, v) =
  // scale * (dot(p - origin, x_axis), dot(p - origin, y_axis)).
  const Point3& normal() const noexcept { return normal_; }
  const Point3& x_axis() const noexcept { return x_axis_; }
  const Point3& y_axis() const noexcept { return y_axis_; }
  const Point3& origin() const noexcept { return origin_; }
  double plane_offset() const noexcept { return plane_offset_; }
  double world_to_image_scale() const noexcept { return scale_; }
  double radius() const noexcept { return radius_; }
  // The kernel's support radius in world units (2.769 r) and in pixels.
  double extent() const noexcept { return extent_; }
  double support_pixels() const noexcept { return scale_ * extent_; }
  // The density is exactly 0 at every point farther than this from the bounding box of the
  // polygon's vertices: |q_z| < extent where h > 0, and in the plane the image is 0 beyond
  // sqrt(2) (extent + 1.5 pixels) of the polygon (the pixel's coverage reaches half a pixel,
  // the separable filter's square support extent, the bilinear cell one pixel, each along
  // both axes), plus the vertices' largest distance from their plane.
  double support_distance() const noexcept { return support_distance_; }
  // The vertices' bounding box (the skeleton box of polygon_element).
  const Point3& bounds_lo() const noexcept { return bounds_lo_; }
  const Point3& bounds_hi() const noexcept { return bounds_hi_; }

  // I(q_xy(p)) as an Fn of the query point (dimension 3).
  Fn lookup(const Fn& p = skeleton_query_point()) const;
  // The polygon's density k h(q_z) I(q_xy) as an Fn of the query point.
  Fn density(const Fn& p = skeleton_query_point(), double k = 1.0) const;

  struct Grid;  // the sampled image with its pyramid (private; shared with the operators)

 private:
  Point3 normal_{}, x_axis_{}, y_axis_{}, origin_{};
  Point3 bounds_lo_{}, bounds_hi_{};
  double plane_offset_ = 0, scale_ = 0, radius_ = 0, extent_ = 0, support_distance_ = 0;
  std::shared_ptr<const Grid> grid_;
  std::shared_ptr<const CustomOp> op_;  // the lookup operator over grid_
};

// The summed density k sum_i h(q_z,i) I_i(q_xy,i) of several polygons of one radius (eq. 6.3).
Fn polygon_convolution(std::span<const SkeletalPolygon> polygons, double radius, const PolygonImageOptions& options = {},
                       double k = 1.0, const Fn& p = skeleton_query_point());
// One polygon's density as an element of a culled field (culled_field.hpp): compact support
// (support_distance() around the vertices' bounding box), so a field of many polygons skips,
// box by box and point by point, the polygons far away.
FieldElement polygon_element(const SkeletalPolygon& polygon, double radius, const PolygonImageOptions& options = {},
                             double k = 1.0);

// f = iso - polygon_convolution(...): genmod's implicit convention, negative inside.
Fn polygon_convolution_surface(std::span<const SkeletalPolygon> polygons, double radius,
                               const PolygonImageOptions& options = {}, double iso = 0.5, double k = 1.0,
                               const Fn& p = skeleton_query_point());
inline Fn polygon_convolution_surface(std::initializer_list<SkeletalPolygon> polygons, double radius,
                                      const PolygonImageOptions& options = {}, double iso = 0.5) {
  return polygon_convolution_surface(std::span<const SkeletalPolygon>(polygons.begin(), polygons.size()), radius,
                                     options, iso);
}

}  // namespace genmod
