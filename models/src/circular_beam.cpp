// Circular beam (thesis Fig 3.20, research/snyder.md 7.22): a generative solid, the wire
// product of a planar REGION s(u, v) (not a boundary curve) along a 2-D wire c(w):
//   beam = m_wire(s, c);
// s is a rectangle, s(u, v) = (width (u - 1/2), height (v - 1/2)); c is an arc of a circle
// of `radius` about the origin, sweeping `angle` radians counter-clockwise from the +x axis.
// The rectangle's first axis goes to the wire's in-plane normal (toward the arc's centre),
// its second to world z. The Jacobian determinant is width height angle (radius - s1) > 0
// (width < 2 radius), so the solid is positively oriented and its volume is
// width height radius angle (Pappus: the rectangle's centroid travels radius angle).
#include "genmod/models/gallery.hpp"
#include "genmod/operators/sweep.hpp"
#include "model_definitions.hpp"

#include <numbers>
#include <stdexcept>
#include <string>

namespace genmod::models {
namespace detail {

Model circular_beam_model() {
  Model m;
  m.name = "circular_beam";
  m.description = "thesis Fig 3.20: generative solid, a rectangle region swept along a circular-arc wire";
  m.parameters = {{"radius", 1.0, "radius of the arc the beam follows (its centre line)"},
                  {"angle", std::numbers::pi / 2.0, "angle the arc sweeps, in radians (0, 2 pi]"},
                  {"width", 0.2, "width of the rectangular section, in the arc's plane (< 2 radius)"},
                  {"height", 0.1, "height of the section, along z"}};
  m.build = [](const ParameterValues& p) {
    const double radius = require_positive(p, "radius");
    const double angle = require_positive(p, "angle");
    const double width = require_positive(p, "width");
    const double height = require_positive(p, "height");
    if (!(angle <= 2.0 * std::numbers::pi))
      throw std::invalid_argument("parameter 'angle' must be in (0, 2 pi], got " + std::to_string(angle));
    if (!(width < 2.0 * radius))
      throw std::invalid_argument("parameter 'width' must be < 2 radius (the section would cross the arc's centre), got " +
                                  std::to_string(width));
    const Fn region = cat({(x(0) - 0.5) * width, (x(1) - 0.5) * height});
    const Fn theta = x(2) * angle;
    const Fn wire = cat({cos(theta) * radius, sin(theta) * radius});
    return wire_product(region, wire, 2);
  };
  m.solid = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
