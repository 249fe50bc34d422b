// Tennis racket (thesis Fig 3.4, research/snyder.md 7.5): the wire product of a small closed
// cross section and the closed oval of the racket head:
//   cross = m_crv("cross.crv", m_x(0)); wire = m_crv("wire.crv", m_x(1));
//   racket_frame = m_wire(cross, wire);
// Substitute curves (curves/tennis_racket_cross.crv, tennis_racket_head.crv): a rounded
// rectangle and an egg-shaped head oval, both closed C2 B-splines, scaled by the parameters.
// The cross section's x axis goes to the wire's in-plane normal (across the frame), its y
// axis to world z. The frame only (no throat or handle): a closed tube, periodic in u and v.
#include "genmod/models/gallery.hpp"
#include "genmod/operators/sweep.hpp"
#include "model_definitions.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace genmod::models {

Fn tennis_racket_cross(const ParameterValues& p) {
  const double width = detail::require_positive(p, "frame_width");
  const double depth = detail::require_positive(p, "frame_depth");
  const Fn c = gallery_curve("tennis_racket_cross")(x(0));
  return cat({c[0] * (width / 2.0), c[1] * (depth / 2.0)});
}

Fn tennis_racket_wire(const ParameterValues& p) {
  const double width = detail::require_positive(p, "head_width");
  const double length = detail::require_positive(p, "head_length");
  const Fn w = gallery_curve("tennis_racket_head")(x(0));
  return cat({w[0] * (width / 2.0), w[1] * (length / 2.0)});
}

namespace detail {

Model tennis_racket_model() {
  Model m;
  m.name = "tennis_racket";
  m.description = "thesis Fig 3.4: wire product of a rounded-rectangle cross section along the closed racket-head oval";
  m.parameters = {{"head_width", 1.4, "width of the head oval (its x extent is about 0.9 head_width)"},
                  {"head_length", 1.8, "length of the head oval along y (throat to tip)"},
                  {"frame_width", 0.05, "width of the frame's cross section, in the head's plane"},
                  {"frame_depth", 0.1, "depth of the frame's cross section, along z"}};
  m.build = [](const ParameterValues& p) {
    // The frame must be thin against the head (the wire product self-intersects where the
    // wire's radius of curvature is below the cross section's half width).
    const double frame = require_positive(p, "frame_width");
    const double head = std::min(require_positive(p, "head_width"), require_positive(p, "head_length"));
    if (!(frame < 0.25 * head))
      throw std::invalid_argument("parameter 'frame_width' must be < 0.25 min(head_width, head_length), got " +
                                  std::to_string(frame));
    return wire_product(tennis_racket_cross(p), curve_in(tennis_racket_wire(p), 1), 1);
  };
  m.periodic_u = true;
  m.periodic_v = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
