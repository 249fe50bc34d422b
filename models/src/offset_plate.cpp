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
// patches (offset_plate_faces): each a Coons patch whose four boundary arcs are the sides'
// top (v = 1) or bottom (v = 0) edge split at the midpoints of the four rounded corners, so
// its edges are the sides' edges point for point and the three patches close the plate.
#include "genmod/models/gallery.hpp"
#include "genmod/operators/offset.hpp"

#include "coons_face.hpp"
#include "model_definitions.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace genmod::models {

namespace {
constexpr double kMinConvexRadius = 0.1;  // the cross section's notch fillets

// Parameters of curves/offset_plate_cross.crv at the midpoints of its four rounded corners
// (the middle of each corner's rational quadratic span, between the knots 0.12495... and
// 0.17402... and their mirror images): the Coons patches' corners, counterclockwise from the
// bottom-right corner (the curve starts at the middle of the bottom edge).
constexpr double kCornerU = 0.5 * (0.12495280079083977 + 0.17402165091708616);
constexpr std::array<double, 4> kCorners{kCornerU, 0.5 - kCornerU, 0.5 + kCornerU, 1.0 - kCornerU};

// The sides Fn of (u, v).
Fn plate_sides(const ParameterValues& p) {
  return offset_product(offset_plate_cross(p)(x(0)), offset_plate_profile(p)(x(1)), 0);
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
  const Fn sides = plate_sides(p);
  // Top seen from above, bottom from below: both normals point out of the plate.
  return {ModelPatch{detail::coons_face(compose(sides, 1, Fn(1.0)), kCorners)},
          ModelPatch{detail::coons_face_flipped(compose(sides, 1, Fn(0.0)), kCorners)}};
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
