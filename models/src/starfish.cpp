// Bloomenthal's starfish joint (starfish.hpp).
#include "genmod/models/starfish.hpp"

#include "genmod/operators/blends.hpp"
#include "genmod/operators/convolution.hpp"
#include "genmod/operators/vector.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace genmod::models {
namespace {

Point3 sub(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Point3 add(const Point3& a, const Point3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Point3 scaled(const Point3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double norm(const Point3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
Point3 set_length(const Point3& a, double l) { return scaled(a, l / norm(a)); }
Point3 cross3(const Point3& a, const Point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Newell's normal of a closed polygon (the source's NormalFromPolygon), unit length.
Point3 polygon_normal(const std::vector<Point3>& pts) {
  Point3 n = {0, 0, 0};
  for (std::size_t i = 0; i < pts.size(); ++i) n = add(n, cross3(pts[i], pts[(i + 1) % pts.size()]));
  return scaled(n, 1 / norm(n));
}

}  // namespace

std::vector<StarfishLimb> starfish_limbs() {
  const double r = 0.1;
  const Point3 o = {0, 0, 0};
  std::vector<StarfishLimb> limbs;
  limbs.push_back({{-.5, -.21, 0}, o, {}, {}, {}, {}, r, r, -1});
  for (const Point3& tip : {Point3{.06, .6, 0}, Point3{.6, .4, 0}, Point3{.7, -.2, 0}, Point3{.1, -.4, 0}})
    limbs.push_back({o, tip, {}, {}, {}, {}, r, r, 0});
  // SetLimb in pre-order (a parent before its children).
  for (std::size_t i = 0; i < limbs.size(); ++i) {
    StarfishLimb& l = limbs[i];
    std::vector<int> children;
    for (std::size_t j = 0; j < limbs.size(); ++j)
      if (limbs[j].parent == static_cast<int>(i)) children.push_back(static_cast<int>(j));
    l.union1 = l.parent < 0 ? add(l.e1, set_length(sub(l.e2, l.e1), l.r1)) : l.e1;
    l.union2 = children.empty() ? add(l.e2, set_length(sub(l.e1, l.e2), l.r2)) : l.e2;
    if (children.empty()) {
      l.n2 = limbs[static_cast<std::size_t>(l.parent)].n2;
    } else {
      std::vector<Point3> pts = {l.e1};  // the limb's own e2 is inside the polygon
      for (int c : children) pts.push_back(limbs[static_cast<std::size_t>(c)].e2);
      l.n2 = polygon_normal(pts);
    }
    l.n1 = l.parent < 0 ? l.n2 : limbs[static_cast<std::size_t>(l.parent)].n2;
  }
  return limbs;
}

StarfishFields starfish_fields(const std::vector<StarfishLimb>& limbs) {
  if (limbs.empty()) throw std::invalid_argument("starfish_fields: no limbs");
  const Fn p = skeleton_query_point();
  StarfishFields out;
  Fn nearest2;   // min over limbs of dist(p, union segment)^2 / r^2
  Fn normal;     // the joint-plane normal of the nearest limb (interpolated along it)
  for (std::size_t i = 0; i < limbs.size(); ++i) {
    const StarfishLimb& l = limbs[i];
    const Fn conv = segment_convolution(l.e1, l.e2, l.r1, l.r2, p);
    const double r = std::max(l.r1, l.r2);
    const Fn d2 = distance2_to_segment(l.union1, l.union2, p) * (1.0 / (r * r));
    const Fn alpha = min(max(segment_parameter(l.e1, l.e2, p), 0.0), 1.0);
    const Fn n = cat({l.n1[0], l.n1[1], l.n1[2]}) + alpha * cat({l.n2[0] - l.n1[0], l.n2[1] - l.n1[1], l.n2[2] - l.n1[2]});
    if (i == 0) {
      out.convolution = conv;
      nearest2 = d2;
      normal = n;
    } else {
      out.convolution = out.convolution + conv;
      // Strictly nearer limbs win, as the source's `temp > unionValue`.
      normal = select(d2 < nearest2, n, normal);
      nearest2 = min(nearest2, d2);
    }
  }
  out.union_density = exp(-kGaussOmega * nearest2);
  const Fn g = cat({derivative(out.convolution, 0), derivative(out.convolution, 1), derivative(out.convolution, 2)});
  // |cos| of the angle between the gradient and the plane normal; the tiny terms keep it
  // defined where the gradient vanishes.
  const Fn cosine = abs(dot(normal, g)) / sqrt((dot(g, g) + 1e-300) * (dot(normal, normal) + 1e-300));
  out.convexity = convexity_from_cosine(cosine);
  out.combination = convexity_blend(out.convolution, out.union_density, out.convexity);
  return out;
}

Fn starfish_implicit(StarfishVariant variant) {
  const StarfishFields f = starfish_fields();
  switch (variant) {
    case StarfishVariant::combination: return density_to_implicit(f.combination);
    case StarfishVariant::convolution: return density_to_implicit(f.convolution);
    case StarfishVariant::union_of_capsules: return density_to_implicit(f.union_density);
  }
  throw std::invalid_argument("starfish_implicit: unknown variant");
}

}  // namespace genmod::models
