// Plate (thesis Fig 3.12, research/snyder.md 7.14): the offset product of a closed cross
// section and a rounded-edge profile, the side walls of a thin plate with rounded corners,
// notches and rounded edges:
//   cross = m_crv("cross.crv", m_x(0)); profile = m_crv("profile.crv", m_x(1));
//   plate = m_offset(cross, profile);      // (cross + d1(v) n(u), d2(v))
// The cross section is models/curves/offset_plate_cross.crv (a 2 x 1.2 rounded rectangle with
// a filleted circular notch in each short side, counterclockwise). The profile (d1, d2) is
// built here from the parameters: from the bottom face (d1 = edge_radius inward, d2 =
// -thickness/2) a quarter circle out to the wall (d1 = 0), straight up the wall, and a
// quarter circle back in to the top face. The top and bottom faces are the planar areas
// bounded by the cross section offset inward by edge_radius (thesis 6.5), the model's extra
// patches (offset_plate_faces): each the fan of segments from the centre (0, 0) to the sides'
// top (v = 1) or bottom (v = 0) edge, F(u, s) = (1 - s) E(u) (top), with the sides' own u, so
// its outer edge is the sides' edge point for point (glued whole, not in parts) and the three
// patches close the plate. The fan is one-to-one because the edge is star-shaped about the
// centre: E x E' > 0 all round, least in the notches (offset_plate_faces explains).
#include "genmod/models/gallery.hpp"
#include "genmod/operators/offset.hpp"

#include "model_definitions.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace genmod::models {

namespace {
constexpr double kMinConvexRadius = 0.1;  // the cross section's notch fillets

// The sides Fn of (u, v).
Fn plate_sides(const ParameterValues& p) {
  // The Curve form: the section joins lines and arcs at double knots (C^0 in u, tangent-
  // continuous in space), where normalize(normal2d(c)) has no finite enclosure.
  return offset_product(offset_plate_cross(p), x(0), offset_plate_profile(p)(x(1)));
}

}  // namespace

Curve offset_plate_cross(const ParameterValues&) { return gallery_curve("offset_plate_cross"); }

Curve offset_plate_profile(const ParameterValues& p) {
  const double t = detail::require_positive(p, "thickness") / 2.0;
  const double rho = detail::require_positive(p, "edge_radius");
  if (!(rho < kMinConvexRadius))
    throw std::invalid_argument("parameter 'edge_radius' must be < 0.1 (the smallest convex radius of the "
                                "cross section), got " + std::to_string(rho));
  if (!(rho <= t))
    throw std::invalid_argument("parameter 'edge_radius' must be <= thickness / 2, got edge_radius " +
                                std::to_string(rho) + " with thickness " + std::to_string(2.0 * t));
  // Degree-2 NURBS: quarter circle (rational, weight cos 45 deg), wall line, quarter circle;
  // the knots split [0, 1] in proportion to the arclengths of the pieces. A full round edge
  // (edge_radius = thickness / 2) has no wall line.
  const double w = std::sqrt(0.5);
  const double arc = rho * std::numbers::pi / 2.0, wall = 2.0 * (t - rho);
  if (wall == 0.0)
    return Curve::nurbs({{rho, -t}, {0.0, -t}, {0.0, 0.0}, {0.0, t}, {rho, t}}, {1.0, w, 1.0, w, 1.0}, 2,
                        {0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0});
  const double a = arc / (2.0 * arc + wall), b = (arc + wall) / (2.0 * arc + wall);
  return Curve::nurbs({{rho, -t}, {0.0, -t}, {0.0, rho - t}, {0.0, 0.0}, {0.0, t - rho}, {0.0, t}, {rho, t}},
                      {1.0, w, 1.0, 1.0, 1.0, w, 1.0}, 2, {0.0, 0.0, 0.0, a, a, b, b, 1.0, 1.0, 1.0});
}

std::vector<ModelPatch> offset_plate_faces(const ParameterValues& p) {
  // Star-shaped about the centre: on a notch (a concave arc about (1, 0) of radius
  // R = 0.2 + edge_radius on the faces' edge, at angles 180 +- 70.5 degrees about its centre)
  // E x E' is proportional to -cos(angle) - R, positive while |angle - 180| < acos(R), which
  // is over 72.5 degrees for any edge_radius < 0.1; on the fillets (centres (0.9, +-0.283),
  // radius 0.1 - edge_radius) it is at least 0.033 + that radius; the corners and straight
  // sides face the centre. So each segment from the centre meets the edge once, and the fan
  // covers the face once. The pole (s = 1 on the top, s = 0 on the bottom) is one point.
  const Fn sides = plate_sides(p);
  const Fn top = compose(sides, 1, Fn(1.0)), bottom = compose(sides, 1, Fn(0.0));
  // Top F = (1 - s) E: F_u x F_s = (1 - s) E x E', along +z; bottom F = s E: -s E x E', along
  // -z. Both point out of the plate.
  const Fn in = 1.0 - x(1), out = x(1);
  auto fan = [](const Fn& edge, const Fn& scale) {
    return ModelPatch{cat({scale * edge[0], scale * edge[1], edge[2]}), Interval(0.0, 1.0), Interval(0.0, 1.0), true};
  };
  return {fan(top, in), fan(bottom, out)};
}

namespace detail {

Model offset_plate_model() {
  Model m;
  m.name = "offset_plate";
  m.description =
      "thesis Fig 3.12: offset product of a notched rounded rectangle and a rounded-edge profile (side walls), planar top and bottom faces (extra patches)";
  m.parameters = {{"thickness", 0.2, "plate thickness (z from -thickness/2 to thickness/2)"},
                  {"edge_radius", 0.05, "radius of the rounded top and bottom edges, in (0, min(0.1, thickness/2)]"}};
  m.build = plate_sides;
  m.periodic_u = true;
  m.extra_patches = offset_plate_faces;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
